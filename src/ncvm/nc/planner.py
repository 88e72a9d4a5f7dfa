"""The look-ahead path planner: how long moves take when the control blends blocks (continuous path).

A control in continuous-path mode (ISO/SINUMERIK G64, Bosch G62) does not stop at the end of every
block: it passes each junction between two moves at a speed the corner allows, and it looks a number of
blocks ahead (its block buffer) so that it can always still brake to rest within them. The planner does
the same, after the ideas of grbl's junction-deviation planner and LinuxCNC's trajectory planner (G64
with a path tolerance); the formulas are written out in docs/planner.md:

* junction speed: the corner between two moves is rounded by the circular arc tangent to both that
  stays within the corner tolerance of the corner point (``R = tol sin(h) / (1 - sin(h))``, h half the
  angle between the moves), passed at the speed whose centripetal acceleration the axes can give in the
  junction's direction (``v^2 = a R``); never faster than either move's own speed. A straight-on
  junction runs at the lower of the two speeds, a reversal stops;
* arcs: their speed is capped by the centripetal acceleration ``v^2 <= a R`` (the plane axes' smaller
  acceleration), straights and arcs by each axis's maximum feed and acceleration
  (:mod:`ncvm.nc.dynamics`);
* the window: every junction is passed no faster than lets the axes stop at the end of the window of
  ``lookahead`` moves that starts there (backward pass), and no faster than they can reach from the
  move before (forward pass); each move is then a trapezoid between its entry and exit speeds.

Exact stops (a rapid positioning, G60/G61/G09, M functions, dwells, tool changes, waits, program end)
are junctions at speed 0. The ``rest-to-rest`` model makes every junction one: the old model.

Time and the clock: moves wait in the planner untimed; they are timed when the window moves on (a
chunk of moves whose window is complete) or when the pending moves are flushed. Reading the simulated
clock flushes (:class:`ncvm.machine.model.SimClock` calls :meth:`Planner.stop`): the pending moves end at
rest, as an exact stop, so what a program reads is never a time that a later block could still change.

Both passes are minimum-plus recurrences that become running minima of prefix sums, so a whole chunk
is planned with a few numpy operations whether its moves came one by one (the kernel's ``rows``) or as
columns (:mod:`ncvm.nc.plainrun`). A flush of fewer than :data:`SMALL` moves added one by one (a short
program, the moves between two M functions) is planned in plain Python instead: the same formulas with
the same float operations in the same order, so the same times to the last bit
(``tests/nc/test_planner_small.py``), without numpy's import (~0.1 s of a short run's start-up).
"""

from __future__ import annotations

import math
from struct import pack as _pack

from ..lazy import lazy
from .dynamics import lengths_columns, straight_limits_columns, trapezoid_time, trapezoid_time_columns

np = lazy("numpy")

LOOKAHEAD = "lookahead"
REST = "rest-to-rest"
MODELS = (LOOKAHEAD, REST)
#: row flags: the move ends at rest / starts at rest (a rapid positioning has both)
STOP_END, STOP_START, POSITIONING = 1, 2, 3
#: moves planned at once beyond the window (the bound on what waits untimed)
CHUNK = 4096
#: fewer moves than this, added one by one and flushed, are planned in plain Python (no numpy)
SMALL = 64
_STRAIGHT, _REVERSAL = -0.999999, 0.999999  # cosines where a junction counts as straight on / as a reversal


