"""Travel-limit check: the first block whose motion leaves an axis's soft limits.

The check reads the toolpath recorder's moves once, at the end, with numpy,
instead of being a canon sink called on every move: straight moves are
tested by their end points (the start was the previous end), arcs by the
extent they reach in their plane.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


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


class LimitCheck:
    """The first violation per axis among the moves of ``recorder`` (the run goes on; the report says where)."""

    def __init__(self, axes, recorder):
        self.axes = axes
        self.recorder = recorder
        self._mins = tuple(ax.min - 1e-9 for ax in axes)
        self._maxs = tuple(ax.max + 1e-9 for ax in axes)

    def _reach(self) -> tuple[np.ndarray, np.ndarray]:
        """Lowest and highest point of every move per axis: the end point, widened by arcs in their plane."""
        lo = self.recorder.end_array().copy()
        hi = lo.copy()
        self.recorder.arc_reach(lo, hi)
        return lo, hi

    @property
    def violations(self) -> dict[str, LimitViolation]:
        """Axis name -> its first violation, in the order they happened (move, then axis order)."""
        if not len(self.recorder):
            return {}
        lo, hi = self._reach()
        found = []
        for i, ax in enumerate(self.axes):
            below = lo[:, i] < self._mins[i]
            bad = below | (hi[:, i] > self._maxs[i])
            if not bad.any():
                continue
            k = int(bad.argmax())
            src = self.recorder.src(k)
            if below[k]:
                found.append((k, i, LimitViolation(ax.name, float(lo[k, i]), ax.min, src.file, src.line)))
            else:
                found.append((k, i, LimitViolation(ax.name, float(hi[k, i]), ax.max, src.file, src.line)))
        found.sort(key=lambda f: (f[0], f[1]))
        return {v.axis: v for _, _, v in found}

    def first(self) -> list[LimitViolation]:
        return sorted(self.violations.values(), key=lambda v: v.line)
