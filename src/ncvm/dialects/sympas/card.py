"""The simulated APCI-8001/8008 card: axes, system registers, spooler, scheduler of the 4 tasks.

Everything runs on one deterministic 64 us clock (digest §10.1): the task with
the smallest local time runs until it waits or passes the others by a slice,
timed actions (scenario inputs, SSF entries) are applied in time order, and
axis positions are computed from the motion profiles at the asking task's time.
"""

from __future__ import annotations

import heapq
import math

from ...diagnostics import Frame, RuntimeFault, Span
from ...runtime.locate import generated_frames
from . import recording
from .commands import Commands
from .motion import TICKS_PER_S, Move
from .task import ENDED, ERROR, RUNNING, STOPPED, Task
from .values import MAX_COUNTS, beyond_counts, fault

PU_FACTOR = {0: 1.0, 1: 25.4, 2: 1000.0, 3: 360.0, 4: 1.0, 5: 180.0 / math.pi}
EVENT_INPUTS = {"EVEO": ("EO",), "EVDNR": ("DR",), "EVLSH": ("LSL", "LSR"), "EVUI": ("UI",)}


class AxisState:
    """One axis channel (digest §10.3). Positions are machine coordinates in axis units."""

    def __init__(self, number: int, name: str, cfg_axis, cfg: dict):
        self.number = number
        self.name = name
        self.m = 0.0  # machine position at rest (or at the start of `move`)
        self.target = 0.0  # last programmed end (machine)
        self.move: Move | None = None
        self.ref = 0.0  # home shift: user = machine - ref - zerooffset - ZO
        self.zerooffset = 0.0
        self.closed = bool(cfg["loop_closed"])
        self.homed = False
        self.flags = 0  # sticky axst flags (refused, saf, home_failed, spool_halted)
        self.digi = 0
        self.digo = 0
        self.ifs = 0
        self.poserr = 0.0
        self.ovr = 1.0  # path override (UTROVR), 0 = feed hold
        self.spool: list = []
        self.spool_halted = False
        acc = cfg_axis.accel
        self.q = {"jvl": cfg_axis.rapid / 60.0, "jac": acc, "jtv": 0.0, "jovr": 1.0, "sdec": acc,
                  "hvl": cfg_axis.max_feed / 600.0, "hac": acc, "ipw": 0.01, "mpe": 1.0,
                  "maxvel": cfg_axis.max_feed / 60.0, "maxacc": acc, "mdvel": 0.0, "jerkrel": 0.0,
                  "sll": cfg_axis.min, "slr": cfg_axis.max, "effradius": 1.0, "gf": 1.0, "gfax": 1.0,
                  "slsp": 4000.0, "dpoffset": 0.0, "dvoffset": 0.0, "aux": 0.0, "lp": 0.0, "lpndx": 0.0,
                  "gcr": 0, "mcp": 0, "sf": 0, "epc": 0, "CFLAGS": 0, "pprev": 0.0}
        self.active = {k: 0.0 for k in ("kp", "ki", "kd", "kpl", "kfca", "kfcv")}
        self.active["kp"] = 1.0
        self.staged = dict(self.active)


