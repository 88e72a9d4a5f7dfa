"""The points of a toolpath plot, collected while the program runs (the drawing: plotview.py).

:class:`PlotPoints` watches the recorder while the program runs and keeps at
most ``max_points`` points: a run of millions of moves is thinned by keeping,
in each bucket of consecutive points, those where the drawn axes reach their
lowest and highest values, so the drawing keeps its shape and its extents.

It is also a canon sink that listens to two calls: ``frame`` (the work frame
changed: points are kept in the workpiece's coordinates, machine position minus
the offsets in force for that move, unless the machine frame was asked for) and
``channel`` (which of a control's parallel programs, the rw_SymPas tasks, makes
the moves that follow: lines are coloured by it instead of by tool). The run
begins wherever the simulator put the machine (its start position), not at a
point of the program: the rapid that leaves from there is the approach,
counted but not drawn; every later rapid leaves from a point a move of the
program reached and is drawn.
"""

from __future__ import annotations

from pathlib import Path

from ..lazy import lazy
from ..nc.canon import CanonSink
from .toolpath import ARC, FEED, RAPID, ToolpathRecorder
from .workbounds import in_force

np = lazy("numpy")

MAX_POINTS = 100_000  # points drawn, all lines together (and as many plunge marks): see docs/decisions.md
#: thinning keeps at most 8 of each BUCKET consecutive points of a line (first, last, the extremes of X, Y, Z): on
#: a smooth curve only the two ends, so 16 (not more) keeps its chords close to it
BUCKET = 16


