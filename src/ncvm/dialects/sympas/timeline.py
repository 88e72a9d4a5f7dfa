"""What the axes really did over simulated time, told to the canon interface in time order.

Moves of the card run concurrently: a move of A1 started without waiting goes on while a move of A2 starts,
two tasks move their axes at the same time, a spooled chain runs while a task jogs another axis. The canon
interface takes one toolpath, so the moves are reported here, not each on its own: every retired move is
kept until no move that could still start or change can begin before it (the horizon), then the time from
the last reported moment on is cut where a move begins or ends. In a stretch where one move runs, it is
reported as its own line, arc or (3-D circle) polyline, from the state all axes have then to the state
they have at its end; where several run together, their combined path is sampled (a polyline within
``TOLERANCE`` of it). So start and end of each canon call are the state of every axis at that moment,
and bounds, plot and G-code follow what the axes did.
"""

from __future__ import annotations

import math

from ...nc.canon import NOBODY, ArcSpec, Frame
from .motion import TICKS_PER_S, TWO_PI

#: largest distance (axis units) of a sampled combined path from the real one
TOLERANCE = 1e-2
#: moves held before the reported time is moved on to the horizon
HOLD = 512
_MAX_DEPTH = 12


class Timeline:
    """The moves retired but not yet reported, and the axes' state at the last reported moment."""

    def __init__(self, card, start):
        self.card = card
        self.canon = card.canon
        self.pos = list(start)  # every axis at time ``t``, as reported so far
        self.rest = None  # the state after a direct move, until a report makes it ``pos``
        self.t = 0.0
        self.pending: list = []  # retired moves not (completely) reported yet
        self.hold = HOLD  # report when this many are pending
        #: path units the card's profiles ran, each along its own path (moves at the same time add up)
        self.profile_length = 0.0
        self.last_end = 0.0  # the latest end of a retired move: the axes stand still after it
        self.task: int | None = None  # the CNC task whose moves were reported last (canon ``channel``)
        self.shift: tuple[float, ...] = (0.0,) * len(start)  # the frame told to the canon last (canon ``frame``)
        self.zero_moved = True  # the card's zero point may differ from ``shift`` (Card.zero_moved): look again

    def add(self, mv) -> None:
        """A move retired: it is final and is reported when the time it ran is reported."""
        if mv.t1 > mv.t0:
            # the user coordinates the move ends in, when a sink takes frames (not per move otherwise)
            mv.shift = None if self.canon.frame is NOBODY else self.card.work_shift()
            self.profile_length += mv.stop_s if mv.stop_s is not None else mv.prof.length
            if mv.t1 > self.last_end:
                self.last_end = mv.t1
            self.pending.append(mv)
            if len(self.pending) >= self.hold:
                self.report(self.card.horizon())
                # a horizon held back (a move held by TROVR = 0) must not make every add a report
                self.hold = max(HOLD, 2 * len(self.pending))

    def direct(self, start, end, feed: float, src, t1: float, length: float, items=()) -> None:
        """A straight move of idle axes while no other move runs (the fast path of MLAW/MLRW); ``items``: the
        (axis, value) pairs it programs."""
        if self.pending:
            self.report(math.inf)
        self._channel(src)
        if self.zero_moved:  # one look per change of the zero point, not one per move
            self.zero_moved = False
            if self.canon.frame is not NOBODY:
                self._frame(self.card.work_shift(), src)
        if self.canon.programmed is not NOBODY:  # a translation: nothing per move otherwise
            self._programmed([ax for ax, _ in items], src)
        self.canon.feed(start, end, feed, src)
        self.profile_length += length
        self.last_end = self.t = t1  # every axis was idle: nothing ends later
        self.rest = end  # the state of all axes now (made the list ``pos`` when a report needs it)

    def _programmed(self, axes, src) -> None:
        """Tell a translation the axes a straight move programs: each is written, also one that stands where
        it is (MLAW with A2 := 0 where A2 stands at 0)."""
        if self.canon.programmed is not NOBODY:
            names = self.card.session.machine.axes  # the canon's axis names
            self.canon.programmed(tuple(names[ax].name for ax in axes), src)

    # -- reporting ----------------------------------------------------------------------------------
    def report(self, horizon: float) -> None:
        """Report what the axes did up to ``horizon`` (inf: everything retired)."""
        if self.rest is not None:
            self.pos, self.rest = list(self.rest), None
        pending = sorted(self.pending, key=lambda m: m.t0)
        n = len(pending)
        i = 0
        t = self.t
        active: list = []
        while True:
            while i < n and pending[i].t0 <= t:
                active.append(pending[i])
                i += 1
            active = [m for m in active if m.t1 > t]
            nxt = pending[i].t0 if i < n else math.inf
            if not active:
                if nxt == math.inf or nxt >= horizon:
                    break
                t = nxt
                continue
            tb = min(min(m.t1 for m in active), nxt, horizon)
            if tb <= t:
                break
            if len(active) == 1:
                self._single(active[0], t, tb)
            else:
                self._combined(active, t, tb)
            t = tb
        self.t = max(self.t, t)
        self.pending = [m for m in pending if m.t1 > self.t]

    def _channel(self, src) -> None:
        """Tell the sinks which task's moves follow, when another task's than before (the plot's colours)."""
        task = self.card.task_at.get((src.file, src.line)) if src is not None else None
        if task is not None and task != self.task:
            self.task = task
            self.canon.channel(task, src)

    def _frame(self, shift: tuple[float, ...], src) -> None:
        """Tell the sinks the user coordinates of the moves that follow, when they changed (homing makes the REF
        point the axis zero; zero offsets add to it): the trace's ``work`` and the translation are the
        program's positions (docs/translate.md). ``G54`` names the card's zero point for the translation."""
        if shift is None:
            return
        if shift != self.shift:  # (checked before the call on the hot path)
            self.canon.frame(Frame("G54", shift, (0.0,) * len(shift)), src)
        self.shift = shift  # also an equal one worked out anew: the next moves find it the same object

    def _place(self, m, t: float) -> None:
        p = m.pos(t)
        for k, ax in enumerate(m.axes):
            self.pos[ax] = p[k]

    def _single(self, m, ta: float, tb: float) -> None:
        """Move ``m`` alone from ``ta`` to ``tb``: its own line, arc or polyline."""
        self._place(m, ta)
        start = tuple(self.pos)
        sa = 0.0 if ta <= m.t0 else m.s_at(ta)
        sb = (m.stop_s if m.stop_s is not None else m.prof.length) if tb >= m.t1 else m.s_at(tb)
        self._place(m, tb)
        end = tuple(self.pos)
        canon = self.canon
        self._channel(m.src)
        if m.shift is not None and m.shift != self.shift:
            self._frame(m.shift, m.src)
        if m.jog:
            if m.homing:
                canon.homing(m.axes, m.src)
            canon.rapid(start, end, m.src)
            return
        if m.kind == "line":
            self._programmed(m.axes, m.src)
            canon.feed(start, end, m.feed, m.src)
            return
        L = m.prof.length
        frac = (sb - sa) / L if L > 0 else 0.0
        if m.kind == "arc" and m.plane_w is None:
            swept = m.phi * frac
            if abs(swept) < 1e-12:
                canon.feed(start, end, m.feed, m.src)
                return
            n_full = abs(swept) / TWO_PI
            whole = math.floor(n_full + 1e-9)
            turns = int(round(n_full)) - 1 if whole >= 1 and abs(n_full - round(n_full)) < 1e-9 else int(whole)
            i, j = m.plane
            spec = ArcSpec(m.axes[i], m.axes[j], m.center, swept < 0, m.radius, turns)
            canon.arc(start, end, spec, m.feed, m.src)
            return
        # a 3-D circle, or a circle on a rotary axis's surface: a polyline, at most 5 degrees per piece
        pieces = max(1, int(math.ceil(abs(m.phi * frac) / math.radians(5.0))))
        prev = start
        full = list(start)
        for k in range(1, pieces + 1):
            p = m.point(sa + (sb - sa) * k / pieces) if k < pieces else m.pos(tb)
            for q, ax in enumerate(m.axes):
                full[ax] = p[q]
            cur = tuple(full)
            canon.feed(prev, cur, m.feed, m.src)
            prev = cur

    def _combined(self, active: list, ta: float, tb: float) -> None:
        """Several moves at once from ``ta`` to ``tb``: their combined path, sampled."""
        base = self.pos

        def at(t: float) -> tuple:
            p = list(base)
            for m in active:
                q = m.pos(t)
                for k, ax in enumerate(m.axes):
                    p[ax] = q[k]
            return tuple(p)

        pa, pb = at(ta), at(tb)
        points = [(ta, pa)]
        _refine(at, ta, pa, tb, pb, 0, points)
        points = _thin(points)
        rapid = all(m.jog for m in active)
        src = max(active, key=lambda m: m.t0).src  # the task that started last names the combined path
        canon = self.canon
        self._channel(src)
        self._frame(max(active, key=lambda m: m.t0).shift, src)
        homing = tuple(ax for m in active if m.homing for ax in m.axes)
        for (t0, p0), (t1, p1) in zip(points, points[1:]):
            d = math.dist(p0, p1)
            if d <= 0.0:
                continue
            if homing:
                canon.homing(homing, src)
            if rapid:
                canon.rapid(p0, p1, src)
            else:
                canon.feed(p0, p1, d / ((t1 - t0) / TICKS_PER_S) * 60.0, src)
        self.pos[:] = pb


