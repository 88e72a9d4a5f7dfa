"""The simulated APCI-8001/8008 card: its parts and the state they share.

The card owns its axes (axes.py), the axes' spoolers (spooler.py) and the scheduler of the 4 tasks
(scheduler.py), and holds the system registers, CI/CD, zero offsets and the moves not yet retired. The
manual's commands (commands/), the axis qualifiers (qualifiers.py) and the events (events.py) are
functions over it. Axis positions are computed from the motion profiles at the asking task's time.
"""

from __future__ import annotations

import math

from ...diagnostics import UsageError
from ...machine.scenario import AxisInput, CommonInteger, EventQueue, PositionError
from ...nc.canon import Src
from ...runtime.session import OperatorOutput
from . import recording, softlimits
from .axes import AxisState
from .motion import TICKS_PER_S, Chain, Move
from .options import Options
from .scheduler import Scheduler
from .spooler import Spooler
from .task import RUNNING, STEP, STOPPED
from .timeline import Timeline
from .values import MAX_COUNTS, beyond_counts, fault

PU_FACTOR = {0: 1.0, 1: 25.4, 2: 1000.0, 3: 360.0, 4: 1.0, 5: 180.0 / math.pi}


class Card:
    def __init__(self, session, cfg: Options):
        self.session = session
        self.cfg = cfg
        self.canon = session.canon
        # the card times its moves itself (its own velocity profiles), not the path planner
        session.canon.timing(None, None, None)
        session.time_model = "card"
        machine = session.machine
        self.names = cfg.axis_names
        self.axes = [AxisState(i, n, a, cfg) for i, (n, a) in enumerate(zip(self.names, machine.axes))]
        start = machine.start_position or [0.0] * len(self.axes)
        for ax, p in zip(self.axes, start):
            ax.m = ax.target = float(p)
        self.rotary = [a.rotary for a in machine.axes]
        self.sys = {"MODEREG": 0, "ERRORREG": 0, "CFLAG": 0, "GFAUX": 1.0, "IRQPC": False, "LEDGN": False,
                    "LEDRD": False, "LEDYL": False, "NOA": len(self.axes), "BOARDTYPE": int(cfg.boardtype),
                    "OSVERSION": int(cfg.osversion)}
        self.ci = [0] * 1000
        self.cd = [0.0] * 1000
        self.zo = {int(k): [float(x) for x in v] for k, v in cfg.zero_offsets.items()}
        self.active_zo = 0
        self._work_shift: tuple[float, ...] | None = None  # work_shift() until the zero point moves
        self.spooler = Spooler(self.axes, int(cfg.spool_capacity))
        self.scheduler = Scheduler(self, cfg, session.steps)
        self.inputs = list(cfg.inputs)
        for i, inp in enumerate(self.inputs):
            if inp.get("axis") not in self.names:
                raise UsageError(f"{machine.source}: key 'sympas.inputs[{i}].axis' names no axis of the card")
        for name in cfg.ref_positions:  # a REF switch of no axis would be ignored unseen
            if name not in self.names:
                raise UsageError(f"{machine.source}: key 'sympas.ref_positions.{name}' names no axis of the card "
                                 f"(axes: {', '.join(self.names)})")
        for ev in machine.scenario:
            self._scenario_action(ev)  # an event the card cannot use is refused before the run
        self.scheduler.set_events(EventQueue(machine.scenario), self.apply_event)
        self.irq_count = 0
        self.live: set = set()  # moves that have not retired yet
        self.counts = float(cfg.counts_per_unit)
        self.refused_mask = 1 << cfg.axst_bits["refused"]
        self.recordings: dict = {}  # axis number -> LPR/LPRS Recording (recording.py)
        #: {"task", "text"} of each output line (see say), kept as the result keeps the lines themselves
        self.output_log = OperatorOutput(session.options.max_output_lines)
        self.timeline = Timeline(self, [a.m for a in self.axes])  # reports the retired moves in time order
        #: (file, line) of a statement -> the lowest-numbered task whose program holds it (filled by the front end)
        self.task_at: dict[tuple[str, int], int] = {}
        #: the values a scenario event set ("CI3", "A1.poserr") -> the event: a read of one is a run-time input
        #: (canon ``frozen``; the axes' digital inputs are marked by every read of them)
        self.outside: dict[str, str] = {}

    # -- scenario events ------------------------------------------------------------------------------
    def apply_event(self, ev) -> None:
        """A scenario event whose time has come."""
        self._scenario_action(ev)()
        if ev.__class__ is CommonInteger:
            self.outside[f"CI{ev.index}"] = f"scenario event at {ev.time:g} s"
        elif ev.__class__ is PositionError:
            self.outside[f"{self._axis_by_name(ev.axis, 'scenario poserr').name}.poserr"] = f"scenario event at {ev.time:g} s"

    def read_outside(self, key: str, value) -> None:
        """The program read ``key``, which a scenario event set: the path from here may depend on it."""
        self.canon.frozen(f"{key} read as {value} (set by the {self.outside[key]})", None)

    def _scenario_action(self, ev):
        """The card's action for a scenario event (machine/scenario.py): an axis' digital input, its
        following error or a common integer; any other event is refused before the run."""
        if ev.__class__ is AxisInput:
            ax = self._axis_by_name(ev.axis, "scenario input")
            mask = 1 << (ev.bit - 1)
            value = ev.value

            def act():
                ax.digi = (ax.digi | mask) if value else (ax.digi & ~mask)
            return act
        if ev.__class__ is PositionError:
            ax = self._axis_by_name(ev.axis, "scenario poserr")
            value = ev.value

            def act():
                ax.poserr = value
            return act
        if ev.__class__ is CommonInteger:
            idx, value = ev.index, ev.value

            def act():
                self.ci[idx] = value
            return act
        if ev.kind == "input":  # an input written for CPL (address) or SINUMERIK (byte)
            self._axis_by_name(None, "scenario input")
        raise UsageError(f"scenario event at {ev.time:g} s: {ev.form}, which the sympas card cannot use "
                         f"(it takes input with axis and bit, poserr, ci)")

    def _axis_by_name(self, name, what):
        if name is None:  # a CPL or SINUMERIK event names no axis
            raise UsageError(f"{what}: no axis given: rw_SymPas events name one with axis = ... "
                             f"(axes: {', '.join(self.names)})")
        if name not in self.names:
            raise UsageError(f"{what}: unknown axis '{name}' (axes: {', '.join(self.names)})")
        return self.axes[self.names.index(name)]

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

    def work_shift(self) -> tuple[float, ...]:
        """Per axis, machine position less user position now: the REF point of homing and the zero offsets.
        Asked for every move when a sink takes frames (the plot): kept until :meth:`zero_moved`."""
        shift = self._work_shift
        if shift is None:
            shift = self._work_shift = tuple(self.user_shift(a) for a in self.axes)
        return shift

    def zero_moved(self) -> None:
        """An axis's REF point (``ref``) or zero offset (``zerooffset``), or the active zero offset (AZO)
        changed: every statement that changes one calls this, so that :meth:`work_shift` is worked out anew."""
        self._work_shift = None
        self.timeline.zero_moved = True

    def busy(self, a: AxisState, t: float) -> bool:
        return a.move is not None and a.move.t1 > t

    # -- system registers ----------------------------------------------------------------------------------------
    def get_sys(self, name: str):
        if name.startswith("CI"):
            value = self.ci[int(name[2:])]
            if self.outside and name in self.outside:
                self.read_outside(name, value)
            return value
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
    def retire_axis(self, a: AxisState, t: float) -> None:
        mv = a.move
        if mv is None:
            return
        if mv.t1 > t:
            mv.stop(t, math.inf)
        self.retire(mv)

    def retire(self, mv: Move) -> None:
        self.live.discard(mv)
        exact = self.sys["MODEREG"] & 0x100  # ExactTargetPos (L1399): no rounding to whole counts
        c = self.counts
        last = mv.segs[-1] if isinstance(mv, Chain) else mv
        if not exact and last.stop_s is not None:  # stopped on the way: it stands on whole counts, and the
            # reported path ends there too (the bounds enclose the position)
            last.stop_p = tuple(round(x * c) / c if math.isfinite(x) else x for x in last.final())
            if last is not mv:
                mv.refresh()
        fin = mv.final()
        for k, ax in enumerate(mv.axes):
            a = self.axes[ax]
            if a.move is mv:
                a.m = fin[k] if exact or not math.isfinite(fin[k]) else round(fin[k] * c) / c
                a.move = None
        mv.emit(self.timeline)

    def horizon(self) -> float:
        """The earliest tick at which a move can still begin or change: a move not retired yet (a chain's
        first segment not retired), or a new move of a running task (at its time or later)."""
        # a stopped task goes on (CONTCNCT, STEPCNCT) at the time of the task that lets it: only running ones count
        t = min((tk.time for tk in self.scheduler.tasks if tk.state == RUNNING), default=math.inf)
        for mv in self.live:
            segs = getattr(mv, "segs", None)
            t0 = min((m.t0 for m in segs if not m.retired), default=mv.t0) if segs else mv.t0
            t = min(t, t0)
        for a in self.axes:
            if a.move is not None and a.move not in self.live:
                t = min(t, a.move.t0)
        return t

    def settle(self, axes, t: float) -> None:
        """Retire finished moves of ``axes`` (positions become rest positions)."""
        for ax in axes:
            mv = self.axes[ax].move
            if mv is not None and mv.t1 <= t:
                self.retire(mv)

    def all_positions(self, t: float) -> tuple:
        return tuple(self.mpos(a, t) for a in self.axes)

    def units(self, tk) -> tuple[float, float]:
        """Factors turning PU into axis units and PU/TU into units per second (§6.3.1.2)."""
        pu = int(tk.sysp["PU"])
        tu = int(tk.sysp["TU"])
        if pu in (6, 7):
            f = 1.0 / float(self.cfg.counts_per_unit)
        elif pu in PU_FACTOR:
            f = PU_FACTOR[pu]
        else:
            fault(256, f"PU = {pu} is not a position unit (0..7)")
        if tu == 0:
            ts = 1.0
        elif tu == 1:
            ts = 60.0
        elif tu == 2:
            ts = self.scheduler.servo / TICKS_PER_S
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
        c = float(self.cfg.counts_per_unit)
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
        if length <= 0 or v <= 0 or acc <= 0:
            why = "no travel" if length <= 0 else "TRVL = 0" if v <= 0 else "TRAC = 0"
            self.refuse(tk, mv.axes, why, loc)
            return False
        for ax in mv.axes:
            a = self.axes[ax]
            a.flags &= ~self.refused_mask
        mv.start(t, length, v, acc, self.jerk(mv.axes))
        if not math.isfinite(mv.t1):
            self.refuse(tk, mv.axes, f"TRVL = {tk.sysp['TRVL']:g}: the profile would never end", loc)
            return False
        mv.ovr0 = plan
        if ovr <= 0.0 and not self.spooler.planning_chain:
            mv.override(t, 0.0, 0.0)  # TROVR = 0: it waits at its start for a raised override
        self.live.add(mv)
        for k, ax in enumerate(mv.axes):
            a = self.axes[ax]
            a.move = mv
            a.target = mv.p1[k]
        if not self.spooler.planning_chain:  # a chain is watched when its times are planned (spooled.py)
            softlimits.watch(self, mv)
        return True

    def say(self, text: str, task: int | None) -> None:
        """An output line and, for the JSON document's ``sympas.output``, the task it came from (None: the
        card's own, e.g. a soft-limit stop of a move whose command no loaded task holds)."""
        self.session.say(text)
        self.output_log.append({"task": task, "text": text})

    def task_of(self, src: Src) -> int | None:
        """The task whose program holds the statement at ``src`` (the lowest-numbered one for a file two
        tasks include)."""
        return self.task_at.get(src)

    def refuse(self, tk, axes, why: str, loc) -> None:
        """The card discards a path profile: the axes' refused bit, and a message (L1415) unless MODEREG
        bit 29 (InhibitProfileRefuse) suppresses it."""
        for ax in axes:
            self.axes[ax].flags |= self.refused_mask
        if self.sys["MODEREG"] & (1 << 29):
            return
        src = loc if isinstance(loc, Src) else tk.unit.srcs[loc]
        names = ", ".join(self.names[ax] for ax in axes)
        task = f" (task {tk.number})" if tk.number else ""
        self.say(f"{src.file}:{src.line}: profile refused: {why} ({names}){task}", tk.number)

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
                if self.cfg.busy_move == "refuse":
                    self.refuse(tk, axes, f"axis {a.name} is still in a profile", loc)
                    return None
                self.retire_axis(a, t)
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
                yield from tk.wait_until(self.scheduler.wake_time(tk, end), ends=end)
        finally:
            tk.held = None
            tk.leaves_wait()

    def summary(self) -> dict:
        """The card's part of the run's JSON document (``sympas``)."""
        tasks = []
        for tk in self.scheduler.tasks:
            if tk.unit is None:
                continue
            where = tk.where() if tk.state in (RUNNING, STOPPED, STEP) else None
            tasks.append({"task": tk.number, "program": tk.unit.prog.name, "state": tk.state,
                          "file": where[0] if where else None, "line": where[1] if where else None,
                          "error": tk.error, "error_line": tk.error_line or None})
        rec, work = self.session.recorder, self.session.work_bounds
        bounds = rec.summary().bounds if rec is not None else {}
        program = work.bounds(bounds) if work is not None else {}  # each move less the zero offsets it ran with
        machine = self.session.machine.axis_names
        axes = {}
        for a in self.axes:
            shift = self.user_shift(a)
            name = machine[a.number]
            axes[a.name] = {"machine_axis": name, "position": a.m - shift, "machine_position": a.m,
                            "bounds_machine": bounds.get(name), "bounds_program": program.get(name)}
        return {"profile_length": round(self.timeline.profile_length, 9), "tasks": tasks,
                "axes": axes, "frames": "position: the program's coordinates (dp) with the zero offsets in force "
                                        "at the end; bounds_program: each move's, with the zero offsets it ran "
                                        "with; machine_position, bounds_machine: the machine's",
                "ci": {str(i): v for i, v in enumerate(self.ci) if v},
                "cd": {str(i): v for i, v in enumerate(self.cd) if v},
                "output": self.output_log.lines()}

    def _motion_end(self) -> float:
        """The tick at which the axes' moves (not a jog running on at jtv) have come to a stand."""
        end = 0.0
        for a in self.axes:
            if a.move is not None and not a.move.drift:
                mv = a.move
                stand = mv.t1 if mv.t1 < math.inf else mv.standstill()
                if stand < math.inf:
                    end = max(end, stand)
        return end

    # -- system reset and the end of the run -----------------------------------------------------------------------------
    def reset_system(self, t: float) -> None:
        for a in self.axes:
            self.retire_axis(a, t)
            a.spool.clear()
            a.closed = False
        for tk in self.scheduler.tasks:
            if tk.state == RUNNING:
                tk.state = STOPPED

    def finish(self) -> float:
        """Let running moves end, with the card still watching them (soft limits, SSF entries, homing
        latches and scenario events act up to their end as while a task ran); report them; the run's
        end time in ticks."""
        idle = self.scheduler.idle_end
        end = idle if idle is not None else max([t.time for t in self.scheduler.tasks] + [0.0])
        while True:
            end = max(end, self._motion_end())
            due = self.scheduler.next_timed()
            if due > end or self.scheduler.fault is not None:
                break
            self.scheduler.apply_timed(due)  # may stop a move (a soft limit) or start one (a drift)
        for a in self.axes:
            if a.move is not None and a.move.drift:
                a.move.stop(max(end, a.move.t0), math.inf)  # still running on at jtv: reported up to the end
            elif a.move is not None and a.move.t1 == math.inf:
                a.move.stop(end, math.inf)  # held by TROVR = 0 when the programs ended: it stands there
        recording.run_out(self)  # the card goes on sampling after the programs end
        for mv in sorted({id(a.move): a.move for a in self.axes if a.move is not None}.values(), key=lambda m: m.t0):
            self.retire(mv)
        for mv in list(self.live):  # started and replaced before they ran (not an axis's move any more)
            self.retire(mv)
        self.timeline.report(math.inf)
        return end
