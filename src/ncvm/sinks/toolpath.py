"""Toolpath recorder: the moves as numpy columns, with running totals (counts, lengths, exact extents).

A run of millions of moves must not hold them all: unless the recorder is
asked to *keep* the toolpath (tests, API users who read :meth:`arrays`), it
holds a window of at most about ``WINDOW`` moves. When the window is full it
is *settled*: its moves are added to the running totals and handed to the
watchers (soft limits, work areas, the plot), which keep what they need (a
first violation, thinned points), and then forgotten.

A window of fewer than :data:`SMALL` single moves (a short program) is settled in plain Python when every
watcher can be shown rows (``observe_rows``): the same totals, extents and first violations, without
numpy's import (~0.1 s of a short run's start-up).
"""

from __future__ import annotations

import math
from bisect import bisect_right
from itertools import chain

from ..lazy import lazy
from ..nc import arcs
from ..nc.canon import ArcSpec, CanonSink, MoveBatch, Src
from ..records import Record

np = lazy("numpy")


RAPID, FEED, ARC = 0, 1, 2
#: moves held before the window is settled and forgotten (without keep)
WINDOW = 1 << 16
#: batches held before the window is settled (many tiny batches: one move per WAIT in a CPL loop)
MAX_CHUNKS = 1024
#: a window of fewer single moves than this (and no batch) is settled in plain Python: numpy sums fewer
#: than 8 numbers one after the other (more pairwise), so the lengths stay the same to the last bit
SMALL = 8


class MotionSummary(Record):
    __slots__ = ("rapid_moves", "feed_moves", "arc_moves", "rapid_length", "feed_length", "bounds",
                 "bounds_program")

    def __init__(self, rapid_moves: int, feed_moves: int, arc_moves: int, rapid_length: float,
                 feed_length: float, bounds: dict[str, list[float]],
                 bounds_program: dict[str, list[float]] | None = None):
        self.rapid_moves = rapid_moves
        self.feed_moves = feed_moves
        self.arc_moves = arc_moves
        self.rapid_length = rapid_length
        self.feed_length = feed_length
        self.bounds = bounds  # the machine's
        self.bounds_program = bounds_program  # the program's work frame (sinks.workbounds)

    def to_json(self) -> dict:
        return {"rapid_moves": self.rapid_moves, "feed_moves": self.feed_moves, "arc_moves": self.arc_moves,
                "rapid_length": self.rapid_length, "feed_length": self.feed_length, "bounds": self.bounds,
                "bounds_program": self.bounds if self.bounds_program is None else self.bounds_program}


