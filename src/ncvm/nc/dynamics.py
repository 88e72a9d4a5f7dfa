"""How long a move takes on the machine: trapezoidal velocity profiles.

:func:`trapezoid_time` is a move from rest to rest; the path planner
(:mod:`ncvm.nc.planner`) blends moves in continuous-path mode from these limits. The path speed is the programmed feed (or
rapid rate), capped so no axis exceeds its own maximum; the path acceleration
is capped the same way by each axis's acceleration.

Every formula is here twice, side by side: the scalar form the kernel uses block
by block, and the column form (suffix ``_columns``, numpy) that
:mod:`ncvm.nc.plainrun` uses for a run of plain blocks, with the same float
operations in the same order, so both give the same times
(``tests/nc/test_motion_formulas.py``). The kernel's straight-move hot path,
:mod:`ncvm.nc.fastmove`, is :func:`move_time` unrolled per machine.
"""

from __future__ import annotations

import math
from operator import sub

from ..lazy import lazy

np = lazy("numpy")


class AxisDynamics:
    """Per-axis limits of one machine, in mm/s and mm/s^2."""

    __slots__ = ("rapid", "max_feed", "accel")

    def __init__(self, axes):
        self.rapid = tuple(a.rapid / 60.0 for a in axes)
        self.max_feed = tuple(a.max_feed / 60.0 for a in axes)
        self.accel = tuple(a.accel for a in axes)

    def straight_time(self, start, end, speed: float, rapid: bool) -> float:
        """Time of a straight move from ``start`` to ``end`` at path speed ``speed`` (mm/s)."""
        deltas = tuple(map(sub, end, start))
        length = math.sqrt(sum(d * d for d in deltas))
        return move_time(deltas, length, speed, self.rapid if rapid else self.max_feed, self.accel)


def trapezoid_time(length: float, v: float, a: float) -> float:
    """Time to travel ``length`` from rest to rest with speed limit ``v`` and acceleration ``a``."""
    if length <= 0.0:
        return 0.0
    if v <= 0.0:
        return math.inf
    if a <= 0.0 or a == math.inf:
        return length / v
    if length * a >= v * v:  # reaches full speed: accelerate, cruise, decelerate
        return length / v + v / a
    return 2.0 * math.sqrt(length / a)


def trapezoid_time_columns(length, v, a) -> np.ndarray:
    """:func:`trapezoid_time`, column-wise."""
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        t = np.where((a <= 0.0) | (a == math.inf), length / v,
                     np.where(length * a >= v * v, length / v + v / a, 2.0 * np.sqrt(length / a)))
        t = np.where(v <= 0.0, math.inf, t)
        return np.where(length > 0.0, t, 0.0)


def move_time(deltas, length: float, speed: float, limits: tuple, accel: tuple) -> float:
    """Time for a straight move with per-axis ``deltas`` and path ``length`` (mm).

    ``speed`` is the requested path speed in mm/s; ``limits`` and ``accel`` the
    per-axis speed and acceleration limits.
    """
    if length <= 0.0:
        return 0.0
    return trapezoid_time(length, *path_limits(deltas, length, speed, limits, accel))


def path_limits(deltas, length: float, speed: float, limits: tuple, accel: tuple) -> tuple[float, float]:
    """Path speed and acceleration of a straight move: ``speed``, capped so no axis exceeds its limits."""
    v = speed
    a = math.inf
    for d, vmax, amax in zip(deltas, limits, accel):
        if d:
            share = abs(d) / length
            if vmax < v * share:
                v = vmax / share
            if amax < a * share:
                a = amax / share
    return v, a


def straight_time_columns(dyn: AxisDynamics, start, end, rapid, feed) -> np.ndarray:
    """:meth:`AxisDynamics.straight_time` column-wise: rows of ``start`` and ``end`` (moves, axes), ``rapid`` a
    bool column, ``feed`` in mm/min (ignored where rapid)."""
    d = end - start
    length = lengths_columns(d)
    return trapezoid_time_columns(length, *straight_limits_columns(dyn, d, length, rapid, feed))


