"""The drawing of a toolpath plot: a top view (XY), a front view (XZ), a side view (YZ) and a 3-D view.

Every view has equal scales on its axes (a circle stays a circle; the 3-D box has the proportions of the
path). Feed moves in the top view are coloured by depth when the program cuts at more than one depth; in
the other views, and in the top view of a flat program, each tool (or rw_SymPas task) has its colour;
rapids are dashed. Start and end, feed moves along the tool axis (drilling) and soft-limit violations are
marked. The legend and the notes sit in a column of their own, beside the views, never on the path. The
points come from :class:`~ncvm.sinks.plot.PlotPoints`, in the work frame unless the machine frame was
asked for; the axis labels say which.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Sequence

from ..lazy import lazy

np = lazy("numpy")

if TYPE_CHECKING:
    from .plot import PlotPoints

TOOL_COLOURS = ["tab:blue", "tab:orange", "tab:green", "tab:red", "tab:purple", "tab:brown", "tab:pink", "tab:olive"]
DEPTH_MAP = "viridis"
#: the shortest side of a view or of the 3-D box, as a share of the longest (a flat program keeps a thin slab)
MIN_SHARE = 0.04
PAD = 0.04  # margin around the path, as a share of its longest extent
#: points of a line drawn at once (one artist): bounds the renderer's memory (see :func:`_pieces`)
PIECE = 4000


def plot_title(program: str | Path, result: dict, machine_name: str = "") -> str:
    """The plot's title: program, dialect, machine, cycle time (and how the run ended when not normally)."""
    from ..timefmt import hms

    parts = [f"{Path(program).name} ({result['dialect']})"]
    if machine_name:
        parts.append(machine_name)
    parts.append(f"cycle time {hms(result['cycle_time_s'])}")
    if result.get("error"):
        parts.append(f"stopped with error {result['error']['code']}")
    return " · ".join(parts)


def plot_run(path: str | Path, program: str | Path, result: dict, session) -> None:
    """Draw the plot of a run (``ncvm run --plot``, ``make run``): its points, title and soft-limit violations."""
    violations = [v for v in session.checks.violations() if getattr(v, "point", None) is not None]
    draw(session.plot, path, plot_title(program, result, session.machine.name), violations=violations)


def draw(points: PlotPoints, path: str | Path, title: str = "", violations: Sequence = ()) -> None:
    """Save the plot of ``points`` (the extension of ``path`` chooses PNG, SVG or PDF)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig = figure(points, title, violations)
    try:
        fig.savefig(path, dpi=100)
    finally:
        plt.close(fig)


def figure(points: PlotPoints, title: str = "", violations: Sequence = ()):
    """The matplotlib figure of the plot (axes in ``fig.views``: "XY", "XZ", "YZ", "3-D")."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.lines import Line2D

    names = points.names or ("X", "Y", "Z")
    x, y, z = points.idx
    frame = "work" if points.in_work_frame else "machine"
    label = {c: f"{names[i]} ({frame})" for c, i in zip("xyz", (x, y, z))}
    lines = points.drawn()
    lo, hi = _extent(lines, points)

    fig = plt.figure(figsize=(15, 10))
    grid = fig.add_gridspec(2, 3, width_ratios=[1, 1, 0.5], left=0.05, right=0.99, top=0.9, bottom=0.06,
                            wspace=0.22, hspace=0.22)
    views = {"XY": fig.add_subplot(grid[0, 0]), "3-D": fig.add_subplot(grid[0, 1], projection="3d"),
             "XZ": fig.add_subplot(grid[1, 0]), "YZ": fig.add_subplot(grid[1, 1])}
    plane = {"XY": (0, 1), "XZ": (0, 2), "YZ": (1, 2)}
    handles = []
    paths = []  # the toolpath's artists: left out of the drawings that only measure the axis titles
    depth = _several_depths(lines, float(np.max(hi - lo)))
    who = "task" if points.by_channel else "T"
    for (rapid, owner), pts in lines.items():
        colour = TOOL_COLOURS[owner % len(TOOL_COLOURS)]
        style, width = ("--", 0.7) if rapid else ("-", 1.1)
        pieces = _pieces(pts)
        for name, (a, b) in plane.items():
            if name == "XY" and depth and not rapid:
                continue
            for piece in pieces:
                paths += views[name].plot(piece[:, a], piece[:, b], style, color=colour, linewidth=width)
        for piece in pieces:
            paths += views["3-D"].plot(piece[:, 0], piece[:, 1], piece[:, 2], style, color=colour, linewidth=width)
        name = f"task {owner}" if who == "task" else f"T{owner}"
        handles.append(Line2D([], [], linestyle=style, color=colour, linewidth=width,
                              label=f"{name} {'rapid' if rapid else 'feed'}"))
    if depth:
        paths.append(_depth_lines(fig, views["XY"], _feed_segments(lines), label["z"]))
    _marks(points, views, handles, violations)
    for name, (a, b) in plane.items():
        ax = views[name]
        ax.set_xlabel(label["xyz"[a]])
        ax.set_ylabel(label["xyz"[b]])
        ax.set_title({"XY": "top view (XY)", "XZ": "front view (XZ)", "YZ": "side view (YZ)"}[name])
        ax.grid(True, linewidth=0.3)
        _equal_2d(ax, lo, hi, a, b)
    _equal_3d(views["3-D"], lo, hi, label)
    views["3-D"].set_title("3-D view")
    _unclash_3d_titles(fig, views["3-D"], paths)
    notes = _notes(points, frame)
    if notes:
        handles += [Line2D([], [], linestyle="none", label=n) for n in notes]
    legend_box = fig.add_subplot(grid[:, 2])
    legend_box.axis("off")
    if handles:
        legend_box.legend(handles=handles, loc="upper left", fontsize=8, frameon=False, borderaxespad=0.0)
    fig.suptitle(title, fontsize=12)
    fig.views = views
    fig.legend_box = legend_box
    return fig


