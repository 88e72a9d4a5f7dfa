"""Long lines of a plot are drawn in pieces (plotview.PIECE points each), so the renderer's memory stays bounded
at the plot's cap of points (issue 18 item 2: "a plot of millions of moves decimates" in bounded memory). The
pieces draw exactly the segments of the line: none left out, none twice, and a piece ends where a line of the
toolpath ends when one does within it. The memory figures are the bench's (proc_sympas_2m_moves_plot_memory)
and tests/review18c's whole-process check."""

from __future__ import annotations

import matplotlib
import numpy as np
import pytest

from ncvm.sinks import plotview, toolpath
from ncvm.sinks.plot import PlotPoints

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def points_of(line: np.ndarray) -> PlotPoints:
    """A plot holding one feed line (T0) and nothing else."""
    p = PlotPoints(toolpath.ToolpathRecorder(keep=False))
    p.names, p.idx = ("X", "Y", "Z"), (0, 1, 2)
    finite = line[np.isfinite(line).all(axis=1)]
    p.lines = {(False, 0): [line]}
    p.extremes = {(False, 0): finite[[0, -1]]}
    p.first, p.last = finite[0].tolist(), finite[-1].tolist()
    return p


def segments(parts: list[np.ndarray]) -> list[tuple]:
    """Every drawn segment (both ends finite) of the parts, sorted."""
    out = []
    for pts in parts:
        a, b = pts[:-1], pts[1:]
        both = np.isfinite(a).all(axis=1) & np.isfinite(b).all(axis=1)
        out += [tuple(a[i]) + tuple(b[i]) for i in np.flatnonzero(both)]
    return sorted(out)


def drawn_feed(fig, view: str) -> list[np.ndarray]:
    """The xy (or xyz in the 3-D view) data of the solid lines of a view, in drawing order."""
    lines = [line for line in fig.views[view].lines if line.get_linestyle() == "-" and len(line.get_xdata()) > 1]
    if view == "3-D":
        return [np.column_stack(line.get_data_3d()) for line in lines]
    return [line.get_xydata() for line in lines]


@pytest.fixture
def small_pieces(monkeypatch):
    monkeypatch.setattr(plotview, "PIECE", 50)


def test_a_line_longer_than_a_piece_is_drawn_in_pieces_with_every_segment_once(small_pieces):
    """A line of 1,000 points (two gaps) drawn as pieces of at most 51 points that share their ends: the
    segments drawn in each view are exactly the line's."""
    rng = np.random.default_rng(7)
    line = rng.random((1000, 3)) * [100.0, 50.0, 0.0]
    line[[0, 400, 700]] = np.nan
    points = points_of(line)
    expected = points.drawn()[(False, 0)]
    fig = plotview.figure(points)
    try:
        for view, cols in (("XY", [0, 1]), ("XZ", [0, 2]), ("YZ", [1, 2]), ("3-D", [0, 1, 2])):
            parts = drawn_feed(fig, view)
            assert len(parts) > 1000 // 50 and all(len(p) <= 51 for p in parts), view
            assert segments(parts) == segments([expected[:, cols]]), view
    finally:
        plt.close(fig)


def test_pieces_end_where_the_lines_of_the_toolpath_end(small_pieces):
    """Lines of 12 points, each after a NaN row: no piece cuts one (its dashes and joins stay as they are);
    every piece after the first begins at a line's start, and together they hold each row once."""
    rows = [np.vstack(([np.nan] * 3, np.column_stack((np.arange(12.0), np.full(12, k), np.zeros(12)))))
            for k in range(40)]
    line = np.concatenate(rows)
    pieces = plotview._pieces(line)
    assert len(pieces) > 1 and all(len(p) <= 51 for p in pieces)
    assert all(np.isnan(p[0]).all() for p in pieces)
    np.testing.assert_array_equal(np.concatenate(pieces), line)


def test_a_line_within_a_piece_is_drawn_as_one_line():
    """A plot of up to PIECE + 1 points a line is drawn as before: one line per view (the examples' pictures
    are unchanged, pixel for pixel)."""
    line = np.column_stack((np.arange(plotview.PIECE - 10.0), np.zeros(plotview.PIECE - 10), np.zeros(plotview.PIECE - 10)))
    points = points_of(line)
    fig = plotview.figure(points)
    try:
        for view in ("XY", "XZ", "YZ", "3-D"):
            assert len(drawn_feed(fig, view)) == 1, view
    finally:
        plt.close(fig)