class Planner:
    """Moves waiting to be timed, the oldest first, and the speed the last timed one left at.

    A move is ``length`` (mm), its speed and acceleration limits ``v`` (mm/s) and ``a`` (mm/s^2),
    :data:`STOP_END` / :data:`STOP_START` ``flags`` and the unit tangents at its start and end (equal for a
    straight move). Waiting moves are kept as arrays of fields by moves (every field a contiguous row for
    numpy); :mod:`ncvm.nc.plainrun` adds such columns.

    Moves added one by one go to ``rows``, a flat list (the cheapest append), ``4 + n`` numbers each:
    ``length, v, a, flags, *u_in``, followed for an arc by ``0, 0, 0, -1, *u_out`` (its end tangent). The
    kernel's straight-move hot path adds ``-1, feed, 0, flags, *deltas`` (feed in mm/min, inf for a rapid
    move): length, limits and tangent of such a row are worked out here, column-wise, with the formulas of
    :func:`ncvm.nc.dynamics.path_limits`; it calls :meth:`commit` when ``rows`` holds more than ``limit``.
    """

    __slots__ = ("clock", "canon", "dyn", "accel", "n", "width", "model", "window", "tolerance", "rows",
                 "blocks", "limit", "entry2", "changes", "rest_times")

    def __init__(self, clock, canon, dyn, model: str = LOOKAHEAD, window: int = 100, tolerance: float = 0.02):
        self.clock = clock
        self.canon = canon  # told each timed move's time and speeds (canon ``timing``)
        self.dyn = dyn  # the axes' limits (nc.dynamics.AxisDynamics)
        self.accel = tuple(map(float, dyn.accel))  # an array when a chunk is planned: no numpy for a run without moves
        self.n = len(dyn.accel)
        self.width = 4 + self.n  # the numbers of one row
        self.model = model
        self.window = max(1, int(window))
        self.tolerance = float(tolerance)
        self.rows: list[float] = []  # moves added one by one, flat
        self.blocks: list[np.ndarray] = []  # moves waiting as arrays (fields, moves), before ``rows``
        self.limit = (self.window + CHUNK) * self.width
        self.entry2 = 0.0  # squared speed (mm/s)^2 the first waiting move starts with
        # (moves waiting, the tolerance before) at each change of the tolerance: junctions 1..moves-1 keep it
        self.changes: list[tuple[int, float]] = []
        #: ``rest_times(rows)``: the time of each move in ``rows`` from rest to rest (:func:`rest_times_for`),
        #: generated at the first flush that needs it (a run that never has one compiles nothing at start-up)
        self.rest_times = None
        clock.pending = self.stop

    def fork(self, clock, canon) -> Planner:
        """An empty planner of the same machine data on another clock (a shadow kernel's)."""
        return Planner(clock, canon, self.dyn, self.model, self.window, self.tolerance)

    def set_tolerance(self, tolerance: float) -> None:
        """The corner tolerance (G64 P) of the junctions that start the moves added from now on; the junctions
        between moves already waiting keep the tolerance they were programmed with."""
        if tolerance == self.tolerance:
            return
        moves = sum(b.shape[1] for b in self.blocks) + sum(1 for f in self.rows[3::self.width] if f >= 0.0)
        if moves > 1 and not (self.changes and self.changes[-1][0] == moves):
            self.changes.append((moves, self.tolerance))
        self.tolerance = float(tolerance)

    def _tolerances(self, p: int) -> list[float]:
        """The tolerance of each junction 0..p of the ``p`` waiting moves (``changes`` applied)."""
        tolerances = [self.tolerance] * (p + 1)
        start = 0
        for end, tolerance in self.changes:  # ends increase
            tolerances[start:end] = [tolerance] * (end - start)
            start = end
        return tolerances

    # -- adding moves ------------------------------------------------------------------------------
    def add(self, length: float, v: float, a: float, flags: int, u_in, u_out) -> None:
        """One move (see the class doc for the fields)."""
        rows = self.rows
        rows += (length, v, a, flags, *u_in)
        if u_out != u_in:
            rows += (0.0, 0.0, 0.0, -1.0, *u_out)
        if len(rows) > self.limit:
            self.commit()

    def add_columns(self, length, v, a, flags, u_in, u_out) -> None:
        """Many moves as columns (``u_in``, ``u_out``: arrays of moves by axes)."""
        if not len(length):
            return
        self._materialise()
        n = self.n
        block = np.empty((4 + 2 * n, len(length)))
        block[0], block[1], block[2], block[3] = length, v, a, flags
        block[4:4 + n] = u_in.T
        block[4 + n:] = u_out.T
        self.blocks.append(block)
        if self.waiting() > self.window + CHUNK:
            self.commit()

    def waiting(self) -> int:
        """Moves waiting (an arc added one by one counts twice until it is materialised)."""
        return sum(b.shape[1] for b in self.blocks) + len(self.rows) // self.width

    def _materialise(self) -> None:
        """The moves of ``rows`` as an array (fields, moves) at the end of ``blocks``."""
        rows = self.rows
        if not rows:
            return
        n = self.n
        r = np.frombuffer(_pack(f"{len(rows)}d", *rows)).reshape(-1, self.width).T
        rows.clear()
        ends = r[3] < 0.0  # an arc's end tangent, in the row after its own
        u_out = None
        if ends.any():
            at = np.flatnonzero(ends)
            u_out = r[4:].copy()
            u_out[:, at - 1] = r[4:, at]
            keep = ~ends
            r, u_out = r[:, keep], u_out[:, keep]
        m = np.empty((4 + 2 * n, r.shape[1]))
        m[:4] = r[:4]
        m[4:4 + n] = r[4:]
        derived = np.flatnonzero(r[0] < 0.0)  # the hot path's straight moves: deltas and the feed
        if len(derived):
            d = r[4:, derived].T
            length = lengths_columns(d)
            rapid = r[3, derived] == POSITIONING
            v, a = straight_limits_columns(self.dyn, d, length, rapid, r[1, derived])
            m[0, derived], m[1, derived], m[2, derived] = length, v, a
            m[4:4 + n, derived] = (d / length[:, None]).T
        m[4 + n:] = m[4:4 + n] if u_out is None else u_out
        if u_out is not None and len(derived):
            m[4 + n:, derived] = m[4:4 + n, derived]
        self.blocks.append(m)

    # -- timing ------------------------------------------------------------------------------------
    def commit(self) -> None:
        """Time the waiting moves whose window is complete (all but the last ``window``)."""
        self._materialise()
        self._plan(self.waiting() - self.window)

    def stop(self) -> None:
        """Exact stop: time every waiting move, the last ending at rest."""
        if self.blocks:
            self._plan(None)
        elif self.rows:
            rows = self.rows
            if len(rows) >= SMALL * self.width:
                self._plan(None)
            elif (len(rows) == self.width and self.entry2 == 0.0) or self._rest_to_rest():
                self._plan_rest()  # a drilling cycle's plunge before its dwell, the moves between two rapids
            else:
                self._plan_rows()
        self.entry2 = 0.0
        self.changes.clear()

    def _rest_to_rest(self) -> bool:
        """Whether every move in ``rows`` starts and ends at rest: the first from rest (``entry2`` 0), each
        junction an exact stop (a rapid positioning on either side, G61/G09: the flags), or the rest-to-rest
        model. Then no junction speed is worked out and each move takes :func:`trapezoid_time`."""
        if self.entry2 != 0.0 or (math.copysign(1.0, self.entry2) < 0.0 and len(self.rows) > self.width):
            return False  # -0.0 left by a plan: _plan_rows reports it as the first entry speed, a lone move 0.0
        if self.model != LOOKAHEAD:
            return True
        before = STOP_END  # the first move: entry2 is 0
        for f in self.rows[3::self.width]:
            if f < 0.0:  # an arc's end tangent, in the row after its own
                continue
            f = int(f)
            if not (before & STOP_END or f & STOP_START):
                return False
            before = f
        return True

    def _plan_rows(self) -> None:
        """:meth:`_plan` of every waiting move, for a few moves in ``rows``: in plain Python, move by move."""
        length, v, a, flags, u_in, u_out = self._row_moves()
        self.rows.clear()
        w = self._speeds_rows(length, v, a, flags, u_in, u_out)
        times = list(map(blended_time, length, v, a, w, w[1:]))
        clock = self.clock
        t = clock.settled
        for dt in times:  # in move order, as the chunk's cumulative sum
            t += dt
        clock.settle(t)
        speeds = [math.sqrt(x) * 60.0 for x in w]
        self.canon.timing(times, speeds[:-1], speeds[1:])

    def _plan_rest(self) -> None:
        """:meth:`_plan_rows` of moves that all start and end at rest (:meth:`_rest_to_rest`): every junction
        speed 0, so each move's :func:`blended_time` is its :func:`trapezoid_time` (:func:`rest_times_for`),
        without the lists of fields and tangents."""
        if self.rest_times is None:
            self.rest_times = rest_times_for(self.dyn)
        times = self.rest_times(self.rows)
        self.rows.clear()
        clock = self.clock
        t = clock.settled
        for dt in times:  # in move order, as _plan_rows
            t += dt
        clock.settle(t)
        self.canon.timing(times, [0.0] * len(times), [0.0] * len(times))

    def _row_moves(self) -> tuple[list, ...]:
        """The moves of ``rows`` as lists of fields (what :meth:`_materialise` makes an array of): an arc's end
        tangent joined to it, the hot path's straight moves' length, limits and tangent worked out."""
        rows, width, dyn = self.rows, self.width, self.dyn
        length, v, a, flags, u_in, u_out = [], [], [], [], [], []
        for i in range(0, len(rows), width):
            ln, vi, ai, f = rows[i], rows[i + 1], rows[i + 2], rows[i + 3]
            u = rows[i + 4:i + width]
            if f < 0.0:  # an arc's end tangent, in the row after its own
                u_out[-1] = u
                continue
            if ln < 0.0:  # the hot path's straight move: deltas and the feed (mm/min; inf for a rapid move)
                ln, vi, ai = straight_row_limits(u, vi, f == POSITIONING, dyn)
                u = [d / ln for d in u]
            length.append(ln)
            v.append(vi)
            a.append(ai)
            flags.append(int(f))
            u_in.append(u)
            u_out.append(u)
        return length, v, a, flags, u_in, u_out

    def _speeds_rows(self, length, v, a, flags, u_in, u_out) -> list[float]:
        """:meth:`_speeds` of moves given as lists (:meth:`_row_moves`): the same passes, loop by loop."""
        p = len(length)
        j = [0.0] * (p + 1)
        if self.model == LOOKAHEAD:
            accel, tolerances = self.accel, self._tolerances(p)
            for i in range(1, p):
                if not (flags[i - 1] & STOP_END or flags[i] & STOP_START):
                    j[i] = junction_speed2(u_out[i - 1], u_in[i], v[i - 1], v[i], accel, tolerances[i])
        j[0] = self.entry2
        if not any(j):
            return j
        s = [0.0] * (p + 1)
        total = 0.0
        for i in range(p):
            total += 2.0 * a[i] * length[i]
            s[i + 1] = total
        b = [0.0] * (p + 1)
        least = math.inf
        for i in range(p, -1, -1):  # backward, a running minimum from the end
            least = min(least, j[i] + s[i])
            b[i] = least - s[i]
        win = self.window
        for i in range(p + 1 - win):  # empty when the window holds every move
            b[i] = min(b[i], s[i + win] - s[i])
        b[0] = j[0]
        w = b
        least = math.inf
        for i in range(p + 1):  # forward, a running minimum from the start
            least = min(least, b[i] - s[i])
            w[i] = max(least + s[i], 0.0)  # numpy's maximum: -0.0 and NaN stay
        return w

    def _plan(self, k: int | None) -> None:
        self._materialise()
        m = self.blocks[0] if len(self.blocks) == 1 else np.concatenate(self.blocks, axis=1)
        p = m.shape[1]
        k = p if k is None else k
        if k <= 0:
            self.blocks = [m]
            return
        length, v, a = m[0], m[1], m[2]
        w = self._speeds(m)
        times = move_times(length[:k], v[:k], a[:k], w[:k], w[1:k + 1])
        clock = self.clock
        clock.settle(float(np.cumsum(np.concatenate(([clock.settled], times)))[-1]))  # in move order
        self.entry2 = float(w[k])
        self.blocks = [m[:, k:]] if k < p else []
        if self.changes:  # the junctions left keep theirs, counted from the first move left
            self.changes = [(end - k, tolerance) for end, tolerance in self.changes if end - k > 1]
        self.canon.timing(times, np.sqrt(w[:k]) * 60.0, np.sqrt(w[1:k + 1]) * 60.0)

    def _speeds(self, m) -> np.ndarray:
        """Squared junction speeds of the moves ``m`` (fields, moves): the entry of each move, then the exit
        of the last (0: it may have to stop)."""
        length, v, a = m[0], m[1], m[2]
        p = len(length)
        j = np.zeros(p + 1)
        if self.model == LOOKAHEAD and p > 1:
            n = self.n
            flags = m[3].astype(np.int64)
            stop = ((flags[:-1] & STOP_END) | (flags[1:] & STOP_START)) != 0
            if not stop.all():
                tolerance = np.asarray(self._tolerances(p)[1:p]) if self.changes else self.tolerance
                j[1:p] = junction_speeds2(m[4 + n:4 + 2 * n, :-1], m[4:4 + n, 1:], v[:-1], v[1:], stop,
                                          np.asarray(self.accel), tolerance)
        j[0] = self.entry2
        if not j.any():  # every move from rest to rest (exact stop, the rest-to-rest model)
            return j
        c = 2.0 * a * length  # what each move can change the squared speed by
        s = np.zeros(p + 1)
        np.cumsum(c, out=s[1:])
        # backward: b_i = min over k >= i of (j_k + s_k) - s_i; and a stop within the window of moves from i
        b = np.minimum.accumulate((j + s)[::-1])[::-1] - s
        win = self.window
        if win < p:
            np.minimum(b[:p + 1 - win], s[win:] - s[:p + 1 - win], out=b[:p + 1 - win])
        b[0] = j[0]
        # forward: w_i = min over k <= i of (b_k - s_k) + s_i
        w = np.minimum.accumulate(b - s) + s
        return np.maximum(w, 0.0, out=w)


