"""Arc geometry: centres from I/J/K or R, sweep angles, lengths, exact extents, sample points.

Sweep, length and extent are here in two forms side by side: scalar for the
kernel's block-by-block path and column-wise (suffix ``_columns``, numpy) for
:mod:`ncvm.nc.plainrun`, giving the same values (``tests/nc/test_motion_formulas.py``).
"""

from __future__ import annotations

import math

from ..lazy import lazy
from ..records import FrozenRecord

np = lazy("numpy")


TWO_PI = 2.0 * math.pi
#: a full circle is programmed by an end point equal to the start point (within this, mm)
SAME_POINT = 1e-9
INCH = 25.4


class RadiusTolerance(FrozenRecord):
    """How far an arc's end may lie off the circle through its start before the control refuses the block.

    An arc is refused when its end radius differs from its start radius by more than ``limit`` times the
    absolute tolerance, or by more than the absolute tolerance *and* more than ``relative`` of the larger
    radius. ``absolute`` holds in metric programs (mm), ``absolute_inch`` in inch programs (inch), as
    LinuxCNC's CENTER_ARC_RADIUS_TOLERANCE_MM/_INCH. A radius-format arc may fall ``reach`` (mm) short of
    half its chord; a centre closer than ``zero`` (mm) to the start or end is a zero-radius arc.
    """

    __slots__ = ("absolute", "absolute_inch", "relative", "limit", "reach", "zero")

    def __init__(self, absolute: float, absolute_inch: float, relative: float, limit: float = math.inf,
                 reach: float = 0.002, zero: float = 1e-9):
        self.absolute = absolute
        self.absolute_inch = absolute_inch
        self.relative = relative
        self.limit = limit
        self.reach = reach
        self.zero = zero

    def allowed(self, inch: bool) -> float:
        """The absolute tolerance in mm for a program in inch (G20/G70) or in mm."""
        return self.absolute_inch * INCH if inch else self.absolute

    def refuses(self, r0: float, r1: float, inch: bool) -> bool:
        """Whether start radius ``r0`` and end radius ``r1`` (mm) are too far apart."""
        diff = abs(r0 - r1)
        tol = self.allowed(inch)
        return diff > self.limit * tol or (diff > tol and diff > self.relative * max(r0, r1))

    def refuses_columns(self, r0: np.ndarray, r1: np.ndarray, inch: bool) -> np.ndarray:
        """:meth:`refuses` column-wise, with the zero-radius test."""
        diff = np.abs(r0 - r1)
        tol = self.allowed(inch)
        return ((diff > self.limit * tol) | ((diff > tol) & (diff > self.relative * np.maximum(r0, r1)))
                | (r0 < self.zero) | (r1 < self.zero))


#: LinuxCNC rs274ngc's rule (interp_arc.cc arc_data_ijk/arc_data_r with the defaults of interp_internal.hh):
#: 2 * 0.01 * sqrt(2) mm or 2 * 0.001 * sqrt(2) inch absolute, 0.1 % relative, never more than 100 times the
#: absolute; R may fall 0.00005 inch short; radii under that are zero. The `din` default.
RS274 = RadiusTolerance(0.02 * math.sqrt(2.0), 0.002 * math.sqrt(2.0), 0.001, 100.0, 0.00005 * INCH, 0.00005 * INCH)
#: the kernel's rule where a control's manual gives none (CPL, SINUMERIK): 0.002 mm or 0.1 %, no cap
KERNEL = RadiusTolerance(0.002, 0.002 / INCH, 0.001)


class ArcError(ValueError):
    """Geometry that no control would accept (radius mismatch, impossible R)."""


