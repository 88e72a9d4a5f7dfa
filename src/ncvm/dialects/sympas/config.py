"""The ``[sympas]`` section of the machine file: the card's configuration and the switchable
provisional choices (status bits, SSF codes, zero offsets, ...) documented in docs/sympas.md."""

from __future__ import annotations

from ...diagnostics import UsageError

AXST_BITS = {"profile_end": 0, "in_position": 1, "loop_closed": 2, "homed": 3, "eo": 4, "dnr": 5,
             "lsh_left": 6, "lsh_right": 7, "lss_left": 8, "lss_right": 9, "mpe": 10, "saf": 11,
             "spool_running": 12, "spool_halted": 13, "refused": 14, "home_failed": 15}
SSF_CODES = {"write_ci": 1, "spool_halt": 1000, "set_output": 1001}

DEFAULTS = {
    "axis_names": None,            # default A1..An, one per machine axis
    "statements_per_tick": 1,      # Q: statements a running task executes per 64 us tick
    "task_slice_ticks": 20,        # ticks a task may run ahead of the others before it yields
    "servo_ticks": 20,             # T_A = 1.28 ms
    "clock_start": 0,              # CLOCK at power-on (to test wrap-around)
    "max_call_depth": 256,         # frame budget: deeper calls are run-time error 8
    "trvl": 100.0, "trac": 1000.0, "trtvl": 0.0, "trovr": 1.0, "pu": 0, "tu": 0,
    "counts_per_unit": 1000.0,     # dp is rounded to whole counts at profile end (unless MODEREG bit 8)
    "axst_bits": AXST_BITS,        # provisional axst layout (digest §10.4)
    "ssf_codes": SSF_CODES,        # provisional SSF function codes (digest A-42b)
    "ssf_ci_index": 1,             # SSF write_ci writes CI<n>
    "zero_offsets": {},            # AZO tables: {"1" = [per axis], ...}
    "dtca_always_relative": False, # MHA target mode: DTCA relative to the start (like MHR)
    "event_trigger": "level",      # "level" (re-fires while active) or "edge"
    "busy_move": "refuse",         # non-spooled move on a moving axis: "refuse" or "override"
    "loop_closed": True,           # position loops closed at power-on
    "spool_capacity": 128,         # entries per axis spooler (8 KiB / 64 bytes)
    "inputs": [],                  # [{axis="A1", bit=1, function="EO"|"DR"|"LSL"|"LSR"|"REF"|"UI", active_low=false}]
    "ref_positions": {},           # machine position of each axis's REF switch (homing), default 0
    "index_period": 1.0,           # distance between index pulses (JHI), axis units
    "write_digits": 10,            # significant digits of single/double in WRITE
    "soft_limit_reaction": "TOM",  # SMD (no event), TOM or SMA (EVLSS fires)
    "load": [],                    # more program files, each loaded into its {$TASK}
    "osversion": 253126, "boardtype": 8001,
}


def sympas_config(machine) -> dict:
    raw = machine.sections.get("sympas", {})
    cfg = dict(DEFAULTS)
    for k, v in raw.items():
        if k not in DEFAULTS:
            raise UsageError(f"{machine.source}: unknown key 'sympas.{k}' (known: {', '.join(sorted(DEFAULTS))})")
        cfg[k] = v
    cfg["axst_bits"] = {**AXST_BITS, **raw.get("axst_bits", {})}
    cfg["ssf_codes"] = {**SSF_CODES, **raw.get("ssf_codes", {})}
    for k in cfg["axst_bits"]:
        if k not in AXST_BITS:
            raise UsageError(f"{machine.source}: unknown key 'sympas.axst_bits.{k}'")
    names = cfg["axis_names"] or [f"A{i + 1}" for i in range(len(machine.axes))]
    if len(names) != len(machine.axes):
        raise UsageError(f"{machine.source}: key 'sympas.axis_names' must name {len(machine.axes)} axes")
    for n in names:
        if not isinstance(n, str) or not n or len(n) > 8:
            raise UsageError(f"{machine.source}: key 'sympas.axis_names': '{n}' must have 1..8 characters")
    cfg["axis_names"] = list(names)
    if cfg["event_trigger"] not in ("level", "edge"):
        raise UsageError(f"{machine.source}: key 'sympas.event_trigger' must be 'level' or 'edge'")
    if cfg["busy_move"] not in ("refuse", "override"):
        raise UsageError(f"{machine.source}: key 'sympas.busy_move' must be 'refuse' or 'override'")
    if int(cfg["statements_per_tick"]) < 1:
        raise UsageError(f"{machine.source}: key 'sympas.statements_per_tick' must be at least 1")
    return cfg
