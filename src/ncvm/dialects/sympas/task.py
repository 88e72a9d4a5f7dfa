"""One CNC task of the card (0..3): state, time, common buffer, string output, events.

Generated code calls these methods; waits and task switches are generators the
code runs with ``yield from``. Time is in 64 us ticks (float); each executed
statement costs 1/Q tick (ncvm's reading; the rw_SymPas manual is silent).
"""

from __future__ import annotations

import math
import struct

from ...nc.canon import NOBODY
from .events import event_active, events_follow_motion
from .motion import TICKS_PER_S
from .symbols import EVENTS
from .values import fault

RUNNING, STOPPED, STEP, ENDED, ERROR, READY, EMPTY = "RUNNING", "STOPPED", "STEP", "ENDED", "ERROR", "READY", "EMPTY"
#: characters of a task's output string that are shown (and kept: a WRITE loop without WRITELN would grow
#: the string, and each WRITE copy it, without end)
MAX_STRING = 255
TASK_SYS = ("DTCA1", "DTCA2", "DTCA3", "LET", "LST", "PHI", "PN1", "PN2", "PN3", "TRAC", "TROVR", "TROVRST",
            "TRTVL", "TRVL", "NFRAX", "PU", "SSFP", "TU")
_I32 = struct.Struct("<i")
_F32 = struct.Struct("<f")
_F64 = struct.Struct("<d")


class TaskEnd(Exception):
    """ABORT, or the task restarted itself with STARTCNCT."""

    def __init__(self, restart: bool = False):
        self.restart = restart