class ToolpathRecorder(CanonSink):
    """Records moves; :meth:`window` gives the window's ``kind``, ``start``, ``end``, ``tool``, ``line`` columns.

    Single moves are appended as rows (one append on the hot path); batches of
    moves arrive as columns and are kept as they are. Both end up as chunks of
    columns, joined when :meth:`arrays` is asked. Arcs keep their
    :class:`ArcSpec` so plots can draw them and extents include the quadrant
    points an arc passes through. With ``keep`` the window is the whole toolpath;
    without, moves before it are only in the totals and the watchers.
    Indices (``src``, ``arcs``, ``arc_reach``, ``polyline``) count within the window.
    """

    def __init__(self, keep: bool = True):
        self.keep = keep
        self.axis_names: tuple[str, ...] = ()
        self.start_point: tuple = ()
        #: single moves not yet in a chunk: (kind, end, file, line, tool) rows
        self._rows: list[tuple] = []
        self._add = self._rows.append
        #: (first move index, columns, file of a batch or None, the files of single moves or None)
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
        #: moves forgotten before the window, and where the window starts
        self.base = 0
        self._window_start: tuple = ()
        self._settled = 0  # moves of the window already in the totals and shown to the watchers
        #: objects with ``observe(recorder, lo, hi)``: told of window moves lo..hi once each
        self._watchers: list = []
        self._counts = [0, 0, 0]
        self._lengths = [0.0, 0.0]  # straight rapid, straight feed
        self._lo: np.ndarray | None = None
        self._hi: np.ndarray | None = None

    def begin(self, axis_names, start):
        self.axis_names = tuple(axis_names)
        self.start_point = self._window_start = tuple(start)

    def watch(self, watcher) -> None:
        """Hand every move to ``watcher.observe(self, lo, hi)``, those already settled included."""
        if self.base:
            raise RuntimeError("a watcher of the toolpath must be added before its moves are forgotten")
        self._watchers.append(watcher)
        if self._settled:
            watcher.observe(self, 0, self._settled)

    def rapid(self, start, end, src: Src):
        self._add((RAPID, end, src.file, src.line, self.tool))
        if len(self._rows) >= WINDOW:
            self._flush()

    def feed(self, start, end, feed, src: Src):
        self._add((FEED, end, src.file, src.line, self.tool))
        if len(self._rows) >= WINDOW:
            self._flush()

    def arc(self, start, end, spec: ArcSpec, feed, src: Src):
        index = self._held()
        self._add((ARC, end, src.file, src.line, self.tool))
        a, b = spec.a, spec.b
        ca, cb = spec.center
        angle = arcs.sweep(start[a], start[b], end[a], end[b], ca, cb, spec.cw, spec.turns)
        helix = math.sqrt(sum((e - s) ** 2 for i, (s, e) in enumerate(zip(start, end)) if i not in (a, b)))
        self._add_arc(index, spec, arcs.arc_length(spec.radius, angle, helix),
                      arcs.arc_plane_extent(start[a], start[b], ca, cb, spec.radius, angle))
        if len(self._rows) >= WINDOW:
            self._flush()

    def move_batch(self, batch: MoveBatch):
        """Moves of a plain run: kept as the batch's columns, arcs as the batch's arc columns."""
        self._flush(settle=False)
        base = self._chunked
        n = len(batch)
        columns = {"kind": batch.kind, "end": batch.end, "tool": np.full(n, self.tool, dtype=np.int32),
                   "line": batch.lines}
        self._chunks.append((base, columns, batch.file, None))
        self._chunked += n
        arc = batch.arcs
        if arc is not None:
            self._arc_batches.append((base, arc))
            self.arc_length = float(np.cumsum(np.concatenate(([self.arc_length], arc.length)))[-1])
            self._widen(arc.a, float(arc.extent[:, 0].min()), float(arc.extent[:, 1].max()))
            self._widen(arc.b, float(arc.extent[:, 2].min()), float(arc.extent[:, 3].max()))
        self._settle_when_full()

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

    def arc_reach(self, lo: np.ndarray, hi: np.ndarray, first: int = 0) -> None:
        """Widen per-move lowest/highest points by where the arcs reach in their plane; row ``r`` of
        ``lo``/``hi`` is move ``first + r``."""
        n = len(lo)
        for index, (a, b, lo_a, hi_a, lo_b, hi_b) in self._arc_bounds.items():
            r = index - first
            if 0 <= r < n:  # rows of arrays or of lists
                lo[r][a], hi[r][a], lo[r][b], hi[r][b] = lo_a, hi_a, lo_b, hi_b
        for base, arc in self._arc_batches:
            rows = base + arc.rows - first
            inside = (rows >= 0) & (rows < n)
            if not inside.any():
                continue
            rows, ext = rows[inside], arc.extent[inside]
            lo[rows, arc.a], hi[rows, arc.a] = ext[:, 0], ext[:, 1]
            lo[rows, arc.b], hi[rows, arc.b] = ext[:, 2], ext[:, 3]

    def _widen(self, axis: int, lo: float, hi: float) -> None:
        """Widen the extent arcs reach on ``axis``."""
        ext = self.arc_extent
        if ext is None:
            ext = self.arc_extent = [[math.inf, -math.inf] for _ in self.axis_names]
        ext[axis][0], ext[axis][1] = min(ext[axis][0], lo), max(ext[axis][1], hi)

    def _flush(self, settle: bool = True) -> None:
        """Turn the single-move rows into a chunk of columns (and settle a full window)."""
        rows = self._rows
        if rows:
            n, n_axes = len(rows), len(self.axis_names)
            ends = np.fromiter(chain.from_iterable(row[1] for row in rows), dtype=float, count=n * n_axes)
            columns = {"kind": np.fromiter((row[0] for row in rows), dtype=np.int8, count=n),
                       "end": ends.reshape(n, n_axes),
                       "tool": np.fromiter((row[4] for row in rows), dtype=np.int32, count=n),
                       "line": np.fromiter((row[3] for row in rows), dtype=np.int32, count=n)}
            self._chunks.append((self._chunked, columns, None, [row[2] for row in rows]))
            self._chunked += n
            rows.clear()
        if settle:
            self._settle_when_full()

    def _settle_when_full(self) -> None:
        if not self.keep and (self._chunked - self._settled >= WINDOW or len(self._chunks) >= MAX_CHUNKS):
            self.settle()

    def settle(self) -> None:
        """Add the moves not yet counted to the totals and show them to the watchers; without keep, forget them."""
        if not self._chunks and len(self._rows) < SMALL and all(hasattr(w, "observe_rows") for w in self._watchers):
            self._settle_rows()
            return
        self._flush(settle=False)
        n = self._chunked
        if n > self._settled:
            lo = self._settled
            arr = self.window()
            self._total(arr["kind"][lo:], arr["start"][lo:], arr["end"][lo:])
            self._settled = n
            for w in self._watchers:
                w.observe(self, lo, n)
        if not self.keep and n:
            self._window_start = tuple(self.window()["end"][-1].tolist())
            self.base += n
            self._chunks.clear()
            self._chunked = self._settled = 0
            self._arcs.clear()
            self._arc_bounds.clear()
            self._arc_batches.clear()
            self._arrays = None

    def _settle_rows(self) -> None:
        """:meth:`settle` of a window held as single-move rows only, in plain Python: watchers are shown the
        rows' lowest and highest points (``observe_rows(recorder, lo, hi, low, high)``)."""
        rows = self._rows
        lo, n = self._settled, len(rows)
        if n > lo:
            start = self._window_start if lo == 0 else rows[lo - 1][1]
            counts, part = self._counts, [0.0, 0.0]  # the window's straight lengths, added as _total does
            low_all = list(self._lo) if self._lo is not None else [math.inf] * len(start)
            high_all = list(self._hi) if self._hi is not None else [-math.inf] * len(start)
            for kind, end, _file, _line, _tool in rows[lo:]:
                counts[kind] += 1
                if kind != ARC:
                    sq = 0.0
                    for s, e in zip(start, end):  # summed in axis order, as numpy sums fewer than 8
                        sq += (e - s) * (e - s)
                    part[kind] += math.sqrt(sq)
                for i, (s, e) in enumerate(zip(start, end)):
                    low_all[i] = min(low_all[i], s, e)
                    high_all[i] = max(high_all[i], s, e)
                start = end
            self._lengths[RAPID] += part[RAPID]
            self._lengths[FEED] += part[FEED]
            self._lo, self._hi = low_all, high_all
            low = [list(r[1]) for r in rows[lo:]]
            high = [list(r[1]) for r in rows[lo:]]
            self.arc_reach(low, high, lo)
            self._settled = n
            for w in self._watchers:
                w.observe_rows(self, lo, n, low, high)
        if not self.keep and n:
            self._window_start = tuple(rows[-1][1])
            self.base += n
            rows.clear()
            self._settled = 0
            self._arcs.clear()
            self._arc_bounds.clear()

    def _total(self, kind: np.ndarray, start: np.ndarray, end: np.ndarray) -> None:
        """Add moves to the running counts, straight lengths and extents."""
        seg = np.sqrt(((end - start) ** 2).sum(axis=1))
        for k in (RAPID, FEED, ARC):
            self._counts[k] += int((kind == k).sum())
        self._lengths[RAPID] += float(seg[kind == RAPID].sum())
        self._lengths[FEED] += float(seg[kind == FEED].sum())
        lo = np.minimum(start.min(axis=0), end.min(axis=0))
        hi = np.maximum(start.max(axis=0), end.max(axis=0))
        self._lo = lo if self._lo is None else np.minimum(self._lo, lo)
        self._hi = hi if self._hi is None else np.maximum(self._hi, hi)

    def tool_change(self, tool, src):
        self.tool = tool

    # -- results ---------------------------------------------------------
    def __len__(self) -> int:
        """Moves recorded so far (the CLI's progress line reads this while the program runs)."""
        return self.base + self._held()

    def _held(self) -> int:
        """Moves in the window."""
        return self._chunked + len(self._rows)

    def src(self, index: int) -> Src:
        """Where move ``index`` of the window came from."""
        if index >= self._chunked:  # a single move not yet in a chunk
            row = self._rows[index - self._chunked]
            return Src(row[2], row[3])
        first, columns, file, files = self._chunks[bisect_right(self._chunks, index, key=lambda c: c[0]) - 1]
        return Src(files[index - first] if files is not None else file, int(columns["line"][index - first]))

    def end_of(self, index: int) -> tuple:
        """Where move ``index`` of the window ends."""
        if index >= self._chunked:  # a single move not yet in a chunk
            return self._rows[index - self._chunked][1]
        return tuple(self.window()["end"][index].tolist())

    def arrays(self) -> dict[str, np.ndarray]:
        """Every move as numpy columns: the whole toolpath, which only a recorder that keeps it has."""
        if self.base:
            raise RuntimeError("the toolpath was not kept (RunOptions(keep_toolpath=True) keeps it)")
        return self.window()

    def window(self) -> dict[str, np.ndarray]:
        """The window's moves as numpy columns; built once per number of moves (watchers share it)."""
        self._flush(settle=False)
        n, n_axes = self._chunked, len(self.axis_names)
        if self._arrays is not None and self._arrays[0] == n:
            return self._arrays[1]
        if self._chunks:
            arr = {name: np.concatenate([c[1][name] for c in self._chunks]) for name in ("kind", "end", "tool", "line")}
        else:
            arr = {"kind": np.zeros(0, np.int8), "end": np.zeros((0, n_axes)), "tool": np.zeros(0, np.int32),
                   "line": np.zeros(0, np.int32)}
        start = np.asarray(self._window_start, dtype=float).reshape(1, n_axes)
        arr["start"] = np.vstack([start, arr["end"][:-1]])
        self._arrays = (n, arr)
        return arr

    def summary(self) -> MotionSummary:
        """Counts, lengths and extents of every move recorded (settles the window)."""
        self.settle()
        bounds = {}
        if self._lo is not None:
            for i, name in enumerate(self.axis_names):
                l, h = float(self._lo[i]), float(self._hi[i])
                if self.arc_extent is not None:
                    l, h = min(l, self.arc_extent[i][0]), max(h, self.arc_extent[i][1])
                bounds[name] = [l, h]
        rapid, feed, arc = self._counts
        return MotionSummary(rapid, feed, arc, self._lengths[RAPID], self._lengths[FEED] + self.arc_length, bounds)

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