def _pieces(pts: np.ndarray) -> list[np.ndarray]:
    """A style's points as lines of at most PIECE + 1 points each, drawn one by one: the renderer (Agg) keeps
    the cells of one line's whole outline until it is drawn, so its memory grows with the length in pixels of
    all the line's segments, gigabytes for the plot's cap of points scattered over a view; a piece's outline is
    bounded. A piece ends where a line of the toolpath ends (a NaN row) when one does within PIECE points, so
    dashes and joins stay as they are; a longer line is cut at a point both pieces share (no segment left out,
    unlike the renderer's own ``agg.path.chunksize``, which leaves out the two segments around each cut)."""
    n = len(pts)
    if n <= PIECE + 1:
        return [pts]
    gaps = np.flatnonzero(np.isnan(pts[:, 0]))
    out, i = [], 0
    while n - i > PIECE + 1:
        k = int(np.searchsorted(gaps, i + PIECE, side="right")) - 1
        if k >= 0 and gaps[k] > i:  # the last line end within the piece: the next piece begins with it
            out.append(pts[i:gaps[k]])
            i = int(gaps[k])
        else:
            out.append(pts[i:i + PIECE + 1])
            i += PIECE
    out.append(pts[i:])
    return out


def _extent(lines: dict, points: PlotPoints) -> tuple[np.ndarray, np.ndarray]:
    """Lowest and highest drawn x, y, z (start and end included); a single point: that point. Line by line:
    no copy of all the drawn points (up to the plot's cap) is made for it."""
    lows, highs = [], []
    for pts in lines.values():
        pts = pts[~np.isnan(pts).any(axis=1)]
        if len(pts):
            lows.append(pts.min(axis=0))
            highs.append(pts.max(axis=0))
    extra = [p for p in (points.first, points.last) if p is not None]
    lows += [np.asarray(p, dtype=float) for p in extra]
    highs += [np.asarray(p, dtype=float) for p in extra]
    if not lows:
        return np.zeros(3), np.zeros(3)
    return np.min(lows, axis=0), np.max(highs, axis=0)


def _limits(lo: np.ndarray, hi: np.ndarray, longest: float) -> tuple[np.ndarray, np.ndarray]:
    """Limits around the path: a margin, and no side shorter than MIN_SHARE of the path's longest extent
    ``longest`` over all three axes (nor than 1)."""
    span = hi - lo
    longest = max(longest, 1.0)
    side = np.maximum(span, MIN_SHARE * longest) + 2 * PAD * longest
    mid = (lo + hi) / 2
    return mid - side / 2, mid + side / 2


