"""Toolpath recorder: every move as rows of numpy arrays, with exact lengths and extents."""

from __future__ import annotations

import math
from bisect import bisect_right
from dataclasses import dataclass
from itertools import chain

import numpy as np

from ..nc import arcs
from ..nc.canon import ArcSpec, CanonSink, MoveBatch, Src

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

    Single moves are appended as rows (one append on the hot path); batches of
    moves arrive as columns and are kept as they are. Both end up as chunks of
    columns, joined when :meth:`arrays` is asked. Arcs keep their
    :class:`ArcSpec` so plots can draw them and extents include the quadrant
    points an arc passes through.
    """

    def __init__(self):
        self.axis_names: tuple[str, ...] = ()
        self.start_point: tuple = ()
        #: single moves not yet in a chunk: (kind, end, src, tool) rows
        self._rows: list[tuple] = []
        self._add = self._rows.append
        #: (first move index, columns, file of a batch or None, Src list of single moves or None)
        self._chunks: list[tuple] = []
        self._chunked = 0  # moves held in chunks
        #: single arcs: move index -> ArcSpec, and -> (a, b, lo_a, hi_a, lo_b, hi_b) where it reaches in its plane
        self._arcs: dict[int, ArcSpec] = {}
        self._arc_bounds: dict[int, tuple] = {}
        #: arcs of batches: (first move index of the batch, BatchArcs)
        self._arc_batches: list[tuple] = []
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
        index = len(self)
        self._add((ARC, end, src, self.tool))
        a, b = spec.a, spec.b
        ca, cb = spec.center
        angle = arcs.sweep(start[a], start[b], end[a], end[b], ca, cb, spec.cw, spec.turns)
        helix = math.sqrt(sum((e - s) ** 2 for i, (s, e) in enumerate(zip(start, end)) if i not in (a, b)))
        self._add_arc(index, spec, arcs.arc_length(spec.radius, angle, helix),
                      arcs.arc_plane_extent(start[a], start[b], ca, cb, spec.radius, angle))

    def move_batch(self, batch: MoveBatch):
        """Moves of a plain run: kept as the batch's columns, arcs as the batch's arc columns."""
        self._flush()
        base = self._chunked
        n = len(batch)
        columns = {"kind": batch.kind, "end": batch.end, "tool": np.full(n, self.tool, dtype=np.int32),
                   "line": batch.lines}
        self._chunks.append((base, columns, batch.file, None))
        self._chunked += n
        arc = batch.arcs
        if arc is None:
            return
        self._arc_batches.append((base, arc))
        self.arc_length = float(np.cumsum(np.concatenate(([self.arc_length], arc.length)))[-1])
        self._widen(arc.a, float(arc.extent[:, 0].min()), float(arc.extent[:, 1].max()))
        self._widen(arc.b, float(arc.extent[:, 2].min()), float(arc.extent[:, 3].max()))

    def _add_arc(self, index: int, spec: ArcSpec, length: float, extent) -> None:
        a, b = spec.a, spec.b
        lo_a, hi_a, lo_b, hi_b = extent
        self._arcs[index] = spec
        self.arc_length += length
        self._arc_bounds[index] = (a, b, lo_a, hi_a, lo_b, hi_b)
        self._widen(a, lo_a, hi_a)
        self._widen(b, lo_b, hi_b)

    @property
    def arcs(self) -> dict[int, ArcSpec]:
        """Move index -> :class:`ArcSpec` of every arc (built from the batches' columns when asked)."""
        out = dict(self._arcs)
        for base, arc in self._arc_batches:
            out.update((base + row, spec) for row, spec in arc.specs().items())
        return out

    def arc_reach(self, lo: np.ndarray, hi: np.ndarray) -> None:
        """Widen per-move lowest/highest points (rows of ``lo``/``hi``) by where the arcs reach in their plane."""
        for index, (a, b, lo_a, hi_a, lo_b, hi_b) in self._arc_bounds.items():
            lo[index, a], hi[index, a], lo[index, b], hi[index, b] = lo_a, hi_a, lo_b, hi_b
        for base, arc in self._arc_batches:
            rows = base + arc.rows
            lo[rows, arc.a], hi[rows, arc.a] = arc.extent[:, 0], arc.extent[:, 1]
            lo[rows, arc.b], hi[rows, arc.b] = arc.extent[:, 2], arc.extent[:, 3]

    def _widen(self, axis: int, lo: float, hi: float) -> None:
        """Widen the extent arcs reach on ``axis``."""
        ext = self.arc_extent
        if ext is None:
            ext = self.arc_extent = [[math.inf, -math.inf] for _ in self.axis_names]
        ext[axis][0], ext[axis][1] = min(ext[axis][0], lo), max(ext[axis][1], hi)

    def _flush(self) -> None:
        """Turn the single-move rows into a chunk of columns."""
        rows = self._rows
        if not rows:
            return
        n, n_axes = len(rows), len(self.axis_names)
        ends = np.fromiter(chain.from_iterable(row[1] for row in rows), dtype=float, count=n * n_axes)
        columns = {"kind": np.fromiter((row[0] for row in rows), dtype=np.int8, count=n),
                   "end": ends.reshape(n, n_axes),
                   "tool": np.fromiter((row[3] for row in rows), dtype=np.int32, count=n),
                   "line": np.fromiter((row[2].line for row in rows), dtype=np.int32, count=n)}
        self._chunks.append((self._chunked, columns, None, [row[2] for row in rows]))
        self._chunked += n
        rows.clear()

    def tool_change(self, tool, src):
        self.tool = tool

    # -- results ---------------------------------------------------------
    def __len__(self) -> int:
        """Moves recorded so far (the CLI's progress line reads this while the program runs)."""
        return self._chunked + len(self._rows)

    def src(self, index: int) -> Src:
        """Where move ``index`` came from."""
        self._flush()
        first, columns, file, srcs = self._chunks[bisect_right(self._chunks, index, key=lambda c: c[0]) - 1]
        return srcs[index - first] if srcs is not None else Src(file, int(columns["line"][index - first]))

    def end_array(self) -> np.ndarray:
        """End point of every move, one row per move (shared with :meth:`arrays`: do not modify it)."""
        return self.arrays()["end"]

    def arrays(self) -> dict[str, np.ndarray]:
        """The moves as numpy columns; built once per number of moves (summary, limit check and plot share it)."""
        self._flush()
        n, n_axes = self._chunked, len(self.axis_names)
        if self._arrays is not None and self._arrays[0] == n:
            return self._arrays[1]
        if self._chunks:
            arr = {name: np.concatenate([c[1][name] for c in self._chunks]) for name in ("kind", "end", "tool", "line")}
        else:
            arr = {"kind": np.zeros(0, np.int8), "end": np.zeros((0, n_axes)), "tool": np.zeros(0, np.int32),
                   "line": np.zeros(0, np.int32)}
        arr["start"] = np.vstack([np.asarray(self.start_point, dtype=float).reshape(1, n_axes), arr["end"][:-1]])
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
        spec = self._arc_at(index)
        if spec is None:
            return [list(end)]
        return arcs.arc_points(start, end, spec)

    def _arc_at(self, index: int) -> ArcSpec | None:
        spec = self._arcs.get(index)
        if spec is not None or not self._arc_batches:
            return spec
        base, arc = self._arc_batches[max(0, bisect_right(self._arc_batches, index, key=lambda c: c[0]) - 1)]
        k = int(np.searchsorted(arc.rows, index - base))
        return arc.spec(k) if k < len(arc.rows) and arc.rows[k] == index - base else None
