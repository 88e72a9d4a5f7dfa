"""CPL system functions of manual chapter 4 on the simulated controller (CPL manual §4.2-4.14, L1240-3343).

SYSTEM_FUNCTIONS has the row format of builtins.FUNCTIONS (table.Builtin; merged there); ``refs`` names argument
positions passed by name (a field the function fills), ``out`` the one variable it writes back (MCODS's
version). SYSTEM_PROCS are the statement forms: ``FXC(...)=v`` and friends (name ending in '=') and the
procedures FXCR, FXDEL, FXINS.
"""

from __future__ import annotations

from ....nc import threads
from ..table import Builtin
from . import areas, ncs, offsets, plc, positions, sercos, sysdata, tools, transforms
from .context import SystemContext


def _b(impl, lo, hi, res, section, **kw) -> Builtin:
    return Builtin(impl, lo, hi, res, section, True, **kw)


SYSTEM_FUNCTIONS: dict[str, Builtin] = {
    "AXO": _b(positions.f_axo, 1, 2, "R", "§4.2.1 L1388"),
    "CPOS": _b(positions.f_cpos, 1, 2, "R", "§4.2.1 L1404"),
    "CPROBE": _b(positions.f_cprobe, 1, 2, "R", "§4.2.1 L1430"),
    "WPOS": _b(positions.f_wpos, 1, 3, "R", "§4.2.1 L1475"),
    "MPOS": _b(positions.f_mpos, 1, 3, "R", "§4.2.2 L1539"),
    "PPOS": _b(positions.f_ppos, 1, 2, "R", "§4.2.2 L1567"),
    "PROBE": _b(positions.f_probe, 1, 2, "R", "§4.2.2 L1619"),
    "APOS": _b(positions.f_apos, 1, 1, "R", "§4.2.3 L1662"),
    "SPOS": _b(positions.f_spos, 1, 1, "R", "§4.2.3 L1688"),
    "FXC": _b(offsets.f_fxc, 1, 4, "R", "§4.3 L1724"),
    "FILEACCESS": _b(offsets.f_fileaccess, 1, 1, "I", "§6 L4406, §4.3 L1809", io=True, params="S"),
    "TC": _b(tools.f_tc, 1, 4, "R", "§4.4 L1842"),
    "COF": _b(transforms.f_cof, 1, 2, "R", "§4.6 L1967"),
    "DPC": _b(transforms.f_dpc, 1, 2, "R", "§4.7 L1990"),
    "SCL": _b(transforms.f_scl, 1, 3, "R", "§4.8 L2020"),
    "TDA": _b(tools.f_tda, 3, 4, "?", "§4.5 L1895"),
    "SD": _b(sysdata.f_sd, 1, 4, "I", "§4.9 L2196"),
    "SDR": _b(sysdata.f_sdr, 1, 3, "R", "§4.9 L2313"),
    "SCS": _b(sercos.f_scs, 3, 4, "?", "§4.9 L2114", out=3),
    "SCSL": _b(sercos.f_scsl, 4, 5, "I", "§4.9 L2167", out=4),
    "MCA": _b(sysdata.f_mca, 2, 3, "?", "§4.9 L2054"),
    "NCF": _b(sysdata.f_ncf, 1, 1, "S", "§4.9 L2090"),
    "AXP": _b(ncs.f_axp, 2, 3, "S", "§4.10 L2352"),
    "IC": _b(plc.f_ic, 1, 3, "B", "§4.11 L2379"),
    "PLC": _b(plc.f_plc, 4, 4, "I", "§4.11 L2420"),
    "CLOCK": _b(plc.f_clock, 0, 0, "I", "§4.12 L2472"),
    "DATE": _b(plc.f_date, 0, 0, "S", "§4.12 L2490"),
    "TIME": _b(plc.f_time, 0, 0, "S", "§4.12 L2498"),
    "GETERR": _b(plc.f_geterr, 3, 4, "I", "§4.13 L2508", refs=(2,)),
    "MCODS": _b(ncs.f_mcods, 5, 8, "I", "§4.14.3 L2687", refs=(3,), out=2),
    "MCOPS": _b(ncs.f_mcops, 2, 6, "I", "§4.14.4 L3128"),
}

#: statement forms: name -> (implementation, min args, max args) with the assigned value as the last argument
SYSTEM_PROCS = {
    "FXC=": (offsets.p_fxc_set, 2, 5),
    "TC=": (tools.p_tc_set, 2, 5),
    "TDA=": (tools.p_tda_set, 4, 5),
    "IC=": (plc.p_ic_set, 2, 4),
    "PLC=": (plc.p_plc_set, 5, 5),
    "FXCR": (offsets.p_fxcr, 2, 3),
    "FXDEL": (offsets.p_fxdel, 2, 2),
    "FXINS": (offsets.p_fxins, 3, 4),
}


def setup(rt: SystemContext) -> None:
    """At program start: the active ZS table and K4 are the NC kernel's offsets and tools; the kernel
    knows the G functions of the transformations (G60/G67, G37-G39, G138); the active work areas and
    dead ranges watch the motion."""
    offsets.setup(rt)
    areas.setup(rt)
    tools.setup(rt)
    transforms.setup(rt)
    rt.kernel.g_handlers.update(threads.FEED_MODES)  # G94/G95, feed per minute or per revolution (L2817)