class Task:
    def __init__(self, card, sched, number: int):
        self.card = card
        self.sched = sched  # the card's scheduler: the clock, the step count, the other tasks
        self.number = number
        self.state = EMPTY
        self.unit = None
        self.ns: dict | None = None
        self.gen = None
        self.time = 0.0
        self.iq = 1.0 / sched.q
        self.budget = 1
        self.check_at = 0.0
        self.depth = 0
        self.main_locals = None
        self.held = None  # sched.steps when this task last found its W-wait held by TROVR = 0
        self.slept_at = 0.0  # when its last sleep (WT, a wait for events) began
        self.clock_reads = 0  # CLOCK reads so far (a task waiting for a time is not deadlocked)
        self.shared_reads: set[str] = set()  # the card's registers (CI, CD, ...) read since the watch last looked
        self.waits_for: float | None = None  # while it sleeps: when it acts again if nothing else happens
        self.waits_mark = 0  # sched.acts when waits_for was worked out (valid while no task has acted since)
        self.polls = False  # whether it looks for events while it sleeps
        self.polled = -1  # sched.timed_done when it last looked for events
        self.max_depth = int(card.cfg.max_call_depth)
        self.reset_state()

    def reset_state(self) -> None:
        cfg = self.card.cfg
        self.sysp = {n: 0.0 for n in TASK_SYS}
        self.sysp.update(TRVL=float(cfg.trvl), TRAC=float(cfg.trac), TRTVL=float(cfg.trtvl),
                         TROVR=float(cfg.trovr), PU=int(cfg.pu), TU=int(cfg.tu), NFRAX=0, SSFP=0,
                         PN3=1.0)
        self.cb = bytearray(1000)
        self.line = ""
        self.tskinfo = 0
        self.enabled: dict[str, object] = {}
        self.in_handler = False
        self.active_before: set[str] = set()
        self.axmap = list(range(len(self.card.axes)))
        self.error = 0
        self.error_line = 0
        self.step_once = False
        self.depth = 0
        self.plain_units = not (self.sysp["PU"] or self.sysp["TU"])

    # -- time ------------------------------------------------------------------------------
    def flush(self, n: int) -> None:
        if n:
            self.time += n * self.iq
            self.sched.steps += n
            self.budget -= n

    def clock(self, n: int) -> int:
        self.clock_reads += 1  # a task reading the clock may be waiting for a time (not a deadlock)
        return (int(self.time + n * self.iq) + self.sched.clock0) & 0xFFFFFFFF

    def set_budget(self) -> None:
        if self.step_once:
            self.budget = 1  # STEPCNCT: stop at the next check point
            return
        sched = self.sched
        room = (self.check_at - self.time) * sched.q
        # at most one more than the statements left under the step limit (which never runs short: the
        # group that would pass it is not begun), so a group that does not fit always finds it spent (fits)
        left = sched.step_limit - sched.steps + 1
        # with events enabled a check point due now polls even with no statement counted since the last
        # (right after a WT, L2232); otherwise at least one statement runs between check points
        self.budget = max(0 if self.enabled else 1, min(int(room) if room < 1e15 else 1 << 60, left))

    def fits(self, n: int, k: int, at: int) -> None:
        """The step limit, tested at the head of a group of ``k`` statements just counted (``n`` counted
        since the last flush): a group that would pass it is not begun. RUN001 names its first statement
        (``at``, an index of the unit's places), and the statements before it are the run's steps."""
        sched = self.sched
        if sched.steps + n > sched.step_limit:
            self.flush(n - k)
            sched.runaway(self.unit.locs[at])

    def checkin(self, n: int, at: int = 0):
        """A check point (a loop back-edge): account the statements, let other tasks run, poll events.
        ``at``: the statement just counted at a back-edge (the loop's test, a GOTO), tested against the
        step limit before it runs."""
        if at:
            self.fits(n, 1, at)
        self.flush(n)
        if self.time >= self.check_at or self.step_once:
            if self.step_once:
                self.step_once = False
                self.state = STEP
            yield
        if self.enabled and not self.in_handler:
            yield from self.poll_events()
        self.set_budget()

    def poll_events(self):
        """Run the highest-priority enabled event whose condition holds (§6.4, L1598-1610)."""
        card = self.card
        self.polled = self.sched.timed_done
        edge = card.cfg.event_trigger == "edge"
        for name in EVENTS:
            fn = self.enabled.get(name)
            if fn is None:
                continue
            active = event_active(card, name, self.time)
            if edge:
                was = name in self.active_before
                if active:
                    self.active_before.add(name)
                else:
                    self.active_before.discard(name)
                if not active or was:
                    continue
            elif not active:
                continue
            self.in_handler = True
            try:
                yield from fn(self)
            finally:
                self.in_handler = False
            return True

    def where(self):
        """(file, line) of the statement this task stands at (suspended in a wait or at a check point), or None."""
        if self.unit is None or self.gen is None:
            return None
        name, src = self.unit.pyname, self.unit.src
        g, frame = self.gen, None
        while g is not None and hasattr(g, "gi_frame"):
            if g.gi_frame is not None and g.gi_frame.f_code.co_filename == name:
                frame = g.gi_frame
            g = g.gi_yieldfrom
        if frame is None:
            return None
        return self.unit.locs[src.source_line(frame.f_lineno)]

    def others_running(self) -> bool:
        return any(t.state == RUNNING and t is not self for t in self.sched.tasks)

    def wait_until(self, tick: float, poll: bool = True, ends: float | None = None):
        """Sleep until ``tick``; ``ends`` is when the wait itself ends if nothing else happens (a W-wait
        looks again at ``tick`` before its move ends, and says when it leaves). With events enabled, look
        for them in the servo cycles where one can have become active: every cycle while EVLSS follows the
        motion, else at the next timed action or when another task can act (the input events change with
        nothing else)."""
        card = self.card
        sched = self.sched
        servo = sched.servo
        self.slept_at = self.time
        try:
            while self.time < tick:
                step = tick
                self.sleeps_until(tick if ends is None else ends, poll)
                if poll and self.enabled:
                    cycle = (math.floor(self.time / servo) + 1) * servo
                    if events_follow_motion(card, self):
                        self.waits_for = None  # a handler can start in any cycle
                    else:
                        quiet = sched.quiet_until(self)
                        cycle = max(cycle, math.ceil(quiet / servo) * servo if quiet < math.inf else quiet)
                    step = min(tick, cycle)
                self.time = step
                yield
                if poll and self.enabled and not self.in_handler:
                    self.waits_for = None  # a handler that starts acts now
                    if (yield from self.poll_events()):
                        sched.acts += 1
        finally:
            if ends is None:
                self.leaves_wait()
            else:
                self.waits_for = None

    def sleeps_until(self, ends: float, poll: bool) -> None:
        """This task sleeps and, if nothing else happens, acts again at ``ends`` (other waiting tasks plan
        their next look by it while no task has acted since); ``poll``: it looks for events meanwhile."""
        self.waits_for = ends
        self.waits_mark = self.sched.acts
        self.polls = poll and bool(self.enabled)

    def leaves_wait(self) -> None:
        """The wait is over: what the task does next may change what the others wait for."""
        self.waits_for = None
        self.sched.acts += 1

    def fast_wait(self, tick: float, poll: bool = True) -> bool:
        """Advance to ``tick`` at once when nothing can happen before (no other task, no timed action)."""
        if (poll and self.enabled) or self.others_running() or self.sched.next_timed() <= tick:
            return False
        if tick > self.time:
            self.time = tick
        return True

    def wt(self, ticks: int, loc: int | None = None):
        """WT(n): sleep n x 64 us; events are not processed meanwhile (L2232). With every axis standing, the
        axes wait that long: a dwell (``loc``: the statement's place), told to a sink that writes programs."""
        target = self.time + (ticks if ticks > 0 else 1)
        card = self.card
        if (loc is not None and card.canon.dwell is not NOBODY and not self.others_running()
                and not any(card.busy(a, self.time) for a in card.axes)):
            card.timeline.report(math.inf)  # the moves before the wait come first
            card.canon.dwell((target - self.time) / TICKS_PER_S, self.unit.srcs[loc])
        if self.fast_wait(target, poll=False):
            return None
        return self.wait_until(target, poll=False)

    # -- system parameters -----------------------------------------------------------------------
    def get_sys(self, name: str):
        if name in self.sysp:
            return self.sysp[name]
        self.shared_reads.add(name)  # what it waits on, for the deadlock watch (scheduler.py)
        return self.card.get_sys(name)

    def set_sys(self, name: str, value) -> None:
        if name in self.sysp:
            if isinstance(value, float) and not math.isfinite(value):
                # a math function's "no valid return value" (NaN, inf) cannot drive a move (Table 40, $8000)
                fault(32768, f"{name} := {value}: not a valid parameter value")
            self.sysp[name] = value
            if name in ("PU", "TU", "NFRAX"):
                self.plain_units = not (self.sysp["PU"] or self.sysp["TU"] or self.sysp["NFRAX"])
        else:
            self.card.set_sys(self, name, value)

    # -- common buffer (§6.6.52-54, 76-78) ---------------------------------------------------------
    def _cb(self, offset: int, size: int) -> int:
        if size == 8 and offset % 8:
            fault(2048, f"common buffer offset {offset} is not divisible by 8")
        if offset % 4:
            fault(256, f"common buffer offset {offset} is not divisible by 4")
        if not 0 <= offset <= 1000 - size:
            fault(256, f"common buffer offset {offset} outside 0..{1000 - size}")
        return offset

    def rdcbd(self, off):
        return _F64.unpack_from(self.cb, self._cb(off, 8))[0]

    def rdcbi(self, off):
        return _I32.unpack_from(self.cb, self._cb(off, 4))[0]

    def rdcbs(self, off):
        return _F32.unpack_from(self.cb, self._cb(off, 4))[0]

    def wrcbd(self, off, v):
        _F64.pack_into(self.cb, self._cb(off, 8), v)

    def wrcbi(self, off, v):
        _I32.pack_into(self.cb, self._cb(off, 4), v)

    def wrcbs(self, off, v):
        _F32.pack_into(self.cb, self._cb(off, 4), v)

    # -- string output (§6.6.79-80) ------------------------------------------------------------------
    def write(self, items: tuple, newline: bool) -> bool:
        if self.tskinfo & 2:
            self.line = ""
            self.tskinfo = 0
        if len(self.line) < MAX_STRING:
            self.line = (self.line + "".join(items))[:MAX_STRING]
        self.tskinfo |= 1
        if newline:
            self.tskinfo |= 2
            self.card.say(self.line, self.number)
            if self.card.sys["MODEREG"] & (1 << 26):
                self.state = STOPPED
                return True
        return False

    def stopped(self):
        yield

    # -- task control (§6.6.2, 10, 56, 65-69) ------------------------------------------------------------
    def abort(self):
        raise TaskEnd()
        yield  # pragma: no cover

    def stop(self):
        self.state = STOPPED
        yield

    def rs(self):
        where = self.where()
        place = f"{where[0]}:{where[1]}: " if where else ""
        self.card.say(f"{place}RS: system reset by task {self.number}: the axes stop, the running tasks "
                      "are stopped", self.number)
        self.card.session.extra["ended"] = f"ended by RS (system reset) at {place.rstrip(': ') or 'task ' + str(self.number)}"
        self.card.reset_system(self.time)
        yield

    def _task(self, n: int) -> Task:
        if not 0 <= n <= 3:
            fault(256, f"task number {n} outside 0..3")
        return self.sched.tasks[n]

    def startcnct(self, n: int):
        t = self._task(n)
        if t.unit is None:
            fault(256, f"STARTCNCT({n}): no program is loaded in task {n}")
        if t is self:
            raise TaskEnd(restart=True)
        t.start(self.time)
        yield

    def stopcnct(self, n: int):
        t = self._task(n)
        if t.state in (RUNNING, STEP):
            t.state = STOPPED
        if t is self:
            yield
        yield

    def contcnct(self, n: int):
        t = self._task(n)
        self.sched.solo = None
        if t.state in (STOPPED, STEP) and t is not self:
            t.state = RUNNING
            t.time = max(t.time, self.time)
        yield

    def stepcnct(self, n: int):
        t = self._task(n)
        self.sched.solo = None
        if t.state in (STOPPED, STEP) and t is not self:
            t.state = RUNNING
            t.step_once = True
            t.time = max(t.time, self.time)
        yield

    def stoptoss(self, n: int):
        t = self._task(n)
        if t.state == STOPPED:
            t.state = STEP
        yield

    def azo(self, n: int):
        if not 0 <= n <= 4:
            fault(256, f"AZO({n}): zero offset set outside 0..4")
        self.card.active_zo = n
        self.card.zero_moved()
        yield

    # -- events ---------------------------------------------------------------------------------------
    def enev(self, name: str, fn) -> None:
        self.enabled[name] = fn
        self.check_at = self.time  # from now on every check point polls the events
        self.budget = 0

    def disev(self, name: str, fn) -> None:
        self.enabled.pop(name, None)
        self.active_before.discard(name)

    # -- life cycle -----------------------------------------------------------------------------------
    def load(self, unit) -> None:
        self.unit = unit
        self.state = READY

    def start(self, at: float) -> None:
        self.sched.solo = None
        self.reset_state()
        self.ns = self.unit.namespace(self.card)
        self.gen = self.ns["_main"](self)
        self.main_locals = None
        self.time = at
        self.state = RUNNING