class PlotPoints(CanonSink):
    """The drawn points of a toolpath, per (rapid?, tool or channel): NaN rows separate the lines of one style.

    ``frame``: "work" (the workpiece's coordinates, as the canon ``frame`` calls give them; until one
    comes, the machine's) or "machine".
    """

    def __init__(self, recorder: ToolpathRecorder, max_points: int | None = None, frame: str = "work"):
        self.max_points = MAX_POINTS if max_points is None else max_points
        self.frame_asked = frame
        self._rec = recorder
        #: (first move index, offsets) of each work frame, and (first move index, number) of each channel
        self._frames: list[tuple[int, np.ndarray]] = []
        self._channels: list[tuple[int, int]] = []
        self.approach = 0  # rapids of the approach from the start position: not drawn
        self._start: np.ndarray | None = None  # where the run began (drawn axes, in the plot's frame)
        self._approach_lines: list[np.ndarray] = []  # drawn only when the program never cuts
        self.names: tuple[str, ...] = ()
        self.idx: tuple[int, int, int] = (0, 0, 0)
        self.lines: dict[tuple[bool, int], list[np.ndarray]] = {}
        self.plunges: list[np.ndarray] = []
        self.first = self.last = None
        self._count = 0
        self._passes: list[str] = []  # the thinning passes the points held have had, in order
        #: per style, the points where each drawn axis reaches its lowest and highest value so far
        self.extremes: dict[tuple[bool, int], np.ndarray] = {}
        self._last_key = None
        self.moves = 0  # moves seen, drawn or thinned away
        recorder.watch(self)

    # -- canon calls --------------------------------------------------------
    def frame(self, frame, src) -> None:
        if self.frame_asked != "work":
            return
        new = np.asarray(frame.removed(), dtype=float)  # the zero offset and the tool length, as the trace's work
        at = len(self._rec)
        if self._frames and self._frames[-1][0] == at:
            self._frames[-1] = (at, new)
        else:
            self._frames.append((at, new))

    def channel(self, number: int, src) -> None:
        at = len(self._rec)
        if self._channels and self._channels[-1][0] == at:
            self._channels[-1] = (at, number)
        else:
            self._channels.append((at, number))

    @property
    def in_work_frame(self) -> bool:
        return bool(self._frames)

    @property
    def by_channel(self) -> bool:
        """Lines are told apart by channel (rw_SymPas task), not by tool."""
        return bool(self._channels)

    def offsets_at(self, move: int) -> np.ndarray:
        """The offsets taken off machine positions for move ``move`` (counted from the run's first)."""
        if not self._frames:
            return np.zeros(len(self.names) or 3)
        starts = [f[0] for f in self._frames]
        return self._frames[max(0, int(np.searchsorted(starts, move, side="right")) - 1)][1]

    @property
    def thinned(self) -> bool:
        return bool(self._passes)

    def note(self) -> str:
        """What the legend says of a thinned drawing: not every point of the toolpath is drawn (on three short
        lines, as the legend's other notes: the legend column is narrow)."""
        return f"{self.moves:,} moves,\nthinned to {self._count:,} points\n(extents exact)"


    # -- moves ----------------------------------------------------------------
    def observe(self, rec: ToolpathRecorder, lo: int, hi: int) -> None:
        if not self.names:
            self.names = rec.axis_names
            self.idx = _drawn_axes(self.names)
        self.moves += hi - lo
        arr = rec.window()
        idx = list(self.idx)
        kind, tool = arr["kind"][lo:hi], arr["tool"][lo:hi]
        start, end = arr["start"][lo:hi], arr["end"][lo:hi]
        shift = None
        if self._frames:  # the workpiece's coordinates: each move less the offsets in force for it
            which = in_force(self._frames, rec.base + lo, hi - lo)
            shift = np.stack([f[1] for f in self._frames])[which]
            start, end = start - shift, end - shift
        if self._channels:
            which = in_force(self._channels, rec.base + lo, hi - lo)
            tool = np.array([c[1] for c in self._channels], dtype=np.int64)[which]
        if self.first is None:  # the approach from the start position (see the module's docstring)
            skip = self._approach_rows(kind, start, end)
            if skip:
                self._hold_approach(start[:skip], end[:skip])
            if skip == hi - lo:
                return
            kind, tool, start, end = kind[skip:], tool[skip:], start[skip:], end[skip:]
            shift = shift[skip:] if shift is not None else None
            lo += skip
        key = tool.astype(np.int64) * 2 + (kind == RAPID)
        new = np.empty(len(key), dtype=bool)
        new[0] = self._last_key is None or key[0] != self._last_key
        new[1:] = key[1:] != key[:-1]
        # rows each move adds: a NaN row and its start when a line begins, then its end (an arc: its samples)
        samples = {int(r): _arc_points(rec, lo + int(r), start[r], end[r], shift, r, idx)
                   for r in np.flatnonzero(kind == ARC)}
        count = np.ones(len(key), dtype=np.int64)
        for r, pts in samples.items():
            count[r] = len(pts)
        rows = count + 2 * new
        offset = np.concatenate(([0], np.cumsum(rows)[:-1]))
        out = np.empty((int(rows.sum()), 3))
        begins = offset[new]
        out[begins] = np.nan
        out[begins + 1] = start[new][:, idx]
        straight = np.flatnonzero(kind != ARC)
        out[offset[straight] + 2 * new[straight]] = end[straight][:, idx]
        for r, pts in samples.items():
            at = offset[r] + 2 * new[r]
            out[at:at + len(pts)] = pts
        row_key = np.repeat(key, rows)
        for k in np.unique(key).tolist():
            part = out[row_key == k]
            style = (bool(k & 1), k >> 1)
            held = self.extremes.get(style)
            self.extremes[style] = _extreme_points(part if held is None else np.vstack((held, part)))
            for thin in self._passes:  # as thin as the points already held, so the density stays even
                part = _THIN[thin](part)
            self.lines.setdefault(style, []).append(part)
            self._count += len(part)
        if self.first is None:
            self.first = start[0][idx].tolist()
        self.last = end[-1][idx].tolist()
        self._last_key = key[-1]
        self._plunges(kind, start, end)
        if self._count > self.max_points:
            self._thin()

    def _approach_rows(self, kind: np.ndarray, start: np.ndarray, end: np.ndarray) -> int:
        """How many of these moves are the approach: rapids that leave from the point where the run began (the
        simulator's power-on position, which the program never named), before the first move away from it.
        Every rapid from a point a move of the program reached is drawn."""
        idx = list(self.idx)
        if self._start is None:
            self._start = start[0, idx].copy()
        drawn = (kind != RAPID) | (start[:, idx] != self._start).any(axis=1)
        return int(np.argmax(drawn)) if drawn.any() else len(kind)

    def _hold_approach(self, start: np.ndarray, end: np.ndarray) -> None:
        """Rapids of the approach: counted; their points kept (a few) in case the program never cuts."""
        self.approach += len(start)
        if sum(len(a) for a in self._approach_lines) < self.max_points:
            idx = list(self.idx)
            line = np.full((3 * len(start), 3), np.nan)
            line[1::3], line[2::3] = start[:, idx], end[:, idx]
            self._approach_lines.append(line)

    def _plunges(self, kind, start, end) -> None:
        """Feed moves straight down the tool axis (drilling) are invisible from above: their ends get rings."""
        x, y, _ = self.idx
        if x == y:
            return
        moved = end - start
        plunge = (kind == FEED) & (moved[:, x] == 0) & (moved[:, y] == 0) & moved.any(axis=1)
        if plunge.any():
            self.plunges.append(np.unique(end[plunge][:, [x, y]], axis=0))
            if sum(len(p) for p in self.plunges) > self.max_points:
                marks = np.unique(np.concatenate(self.plunges), axis=0)
                self.plunges = [marks if len(marks) <= self.max_points // 2 else _every_other_keeping_ends(marks)]

    def _thin(self) -> None:
        """Thin every line until all of them hold at most half of ``max_points``; later points get the same passes."""
        lines = {k: np.concatenate(parts) for k, parts in self.lines.items()}
        while (before := sum(len(v) for v in lines.values())) > self.max_points // 2:
            thin = "buckets"
            thinner = {k: _THIN[thin](v) for k, v in lines.items()}
            if sum(len(v) for v in thinner.values()) > 0.9 * before:  # lines too short to thin: drop every other
                thin = "lines"
                thinner = {k: _THIN[thin](v) for k, v in lines.items()}
                if sum(len(v) for v in thinner.values()) == before:
                    break
            lines = thinner
            self._passes.append(thin)
        self.lines = {k: [v] for k, v in lines.items()}
        self._count = sum(len(v) for v in lines.values())

    def drawn(self) -> dict[tuple[bool, int], np.ndarray]:
        """(rapid?, tool or channel) -> the points of its lines, NaN rows between them; then, each on its own, the
        points where the drawn axes reach their extremes (they draw nothing but keep the plot's extents).
        A program that never cuts: its rapids, the approach included."""
        if not self.lines and self._approach_lines:
            return {(True, 0): np.concatenate(self._approach_lines)}
        out = {}
        for style in sorted(self.lines, key=lambda k: (k[1], k[0])):
            alone = np.full((2 * len(self.extremes[style]), 3), np.nan)
            alone[1::2] = self.extremes[style]
            out[style] = np.concatenate((*self.lines[style], alone))
        return out


def _arc_points(rec: ToolpathRecorder, index: int, start, end, shift, row: int, idx: list) -> np.ndarray:
    """The sampled points of arc ``index`` in the plot's frame (the recorder samples in machine coordinates)."""
    if shift is None:
        return np.asarray(rec.polyline(index, start, end), dtype=float)[:, idx]
    pts = np.asarray(rec.polyline(index, start + shift[row], end + shift[row]), dtype=float)
    return (pts - shift[row])[:, idx]


def _drawn_axes(names: tuple[str, ...]) -> tuple[int, int, int]:
    """Columns drawn as x, y and z: X Y Z when the machine has them."""
    idx = tuple(names.index(n) if n in names else None for n in ("X", "Y", "Z"))
    if idx[0] is None:
        idx = (0, 1 if len(names) > 1 else 0, idx[2])
    x, y = idx[0], idx[1] if idx[1] is not None else idx[0]
    z = idx[2] if idx[2] is not None else y
    return x, y, z


def _extremes(points: np.ndarray, group: np.ndarray) -> np.ndarray:
    """Rows where each column reaches its lowest and its highest value within each group (rows of a group are
    consecutive; NaN rows are groups of their own)."""
    keep = []
    for col in range(points.shape[1]):
        order = np.lexsort((points[:, col], group))
        g = group[order]
        edge = np.flatnonzero(g[1:] != g[:-1])
        keep += [order[np.concatenate(([0], edge + 1))], order[np.concatenate((edge, [len(g) - 1]))]]
    return np.concatenate(keep)


def _thin_buckets(points: np.ndarray) -> np.ndarray:
    """Keep each line's first and last point and, per bucket of BUCKET points, its extremes on every axis."""
    if len(points) < 2:
        return points
    gap = np.isnan(points[:, 0])
    n = len(points)
    index = np.arange(n)
    line_start = np.maximum.accumulate(np.where(gap, index, 0))
    begins = gap | np.concatenate(([True], gap[:-1])) | ((index - line_start) % BUCKET == 0)
    group = np.cumsum(begins)
    ends = np.concatenate((begins[1:], [True]))
    keep = np.unique(np.concatenate((np.flatnonzero(begins), np.flatnonzero(ends), _extremes(points, group))))
    return points[keep]


def _drop_lines(points: np.ndarray) -> np.ndarray:
    """Drop every other line (lines are NaN-separated)."""
    line = np.cumsum(np.isnan(points[:, 0]))
    return points[line % 2 == 0]


def _extreme_points(points: np.ndarray) -> np.ndarray:
    """The points where each column is lowest and highest."""
    rows = [f(points[:, col]) for col in range(points.shape[1]) for f in (np.nanargmin, np.nanargmax)]
    return points[np.unique(rows)]


_THIN = {"buckets": _thin_buckets, "lines": _drop_lines}


def _every_other_keeping_ends(marks: np.ndarray) -> np.ndarray:
    """Every other mark, and those at the lowest and highest x and y."""
    keep = np.zeros(len(marks), dtype=bool)
    keep[::2] = True
    for col in range(marks.shape[1]):
        keep[np.argmin(marks[:, col])] = keep[np.argmax(marks[:, col])] = True
    return marks[keep]


def plot_toolpath(rec: ToolpathRecorder, path: str | Path, title: str = "") -> None:
    """Draw a recorder's toolpath (a recorder that keeps it, or one a :class:`PlotPoints` watched)."""
    points = PlotPoints(rec)
    rec.settle()
    draw(points, path, title)


from .plotview import draw  # noqa: E402  (the drawing, for callers that import it from here)