def straight_row_limits(deltas, feed: float, rapid: bool, dyn) -> tuple[float, float, float]:
    """(length, path speed, path acceleration) of the kernel's hot-path row of a straight move (its ``deltas``,
    ``feed`` in mm/min): what :meth:`Planner._materialise` works out column-wise, with the same float
    operations (the length summed in axis order as lengths_columns, the shares |d| * (1 / length) as
    straight_limits_columns, then path_limits of the shares written out)."""
    ln = 0.0
    for d in deltas:
        ln += d * d
    ln = math.sqrt(ln)
    inv = 1.0 / ln
    vi, ai = math.inf if rapid else feed / 60.0, math.inf
    for d, vmax, amax in zip(deltas, dyn.rapid if rapid else dyn.max_feed, dyn.accel):
        share = abs(d * inv)
        if share:
            if vmax < vi * share:
                vi = vmax / share
            if amax < ai * share:
                ai = amax / share
    return ln, vi, ai


_REST_TIMES: dict = {}  # the generated functions, per machine's limits (a shadow kernel's planner shares them)


def rest_times_for(dyn):
    """``rest_times(rows)``: the time of each move in a planner's ``rows`` (an arc's end tangent row
    skipped) from rest to rest, generated for the machine's axes and limits, one unrolled line per axis:
    :func:`straight_row_limits` of a hot-path row, then :func:`trapezoid_time`, with the same float
    operations (a drilling cycle's flush at each dwell, issue 18)."""
    key = (tuple(dyn.rapid), tuple(dyn.max_feed), tuple(dyn.accel))
    made = _REST_TIMES.get(key)
    if made is not None:
        return made
    n = len(dyn.accel)
    idx = range(n)

    def shares(limits: str) -> list[str]:  # path_limits of the shares, per axis: its speed and acceleration
        return [line for j in idx for line in (f"                share = abs(d{j} * inv)",
                                               "                if share:",
                                               f"                    if {limits}{j} < vi * share:",
                                               f"                        vi = {limits}{j} / share",
                                               f"                    if A{j} < ai * share:",
                                               f"                        ai = A{j} / share")]

    lines = ["def rest_times(rows):",
             "    times = []",
             f"    for i in range(0, len(rows), {4 + n}):",
             "        f = rows[i + 3]",
             "        if f < 0.0:",
             "            continue  # an arc's end tangent",
             "        ln = rows[i]",
             "        if ln < 0.0:  # the hot path's straight move: deltas and the feed",
             *(f"            d{j} = rows[i + {4 + j}]" for j in idx),
             f"            ln = _sqrt({' + '.join(f'd{j} * d{j}' for j in idx) or '0.0'})",
             "            inv = 1.0 / ln",
             "            ai = _INF",
             f"            if f == {POSITIONING}:",
             "                vi = _INF",
             *shares("R"),
             "            else:",
             "                vi = rows[i + 1] / 60.0",
             *shares("M")]
    lines += ["        else:",
              "            vi, ai = rows[i + 1], rows[i + 2]",
              "        if ln <= 0.0:  # trapezoid_time",
              "            times.append(0.0)",
              "        elif vi <= 0.0:",
              "            times.append(_INF)",
              "        elif ai <= 0.0 or ai == _INF:",
              "            times.append(ln / vi)",
              "        elif ln * ai >= vi * vi:",
              "            times.append(ln / vi + vi / ai)",
              "        else:",
              "            times.append(2.0 * _sqrt(ln / ai))",
              "    return times"]
    namespace = {"_sqrt": math.sqrt, "_INF": math.inf}
    for j in idx:
        namespace[f"R{j}"], namespace[f"M{j}"], namespace[f"A{j}"] = dyn.rapid[j], dyn.max_feed[j], dyn.accel[j]
    exec(compile("\n".join(lines) + "\n", f"<ncvm rest-to-rest times, {n} axes>", "exec"), namespace)
    return _REST_TIMES.setdefault(key, namespace["rest_times"])


