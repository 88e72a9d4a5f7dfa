"""Travel-limit check: the first block whose motion leaves an axis's soft limits."""

from __future__ import annotations

from dataclasses import dataclass
from operator import le

from ..nc import arcs
from ..nc.canon import CanonSink


@dataclass
class LimitViolation:
    axis: str
    value: float
    limit: float
    file: str
    line: int

    def message(self) -> str:
        side = "above" if self.value > self.limit else "below"
        return (f"axis {self.axis} reaches {self.value:.4f}, {side} its soft limit {self.limit:.4f} "
                f"(first at {self.file}:{self.line})")


class LimitCheck(CanonSink):
    """Remembers the first violation per axis; the run goes on (the report says where)."""

    def __init__(self, axes):
        self.axes = axes
        self.violations: dict[str, LimitViolation] = {}
        self._mins = tuple(ax.min - 1e-9 for ax in axes)
        self._maxs = tuple(ax.max + 1e-9 for ax in axes)

    def _check(self, lo, hi, src):
        for i, ax in enumerate(self.axes):
            if ax.name in self.violations:
                continue
            if lo[i] < self._mins[i]:
                self.violations[ax.name] = LimitViolation(ax.name, lo[i], ax.min, src.file, src.line)
            elif hi[i] > self._maxs[i]:
                self.violations[ax.name] = LimitViolation(ax.name, hi[i], ax.max, src.file, src.line)

    def begin(self, axis_names, start):
        pass

    def rapid(self, start, end, src):
        # a straight move stays inside the box when its end point does (the start was checked before)
        if not (all(map(le, self._mins, end)) and all(map(le, end, self._maxs))):
            self._check(end, end, src)

    def feed(self, start, end, feed, src):
        # the same test as rapid, spelled out: one call less on every feed move
        if not (all(map(le, self._mins, end)) and all(map(le, end, self._maxs))):
            self._check(end, end, src)

    def arc(self, start, end, spec, feed, src):
        a, b = spec.a, spec.b
        ca, cb = spec.center
        angle = arcs.sweep(start[a], start[b], end[a], end[b], ca, cb, spec.cw, spec.turns)
        lo_a, hi_a, lo_b, hi_b = arcs.arc_plane_extent(start[a], start[b], ca, cb, spec.radius, angle)
        lo, hi = list(end), list(end)
        lo[a], hi[a], lo[b], hi[b] = lo_a, hi_a, lo_b, hi_b
        self._check(lo, hi, src)

    def first(self) -> list[LimitViolation]:
        return sorted(self.violations.values(), key=lambda v: v.line)
