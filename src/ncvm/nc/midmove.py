"""Where the axes are part-way through an executed block: the kernel's move profile, read at a time.

The kernel executes a block whole and advances the clock by its move time. A front end whose program reads
the executed state at an earlier time (CPL: a WAIT(,ms) that ends while a block is still moving) records
the block's canon motion with :class:`MotionRecorder` and asks :func:`position_at` for the position at that
time: along the straight line or the arc, with the same trapezoidal speed profile (start and end at rest,
path speed and acceleration capped per axis) the kernel used for the block's time; a dwell holds position.
"""

from __future__ import annotations

import math
from operator import sub

from . import arcs
from .canon import CanonSink
from .dynamics import arc_limits, path_limits, trapezoid_distance, trapezoid_time

RAPID, FEED, ARC = 0, 1, 2


class MotionRecorder(CanonSink):
    """Records the motion canon calls of the blocks a kernel executes while it listens on the canon.

    Each entry is ``(time, kind, start, end, spec, feed)`` with the machine clock at the call, which the
    kernel makes after it has advanced the clock by the move (or dwell) time: the time the motion ends.
    """

    def __init__(self, canon, clock):
        self.canon, self.clock = canon, clock
        self.moves: list = []

    def __enter__(self) -> MotionRecorder:
        self.canon.add(self)
        return self

    def __exit__(self, *exc) -> None:
        self.canon.remove(self)

    def rapid(self, start, end, src) -> None:
        self.moves.append((self.clock.now, RAPID, start, end, None, math.inf))

    def feed(self, start, end, feed, src) -> None:
        self.moves.append((self.clock.now, FEED, start, end, None, feed))

    def arc(self, start, end, spec, feed, src) -> None:
        self.moves.append((self.clock.now, ARC, start, end, spec, feed))


def position_at(moves: list, dyn, t: float, before: tuple) -> tuple:
    """The machine position at time ``t`` given the recorded ``moves`` of one block (see
    :class:`MotionRecorder`) and the position ``before`` the block. Before a move starts the axes stand at its
    start point; after it ends, at its end point (so a dwell, or time between moves, holds position)."""
    pos = before
    for t_end, kind, start, end, spec, feed in moves:
        length, v, a = _profile(kind, start, end, spec, feed, dyn)
        t_start = t_end - trapezoid_time(length, v, a)
        if t < t_start:
            return tuple(start)
        if t < t_end and length > 0.0:
            return _point(kind, start, end, spec, trapezoid_distance(length, v, a, t - t_start) / length)
        pos = end
    return tuple(pos)


def _profile(kind: int, start, end, spec, feed: float, dyn) -> tuple[float, float, float]:
    """Path length, speed and acceleration of a move, as the kernel times it."""
    if kind == ARC:
        length = arcs.arc_length(spec.radius, _sweep(start, end, spec), arcs.helix_travel(start, end, spec.a, spec.b))
        return (length, *arc_limits(tuple(map(sub, end, start)), spec.a, spec.b, length, feed / 60.0, dyn.max_feed, dyn.accel))
    deltas = tuple(map(sub, end, start))
    length = math.sqrt(sum(d * d for d in deltas))
    limits = dyn.rapid if kind == RAPID else dyn.max_feed
    return (length, *path_limits(deltas, length, math.inf if kind == RAPID else feed / 60.0, limits, dyn.accel))


def _sweep(start, end, spec) -> float:
    ca, cb = spec.center
    return arcs.sweep(start[spec.a], start[spec.b], end[spec.a], end[spec.b], ca, cb, spec.cw, spec.turns)


def _point(kind: int, start, end, spec, f: float) -> tuple:
    """The point a fraction ``f`` of the path length along the move (an arc turns its sweep uniformly; the
    axes off the plane move linearly, a helix)."""
    line = [s + (e - s) * f for s, e in zip(start, end)]
    if kind == ARC:
        a, b = spec.a, spec.b
        ca, cb = spec.center
        r0 = math.hypot(start[a] - ca, start[b] - cb)
        r1 = math.hypot(end[a] - ca, end[b] - cb)
        angle = math.atan2(start[b] - cb, start[a] - ca) + _sweep(start, end, spec) * f
        r = r0 + (r1 - r0) * f
        line[a], line[b] = ca + r * math.cos(angle), cb + r * math.sin(angle)
    return tuple(line)