def junction_speeds2(u_prev, u_next, v_prev, v_next, stop, accel, tolerance) -> np.ndarray:
    """Squared speeds (mm/s)^2 at the junctions from moves ending with tangent ``u_prev`` to moves starting
    with ``u_next`` (unit vectors, arrays of axes by junctions), at most both moves' speeds; 0 where
    ``stop`` (either side stops) or the moves reverse. ``tolerance``: one for all, or one per junction."""
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        cos = -_dot(u_prev, u_next)
        jv = u_next - u_prev  # the direction the velocity changes in: the axes' acceleration limits apply there
        # min over axes of accel_i / (|jv_i| / |jv|)
        acc = np.sqrt(_dot(jv, jv)) / (np.abs(jv) / accel[:, None]).max(axis=0)
        sin_half = np.sqrt(np.maximum(0.5 * (1.0 - cos), 0.0))
        slower = np.minimum(v_prev, v_next)
        slower *= slower
        j = np.minimum(acc * (tolerance * sin_half / (1.0 - sin_half)), slower)
    straight = cos <= _STRAIGHT
    j[straight] = slower[straight]
    j[(cos >= _REVERSAL) | stop] = 0.0
    return j


def junction_speed2(u_prev, u_next, v_prev: float, v_next: float, accel, tolerance: float) -> float:
    """:func:`junction_speeds2` of one junction that neither side stops at, in plain Python."""
    cos = -_dot(u_prev, u_next)
    slower = min(v_prev, v_next)
    slower *= slower
    if cos >= _REVERSAL:
        return 0.0
    if cos <= _STRAIGHT:
        return slower
    jv = [n - p for p, n in zip(u_prev, u_next)]
    most = max([abs(d) / am for d, am in zip(jv, accel)])
    norm = math.sqrt(_dot(jv, jv))
    acc = norm / most if most else math.inf  # numpy's division by 0 (|jv| > 0 here)
    sin_half = math.sqrt(max(0.5 * (1.0 - cos), 0.0))
    return min(acc * (tolerance * sin_half / (1.0 - sin_half)), slower)