def center_from_radius(sa: float, sb: float, ea: float, eb: float, r: float, cw: bool,
                       reach: float = KERNEL.reach) -> tuple[float, float]:
    """Centre of the arc of signed radius ``r`` from (sa, sb) to (ea, eb).

    As in DIN 66025 and LinuxCNC: r > 0 takes the arc of at most 180 degrees,
    r < 0 the one of more than 180 degrees. ``r`` may fall ``reach`` (mm) short of half the chord.
    """
    dx, dy = ea - sa, eb - sb
    chord = math.hypot(dx, dy)
    if chord < SAME_POINT:
        raise ArcError("a radius-format arc needs an end point different from its start point")
    half = chord / 2.0
    rad = abs(r)
    if half - rad > reach:
        raise ArcError(f"radius {rad:g} is too small for a chord of {chord:g}")
    h = math.sqrt(max(rad * rad - half * half, 0.0))
    mx, my = sa + dx / 2.0, sb + dy / 2.0
    # unit normal to the chord, pointing left of the travel direction
    nx, ny = -dy / chord, dx / chord
    # for a CW short arc the centre lies right of the chord; flip for CCW or long arcs
    side = -1.0 if cw else 1.0
    if r < 0:
        side = -side
    return mx + side * h * nx, my + side * h * ny


def sweep(sa: float, sb: float, ea: float, eb: float, ca: float, cb: float, cw: bool, turns: int = 0) -> float:
    """Signed sweep angle (radians, negative for CW) from start to end around the centre."""
    a0 = math.atan2(sb - cb, sa - ca)
    a1 = math.atan2(eb - cb, ea - ca)
    d = a1 - a0
    if cw:
        while d >= -1e-12:
            d -= TWO_PI
        if d < -TWO_PI:
            d += TWO_PI
        if math.hypot(ea - sa, eb - sb) < SAME_POINT:
            d = -TWO_PI
        return d - TWO_PI * turns
    while d <= 1e-12:
        d += TWO_PI
    if d > TWO_PI:
        d -= TWO_PI
    if math.hypot(ea - sa, eb - sb) < SAME_POINT:
        d = TWO_PI
    return d + TWO_PI * turns


def sweep_columns(sa, sb, ea, eb, ca, cb, cw) -> tuple[np.ndarray, np.ndarray]:
    """:func:`sweep` (no extra turns), column-wise; returns the sweeps and the start angles."""
    a0 = np.arctan2(sb - cb, sa - ca)
    d = np.arctan2(eb - cb, ea - ca) - a0
    for _ in range(3):
        d = np.where(cw & (d >= -1e-12), d - TWO_PI, d)
        d = np.where(~cw & (d <= 1e-12), d + TWO_PI, d)
    d = np.where(cw & (d < -TWO_PI), d + TWO_PI, d)
    d = np.where(~cw & (d > TWO_PI), d - TWO_PI, d)
    closed = np.hypot(ea - sa, eb - sb) < SAME_POINT
    return np.where(closed, np.where(cw, -TWO_PI, TWO_PI), d), a0


def check_radii(sa, sb, ea, eb, ca, cb, tolerance: RadiusTolerance = KERNEL, inch: bool = False) -> float:
    """Start radius; raises :class:`ArcError` when the end lies on another radius (``tolerance``, for a
    program in inch or mm) or the radius is zero."""
    r0 = math.hypot(sa - ca, sb - cb)
    r1 = math.hypot(ea - ca, eb - cb)
    if r0 < tolerance.zero or r1 < tolerance.zero:
        raise ArcError("zero radius arc")
    if tolerance.refuses(r0, r1, inch):
        raise ArcError(f"radius to end of arc differs from radius to start: start radius {r0:.4f}, end radius "
                       f"{r1:.4f}, difference {abs(r0 - r1):.4f}")
    return r0


def arc_length(radius: float, angle: float, helix: float = 0.0) -> float:
    """Length of an arc (or helix with linear travel ``helix``) of ``angle`` radians."""
    planar = abs(angle) * radius
    return math.hypot(planar, helix) if helix else planar


def helix_travel(start, end, a: int, b: int) -> float:
    """The straight travel of the axes off the arc's plane (``a``, ``b``): a helix's rise."""
    return math.sqrt(sum((e - s) ** 2 for i, (s, e) in enumerate(zip(start, end)) if i != a and i != b))


