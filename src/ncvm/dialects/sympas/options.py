"""The ``[sympas]`` section of the machine file: the card's configuration and the switchable
provisional choices (status bits, SSF codes, zero offsets, ...) documented in docs/sympas.md. Its schema,
with the documentation of each key, is machine/sections.py's SYMPAS, which checks it first."""

from __future__ import annotations

from dataclasses import asdict, dataclass, field, replace
from typing import Any

from ...machine.config import dialect_options

AXST_BITS = {"profile_end": 0, "in_position": 1, "loop_closed": 2, "homed": 3, "eo": 4, "dnr": 5,
             "lsh_left": 6, "lsh_right": 7, "lss_left": 8, "lss_right": 9, "mpe": 10, "saf": 11,
             "spool_running": 12, "spool_halted": 13, "refused": 14, "home_failed": 15}
SSF_CODES = {"write_ci": 1, "spool_halt": 1000, "set_output": 1001}


@dataclass
class Options:
    """One field per key of ``[sympas]``. ``busy_move`` is switched by the card while SSF runs a spooled
    entry (commands/spooled.py), so the options are not frozen."""

    axis_names: list[str] | None = None  # default A1..An, one per machine axis
    statements_per_tick: int = 1  # Q: statements a running task executes per 64 us tick
    task_slice_ticks: float = 20  # ticks a task may run ahead of the others before it yields
    servo_ticks: float = 20  # T_A = 1.28 ms
    clock_start: int = 0  # CLOCK at power-on (to test wrap-around)
    max_call_depth: int = 256  # frame budget: deeper calls are run-time error 8
    trvl: float = 100.0
    trac: float = 1000.0
    trtvl: float = 0.0
    trovr: float = 1.0
    pu: int = 0
    tu: int = 0
    counts_per_unit: float = 1000.0  # dp is rounded to whole counts at profile end (unless MODEREG bit 8)
    axst_bits: dict[str, int] = field(default_factory=lambda: dict(AXST_BITS))  # provisional (ncvm's reading; the rw_SymPas manual is silent)
    ssf_codes: dict[str, int] = field(default_factory=lambda: dict(SSF_CODES))  # provisional (rw_SymPas manual L2091)
    ssf_ci_index: int = 1  # SSF write_ci writes CI<n>
    zero_offsets: dict[str, list[float]] = field(default_factory=dict)  # AZO tables: {"1" = [per axis], ...}
    dtca_always_relative: bool = False  # MHA target mode: DTCA relative to the start (like MHR)
    event_trigger: str = "level"  # "level" (re-fires while active) or "edge"
    busy_move: str = "refuse"  # non-spooled move on a moving axis: "refuse" or "override"
    loop_closed: bool = True  # position loops closed at power-on
    spool_capacity: int = 128  # entries per axis spooler (8 KiB / 64 bytes)
    inputs: list[dict[str, Any]] = field(default_factory=list)  # {axis, bit, function, active_low}
    ref_positions: dict[str, float] = field(default_factory=dict)  # REF switch of each axis (homing), default 0
    index_period: float = 1.0  # distance between index pulses (JHI), axis units
    write_digits: int = 10  # significant digits of single/double in WRITE
    soft_limit_reaction: str = "TOM"  # SMD (no event), TOM or SMA (EVLSS fires)
    load: list[str] = field(default_factory=list)  # more program files, each loaded into its {$TASK}
    osversion: int = 253126
    boardtype: int = 8001


#: the [sympas] keys and their defaults
DEFAULTS = asdict(Options())
DEFAULTS["axst_bits"], DEFAULTS["ssf_codes"] = AXST_BITS, SSF_CODES


def sympas_config(machine) -> Options:
    """The [sympas] section of the machine, checked, with the axis names and the bit and code tables filled
    in; an unknown key or a wrong value is a usage error."""
    opts = dialect_options(Options, machine.sections, "sympas", machine.axes)
    return replace(opts, axis_names=list(opts.axis_names or [f"A{i + 1}" for i in range(len(machine.axes))]),
                   axst_bits={**AXST_BITS, **opts.axst_bits}, ssf_codes={**SSF_CODES, **opts.ssf_codes})