def _dot(x, y):
    """Scalar product of two tangents, summed in axis order; of arrays (axes by junctions) column by column,
    the same operations (no fused multiply-add, unlike einsum may)."""
    total = x[0] * y[0]
    for i in range(1, len(x)):
        total = total + x[i] * y[i]
    return total


def blended_time(length: float, v: float, a: float, w0: float, w1: float) -> float:
    """:func:`move_times` of one move, in plain Python."""
    if w0 == 0.0 and w1 == 0.0:
        return trapezoid_time(length, v, a)
    v0, v1 = math.sqrt(w0), math.sqrt(w1)
    cruise = length - (2.0 * v * v - w0 - w1) / (2.0 * a)
    peak = min(v, math.sqrt(a * length + 0.5 * (w0 + w1)))
    peak = max(peak, max(v0, v1))
    return (2.0 * peak - v0 - v1) / a + max(cruise, 0.0) / v


def move_times(length, v, a, w0, w1) -> np.ndarray:
    """Time of each move from squared entry speed ``w0`` to squared exit speed ``w1``: accelerate, cruise at
    ``v`` if the length allows, decelerate. Moves from rest to rest take :func:`trapezoid_time_columns`'s
    time exactly (the rest-to-rest model's figures stay as they were)."""
    rest = (w0 == 0.0) & (w1 == 0.0)
    if rest.all():
        return trapezoid_time_columns(length, v, a)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        v0, v1 = np.sqrt(w0), np.sqrt(w1)
        cruise = length - (2.0 * v * v - w0 - w1) / (2.0 * a)
        peak = np.minimum(v, np.sqrt(a * length + 0.5 * (w0 + w1)))
        peak = np.maximum(peak, np.maximum(v0, v1))
        t = (2.0 * peak - v0 - v1) / a + np.maximum(cruise, 0.0) / v
    rest = np.flatnonzero(rest)
    if len(rest):
        t[rest] = trapezoid_time_columns(length[rest], v[rest], a[rest])
    return t


