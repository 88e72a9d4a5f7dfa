"""Toolpath recorder: every move as rows of numpy arrays, with exact lengths and extents."""

from __future__ import annotations

import math
from dataclasses import dataclass
from itertools import chain

import numpy as np

from ..nc import arcs
from ..nc.canon import ArcSpec, CanonSink, Src

RAPID, FEED, ARC = 0, 1, 2


@dataclass
class MotionSummary:
    rapid_moves: int
    feed_moves: int
    arc_moves: int
    rapid_length: float
    feed_length: float
    bounds: dict[str, list[float]]

    def to_json(self) -> dict:
        return {"rapid_moves": self.rapid_moves, "feed_moves": self.feed_moves, "arc_moves": self.arc_moves,
                "rapid_length": self.rapid_length, "feed_length": self.feed_length, "bounds": self.bounds}


class ToolpathRecorder(CanonSink):
    """Records moves; :meth:`arrays` gives ``kind``, ``start``, ``end``, ``tool``, ``line`` as numpy arrays.

    Arcs keep their :class:`ArcSpec` so plots can draw them and extents include
    the quadrant points an arc passes through.
    """

    def __init__(self):
        self.axis_names: tuple[str, ...] = ()
        self.start_point: tuple = ()
        #: one (kind, end, src, tool) row per move: a single append on the hot path
        self.moves: list[tuple] = []
        self._add = self.moves.append
        self.arcs: dict[int, ArcSpec] = {}
        #: move index -> (a, b, lo_a, hi_a, lo_b, hi_b): where each arc reaches in its plane (limit check)
        self.arc_bounds: dict[int, tuple] = {}
        self.arc_length = 0.0
        self.arc_extent: list[list[float]] | None = None  # per axis [lo, hi]
        self.tool = 0
        self._arrays: tuple[int, dict] | None = None  # (number of moves, arrays()) of the last call

    def begin(self, axis_names, start):
        self.axis_names = tuple(axis_names)
        self.start_point = tuple(start)

    def rapid(self, start, end, src: Src):
        self._add((RAPID, end, src, self.tool))

    def feed(self, start, end, feed, src: Src):
        self._add((FEED, end, src, self.tool))

    def arc(self, start, end, spec: ArcSpec, feed, src: Src):
        index = len(self.moves)
        self.arcs[index] = spec
        self._add((ARC, end, src, self.tool))
        a, b = spec.a, spec.b
        ca, cb = spec.center
        angle = arcs.sweep(start[a], start[b], end[a], end[b], ca, cb, spec.cw, spec.turns)
        helix = math.sqrt(sum((e - s) ** 2 for i, (s, e) in enumerate(zip(start, end)) if i not in (a, b)))
        self.arc_length += arcs.arc_length(spec.radius, angle, helix)
        lo_a, hi_a, lo_b, hi_b = arcs.arc_plane_extent(start[a], start[b], ca, cb, spec.radius, angle)
        self.arc_bounds[index] = (a, b, lo_a, hi_a, lo_b, hi_b)
        ext = self.arc_extent
        if ext is None:
            ext = self.arc_extent = [[math.inf, -math.inf] for _ in self.axis_names]
        ext[a][0], ext[a][1] = min(ext[a][0], lo_a), max(ext[a][1], hi_a)
        ext[b][0], ext[b][1] = min(ext[b][0], lo_b), max(ext[b][1], hi_b)

    def tool_change(self, tool, src):
        self.tool = tool

    # -- results ---------------------------------------------------------
    def __len__(self) -> int:
        """Moves recorded so far (the CLI's progress line reads this while the program runs)."""
        return len(self.moves)

    @property
    def kinds(self) -> list[int]:
        return [row[0] for row in self.moves]

    @property
    def ends(self) -> list[tuple]:
        return [row[1] for row in self.moves]

    @property
    def lines(self) -> list[int]:
        return [row[2].line for row in self.moves]

    @property
    def srcs(self) -> list[Src]:
        return [row[2] for row in self.moves]

    def end_array(self) -> np.ndarray:
        """End point of every move, one row per move (shared with :meth:`arrays`: do not modify it)."""
        return self.arrays()["end"]

    @property
    def tools(self) -> list[int]:
        return [row[3] for row in self.moves]

    def arrays(self) -> dict[str, np.ndarray]:
        """The moves as numpy columns; built once per number of moves (summary, limit check and plot share it)."""
        moves = self.moves
        if self._arrays is not None and self._arrays[0] == len(moves):
            return self._arrays[1]
        n, n_axes = len(moves), len(self.axis_names)
        ends = np.fromiter(chain.from_iterable(row[1] for row in moves), dtype=float, count=n * n_axes)
        ends = ends.reshape(n, n_axes)
        starts = np.vstack([np.asarray(self.start_point, dtype=float).reshape(1, n_axes), ends[:-1]]) if n else ends
        arr = {"kind": np.fromiter((row[0] for row in moves), dtype=np.int8, count=n), "start": starts, "end": ends,
               "tool": np.fromiter((row[3] for row in moves), dtype=np.int32, count=n),
               "line": np.fromiter((row[2].line for row in moves), dtype=np.int32, count=n)}
        self._arrays = (n, arr)
        return arr

    def summary(self) -> MotionSummary:
        arr = self.arrays()
        kind, start, end = arr["kind"], arr["start"], arr["end"]
        seg = np.sqrt(((end - start) ** 2).sum(axis=1)) if len(kind) else np.zeros(0)
        rapid_len = float(seg[kind == RAPID].sum())
        feed_len = float(seg[kind == FEED].sum()) + self.arc_length
        bounds = {}
        if len(kind):
            lo = np.minimum(start.min(axis=0), end.min(axis=0))
            hi = np.maximum(start.max(axis=0), end.max(axis=0))
            for i, name in enumerate(self.axis_names):
                l, h = float(lo[i]), float(hi[i])
                if self.arc_extent is not None:
                    l, h = min(l, self.arc_extent[i][0]), max(h, self.arc_extent[i][1])
                bounds[name] = [l, h]
        return MotionSummary(int((kind == RAPID).sum()), int((kind == FEED).sum()), int((kind == ARC).sum()),
                             rapid_len, feed_len, bounds)

    def polyline(self, index: int, start, end) -> list:
        """Points of move ``index`` for drawing (arcs sampled)."""
        spec = self.arcs.get(index)
        if spec is None:
            return [list(end)]
        return arcs.arc_points(start, end, spec)