def _equal_2d(ax, lo, hi, a: int, b: int) -> None:
    """Equal scales: the limits cover the path, and the shorter range grows until it fills the view's box."""
    low, high = _limits(lo[[a, b]], hi[[a, b]], float(np.max(hi - lo)))
    fig = ax.get_figure()
    box = ax.get_position()
    ratio = (box.width * fig.get_figwidth()) / (box.height * fig.get_figheight())
    span = high - low
    mid = (low + high) / 2
    if span[0] / span[1] < ratio:
        span[0] = span[1] * ratio
    else:
        span[1] = span[0] / ratio
    ax.set_xlim(mid[0] - span[0] / 2, mid[0] + span[0] / 2)
    ax.set_ylim(mid[1] - span[1] / 2, mid[1] + span[1] / 2)
    ax.set_aspect("equal", adjustable="box")


def _equal_3d(ax, lo, hi, label) -> None:
    """A box with the proportions of the path (a flat one: a thin slab whose Z axis shows its one depth)."""
    low, high = _limits(lo, hi, float(np.max(hi - lo)))
    ax.set_xlim(low[0], high[0])
    ax.set_ylim(low[1], high[1])
    ax.set_zlim(low[2], high[2])
    ax.set_box_aspect(tuple(high - low), zoom=0.9)
    from matplotlib.ticker import MaxNLocator

    share = (high - low) / float(np.max(high - low))
    flat = hi - lo <= 1e-9 * max(1.0, float(np.max(hi - lo)))
    for axis, s, one, at in zip((ax.xaxis, ax.yaxis, ax.zaxis), share, flat, lo):
        if one:  # the path does not move along this axis: its one value, no meaningless scale
            axis.set_ticks([at])
        else:  # a short side of the box: fewer ticks
            axis.set_major_locator(MaxNLocator(max(2, int(round(6 * s)))))
    ax.set_xlabel(label["x"])
    ax.set_ylabel(label["y"])
    ax.set_zlabel(label["z"])


def _unclash_3d_titles(fig, ax, paths: Sequence = (), tries: int = 6) -> None:
    """With equal scales a long, thin path makes a needle of the 3-D box, and its axis titles land on each
    other or on tick numbers: move such a title away from its axis until it is clear (one draw per try);
    a tick number a title still covers is left out (the flat views carry every number). The toolpath's
    artists ``paths`` are hidden during these drawings: titles and ticks follow the axes' limits, set
    before, not the lines, whose drawing (up to the plot's cap of points, in four views) would only cost
    time and memory each try."""
    for artist in paths:
        artist.set_visible(False)
    try:
        _place_3d_titles(fig, ax, tries)
    finally:
        for artist in paths:
            artist.set_visible(True)


def _place_3d_titles(fig, ax, tries: int) -> None:
    axes = (ax.xaxis, ax.yaxis, ax.zaxis)
    for last in [False] * tries + [True]:
        fig.canvas.draw()
        renderer = fig.canvas.get_renderer()
        ticks = [t for axis in axes for t in axis.get_ticklabels() if t.get_visible() and t.get_text()]
        boxes = [axis.label.get_window_extent(renderer) for axis in axes]
        covered = [t for t in ticks if any(b.overlaps(t.get_window_extent(renderer)) for b in boxes)]
        clashing = [axis for i, axis in enumerate(axes)
                    if any(boxes[i].overlaps(b) for j, b in enumerate(boxes) if j != i)]
        if last:
            for tick in covered:
                tick.set_visible(False)
        elif clashing or covered:  # one at a time: two titles pushed alike would move together
            (clashing or [a for a, b in zip(axes, boxes)
                          if any(b.overlaps(t.get_window_extent(renderer)) for t in covered)])[0].labelpad += 10
        else:
            return


def _several_depths(lines: dict, longest: float) -> bool:
    """Do the feed moves seen from above (segments that move in X or Y; not the plunges, points there) lie
    at several depths (the deeper end of each segment)? Worked out line by line on the points, without the
    segments' array (:func:`_feed_segments`, built only to draw them by depth)."""
    low = high = None
    for (rapid, _), pts in lines.items():
        if rapid or len(pts) < 2:
            continue
        a, b = pts[:-1], pts[1:]
        seen = np.isfinite(a).all(axis=1) & np.isfinite(b).all(axis=1)
        seen &= np.hypot(b[:, 0] - a[:, 0], b[:, 1] - a[:, 1]) > 1e-9
        if not seen.any():
            continue
        deep = np.minimum(a[seen, 2], b[seen, 2])
        low = deep.min() if low is None else min(low, deep.min())
        high = deep.max() if high is None else max(high, deep.max())
    return low is not None and high - low > 1e-9 * max(1.0, longest)