def arc_tangents(start, end, spec, sweep: float, length: float, n: int) -> tuple[tuple, tuple]:
    """Unit tangents at the start and end of an arc (a helix: the axes off the plane move linearly)."""
    a, b = spec.a, spec.b
    ca, cb = spec.center
    turn = 1.0 if sweep >= 0.0 else -1.0
    plane = spec.radius * abs(sweep)
    tangents = []
    for p in (start, end):
        phi = math.atan2(p[b] - cb, p[a] - ca)
        u = [(e - s) / length if length > 0.0 else 0.0 for s, e in zip(start, end)]
        u[a] = -turn * math.sin(phi) * plane / length if length > 0.0 else 0.0
        u[b] = turn * math.cos(phi) * plane / length if length > 0.0 else 0.0
        tangents.append(tuple(u))
    return tangents[0], tangents[1]


def arc_tangents_columns(start, end, a: int, b: int, center, radius, sweep, length):
    """:func:`arc_tangents` for columns of arcs in one plane: (u_in, u_out), arrays of arcs by axes."""
    with np.errstate(divide="ignore", invalid="ignore"):
        inv = np.where(length > 0.0, 1.0 / length, 0.0)
        line = (end - start) * inv[:, None]
        plane = radius * np.abs(sweep) * inv
        turn = np.where(sweep >= 0.0, 1.0, -1.0)
        out = []
        for p in (start, end):
            phi = np.arctan2(p[:, b] - center[:, 1], p[:, a] - center[:, 0])
            u = line.copy()
            u[:, a] = -turn * np.sin(phi) * plane
            u[:, b] = turn * np.cos(phi) * plane
            out.append(u)
    return out[0], out[1]
