"""The scheduler of the card's 4 CNC tasks on one deterministic 64 us clock (ncvm's reading; the rw_SymPas manual is silent).

The task with the smallest local time runs until it waits or passes the others by a slice; the scenario
events (machine/scenario.py's ``EventQueue``, times in s) and the card's timed actions (SSF entries, homing
latches, recording samples, drift: a heap in ticks) are applied in one time order, an event before an
action of the same tick.
"""

from __future__ import annotations

import heapq
import math

from ...diagnostics import Frame, RuntimeFault, Span
from ...machine.scenario import EventQueue
from ...runtime.locate import generated_frames
from .motion import TICKS_PER_S
from .options import Options
from .task import ENDED, ERROR, RUNNING, Task, TaskEnd

#: simulated seconds the card must stay quiet (no motion, no timed action or scenario event) before the run
#: ends with tasks still looping (after the main task ended), or is a deadlock (docs/decisions.md)
QUIET_S = 10.0


class Scheduler:
    def __init__(self, card, cfg: Options, counter):
        self.card = card
        self.counter = counter  # the run's StepCounter: the step limit and the statements counted before
        self.q = int(cfg.statements_per_tick)
        self.servo = float(cfg.servo_ticks)
        self.slice = float(cfg.task_slice_ticks)
        self.clock0 = int(cfg.clock_start) & 0xFFFFFFFF
        self.tasks = [Task(card, self, n) for n in range(4)]
        self.steps = 0
        self.acts = 0  # counts the moments a task may have changed the card (see quiet_until)
        self.timed_done = 0  # timed actions and scenario events carried out so far
        self.step_limit = counter.limit - counter.steps
        self.timed: list = []  # heap of (tick, seq, fn)
        self._seq = 0
        self.events = EventQueue()  # the scenario events still to come (Card sets them)
        self.event_act = None  # the card's function that applies a scenario event
        self._event_tick = math.inf  # the tick of the next scenario event
        self.fault: RuntimeFault | None = None  # the first run-time error of a task (reported at the end)
        self.solo = None  # the only running task, when there is just one
        self.main: Task | None = None  # the task of the program run (its end ends the run, see _quiet_end)
        self.last_timed = 0.0  # tick of the last timed action applied
        self.quiet_ticks = QUIET_S * TICKS_PER_S
        self._quiet = None  # (quiet since, snapshot, taken at): the deadlock watch
        self.idle_end: float | None = None  # the run's end when it ended with tasks still looping
        self.left_running: list = []  # those tasks

    # -- timed actions -----------------------------------------------------------------------------
    def add_timed(self, tick: float, fn) -> None:
        self._seq += 1
        heapq.heappush(self.timed, (tick, self._seq, fn))
        for tk in self.tasks:  # the running task must come back to the scheduler in time for it
            if tk.state == RUNNING and tk.check_at > tick:
                tk.check_at = tick
                tk.set_budget()

    def set_events(self, events: EventQueue, act) -> None:
        """The scenario events, applied by ``act(event)`` when their time comes."""
        self.events, self.event_act = events, act
        self._event_tick = self._tick_of_next_event()

    def _tick_of_next_event(self) -> float:
        t = self.events.next_time()
        return math.inf if t is None else t * TICKS_PER_S

    def next_timed(self) -> float:
        """The tick of the next scenario event or timed action."""
        t = self.timed[0][0] if self.timed else math.inf
        return t if t < self._event_tick else self._event_tick

    def apply_timed(self, upto: float) -> None:
        """Carry out the scenario events and timed actions up to tick ``upto``, in time order."""
        timed = self.timed
        while True:
            t = timed[0][0] if timed else math.inf
            e = self._event_tick
            if e <= t:  # an event first (none left: both are inf)
                if e > upto or e == math.inf:
                    return
                ev = self.events.pop()
                self.last_timed = max(self.last_timed, e)
                self._event_tick = self._tick_of_next_event()
                self.event_act(ev)
            elif t <= upto:
                tick, _, fn = heapq.heappop(timed)
                self.last_timed = max(self.last_timed, tick)
                fn()
            else:
                return
            self.timed_done += 1

    # -- waiting tasks ----------------------------------------------------------------------------------
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
            nt = self.next_timed()  # a timed action (a soft-limit stop) may end the move before
            return min(until, nt) if nt > tk.time else until
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


    # -- the scheduler loop ----------------------------------------------------------------------------
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
            if self.next_timed() == math.inf and not self.card.live and self._quiet_end(tk):
                return
            horizon = math.inf
            for o in running:
                if o is not tk:
                    horizon = min(horizon, o.time + self.slice)
            horizon = min(horizon, self.next_timed(), tk.time + 0.25 * self.quiet_ticks)  # back to see if it is over
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

    # -- the end of a run that does not end by itself --------------------------------------------------
    def _quiet_end(self, tk) -> bool:
        """Whether the run is over although tasks still run: the card has been quiet (nothing moves, no
        timed action or scenario event ahead) for QUIET_S since the main task ended, and ``tk``, the task
        due next, does not wake from a sleep that began before then (it may still start a move). The
        manual's monitor tasks loop for ever (L1548): they end with the run. With the main task still
        running, a quiet card whose state (CI, CD, the tasks' variables, CLOCK reads) has not changed over
        another QUIET_S is a deadlock: RUN005 with each task's line."""
        card, main = self.card, self.main
        since = max(card.timeline.last_end, self.last_timed)
        ended = main is not None and main.state in (ENDED, ERROR)
        if ended:
            since = max(since, main.time)
        if tk.time < since + self.quiet_ticks:
            return False
        if ended:
            if tk.waits_for is not None and tk.slept_at < since + self.quiet_ticks:
                return False
            self.idle_end = max(card.timeline.last_end, main.time)  # the run's work was done then
            self.left_running = [t for t in self.tasks if t.state == RUNNING]
            return True
        q = self._quiet
        if q is not None and q[0] == since and tk.time < q[2] + self.quiet_ticks:
            return False  # compared once per window
        snap = self._snapshot()
        if q is None or q[0] != since or not self._stuck(q[1], snap, q[2]):
            self._quiet = (since, snap, tk.time)
            for t in self.tasks:
                t.shared_reads.clear()  # what each reads in the window from now on
            return False
        waiting = [t for t in self.tasks if t.state == RUNNING]
        places = ", ".join(f"task {t.number} at line {w[1]}" for t in waiting if (w := t.where()) is not None)
        at = (main.where() if main is not None and main.state == RUNNING else None) or waiting[0].where()
        raise RuntimeFault("RUN005", f"waiting for ever: the program waits for something no task, move or "
                                     f"scenario event can bring ({places})",
                           Span(at[0], at[1], 1) if at else None)

    def _snapshot(self) -> tuple:
        """The card's shared state (CI, CD, the system registers) and each running task's own (its
        variables, its line, its CLOCK reads)."""
        card = self.card
        tasks = {}
        for t in self.tasks:
            if t.state == RUNNING and t.unit is not None and t.ns is not None:
                tasks[t.number] = (repr(t.unit.variables(t)), t.where(), t.clock_reads)
        return (tuple(card.ci), tuple(card.cd), repr(card.sys)), tasks

    def _stuck(self, before: tuple, now: tuple, since: float) -> bool:
        """Whether the window from ``since`` to now, with the card quiet, shows a deadlock: no task slept
        through the window (it wakes at a time and may act then), the main task neither moved on nor read
        the clock, and what it reads of the card cannot change: the shared state did not change, or no
        other running task assigns any register the main task read in the window (a heartbeat CI := CLOCK
        of a monitor beside it, L1548, releases nothing). Another task that only changed its own
        variables or read the clock cannot free the main task: as after the main task's end
        (:meth:`_quiet_end`), what it does not show on the card does not count."""
        if before[1].keys() != now[1].keys():
            return False
        for t in self.tasks:
            if t.state == RUNNING and t.waits_for is not None and t.slept_at < since:
                return False
        main = self.main
        if main is None or main.number not in now[1]:
            return before == now
        if before[1][main.number] != now[1][main.number]:
            return False
        return before[0] == now[0] or self._reads_settled(main, before[0], now[0])

    def _reads_settled(self, main, before: tuple, now: tuple) -> bool:
        """Whether the registers ``main`` read in the window kept their values and no other running task
        has a statement that assigns one of them (only its own statements could, and it stands still)."""
        reads = main.shared_reads
        for t in self.tasks:
            if t is not main and t.state == RUNNING and t.unit is not None and reads & t.unit.shared_writes:
                return False
        for name in reads:
            kind, index = name[:2], name[2:]
            if kind in ("CI", "CD") and index.isdigit():
                k = 0 if kind == "CI" else 1
                if before[k][int(index)] != now[k][int(index)]:
                    return False
            elif before[2] != now[2]:  # a system register: any change of them counts
                return False
        return True

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

    def runaway(self, at: tuple[str, int]):
        """RUN001 at ``at`` (file, line), the first statement that did not run; the steps that ran are
        handed to the run's counter when the run ends (sympas.run)."""
        raise RuntimeFault("RUN001", f"step limit of {self.counter.limit:,} statements reached "
                                     "(runaway program? raise it with --max-steps)", Span(*at))
