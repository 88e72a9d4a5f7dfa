"""Travel-limit check: the first block whose motion leaves an axis's soft limits.

The check watches the toolpath recorder (:meth:`ToolpathRecorder.watch`)
instead of being a canon sink called on every move: it is shown the moves a
window at a time and tests them with numpy, straight moves by their end points
(the start was the previous end), arcs by the extent they reach in their plane.
"""

from __future__ import annotations

from ..lazy import lazy
from ..records import Record

np = lazy("numpy")


class LimitViolation(Record):
    __slots__ = ("axis", "value", "limit", "file", "line", "frame", "point", "move")

    def __init__(self, axis: str, value: float, limit: float, file: str, line: int, frame: str = "",
                 point: tuple | None = None, move: int = 0):
        self.axis = axis
        self.value = value
        self.limit = limit
        self.file = file
        self.line = line
        self.frame = frame  # said where the program's other figures are in another frame ("machine")
        self.point = point  # machine position where the axis is beyond its limit (the plot marks it)
        self.move = move  # the move's number in the run (the plot takes off the offsets in force for it)

    def message(self) -> str:
        side = "above" if self.value > self.limit else "below"
        frame = f" in {self.frame} coordinates" if self.frame else ""
        return (f"axis {self.axis} reaches {self.value:.4f}{frame}, {side} its soft limit {self.limit:.4f} "
                f"(first at {self.file}:{self.line})")


class LimitCheck:
    """The first violation per axis among the moves of ``recorder`` (the run goes on; the report says where)."""

    def __init__(self, axes, recorder):
        self.axes = axes
        self.recorder = recorder
        self._mins = [ax.min - 1e-9 for ax in axes]
        self._maxs = [ax.max + 1e-9 for ax in axes]
        #: axis index -> (move number, axis index, its first violation)
        self._found: dict[int, tuple] = {}
        recorder.watch(self)

    def observe(self, rec, lo: int, hi: int) -> None:
        """Moves ``lo``..``hi`` of the recorder's window: the first violation of each axis not yet found."""
        if len(self._found) == len(self.axes):
            return
        low = rec.window()["end"][lo:hi].copy()
        high = low.copy()
        rec.arc_reach(low, high, lo)
        for i in range(len(self.axes)):
            if i in self._found:
                continue
            below = low[:, i] < self._mins[i]
            bad = below | (high[:, i] > self._maxs[i])
            if not bad.any():
                continue
            k = int(bad.argmax())
            self._found_at(rec, lo + k, i, bool(below[k]), float(low[k, i]) if below[k] else float(high[k, i]),
                           rec.window()["end"][lo + k].tolist())

    def observe_rows(self, rec, lo: int, hi: int, low: list, high: list) -> None:
        """:meth:`observe` of a few moves as rows (their lowest and highest points), in plain Python."""
        for i in range(len(self.axes)):
            if i in self._found:
                continue
            for k, (lw, hg) in enumerate(zip(low, high)):
                below = lw[i] < self._mins[i]
                if below or hg[i] > self._maxs[i]:
                    self._found_at(rec, lo + k, i, below, lw[i] if below else hg[i], list(rec.end_of(lo + k)))
                    break

    def _found_at(self, rec, k: int, i: int, below: bool, value: float, point: list) -> None:
        """Window move ``k`` is the first to take axis ``i`` to ``value``, past a limit; ``point`` its end."""
        ax = self.axes[i]
        src = rec.src(k)
        point[i] = value
        self._found[i] = (rec.base + k, i, LimitViolation(ax.name, value, ax.min if below else ax.max, src.file,
                                                         src.line, point=tuple(point), move=rec.base + k))

    @property
    def violations(self) -> dict[str, LimitViolation]:
        """Axis name -> its first violation, in the order they happened (move, then axis order)."""
        self.recorder.settle()
        return {v.axis: v for _, _, v in sorted(self._found.values(), key=lambda f: (f[0], f[1]))}

    def first(self) -> list[LimitViolation]:
        return sorted(self.violations.values(), key=lambda v: v.line)
