"""The bounds of a run in the program's work frame, kept as running extremes while the program runs.

The recorder keeps the machine's bounds (every move as the axes went); the user compares the run with the
program, whose coordinates are those of the work frame: machine positions less the zero offset and the tool
length in force for each move (:meth:`~ncvm.nc.canon.Frame.removed`, the same frame the plot draws in). Shifts
and coordinate transformations stay in, as the plot and the trace's ``work`` keep them. Nothing is held per
move: each settled window of moves widens two arrays, and only the frames still in force are kept.
"""

from __future__ import annotations

import math
from bisect import bisect_right

from ..lazy import lazy
from ..nc.canon import CanonSink
from .toolpath import ToolpathRecorder

np = lazy("numpy")


def in_force(marks: list[tuple[int, object]], first: int, n: int) -> np.ndarray:
    """Index into ``marks`` ((first move, value), by move) of the entry in force for moves first..first+n
    (before the first mark: the first)."""
    starts = np.array([m[0] for m in marks])
    return np.maximum(np.searchsorted(starts, np.arange(first, first + n), side="right") - 1, 0)


class WorkBounds(CanonSink):
    """Lowest and highest work coordinate per axis; told each work frame (canon ``frame``) and each settled
    window of moves (a watcher of the recorder)."""

    def __init__(self, recorder: ToolpathRecorder):
        self._rec = recorder
        #: (first move, offsets removed), from the one in force on (tuples: a run without moves needs no numpy)
        self._frames: list[tuple[int, tuple[float, ...]]] = []
        self._lo: np.ndarray | None = None
        self._hi: np.ndarray | None = None
        recorder.watch(self)

    def frame(self, frame, src) -> None:
        new = tuple(map(float, frame.removed()))
        at = len(self._rec)
        if not self._frames and at:  # the moves before the first frame: in the machine's
            self._frames.append((0, (0.0,) * len(new)))
        if self._frames and self._frames[-1][0] == at:
            self._frames[-1] = (at, new)
        else:
            self._frames.append((at, new))

    def observe(self, rec: ToolpathRecorder, lo: int, hi: int) -> None:
        if not self._frames:  # no offset yet: the work frame is the machine's
            self._frames.append((0, (0.0,) * len(rec.axis_names)))
        arr = rec.window()
        # the points the program reached: the ends of its moves, and where arcs reach between their ends (not
        # the start of the run, the machine's power-on position, nor a start told in a frame changed since)
        low, high = arr["end"][lo:hi].copy(), arr["end"][lo:hi].copy()
        rec.arc_reach(low, high, lo)
        shift = np.array([f[1] for f in self._frames], dtype=float)[in_force(self._frames, rec.base + lo, hi - lo)]
        low, high = (low - shift).min(axis=0), (high - shift).max(axis=0)
        self._lo = low if self._lo is None else np.minimum(self._lo, low)
        self._hi = high if self._hi is None else np.maximum(self._hi, high)
        self._done(rec.base + hi)

    def observe_rows(self, rec: ToolpathRecorder, lo: int, hi: int, low: list, high: list) -> None:
        """:meth:`observe` of a few moves as rows (their lowest and highest points), in plain Python."""
        if not self._frames:
            self._frames.append((0, (0.0,) * len(rec.axis_names)))
        starts = [f[0] for f in self._frames]
        n = len(rec.axis_names)
        least = list(self._lo) if self._lo is not None else [math.inf] * n
        most = list(self._hi) if self._hi is not None else [-math.inf] * n
        for k, (lw, hg) in enumerate(zip(low, high)):
            shift = self._frames[max(bisect_right(starts, rec.base + lo + k) - 1, 0)][1]  # as in_force
            for i in range(n):
                least[i] = min(least[i], lw[i] - shift[i])
                most[i] = max(most[i], hg[i] - shift[i])
        self._lo, self._hi = least, most
        self._done(rec.base + hi)

    def _done(self, last: int) -> None:
        """Forget the frames before the one in force for move ``last`` (the next to come)."""
        keep = max(0, bisect_right([f[0] for f in self._frames], last) - 1)
        del self._frames[:keep]

    def bounds(self, machine: dict[str, list[float]]) -> dict[str, list[float]]:
        """Per axis [lowest, highest] work coordinate, given the run's ``machine`` bounds (the recorder's,
        settled); a run in no offset has the machine's."""
        if self._lo is None:  # no move
            return {}
        names = self._rec.axis_names
        return {names[i]: [float(self._lo[i]), float(self._hi[i])] for i in range(len(names)) if names[i] in machine}