def _refine(at, ta: float, pa: tuple, tb: float, pb: tuple, depth: int, out: list) -> None:
    """Append the samples after ``ta`` up to ``tb`` so that the polyline stays within TOLERANCE."""
    tm = 0.5 * (ta + tb)
    pm = at(tm)
    if depth < _MAX_DEPTH and (depth < 2 or _off_chord(pm, pa, pb) > TOLERANCE):
        _refine(at, ta, pa, tm, pm, depth + 1, out)
        _refine(at, tm, pm, tb, pb, depth + 1, out)
        return
    out.append((tb, pb))


def _off_chord(p, a, b) -> float:
    """Distance of point ``p`` from the segment a-b."""
    ab = [y - x for x, y in zip(a, b)]
    ap = [y - x for x, y in zip(a, p)]
    L2 = sum(x * x for x in ab)
    if L2 <= 0.0:
        return math.sqrt(sum(x * x for x in ap))
    f = min(1.0, max(0.0, sum(x * y for x, y in zip(ab, ap)) / L2))
    return math.sqrt(sum((y - f * x) ** 2 for x, y in zip(ab, ap)))


def _thin(points: list) -> list:
    """Drop samples that lie on the straight line between their neighbours (within TOLERANCE)."""
    if len(points) <= 2:
        return points
    out = [points[0]]
    for k in range(1, len(points) - 1):
        if _off_chord(points[k][1], out[-1][1], points[k + 1][1]) > TOLERANCE / 10.0:
            out.append(points[k])
    out.append(points[-1])
    return out
