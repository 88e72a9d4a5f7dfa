"""Plots of a recorded toolpath: an XY view and a 3-D view side by side.

Rapids are dashed, feed moves solid, one colour per tool; start and end are marked.
"""

from __future__ import annotations

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from .toolpath import FEED, RAPID, ToolpathRecorder  # noqa: E402

TOOL_COLOURS = ["tab:blue", "tab:orange", "tab:green", "tab:red", "tab:purple", "tab:brown", "tab:pink", "tab:olive"]


def _runs(rec: ToolpathRecorder, idx: tuple[int, int, int]):
    """Group consecutive moves of the same kind and tool into polylines (for fast drawing)."""
    arr = rec.arrays()
    kinds, starts, ends, tools = arr["kind"], arr["start"], arr["end"], arr["tool"]
    runs = []
    cur_key, pts = None, []
    for i in range(len(kinds)):
        key = (kinds[i] == RAPID, int(tools[i]))
        if key != cur_key:
            if pts:
                runs.append((cur_key, pts))
            cur_key, pts = key, [[float(starts[i][j]) for j in idx]]
        for p in rec.polyline(i, starts[i], ends[i]):
            pts.append([float(p[j]) for j in idx])
    if pts:
        runs.append((cur_key, pts))
    return runs


def _mark_plunges(ax, rec: ToolpathRecorder, x: int, y: int) -> None:
    """Feed moves straight down the tool axis (drilling) are invisible from above: ring them."""
    arr = rec.arrays()
    if not len(arr["kind"]) or x == y:
        return
    moved = arr["end"] - arr["start"]
    plunge = (arr["kind"] == FEED) & (moved[:, x] == 0) & (moved[:, y] == 0) & (moved.any(axis=1))
    if plunge.any():
        ax.plot(arr["end"][plunge, x], arr["end"][plunge, y], "o", markerfacecolor="none", color="black",
                markersize=6, linewidth=0, label="feed along the tool axis")


def plot_toolpath(rec: ToolpathRecorder, path: str | Path, title: str = "") -> None:
    names = rec.axis_names
    idx = tuple(names.index(n) if n in names else None for n in ("X", "Y", "Z"))
    if idx[0] is None:
        idx = (0, 1 if len(names) > 1 else 0, idx[2])
    x, y = idx[0], idx[1] if idx[1] is not None else idx[0]
    z = idx[2] if idx[2] is not None else y
    runs = _runs(rec, (x, y, z))
    fig = plt.figure(figsize=(13, 6))
    ax2 = fig.add_subplot(1, 2, 1)
    ax3 = fig.add_subplot(1, 2, 2, projection="3d")
    seen = set()
    for (rapid, tool), pts in runs:
        colour = TOOL_COLOURS[tool % len(TOOL_COLOURS)]
        style = "--" if rapid else "-"
        label = None
        if (rapid, tool) not in seen:
            seen.add((rapid, tool))
            label = f"T{tool} {'rapid' if rapid else 'feed'}"
        xs, ys, zs = zip(*pts)
        ax2.plot(xs, ys, style, color=colour, linewidth=0.6 if rapid else 1.0, label=label)
        ax3.plot(xs, ys, zs, style, color=colour, linewidth=0.6 if rapid else 1.0)
    _mark_plunges(ax2, rec, x, y)
    if runs:
        first, last = runs[0][1][0], runs[-1][1][-1]
        for ax in (ax2,):
            ax.plot(first[0], first[1], "o", color="green", markersize=7, label="start")
            ax.plot(last[0], last[1], "s", color="red", markersize=7, label="end")
        ax3.scatter([first[0]], [first[1]], [first[2]], color="green", marker="o")
        ax3.scatter([last[0]], [last[1]], [last[2]], color="red", marker="s")
    ax2.set_xlabel(names[x])
    ax2.set_ylabel(names[y])
    ax2.set_aspect("equal", adjustable="datalim")
    ax2.grid(True, linewidth=0.3)
    ax2.set_title(f"{names[x]}{names[y]} view")
    if runs:
        ax2.legend(loc="best", fontsize=7)
    ax3.set_xlabel(names[x])
    ax3.set_ylabel(names[y])
    ax3.set_zlabel(names[z])
    ax3.set_title("3-D view")
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
