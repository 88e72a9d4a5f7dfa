"""The moves of a run as a table: one row per move with its kind, start, end, feed, time, file, line and tool.

Only the Python API records it, and only when asked (``ncvm.run(..., moves=True)``): the table holds every
move of the run, so its memory grows with the program, unlike the rest of a run (issue 18, docs/api.md).
The time of a move is what the path planner gave it (the cycle-time model of the run); a straight move
of length 0 takes none; moves the front end times itself (the rw_SymPas card) have no time of their own (NaN).
"""

from __future__ import annotations

import math
from collections import deque

from ..lazy import lazy
from ..nc.canon import CanonSink, floats

np = lazy("numpy")

KINDS = ("rapid", "feed", "arc")


class MoveTable(CanonSink):
    """Records every move; :meth:`array` gives them as a numpy structured array."""

    def __init__(self):
        self.axis_names: tuple[str, ...] = ()
        self.tool = 0
        #: where a move was programmed, as the user sees it (a CL 800 program's own lines): set by the run
        self.place = None
        self.file_names: dict[str, str] = {}  # a file's name in the table instead of its path (program text)
        self._rows: list[tuple] = []  # (kind, start, end, feed, file, line, tool)
        self._times: list[float] = []
        self._untimed: deque[int] = deque()  # rows waiting for the planner's time, oldest first
        self._early: deque[float] = deque()  # times the planner gave before their move arrived
        self._planned = True

    def begin(self, axis_names, start):
        self.axis_names = tuple(axis_names)

    def tool_change(self, tool, src):
        self.tool = tool

    def rapid(self, start, end, src):
        self._move(0, start, end, math.nan, src)

    def feed(self, start, end, feed, src):
        self._move(1, start, end, feed, src)

    def arc(self, start, end, spec, feed, src):
        self._move(2, start, end, feed, src)

    def _move(self, kind: int, start, end, feed: float, src) -> None:
        if self.place is not None:
            src = self.place(src)
        self._rows.append((kind, tuple(start), tuple(end), feed, src.file, src.line, self.tool))
        if not self._planned:
            self._times.append(math.nan)
        elif start == end and kind != 2:
            self._times.append(0.0)  # not planned: it takes no time
        elif self._early:
            self._times.append(self._early.popleft())
        else:
            self._times.append(math.nan)
            self._untimed.append(len(self._rows) - 1)

    def timing(self, times, entry, exit):
        if times is None:
            self._planned = False
            return
        for t in floats(times):
            if self._untimed:
                self._times[self._untimed.popleft()] = t
            else:
                self._early.append(t)

    def __len__(self) -> int:
        return len(self._rows)

    def array(self, labels: dict[str, str] | None = None):
        """The moves as a numpy structured array: ``kind`` ("rapid", "feed", "arc"), ``start_<axis>`` and
        ``end_<axis>`` per axis (machine coordinates, the program's axis names), ``feed`` (mm/min; NaN for a
        rapid move), ``time`` (s), ``file``, ``line``, ``tool``."""
        labels = labels or {}
        names = [labels.get(a, a) for a in self.axis_names]
        rows = self._rows
        width = max((len(self.file_names.get(r[4], r[4])) for r in rows), default=1)
        dtype = [("kind", "U5"), *((f"start_{n}", "f8") for n in names), *((f"end_{n}", "f8") for n in names),
                 ("feed", "f8"), ("time", "f8"), ("file", f"U{width}"), ("line", "i4"), ("tool", "i4")]
        out = np.zeros(len(rows), dtype=dtype)
        if rows:
            n = len(names)
            out["kind"] = [KINDS[r[0]] for r in rows]
            starts = np.array([r[1] for r in rows], dtype=float).reshape(len(rows), n)
            ends = np.array([r[2] for r in rows], dtype=float).reshape(len(rows), n)
            for i, name in enumerate(names):
                out[f"start_{name}"] = starts[:, i]
                out[f"end_{name}"] = ends[:, i]
            out["feed"] = [r[3] for r in rows]
            out["time"] = self._times
            names = self.file_names
            out["file"] = [names.get(r[4], r[4]) for r in rows]
            out["line"] = [r[5] for r in rows]
            out["tool"] = [r[6] for r in rows]
        return out
