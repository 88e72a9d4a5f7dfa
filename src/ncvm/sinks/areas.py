"""Protection-zone check: moves that enter a dead range or leave a work area.

A zone is an axis-parallel rectangle on two machine axes (machine coordinates,
mm; :class:`~ncvm.runtime.checks.Area`, the kind of zone front ends register). Like
:class:`~ncvm.sinks.limits.LimitCheck` it watches the toolpath
recorder, a window of moves at a time, and reports the first offending move per
zone; the run goes on. Work areas are convex, so a move stays inside exactly when its
extent (end points, widened by where arcs reach) does. Dead ranges are open
rectangles: a straight move enters one when the part of the segment inside it
has a length (Liang-Barsky clipping, vectorised); an arc in the zone's plane is
cut at its crossings of the four edges and each piece is tested at its middle;
an arc in another plane is tested as its sampled polyline.
"""

from __future__ import annotations

import math
from typing import Sequence

from ..lazy import lazy
from ..nc import arcs
from ..records import FrozenRecord, Record
from ..runtime.checks import DEAD, WORK, Area

np = lazy("numpy")


TOL = 1e-6  # mm: touching an edge is neither entering a dead range nor leaving a work area


class Zone(FrozenRecord):
    """Zone ``number`` (1..) of ``kind`` DEAD or WORK on the machine axes ``a`` and ``b`` (indices)."""

    __slots__ = ("number", "kind", "a", "b", "lo", "hi")

    def __init__(self, number: int, kind: str, a: int, b: int, lo: tuple[float, float], hi: tuple[float, float]):
        self.number = number
        self.kind = kind
        self.a = a
        self.b = b
        self.lo = lo  # lowest corner (a, b)
        self.hi = hi  # highest corner (a, b)


class ZoneViolation(Record):
    __slots__ = ("zone", "names", "file", "line")

    def __init__(self, zone: Zone, names: tuple[str, str], file: str, line: int):
        self.zone = zone
        self.names = names
        self.file = file
        self.line = line

    @property
    def axis(self) -> str:
        return f"{self.zone.kind} {self.zone.number}"

    def message(self) -> str:
        z, (na, nb) = self.zone, self.names
        verb = "enters" if z.kind == DEAD else "leaves"
        return (f"the path {verb} {z.kind} {z.number} ({na} {z.lo[0]:.4f}..{z.hi[0]:.4f}, "
                f"{nb} {z.lo[1]:.4f}..{z.hi[1]:.4f}) (first at {self.file}:{self.line})")


class ZoneCheck:
    """The first violation per zone among the moves of ``recorder``."""

    def __init__(self, zones: list[Zone], axis_names, recorder):
        self.zones = zones
        self.axis_names = tuple(axis_names)
        self.recorder = recorder
        #: zone number -> (move number, zone number, its first violation)
        self._found: dict[int, tuple] = {}
        recorder.watch(self)

    def first(self) -> list[ZoneViolation]:
        self.recorder.settle()
        return [v for _, _, v in sorted(self._found.values(), key=lambda f: (f[0], f[1]))]

    def observe(self, rec, lo: int, hi: int) -> None:
        """Moves ``lo``..``hi`` of the recorder's window: the first violation of each zone not yet found."""
        for z in self.zones:
            if z.number in self._found:
                continue
            k = self._first_work(rec, z, lo, hi) if z.kind == WORK else self._first_dead(rec, z, lo, hi)
            if k is not None:
                src = rec.src(k)
                self._found[z.number] = (rec.base + k, z.number, ZoneViolation(
                    z, (self.axis_names[z.a], self.axis_names[z.b]), src.file, src.line))

    @staticmethod
    def _first_work(rec, z: Zone, lo: int, hi: int) -> int | None:
        low = rec.window()["end"][lo:hi].copy()
        high = low.copy()
        rec.arc_reach(low, high, lo)
        bad = np.zeros(len(low), dtype=bool)
        for col, zl, zh in ((z.a, z.lo[0], z.hi[0]), (z.b, z.lo[1], z.hi[1])):
            bad |= (low[:, col] < zl - TOL) | (high[:, col] > zh + TOL)
        return lo + int(bad.argmax()) if bad.any() else None

    @staticmethod
    def _first_dead(rec, z: Zone, lo: int, hi: int) -> int | None:
        arr = rec.window()
        start, end = arr["start"], arr["end"]
        arc_specs = {i: spec for i, spec in rec.arcs.items() if lo <= i < hi}
        hits = _segments_enter(z, start[lo:hi], end[lo:hi])
        if arc_specs:
            hits[[i - lo for i in arc_specs]] = False  # arcs are tested on their curve, not their chord
        k = lo + int(hits.argmax()) if hits.any() else None
        for index in sorted(arc_specs):
            if k is not None and index >= k:
                break
            if _arc_enters(z, start[index], end[index], arc_specs[index]):
                return index
        return k


