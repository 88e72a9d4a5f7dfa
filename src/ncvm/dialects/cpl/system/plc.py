"""PLC interface (manual §4.11: IC, PLC), time (§4.12: CLOCK, DATE, TIME) and errors (§4.13: GETERR).

Interface bits live in the machine's PLC image under keys "IC(bit,group,index)"; inputs change only by
scenario events (kind "input"), outputs written by IC(bit,0,chan)=... are visible as group 3. PLC memory
is the [cpl] plc table of bytes ("I:10", "D98:2", "T:1" ...), multi-byte values big-endian.
"""

from __future__ import annotations

import time as _time

from ..errors import CplError
from .axes import nul
from .context import SystemContext

#: group -> (highest bit, default index is the channel?)
IC_GROUPS = {0: (111, True), 1: (111, False), 2: (111, False), 3: (95, True), 4: (63, False), 5: (63, False),
             6: (31, False), 7: (31, False), 8: (7, False), 9: (7, False)}
OUTPUT_GROUPS = (3, 4, 5, 7, 9)


def ic_key(rt: SystemContext, bit, group=None, index=None) -> str:
    bit, group = nul(bit), 0 if group is None else group
    if group not in IC_GROUPS:
        raise CplError("CPL023", f"IC group {group}: 0..9")
    top, per_channel = IC_GROUPS[group]
    if bit.__class__ is not int or not 0 <= bit <= top:
        raise CplError("CPL023", f"IC bit {bit!r} of group {group}: 0..{top}")
    if index is None:
        index = rt.ctl.channel if per_channel else 1
    lo, hi = _index_range(rt.ctl, group)
    if index.__class__ is not int or not lo <= index <= hi:
        raise CplError("CPL023", f"IC index {index!r} of group {group}: {lo}..{hi}")
    return f"IC({bit},{group},{index})"


def _index_range(c, group: int) -> tuple[int, int]:
    """The index range of an IC group (L2396-2405): channels 0..max, axes and spindles 1..max, else 1."""
    if group in (0, 3):
        return 0, max([c.channel] + [a.channel for a in c.axes.values()])
    if group in (1, 4):
        return 1, max(c.axes, default=1)
    return 1, 1  # one spindle; the global and HighSpeed interfaces have index 1


def f_ic(rt: SystemContext, bit, group=None, index=None) -> bool:
    """IC read: an interface bit; input groups follow the scenario's timed events (L2379-2418)."""
    key = ic_key(rt, bit, group, index)
    rt._apply_events(rt.t_prep)
    plc = rt.machine.plc
    if (0 if group is None else group) in OUTPUT_GROUPS:
        return bool(plc.outputs.get(key, plc.inputs.get(key, False)))
    value = bool(plc.inputs.get(key, False))
    rt.frozen(f"PLC input IC {key} read as {int(value)}", scenario=True)
    return value


def p_ic_set(rt: SystemContext, bit, group=None, index=None, value=None):
    """IC(bit,0,chan)=bool: only the channel outputs 81..96 (bits 80..95), written with group 0 (L2404)."""
    if group != 0 or bit.__class__ is not int or not 80 <= bit <= 95:
        raise CplError("CPL040", "IC can be written only as IC(80..95,0,channel) (channel outputs 81..96)")
    if value is not True and value is not False:
        raise CplError("CPL032", "IC needs a BOOLEAN value")
    rt.machine.plc.outputs[ic_key(rt, bit, 3, index)] = value


PLC_TYPES = {1: "I", 2: "O", 3: "M", 4: "D", 5: "DB", 6: "DF", 7: "T", 8: "C", 9: "SM", 10: "S", 11: "EI", 12: "EO"}


def _plc_args(rt: SystemContext, ptype, dm, addr, size):
    if ptype not in PLC_TYPES:
        raise CplError("CPL023", f"PLC type {ptype!r}: 1..12")
    if ptype == 4 and dm is None:
        raise CplError("CPL023", "PLC type 4 (D) needs a data module")
    if addr.__class__ is not int or addr < 0:
        raise CplError("CPL023", f"PLC address {addr!r}")
    if size not in (1, 2, 4):
        raise CplError("CPL023", f"PLC size {size!r}: 1, 2 or 4")
    return f"{PLC_TYPES[ptype]}{dm if ptype == 4 else ''}:"