class Card(Commands):
    def __init__(self, session, cfg: dict):
        self.session = session
        self.cfg = cfg
        self.q = int(cfg["statements_per_tick"])
        self.servo = float(cfg["servo_ticks"])
        self.slice = float(cfg["task_slice_ticks"])
        self.clock0 = int(cfg["clock_start"]) & 0xFFFFFFFF
        self.canon = session.canon
        machine = session.machine
        self.names = cfg["axis_names"]
        self.axes = [AxisState(i, n, a, cfg) for i, (n, a) in enumerate(zip(self.names, machine.axes))]
        start = machine.start_position or [0.0] * len(self.axes)
        for ax, p in zip(self.axes, start):
            ax.m = ax.target = float(p)
        self.rotary = [a.rotary for a in machine.axes]
        self.sys = {"MODEREG": 0, "ERRORREG": 0, "CFLAG": 0, "GFAUX": 1.0, "IRQPC": False, "LEDGN": False,
                    "LEDRD": False, "LEDYL": False, "NOA": len(self.axes), "BOARDTYPE": int(cfg["boardtype"]),
                    "OSVERSION": int(cfg["osversion"])}
        self.ci = [0] * 1000
        self.cd = [0.0] * 1000
        self.zo = {int(k): [float(x) for x in v] for k, v in cfg["zero_offsets"].items()}
        self.active_zo = 0
        self.tasks = [Task(self, n) for n in range(4)]
        self.steps = 0
        self.acts = 0  # counts the moments a task may have changed the card (see quiet_until)
        self.timed_done = 0  # timed actions and scenario events carried out so far
        self.step_limit = session.steps.limit - session.steps.steps
        self.timed: list = []  # heap of (tick, seq, fn)
        self._seq = 0
        self.moves: list[Move] = []
        self.inputs = list(cfg["inputs"])
        from ...diagnostics import UsageError
        for i, inp in enumerate(self.inputs):
            if inp.get("axis") not in self.names:
                raise UsageError(f"{machine.source}: key 'sympas.inputs[{i}].axis' names no axis of the card")
        for name in cfg["ref_positions"]:  # a REF switch of no axis would be ignored unseen
            if name not in self.names:
                raise UsageError(f"{machine.source}: key 'sympas.ref_positions.{name}' names no axis of the card "
                                 f"(axes: {', '.join(self.names)})")
        for ev in machine.scenario:
            self.add_timed(ev.time * TICKS_PER_S, self._scenario_action(ev))
        self.irq_count = 0
        self.fault: RuntimeFault | None = None  # the first run-time error of a task (reported at the end)
        self.live: set = set()  # moves that have not retired yet
        self.solo = None  # the only running task, when there is just one
        self.counts = float(cfg["counts_per_unit"])
        self.refused_mask = 1 << cfg["axst_bits"]["refused"]
        self.recordings: dict = {}  # axis number -> LPR/LPRS Recording (recording.py)
        self.planning_chain = False  # SSMS is planning a chain: no feed hold on its single segments

    # -- timed actions -----------------------------------------------------------------------------
    def add_timed(self, tick: float, fn) -> None:
        self._seq += 1
        heapq.heappush(self.timed, (tick, self._seq, fn))
        for tk in self.tasks:  # the running task must come back to the scheduler in time for it
            if tk.state == RUNNING and tk.check_at > tick:
                tk.check_at = tick
                tk.set_budget()

    def next_timed(self) -> float:
        return self.timed[0][0] if self.timed else math.inf

    def apply_timed(self, upto: float) -> None:
        while self.timed and self.timed[0][0] <= upto:
            _, _, fn = heapq.heappop(self.timed)
            fn()
            self.timed_done += 1

    def _scenario_action(self, ev):
        d = ev.data
        from ...diagnostics import UsageError
        if ev.kind == "input":
            ax = self._axis_by_name(d.get("axis"), "scenario input")
            bit = int(d.get("bit", 0))
            if not 1 <= bit <= 32:
                raise UsageError("scenario input: 'bit' must be 1..32")
            mask = 1 << (bit - 1)
            value = bool(d.get("value", True))

            def act():
                ax.digi = (ax.digi | mask) if value else (ax.digi & ~mask)
            return act
        if ev.kind == "poserr":
            ax = self._axis_by_name(d.get("axis"), "scenario poserr")
            value = float(d.get("value", 0.0))

            def act():
                ax.poserr = value
            return act
        if ev.kind == "ci":
            idx, value = int(d.get("index", 0)), int(d.get("value", 0))

            def act():
                self.ci[idx] = value
            return act
        raise UsageError(f"scenario kind '{ev.kind}' is not known to the sympas card (input, poserr, ci)")

    def _axis_by_name(self, name, what):
        from ...diagnostics import UsageError
        if name is None:  # a CPL or SINUMERIK event names no axis
            raise UsageError(f"{what}: no axis given: rw_SymPas events name one with axis = ... "
                             f"(axes: {', '.join(self.names)})")
        if name not in self.names:
            raise UsageError(f"{what}: unknown axis '{name}' (axes: {', '.join(self.names)})")
        return self.axes[self.names.index(name)]

    # -- events (§6.4) --------------------------------------------------------------------------------
    def input_active(self, ax: AxisState, inp: dict) -> bool:
        level = bool(ax.digi >> (int(inp["bit"]) - 1) & 1)
        return level != bool(inp.get("active_low", False))

    def event_active(self, name: str, t: float) -> bool:
        if name in EVENT_INPUTS:
            funcs = EVENT_INPUTS[name]
            for inp in self.inputs:
                if inp.get("function") in funcs:
                    ax = self.axes[self.names.index(inp["axis"])]
                    active = self.input_active(ax, inp)
                    if name == "EVDNR":
                        active = not active  # drive not ready: the DR input became inactive
                    if active:
                        return True
            return False
        if name == "EVLSS":
            if self.cfg["soft_limit_reaction"] not in ("TOM", "SMA"):
                return False
            for ax in self.axes:
                p = self.mpos(ax, t)
                if p < ax.q["sll"] or p > ax.q["slr"]:
                    return True
            return False
        if name == "EVMPE":
            return any(ax.closed and abs(ax.poserr) > ax.q["mpe"] for ax in self.axes)
        return False

    # -- positions ----------------------------------------------------------------------------------------
    def check_axis(self, ax: int) -> AxisState:
        if not 0 <= ax < len(self.axes):
            fault(256, f"axis number {ax} outside 0..{len(self.axes) - 1}")
        return self.axes[ax]

    def mpos(self, a: AxisState, t: float) -> float:
        mv = a.move
        if mv is None:
            return a.m
        return mv.pos(t)[mv.axes.index(a.number)]

    def axis_velocity(self, a: AxisState, t: float) -> float:
        """The axis's share of its move's path velocity at ``t`` (units/s, signed)."""
        mv = a.move
        if mv is None or mv.t1 <= t:
            return 0.0
        return mv.velocity(t, a.number)

    def user_shift(self, a: AxisState) -> float:
        zo = self.zo.get(self.active_zo)
        return a.ref + a.zerooffset + (zo[a.number] if zo and a.number < len(zo) else 0.0)

    def busy(self, a: AxisState, t: float) -> bool:
        return a.move is not None and a.move.t1 > t

    def axst(self, a: AxisState, t: float) -> int:
        b = self.cfg["axst_bits"]
        v = a.flags
        if (not self.busy(a, t) or a.move.drift) and not a.spool:
            v |= 1 << b["profile_end"]
            if abs(a.poserr) <= a.q["ipw"]:
                v |= 1 << b["in_position"]
        if a.closed:
            v |= 1 << b["loop_closed"]
        if a.homed:
            v |= 1 << b["homed"]
        for inp in self.inputs:
            if inp["axis"] == a.name and self.input_active(a, inp):
                key = {"EO": "eo", "LSL": "lsh_left", "LSR": "lsh_right"}.get(inp.get("function"))
                if key:
                    v |= 1 << b[key]
        p = self.mpos(a, t)
        if p < a.q["sll"]:
            v |= 1 << b["lss_left"]
        if p > a.q["slr"]:
            v |= 1 << b["lss_right"]
        if a.closed and abs(a.poserr) > a.q["mpe"]:
            v |= 1 << b["mpe"]
        return v

    # -- qualifiers (§6.3.3) ---------------------------------------------------------------------------------
    def get_qual(self, tk, ax: int, name: str):
        a = self.check_axis(ax)
        t = tk.time
        if name in ("dp", "rp"):
            u = self.mpos(a, t) - self.user_shift(a)
            return u - a.poserr if name == "rp" else u
        if name == "tp":
            return a.target - self.user_shift(a)
        if name in ("dv", "rv"):
            return self.axis_velocity(a, t)
        if name == "poserr":
            return a.poserr
        if name == "zerooffset":
            return a.zerooffset
        if name == "axst":
            return self.axst(a, t)
        if name in ("digi", "digo", "ifs"):
            return getattr(a, name)
        if name in ("kp", "ki", "kd", "kpl", "kfca", "kfcv"):
            return a.staged[name]
        if name == "lsm":  # the running chain's unfinished segments still hold their entries
            return (int(self.cfg["spool_capacity"]) - self.spool_used(ax, t)) * 64
        if name == "mcis":
            return sum(1 for e in a.spool if e[0] == "move") + self.chain_pending(ax, t)
        return a.q[name]

    def set_qual(self, tk, ax: int, name: str, value) -> None:
        a = self.check_axis(ax)
        if isinstance(value, float) and not math.isfinite(value):
            # NaN or inf (a math function's "no valid return value") as a position, velocity or gain
            fault(32768, f"{a.name}.{name} := {value}: not a valid parameter value")
        if name in ("digi", "ifs"):
            setattr(a, name, 0 if name == "ifs" else a.digi)  # writing clears the latched flags (L1444)
            return
        if name == "digo":
            a.digo = value & 0xFFFFFFFF
            return
        if name == "dp":
            shift = self.user_shift(a)
            self._retire(a, tk.time)
            a.m = a.target = value + shift
            return
        if name in ("kp", "ki", "kd", "kpl", "kfca", "kfcv"):
            a.staged[name] = value
            return
        a.q[name] = value

    def get_bit(self, tk, ax: int, squal: str, bit: int) -> bool:
        word = {"digib": "digi", "digob": "digo", "ifsb": "ifs", "axstb": "axst"}[squal]
        return bool(self.get_qual(tk, ax, word) >> (bit - 1) & 1)

    def set_bit(self, ax: int, squal: str, bit: int, value: bool) -> None:
        a = self.check_axis(ax)
        mask = 1 << (bit - 1)
        a.digo = (a.digo | mask) if value else (a.digo & ~mask)

    # -- system registers ----------------------------------------------------------------------------------------
    def get_sys(self, name: str):
        if name.startswith("CI"):
            return self.ci[int(name[2:])]
        if name.startswith("CD"):
            return self.cd[int(name[2:])]
        if name == "CFLAG":
            return self.axes[0].q["CFLAGS"]
        if name == "GFAUX":
            return self.axes[0].q["gfax"]
        return self.sys[name]

    def set_sys(self, tk, name: str, value) -> None:
        if name.startswith("CI"):
            self.ci[int(name[2:])] = value
        elif name.startswith("CD"):
            self.cd[int(name[2:])] = value
        elif name == "CFLAG":
            for a in self.axes:
                a.q["CFLAGS"] = value
        elif name == "GFAUX":
            for a in self.axes:
                a.q["gfax"] = value
        else:
            if name == "IRQPC" and value and not self.sys["IRQPC"]:
                self.irq_count += 1  # the host's interrupt service routine would run now
            self.sys[name] = value

    # -- motion helpers ------------------------------------------------------------------------------------------------
    def _retire(self, a: AxisState, t: float) -> None:
        mv = a.move
        if mv is None:
            return
        if mv.t1 > t:
            mv.stop(t, math.inf)
        self._finish(mv)

    def _finish(self, mv: Move) -> None:
        self.live.discard(mv)
        fin = mv.final()
        for k, ax in enumerate(mv.axes):
            a = self.axes[ax]
            if a.move is mv:
                a.m = fin[k]
                a.move = None
        mv.emit(self.canon, len(self.axes))

    def settle(self, axes, t: float) -> None:
        """Retire finished moves of ``axes`` (positions become rest positions)."""
        for ax in axes:
            mv = self.axes[ax].move
            if mv is not None and mv.t1 <= t:
                self._finish(mv)

    def all_positions(self, t: float) -> tuple:
        return tuple(self.mpos(a, t) for a in self.axes)

    def units(self, tk) -> tuple[float, float]:
        """Factors turning PU into axis units and PU/TU into units per second (§6.3.1.2)."""
        pu = int(tk.sysp["PU"])
        tu = int(tk.sysp["TU"])
        if pu in (6, 7):
            f = 1.0 / float(self.cfg["counts_per_unit"])
        elif pu in PU_FACTOR:
            f = PU_FACTOR[pu]
        else:
            fault(256, f"PU = {pu} is not a position unit (0..7)")
        if tu == 0:
            ts = 1.0
        elif tu == 1:
            ts = 60.0
        elif tu == 2:
            ts = self.servo / TICKS_PER_S
        else:
            fault(256, f"TU = {tu} is not a time unit (0..2)")
        return f, ts

    def path_override(self, axes) -> float:
        """The override a path group runs with: the smallest UTROVR factor of its axes."""
        return min(self.axes[ax].ovr for ax in axes)

    def jerk(self, axes) -> float:
        """The S-profile's jerk-limited ramp fraction for a move of ``axes``: with MODEREG bit 1 the
        largest jerkrel of the axes, within 0..1; 0 (trapezoid) without the bit (L1392, L1462)."""
        if not self.sys["MODEREG"] & 0x2:
            return 0.0
        return min(1.0, max(0.0, max(float(self.axes[ax].q["jerkrel"]) for ax in axes)))

    def round_counts(self, x: float) -> float:
        c = float(self.cfg["counts_per_unit"])
        counts = x * c
        if not -MAX_COUNTS <= counts <= MAX_COUNTS:
            beyond_counts(x)
        if self.sys["MODEREG"] & 0x100:
            return x
        return round(counts) / c

    def start_path(self, tk, mv: Move, length: float, loc: int) -> bool:
        """Start a path move at the task's time; False when the card refuses it."""
        t = tk.time
        f, ts = self.units(tk)
        ovr = self.path_override(mv.axes)
        plan = ovr if ovr > 0.0 else 1.0  # under a feed hold the move is planned at 100 % and held
        v = tk.sysp["TRVL"] * f / ts * plan
        acc = tk.sysp["TRAC"] * f / (ts * ts)
        bit = 1 << self.cfg["axst_bits"]["refused"]
        if length <= 0 or v <= 0 or acc <= 0:
            for ax in mv.axes:
                self.axes[ax].flags |= bit
            return False
        for ax in mv.axes:
            a = self.axes[ax]
            a.flags &= ~bit
        mv.start(t, length, v, acc, self.jerk(mv.axes))
        mv.ovr0 = plan
        if ovr <= 0.0 and not self.planning_chain:
            mv.override(t, 0.0, 0.0)  # TROVR = 0: it waits at its start for a raised override
        self.live.add(mv)
        for k, ax in enumerate(mv.axes):
            a = self.axes[ax]
            a.move = mv
            a.target = mv.p1[k]
        return True

    def prepare(self, tk, axes, loc: int, moving=()):
        """Common start of a move command: axis checks, busy rule (not for the ``moving`` axes, which the
        command takes over on the fly), start point."""
        t = tk.time
        for ax in axes:
            self.check_axis(ax)
        if len(set(axes)) != len(axes):
            fault(256, "the same axis appears twice")
        self.settle(axes, t)
        for ax in axes:
            a = self.axes[ax]
            if self.busy(a, t) and ax not in moving:
                if self.cfg["busy_move"] == "refuse":
                    a.flags |= 1 << self.cfg["axst_bits"]["refused"]
                    return None
                self._retire(a, t)
        return self.all_positions(t)

    def wait_axes(self, tk, axes):
        end = max((self.axes[ax].move.t1 for ax in axes if self.axes[ax].move is not None
                   and not self.axes[ax].move.drift), default=0.0)
        end = max([end] + [e[1] for ax in axes for e in self.axes[ax].spool if e[0] == "pending"])
        if end <= tk.time:
            self.settle(axes, tk.time)
            return None
        if end < math.inf and tk.fast_wait(end):
            self.settle(axes, tk.time)
            return None
        return self._wait_axes(tk, axes)

    def _wait_axes(self, tk, axes):
        try:
            while True:
                end = max((self.axes[ax].move.t1 for ax in axes if self.axes[ax].move is not None
                           and not self.axes[ax].move.drift), default=0.0)  # a jog running on at jtv: at profile end
                if end <= tk.time:
                    self.settle(axes, tk.time)
                    return
                yield from tk.wait_until(self.wake_time(tk, end), ends=end)
        finally:
            tk.held = None
            tk.leaves_wait()

    def wake_time(self, tk, until: float) -> float:
        """When a task waiting for ``until`` looks again: at ``until`` if it runs alone, else every servo
        cycle; ``until`` = inf is motion held by TROVR = 0, which only another task, an event or a timed
        action can release (a stall with none of them is RUN005)."""
        if until == math.inf:
            self._check_stall(tk)
            step = tk.time + self.servo
            if not tk.others_running():
                step = max(step, min(self.next_timed(), tk.time + 1000.0 * self.servo))
            return step
        if not tk.others_running():
            return until
        # looking every servo cycle, the task could first see a change at the first of its cycles at or
        # after the moment another task or a timed action can act: it looks then, not in every cycle before
        quiet = self.quiet_until(tk)
        if quiet == math.inf:
            return until
        return min(until, tk.time + self.servo * max(1, math.ceil((quiet - tk.time) / self.servo)))

    def quiet_until(self, tk) -> float:
        """The earliest moment something outside ``tk`` can change the card: another running task acts no
        earlier than its own time (the scheduler runs the earliest task first), a sleeping one when its wait
        ends (as it worked that out, if no task has acted since), a timed action or scenario event at its
        time. Until then only ``tk``'s own motion goes on."""
        t = self.next_timed()
        acts, done = self.acts, self.timed_done
        for o in self.tasks:
            if o is not tk and o.state == RUNNING:
                if o.waits_for is None or o.waits_mark != acts or (o.polls and o.polled != done):
                    at = o.time  # it may act when it looks next: a handler may start after a timed action
                else:
                    at = o.waits_for
                if at < t:
                    t = at
        return t

    def events_follow_motion(self, tk) -> bool:
        """Whether an event ``tk`` has enabled can change while the axes move: EVLSS (an axis crossing its
        soft limit) when the soft-limit reaction raises it. The input events change with timed actions only."""
        return ("EVLSS" in tk.enabled and self.cfg["soft_limit_reaction"] in ("TOM", "SMA")
                and any(a.move is not None for a in self.axes))

    def _check_stall(self, tk) -> None:
        """Run-time error RUN005 when every running task waits on held motion and nothing ran since
        they last looked, with no timed action ahead: no UTROVR can come any more (the card would hang)."""
        quiet = tk.held == self.steps
        tk.held = self.steps
        if not quiet or self.next_timed() < math.inf:
            return
        if all(t.held == self.steps for t in self.tasks if t.state == RUNNING):
            raise RuntimeFault("RUN005", "waiting for ever: the axes are held by TROVR = 0 and no task "
                                         "can raise the override any more")

    # -- system reset and the end of the run -----------------------------------------------------------------------------
    def reset_system(self, t: float) -> None:
        for a in self.axes:
            self._retire(a, t)
            a.spool.clear()
            a.closed = False
        for tk in self.tasks:
            if tk.state == RUNNING:
                tk.state = STOPPED

    def finish(self) -> float:
        """Let running moves end; report them; the run's end time in ticks."""
        end = max([t.time for t in self.tasks] + [0.0])
        for a in self.axes:
            if a.move is not None and not a.move.drift:
                mv = a.move
                stand = mv.t1 if mv.t1 < math.inf else mv.standstill()
                if stand < math.inf:
                    end = max(end, stand)
        for a in self.axes:
            if a.move is not None and a.move.drift:
                a.move.stop(max(end, a.move.t0), math.inf)  # still running on at jtv: reported up to the end
            elif a.move is not None and a.move.t1 == math.inf:
                a.move.stop(end, math.inf)  # held by TROVR = 0 when the programs ended: it stands there
        recording.run_out(self)  # the card goes on sampling after the programs end
        for mv in sorted({id(a.move): a.move for a in self.axes if a.move is not None}.values(), key=lambda m: m.t0):
            self._finish(mv)
        return end

    # -- the scheduler -------------------------------------------------------------------------------------------------------
    def run(self) -> None:
        """Run the tasks until none is running. A run-time error halts only its own task (§8, L2259):
        the others go on, and the first error becomes the run's error when they are done."""
        try:
            self._run()
        except RuntimeFault as e:
            if e.code == "RUN001" and self.fault is not None:
                raise self.fault from None  # the others ran away after the error: the error is the news
            raise
        if self.fault is not None:
            raise self.fault

    def _run(self) -> None:
        tasks = self.tasks
        while True:
            running = [t for t in tasks if t.state == RUNNING]
            if not running:
                return
            tk = min(running, key=lambda t: (t.time, t.number))
            self.solo = tk if len(running) == 1 else None
            self.apply_timed(tk.time)
            if tk.state != RUNNING:
                continue  # a timed action (RS by ForbidTargetVel) halted it
            horizon = math.inf
            for o in running:
                if o is not tk:
                    horizon = min(horizon, o.time + self.slice)
            horizon = min(horizon, self.next_timed())
            if tk.enabled:
                horizon = min(horizon, tk.time)
            tk.check_at = horizon
            tk.set_budget()
            if tk.waits_for is None:
                self.acts += 1  # a task that is not sleeping may change anything
            try:
                next(tk.gen)
            except StopIteration:
                tk.state = ENDED
                tk.enabled.clear()
            except BaseException as e:  # noqa: B036 - every way a task stops is handled or re-raised
                self.capture_locals(tk, e.__traceback__)
                from .task import TaskEnd
                if isinstance(e, TaskEnd):
                    tk.enabled.clear()
                    if e.restart:
                        tk.start(tk.time)
                    else:
                        tk.state = ENDED
                    continue
                if isinstance(e, RuntimeFault) and e.code == "RUN001":
                    raise
                if isinstance(e, RecursionError):
                    fault8 = RuntimeFault("8", "stack overflow: calls nested too deep")
                    fault8.__traceback__ = e.__traceback__
                    e = fault8
                if isinstance(e, RuntimeFault):
                    tk.state = ERROR
                    tk.enabled.clear()
                    located = self.locate(tk, e)
                    if self.fault is None:
                        self.fault = located
                    continue
                raise

    def capture_locals(self, tk, tb) -> None:
        """Keep the main block's locals (its variables) when the task stops by an exception."""
        if tk.unit:
            for g in generated_frames(tb, {tk.unit.pyname: tk.unit.src}):
                if g.frame.f_code.co_name == "_main":
                    tk.main_locals = dict(g.frame.f_locals)

    def locate(self, tk, e: RuntimeFault) -> RuntimeFault:
        if e.span is not None and getattr(e, "number", None) is None:
            return e
        unit = tk.unit
        frames = generated_frames(e.__traceback__, {unit.pyname: unit.src})
        stack = []
        for g in frames:
            name = g.frame.f_code.co_name
            stack.append(Frame("main program" if name == "_main" else name[2:], Span(*unit.locs[g.line])))
        span = stack[-1].span if stack else None
        if e.code == "8" and len(stack) >= 2:
            span = stack[-2].span  # the call that did not fit, not the routine's header
            stack = stack[:-1]
        if len(stack) > 20:
            stack = stack[:5] + [Frame(f"... {len(stack) - 20} more calls ...", None)] + stack[-15:]
        # statements counted but not yet handed to the task when the fault struck
        for g in frames:
            self.steps += int(g.frame.f_locals.get("_n", 0) or 0)
        tk.error |= int(e.code) if e.code.isdigit() else 0
        tk.error_line = span.line if span else 0
        msg = e.message
        if len(self.tasks) and tk.number != 0:
            msg = f"{msg} (task {tk.number})"
        return RuntimeFault(e.code, msg, span, stack)

    def runaway(self):
        self.session.steps.steps += self.steps
        self.steps = 0
        raise RuntimeFault("RUN001", f"step limit of {self.session.steps.limit:,} statements reached "
                                     "(runaway program? raise it with --max-steps)")