def _feed_segments(lines: dict) -> np.ndarray:
    """The feed moves' drawn segments, (segments, 2 ends, xyz)."""
    segs = []
    for (rapid, _), pts in lines.items():
        if rapid or len(pts) < 2:
            continue
        pair = np.stack([pts[:-1], pts[1:]], axis=1)
        segs.append(pair[np.isfinite(pair).all(axis=(1, 2))])
    return np.concatenate(segs) if segs else np.zeros((0, 2, 3))


def _depth_lines(fig, ax, segs: np.ndarray, zlabel: str):
    """Feed moves in the top view, each segment coloured by its depth (the deeper of its ends: a plunge shows
    the depth it reaches), the deepest drawn on top."""
    from matplotlib.collections import LineCollection

    depth = segs[:, :, 2].min(axis=1)
    order = np.argsort(-depth, kind="stable")
    segs, depth = segs[order], depth[order]
    coll = LineCollection(segs[:, :, :2], cmap=DEPTH_MAP, linewidths=1.1)
    coll.set_array(depth)
    ax.add_collection(coll)
    bar = fig.colorbar(coll, ax=ax, fraction=0.04, pad=0.02)
    bar.set_label(f"feed moves by depth: {zlabel}")
    return coll


def _marks(points: PlotPoints, views: dict, handles: list, violations: Sequence) -> None:
    """Start, end, feeds along the tool axis and the soft-limit violations, in every view."""
    from matplotlib.lines import Line2D

    plane = {"XY": (0, 1), "XZ": (0, 2), "YZ": (1, 2)}
    if points.plunges:
        marks = np.concatenate(points.plunges)
        views["XY"].plot(marks[:, 0], marks[:, 1], "o", markerfacecolor="none", color="black", markersize=6,
                         linewidth=0)
        handles.append(Line2D([], [], marker="o", markerfacecolor="none", color="black", linestyle="none",
                              label="feed along the tool axis (top view)"))
    # (point, marker, colour, size, filled, legend): the end is a large open square around a small start dot,
    # so a program that ends where it began shows both
    spots = []
    if points.first is not None:
        spots += [(points.first, "o", "green", 6, True, "start"), (points.last, "s", "red", 11, False, "end")]
    for v in violations:
        where = np.asarray(v.point, dtype=float) - points.offsets_at(v.move)
        spots.append((where[list(points.idx)].tolist(), "X", "crimson", 9, True,
                      f"soft limit {v.axis} {v.limit:g} passed:\n{v.value:.3f} (machine), line {v.line}"))
    for p, marker, colour, size, filled, text in spots:
        face = colour if filled else "none"
        for name, (a, b) in plane.items():
            views[name].plot(p[a], p[b], marker, color=colour, markerfacecolor=face, markersize=size,
                             markeredgewidth=1.5, zorder=6 if filled else 5)
        views["3-D"].scatter([p[0]], [p[1]], [p[2]], edgecolors=colour, facecolors=face, marker=marker,
                             s=size * size, linewidths=1.5, depthshade=False)
        handles.append(Line2D([], [], marker=marker, color=colour, markerfacecolor=face, linestyle="none",
                              markersize=7, label=text))


def _notes(points: PlotPoints, frame: str) -> list[str]:
    """What the picture leaves out or how it is drawn, said in the legend column."""
    notes = []
    if frame == "work":
        notes.append("work frame: the program's\ncoordinates (zero offsets and\ntool length taken off)")
    else:
        notes.append("machine frame")
    if points.approach and points.lines:
        n = points.approach
        notes.append(f"{n} rapid{'s' if n != 1 else ''} from the start\nposition (the simulator's, not\nthe program's): not drawn")
    if points.thinned:  # the drawing is decimated: not every point of the toolpath is drawn
        notes.append(points.note())
    return notes