def f_plc(rt: SystemContext, ptype, dm, addr, size):
    """PLC read: bytes big-endian; timers give the remaining ms, counters their value (L2420-2468)."""
    prefix = _plc_args(rt, ptype, dm, addr, size)
    mem = rt.ctl.plc
    if ptype == 7:
        v = max(0, mem.get(f"{prefix}{addr}", 0) - int(rt.t_prep * 1000))
    elif ptype == 8:
        v = mem.get(f"{prefix}{addr}", 0)
    else:
        v = 0
        for k in range(size):
            v = (v << 8) | (mem.get(f"{prefix}{addr + k}", 0) & 0xFF)
        if v >= 1 << (8 * size - 1) and size == 4:
            v -= 1 << 32
    what = {7: "timer", 8: "counter"}.get(ptype, f"{size}-byte value at")
    rt.frozen(f"PLC {what} {prefix}{addr} read as {v} (the simulated PLC: [cpl] plc)")
    return v


def p_plc_set(rt: SystemContext, ptype, dm, addr, size, value=None):
    """PLC(4,dm,addr,size)=value: only data modules MACODA 2060 00100 .. + 2060 00110 - 1 may be written."""
    c = rt.ctl
    prefix = _plc_args(rt, ptype, dm, addr, size)
    first, count = c.macoda[206000100][0], c.macoda[206000110][0]
    if ptype != 4 or not first <= dm < first + count:
        raise CplError("CPL040", f"PLC write only to data modules D{first}..D{first + count - 1}")
    if value.__class__ is not int:
        raise CplError("CPL032", "PLC needs an INTEGER value")
    v = value & ((1 << (8 * size)) - 1)
    for k in range(size - 1, -1, -1):
        c.plc[f"{prefix}{addr + k}"] = v & 0xFF
        v >>= 8


def f_clock(rt: SystemContext) -> int:
    """CLOCK: the system time counter in ms at the program's time (simulated: a WAIT lets it run on to the
    end of the executed blocks, or by its duration, also into the middle of a block still moving)."""
    return int(round(rt.t_prep * 1000.0))


def _now(rt: SystemContext):
    return _time.gmtime(rt.machine.clock.start_epoch + rt.t_prep)


def f_date(rt: SystemContext) -> str:
    t = _now(rt)
    text = f"{t.tm_mday:02d}.{t.tm_mon:02d}"
    text = text if rt.ctl.date_format == "DD.MM" else f"{text}.{t.tm_year % 100:02d}"
    rt.frozen(f"DATE read as {text} (the simulated clock, not the day the new control runs the program)")
    return text


def f_time(rt: SystemContext) -> str:
    t = _now(rt)
    text = f"{t.tm_hour:02d}.{t.tm_min:02d}.{t.tm_sec:02d}"
    rt.frozen(f"TIME read as {text} (the simulated clock, not the hour the new control runs the program)")
    return text


def f_geterr(rt: SystemContext, chan, cat, errarr, count=1):
    """GETERR: fill errarr(k,1..3) with number, channel, category, oldest first; the count of current
    errors for chan and cat, or -1 (L2508-2618)."""
    cat = 0 if cat is None else cat
    if chan.__class__ is not int or (chan != -1 and chan < 1) or cat not in range(11):
        return -1
    errarr, ty = errarr if isinstance(errarr, tuple) else (errarr, None)
    if ty != "I" or not errarr or not isinstance(errarr[0], list) or len(errarr[0]) < 4:
        raise CplError("CPL035", "GETERR needs a 2-dimensional INTEGER field DIM E%(n,3), given by name")
    found = [e for e in rt.ctl.errors
             if (chan == -1 or e["channel"] in (chan, -1)) and (cat == 0 or e["category"] == cat)]
    n = min(count, len(errarr) - 1, len(found))
    for k in range(n):
        e = found[k]
        errarr[k + 1][1], errarr[k + 1][2], errarr[k + 1][3] = e["number"], e["channel"], e["category"]
    return len(found)