def _segments_enter(z: Zone, start: np.ndarray, end: np.ndarray) -> np.ndarray:
    """Per straight move: does the segment run through the open rectangle (shrunk by TOL)?"""
    t0 = np.zeros(len(start))
    t1 = np.ones(len(start))
    with np.errstate(divide="ignore", invalid="ignore"):
        for k, col in enumerate((z.a, z.b)):
            s, d = start[:, col], end[:, col] - start[:, col]
            lo, hi = z.lo[k] + TOL, z.hi[k] - TOL
            still = d == 0.0
            ta, tb = (lo - s) / d, (hi - s) / d
            enter = np.where(still, np.where((s > lo) & (s < hi), -np.inf, np.inf), np.minimum(ta, tb))
            leave = np.where(still, np.where((s > lo) & (s < hi), np.inf, -np.inf), np.maximum(ta, tb))
            t0 = np.maximum(t0, enter)
            t1 = np.minimum(t1, leave)
    return t1 > t0


def _inside(z: Zone, p) -> bool:
    return (z.lo[0] + TOL < p[z.a] < z.hi[0] - TOL) and (z.lo[1] + TOL < p[z.b] < z.hi[1] - TOL)


def _arc_enters(z: Zone, start, end, spec) -> bool:
    if {spec.a, spec.b} != {z.a, z.b}:  # seen edge-on or slanted: its sampled polyline
        pts = np.array([list(start)] + arcs.arc_points(start, end, spec, max_seg_deg=0.5), dtype=float)
        return bool(_segments_enter(z, pts[:-1], pts[1:]).any())
    ca, cb = spec.center
    r = spec.radius
    a0 = math.atan2(start[spec.b] - cb, start[spec.a] - ca)
    ang = arcs.sweep(start[spec.a], start[spec.b], end[spec.a], end[spec.b], ca, cb, spec.cw, spec.turns)
    if ang == 0.0 or r <= 0.0:
        return False
    # where the circle crosses the edge lines, as fractions t of the sweep; the pieces between are inside or not
    cuts = {0.0, 1.0}
    centre = {spec.a: ca, spec.b: cb}
    for k, col in enumerate((z.a, z.b)):
        for edge in (z.lo[k] + TOL, z.hi[k] - TOL):
            c = (edge - centre[col]) / r
            if abs(c) > 1.0:
                continue
            base = math.acos(c) if col == spec.a else math.asin(c)
            for phi in ((base, -base) if col == spec.a else (base, math.pi - base)):
                turn = (phi - a0) / ang
                step = 2.0 * math.pi / abs(ang)
                t = turn - math.floor(turn / step) * step
                while t < 1.0:
                    cuts.add(t)
                    t += step
    ts = sorted(cuts)
    for t_lo, t_hi in zip(ts, ts[1:]):
        theta = a0 + ang * (t_lo + t_hi) / 2.0
        p = {spec.a: ca + r * math.cos(theta), spec.b: cb + r * math.sin(theta)}
        if _inside(z, p):
            return True
    return False


def zone_check(areas: Sequence[Area], axis_names, recorder) -> ZoneCheck:
    """Build the check from :class:`~ncvm.runtime.checks.Area` records (or tuples of its fields); a zone
    is ``centre ± size / 2`` on each of its axes."""
    names = [n.upper() for n in axis_names]
    zones = []
    for number, kind, (na, nb), centre, size in areas:
        a, b = names.index(na.upper()), names.index(nb.upper())
        zones.append(Zone(number, kind, a, b, (centre[0] - size[0] / 2, centre[1] - size[1] / 2),
                          (centre[0] + size[0] / 2, centre[1] + size[1] / 2)))
    return ZoneCheck(zones, names, recorder)
