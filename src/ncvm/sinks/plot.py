"""Plots of a recorded toolpath: an XY view and a 3-D view side by side.

Rapids are dashed, feed moves solid, one colour per tool; start and end are marked.
:class:`PlotPoints` watches the recorder while the program runs and keeps at
most ``max_points`` points: a run of millions of moves is thinned by keeping,
in each bucket of consecutive points, those where the drawn axes reach their
lowest and highest values, so the drawing keeps its shape and its extents.
"""

from __future__ import annotations

from pathlib import Path

from ..lazy import lazy
from .toolpath import ARC, FEED, RAPID, ToolpathRecorder

np = lazy("numpy")


TOOL_COLOURS = ["tab:blue", "tab:orange", "tab:green", "tab:red", "tab:purple", "tab:brown", "tab:pink", "tab:olive"]
MAX_POINTS = 200_000  # points drawn, all lines together (and as many plunge marks)
#: thinning keeps at most 8 of each BUCKET consecutive points of a line (first, last, the extremes of X, Y, Z): on
#: a smooth curve only the two ends, so 16 (not more) keeps its chords close to it
BUCKET = 16


class PlotPoints:
    """The drawn points of a toolpath, per (rapid?, tool): NaN rows separate the lines of one style."""

    def __init__(self, recorder: ToolpathRecorder, max_points: int = MAX_POINTS):
        self.max_points = max_points
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

    @property
    def thinned(self) -> bool:
        return bool(self._passes)

    def note(self) -> str:
        """What the legend says of a thinned drawing: not every point of the toolpath is drawn."""
        return f"{self.moves:,} moves, thinned to {self._count:,} points (extents exact)"

    def observe(self, rec: ToolpathRecorder, lo: int, hi: int) -> None:
        if not self.names:
            self.names = rec.axis_names
            self.idx = _drawn_axes(self.names)
        self.moves += hi - lo
        arr = rec.window()
        idx = list(self.idx)
        kind, tool = arr["kind"][lo:hi], arr["tool"][lo:hi]
        start, end = arr["start"][lo:hi], arr["end"][lo:hi]
        key = tool.astype(np.int64) * 2 + (kind == RAPID)
        new = np.empty(len(key), dtype=bool)
        new[0] = self._last_key is None or key[0] != self._last_key
        new[1:] = key[1:] != key[:-1]
        # rows each move adds: a NaN row and its start when a line begins, then its end (an arc: its samples)
        samples = {int(r): np.asarray(rec.polyline(lo + int(r), start[r], end[r]), dtype=float)[:, idx]
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
        """(rapid?, tool) -> the points of its lines, NaN rows between them; then, each on its own, the points
        where the drawn axes reach their extremes (they draw nothing but keep the plot's extents)."""
        out = {}
        for style in sorted(self.lines, key=lambda k: (k[1], k[0])):
            alone = np.full((2 * len(self.extremes[style]), 3), np.nan)
            alone[1::2] = self.extremes[style]
            out[style] = np.concatenate((*self.lines[style], alone))
        return out


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


def draw(points: PlotPoints, path: str | Path, title: str = "") -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    names = points.names or ("X", "Y", "Z")
    x, y, z = points.idx
    fig = plt.figure(figsize=(13, 6))
    ax2 = fig.add_subplot(1, 2, 1)
    ax3 = fig.add_subplot(1, 2, 2, projection="3d")
    lines = points.drawn()
    for (rapid, tool), pts in lines.items():
        colour = TOOL_COLOURS[tool % len(TOOL_COLOURS)]
        style, width = ("--", 0.6) if rapid else ("-", 1.0)
        label = f"T{tool} {'rapid' if rapid else 'feed'}"
        ax2.plot(pts[:, 0], pts[:, 1], style, color=colour, linewidth=width, label=label)
        ax3.plot(pts[:, 0], pts[:, 1], pts[:, 2], style, color=colour, linewidth=width)
    if points.plunges:
        marks = np.concatenate(points.plunges)
        ax2.plot(marks[:, 0], marks[:, 1], "o", markerfacecolor="none", color="black", markersize=6, linewidth=0,
                 label="feed along the tool axis")
    if points.first is not None:
        first, last = points.first, points.last
        ax2.plot(first[0], first[1], "o", color="green", markersize=7, label="start")
        ax2.plot(last[0], last[1], "s", color="red", markersize=7, label="end")
        ax3.scatter([first[0]], [first[1]], [first[2]], color="green", marker="o")
        ax3.scatter([last[0]], [last[1]], [last[2]], color="red", marker="s")
    ax2.set_xlabel(names[x])
    ax2.set_ylabel(names[y])
    ax2.set_aspect("equal", adjustable="datalim")
    ax2.grid(True, linewidth=0.3)
    ax2.set_title(f"{names[x]}{names[y]} view")
    if points.thinned:  # a legend entry without a line: the drawing is decimated
        ax2.plot([], [], " ", label=points.note())
    if lines:
        ax2.legend(loc="best", fontsize=7)
    ax3.set_xlabel(names[x])
    ax3.set_ylabel(names[y])
    ax3.set_zlabel(names[z])
    ax3.set_title("3-D view")
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
