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
columns (:mod:`ncvm.nc.plainrun`).
"""

from __future__ import annotations

import math

import numpy as np

from .dynamics import trapezoid_time_columns

LOOKAHEAD = "lookahead"
REST = "rest-to-rest"
MODELS = (LOOKAHEAD, REST)
#: row flags: the move ends at rest / starts at rest (a rapid positioning has both)
STOP_END, STOP_START, POSITIONING = 1, 2, 3
#: moves planned at once beyond the window (the bound on what waits untimed)
CHUNK = 4096
_STRAIGHT, _REVERSAL = -0.999999, 0.999999  # cosines where a junction counts as straight on / as a reversal


class Planner:
    """Moves waiting to be timed, the oldest first, and the speed the last timed one left at.

    A row is ``(length mm, speed mm/s, acceleration mm/s^2, flags, *u_in, *u_out)``: the move's path
    length, its speed and acceleration limits, :data:`STOP_END` / :data:`STOP_START` flags and the unit
    tangents at its start and end (equal for a straight move). The kernel's straight-move hot path
    appends rows itself and calls :meth:`commit` when more than ``limit`` wait.
    """

    __slots__ = ("clock", "canon", "accel", "n", "model", "window", "tolerance", "rows", "blocks", "limit",
                 "entry2", "exact")

    def __init__(self, clock, canon, accel: tuple, model: str = LOOKAHEAD, window: int = 100,
                 tolerance: float = 0.02):
        self.clock = clock
        self.canon = canon  # told each timed move's time and speeds (canon ``timing``)
        self.accel = np.asarray(accel, dtype=float)
        self.n = len(accel)
        self.model = model
        self.window = max(1, int(window))
        self.tolerance = float(tolerance)
        self.rows: list[tuple] = []  # moves added one by one
        self.blocks: list[np.ndarray] = []  # moves added as columns, before ``rows``
        self.limit = self.window + CHUNK
        self.entry2 = 0.0  # squared speed (mm/s)^2 the first waiting move starts with
        clock.pending = self.stop

    def fork(self, clock, canon) -> Planner:
        """An empty planner of the same machine data on another clock (a shadow kernel's)."""
        return Planner(clock, canon, tuple(self.accel.tolist()), self.model, self.window, self.tolerance)

    # -- adding moves ------------------------------------------------------------------------------
    def add(self, length: float, v: float, a: float, flags: int, u_in, u_out) -> None:
        """One move (see the class doc for the fields)."""
        self.rows.append((length, v, a, flags, *u_in, *u_out))
        if len(self.rows) > self.limit:
            self.commit()

    def add_columns(self, length, v, a, flags, u_in, u_out) -> None:
        """Many moves as columns (``u_in``, ``u_out``: arrays of moves by axes)."""
        if not len(length):
            return
        self._materialise()
        self.blocks.append(np.column_stack((length, v, a, flags, u_in, u_out)))
        if self.waiting() > self.limit:
            self.commit()

    def waiting(self) -> int:
        return sum(map(len, self.blocks)) + len(self.rows)

    def _materialise(self) -> None:
        if self.rows:
            self.blocks.append(np.array(self.rows, dtype=float).reshape(len(self.rows), 4 + 2 * self.n))
            self.rows.clear()

    # -- timing ------------------------------------------------------------------------------------
    def commit(self) -> None:
        """Time the waiting moves whose window is complete (all but the last ``window``)."""
        self._plan(self.waiting() - self.window)

    def stop(self) -> None:
        """Exact stop: time every waiting move, the last ending at rest."""
        if self.rows or self.blocks:
            self._plan(None)
        self.entry2 = 0.0

    def _plan(self, k: int | None) -> None:
        self._materialise()
        m = self.blocks[0] if len(self.blocks) == 1 else np.vstack(self.blocks)
        p = len(m)
        k = p if k is None else k
        if k <= 0:
            self.blocks = [m]
            return
        n = self.n
        length, v, a = m[:, 0], m[:, 1], m[:, 2]
        flags = m[:, 3].astype(np.int64)
        w = self._speeds(length, v, a, flags, m[:, 4:4 + n], m[:, 4 + n:4 + 2 * n])
        times = move_times(length[:k], v[:k], a[:k], w[:k], w[1:k + 1])
        clock = self.clock
        clock.settle(float(np.cumsum(np.concatenate(([clock.settled], times)))[-1]))  # in move order
        self.entry2 = float(w[k])
        self.blocks = [m[k:]] if k < p else []
        self.canon.timing(times, np.sqrt(w[:k]) * 60.0, np.sqrt(w[1:k + 1]) * 60.0)

    def _speeds(self, length, v, a, flags, u_in, u_out) -> np.ndarray:
        """Squared junction speeds: entry of each move, then the exit of the last (0, it may stop)."""
        p = len(length)
        j = np.zeros(p + 1)
        if self.model == LOOKAHEAD and p > 1:
            j[1:p] = junction_speeds2(u_out[:-1], u_in[1:], v[:-1], v[1:], flags[:-1], flags[1:], self.accel,
                                      self.tolerance)
        j[0] = self.entry2
        c = 2.0 * a * length  # what each move can change the squared speed by
        s = np.concatenate(([0.0], np.cumsum(c)))
        # backward: b_i = min over k >= i of (j_k + s_k) - s_i; and a stop within the window of moves from i
        b = np.minimum.accumulate((j + s)[::-1])[::-1] - s
        win = self.window
        if win < p:
            b[:p + 1 - win] = np.minimum(b[:p + 1 - win], s[win:] - s[:p + 1 - win])
        b[0] = j[0]
        # forward: w_i = min over k <= i of (b_k - s_k) + s_i
        w = np.minimum.accumulate(b - s) + s
        return np.maximum(w, 0.0, out=w)


def junction_speeds2(u_prev, u_next, v_prev, v_next, f_prev, f_next, accel, tolerance: float) -> np.ndarray:
    """Squared speeds (mm/s)^2 at the junctions from moves ending with tangent ``u_prev`` to moves starting
    with ``u_next`` (rows of unit vectors), at most both moves' speeds; 0 where either side stops."""
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        cos = np.clip(-(u_prev * u_next).sum(axis=1), -1.0, 1.0)
        sin_half = np.sqrt(0.5 * (1.0 - cos))
        jv = u_next - u_prev  # the direction the velocity changes in: the axes' acceleration limits apply there
        share = np.abs(jv) / np.sqrt((jv * jv).sum(axis=1))[:, None]
        acc = np.where(share > 0.0, accel / share, math.inf).min(axis=1)
        radius = tolerance * sin_half / (1.0 - sin_half)
        slower = np.minimum(v_prev, v_next) ** 2
        j = np.where(cos <= _STRAIGHT, slower, np.minimum(acc * radius, slower))
        j = np.where((cos >= _REVERSAL) | np.isnan(j), 0.0, j)
    j[((f_prev & STOP_END) | (f_next & STOP_START)) != 0] = 0.0
    return j


def move_times(length, v, a, w0, w1) -> np.ndarray:
    """Time of each move from squared entry speed ``w0`` to squared exit speed ``w1``: accelerate, cruise at
    ``v`` if the length allows, decelerate. Moves from rest to rest take :func:`trapezoid_time_columns`'s
    time exactly (the rest-to-rest model's figures stay as they were)."""
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        v0, v1 = np.sqrt(w0), np.sqrt(w1)
        cruise = length - (2.0 * v * v - w0 - w1) / (2.0 * a)
        peak = np.minimum(v, np.sqrt(a * length + 0.5 * (w0 + w1)))
        peak = np.maximum(peak, np.maximum(v0, v1))
        t = (2.0 * peak - v0 - v1) / a + np.maximum(cruise, 0.0) / v
        return np.where((w0 == 0.0) & (w1 == 0.0), trapezoid_time_columns(length, v, a), t)


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