def helix_travel_columns(start, end, a: int, b: int) -> np.ndarray:
    """:func:`helix_travel`, column-wise over rows of ``start`` and ``end`` (moves, axes)."""
    helix = np.zeros(len(start))
    for i in range(start.shape[1]):
        if i != a and i != b:
            helix = helix + (end[:, i] - start[:, i]) ** 2
    return np.sqrt(helix)


def arc_plane_extent(sa, sb, ca, cb, radius, angle) -> tuple[float, float, float, float]:
    """(min_a, max_a, min_b, max_b) of the arc including the quadrant points it passes."""
    a0 = math.atan2(sb - cb, sa - ca)
    a1 = a0 + angle
    ea, eb = ca + radius * math.cos(a1), cb + radius * math.sin(a1)
    lo_a, hi_a = min(sa, ea), max(sa, ea)
    lo_b, hi_b = min(sb, eb), max(sb, eb)
    if abs(angle) >= TWO_PI - 1e-12:
        return ca - radius, ca + radius, cb - radius, cb + radius
    lo, hi = (a0, a1) if angle >= 0 else (a1, a0)
    k = math.ceil(lo / (math.pi / 2))
    while k * (math.pi / 2) <= hi:
        q = k % 4
        if q == 0:
            hi_a = ca + radius
        elif q == 1:
            hi_b = cb + radius
        elif q == 2:
            lo_a = ca - radius
        else:
            lo_b = cb - radius
        k += 1
    return lo_a, hi_a, lo_b, hi_b


def arc_length_columns(radius, angle, helix) -> np.ndarray:
    """:func:`arc_length`, column-wise."""
    planar = np.abs(angle) * radius
    return np.where(helix != 0.0, np.hypot(planar, helix), planar)


def arc_plane_extent_columns(sa, sb, ca, cb, r, a0, angle) -> np.ndarray:
    """:func:`arc_plane_extent`, column-wise, given the start angles ``a0``: rows of (lo_a, hi_a, lo_b, hi_b)."""
    half_pi = math.pi / 2
    a1 = a0 + angle
    ea, eb = ca + r * np.cos(a1), cb + r * np.sin(a1)
    lo_a, hi_a = np.minimum(sa, ea), np.maximum(sa, ea)
    lo_b, hi_b = np.minimum(sb, eb), np.maximum(sb, eb)
    lo = np.where(angle >= 0, a0, a1)
    hi = np.where(angle >= 0, a1, a0)
    k0 = np.ceil(lo / half_pi)
    for j in range(5):
        kq = k0 + j
        inside = kq * half_pi <= hi
        q = np.mod(kq, 4)
        hi_a = np.where(inside & (q == 0), ca + r, hi_a)
        hi_b = np.where(inside & (q == 1), cb + r, hi_b)
        lo_a = np.where(inside & (q == 2), ca - r, lo_a)
        lo_b = np.where(inside & (q == 3), cb - r, lo_b)
    full = np.abs(angle) >= TWO_PI - 1e-12
    return np.column_stack((np.where(full, ca - r, lo_a), np.where(full, ca + r, hi_a),
                            np.where(full, cb - r, lo_b), np.where(full, cb + r, hi_b)))


def arc_points(start, end, spec, max_seg_deg: float = 5.0):
    """Sample points along an arc (start excluded, end included), for plots."""
    a, b = spec.a, spec.b
    ca, cb = spec.center
    ang = sweep(start[a], start[b], end[a], end[b], ca, cb, spec.cw, spec.turns)
    n = max(2, int(abs(math.degrees(ang)) / max_seg_deg) + 1)
    a0 = math.atan2(start[b] - cb, start[a] - ca)
    pts = []
    for i in range(1, n + 1):
        t = i / n
        p = [s + (e - s) * t for s, e in zip(start, end)]
        p[a] = ca + spec.radius * math.cos(a0 + ang * t)
        p[b] = cb + spec.radius * math.sin(a0 + ang * t)
        pts.append(p)
    pts[-1] = list(end)
    return pts