def lengths_columns(d) -> np.ndarray:
    """Path length of each row of per-axis ``d`` (moves, axes), summed in axis order as the scalar form."""
    sq = d[:, 0] * d[:, 0]
    for i in range(1, d.shape[1]):
        sq = sq + d[:, i] * d[:, i]
    return np.sqrt(sq)


def straight_limits_columns(dyn: AxisDynamics, d, length, rapid, feed) -> tuple:
    """:func:`path_limits` column-wise: path speed and acceleration of straight moves ``d`` (moves, axes)."""
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        inv = 1.0 / length
        v = np.where(rapid, math.inf, feed / 60.0)
        a = np.full(len(d), math.inf)
        for i in range(d.shape[1]):
            di = d[:, i]
            nz = di != 0.0
            share = np.abs(di) * inv
            vmax = np.where(rapid, dyn.rapid[i], dyn.max_feed[i])
            v = np.where(nz & (vmax < v * share), vmax / share, v)
            a = np.where(nz & (dyn.accel[i] < a * share), dyn.accel[i] / share, a)
        return v, a


def arc_limits(deltas, a: int, b: int, length: float, speed: float, limits: tuple,
               accel: tuple) -> tuple[float, float]:
    """Path speed and acceleration of an arc (or helix) of ``length`` in the plane of axes ``a`` and ``b``;
    ``deltas`` are each axis's travel from start to end (the plane axes' are not read).

    Somewhere on an arc the path may run along one plane axis alone (at the quadrant points), and that
    axis then takes the plane's whole share of the speed and of the tangential ramp: both are capped by
    the smaller of the plane axes' limits, as if the plane were one axis. Its share of the path is 1 on a
    flat arc; on a helix the plane and each linear axis share the path by their travel (a helix has a
    constant pitch, so the shares hold all along it)."""
    if not length:
        return speed, math.inf
    v, acc, rest = speed, math.inf, 1.0
    for i, d in enumerate(deltas):
        if d and i != a and i != b:  # a helix's linear axis: its own share
            share = abs(d) / length
            rest -= share * share
            if limits[i] < v * share:
                v = limits[i] / share
            if accel[i] < acc * share:
                acc = accel[i] / share
    plane = math.sqrt(rest) if rest > 0.0 else 0.0
    vmax, amax = min(limits[a], limits[b]), min(accel[a], accel[b])
    if vmax < v * plane:
        v = vmax / plane
    if amax < acc * plane:
        acc = amax / plane
    return v, acc


def arc_limits_columns(d, a: int, b: int, length, speed, limits: tuple, accel: tuple) -> tuple:
    """:func:`arc_limits`, column-wise: ``d`` the per-axis travel (moves, axes); ``length`` and ``speed``
    (mm/s) columns."""
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        inv = 1.0 / length
        v = speed
        acc = np.full(len(length), math.inf)
        rest = np.ones(len(length))
        for i in range(d.shape[1]):
            if i != a and i != b:
                di = d[:, i]
                nz = di != 0.0
                share = np.abs(di) * inv
                rest = np.where(nz, rest - share * share, rest)
                v = np.where(nz & (limits[i] < v * share), limits[i] / share, v)
                acc = np.where(nz & (accel[i] < acc * share), accel[i] / share, acc)
        plane = np.sqrt(np.maximum(rest, 0.0))
        vmax, amax = min(limits[a], limits[b]), min(accel[a], accel[b])
        moves = length != 0.0
        v = np.where(moves & (vmax < v * plane), vmax / plane, v)
        acc = np.where(moves & (amax < acc * plane), amax / plane, acc)
    return v, acc


def trapezoid_distance(length: float, v: float, a: float, t: float) -> float:
    """Distance covered ``t`` seconds into the rest-to-rest profile of :func:`trapezoid_time`."""
    total = trapezoid_time(length, v, a)
    if t <= 0.0 or length <= 0.0:
        return 0.0
    if t >= total:
        return length
    if a <= 0.0 or a == math.inf:
        return v * t
    peak = min(v, math.sqrt(length * a))  # the speed reached: full speed or the triangle's top
    ramp = peak / a
    if t <= ramp:
        return 0.5 * a * t * t
    if t <= total - ramp:
        return 0.5 * a * ramp * ramp + peak * (t - ramp)
    left = total - t
    return length - 0.5 * a * left * left
