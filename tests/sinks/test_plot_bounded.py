"""The plot of a long run is bounded by its cap of points, in every dialect (issue 18, "Memory bounded by
design": a plot of millions of moves decimates and says so in the legend), and below the cap it draws every
move as before. Behaviour only: the memory figures themselves are the bench's
(``proc_sympas_2m_moves_plot_memory``), not the suite's."""

from __future__ import annotations

from pathlib import Path

import matplotlib
import numpy as np
import pytest

from ncvm.api import run
from ncvm.runtime.session import RunOptions
from ncvm.sinks import plot as plot_module
from ncvm.sinks import plotview, toolpath
from ncvm.sinks.plotview import figure

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

#: the shape of the bench's rw_SymPas program (bench/cases_process.py, SYMPAS_MOVES): ``rows`` rows of 1000
#: relative MLRW moves, A1 forth and back, A2 up by 0.01 a move (the bench's 0.0001 is below the card's resolution)
RASTER = """\
program Moves;
var row, k: integer; dir: double;
begin
  TRVL := 100.0; TRAC := 10000.0;
  for row := 0 to {last} do
  begin
    dir := 1.0 - 2.0 * (row mod 2);
    for k := 1 to 1000 do
      MLRW(A1 := dir * 0.1, A2 := 0.01);
  end;
end.
"""


def run_raster(tmp_path: Path, rows: int, **options):
    program = tmp_path / "moves.sap"
    program.write_text(RASTER.format(last=rows - 1))
    result, session = run(program, dialect="sympas",
                          options=RunOptions(state_dir=tmp_path / "state", plot=True, **options))
    assert result["status"] == "ok", result["error"]
    assert result["motion"]["feed_moves"] == rows * 1000
    return result, session


def legend_texts(fig) -> list[str]:
    return [t.get_text() for t in fig.legend_box.get_legend().get_texts()]


def test_a_rw_sympas_plot_past_its_cap_is_thinned_and_says_so_in_the_legend(tmp_path, monkeypatch):
    """Past the cap the rw_SymPas plot holds at most the cap of points while the moves come (windows of moves
    forgotten after each is thinned), keeps the extents exact, and the legend says how many moves were thinned
    to how many points."""
    monkeypatch.setattr(toolpath, "WINDOW", 1000)
    monkeypatch.setattr(plot_module, "MAX_POINTS", 2000)
    _, session = run_raster(tmp_path, 6)
    points = session.plot
    assert points.max_points == 2000 and points.thinned and points.moves == 6000
    drawn = np.concatenate(list(points.drawn().values()))
    assert len(drawn) <= 2000
    # the zig-zag's extents: A1 from 0 to 100 (1000 x 0.1 forward, then back), A2 up by 0.01 a move
    assert np.nanmin(drawn[:, 0]) == pytest.approx(0.0, abs=1e-9)
    assert np.nanmax(drawn[:, 0]) == pytest.approx(100.0)
    assert np.nanmin(drawn[:, 1]) == pytest.approx(0.0, abs=1e-9)
    assert np.nanmax(drawn[:, 1]) == pytest.approx(60.0)
    fig = figure(points, "thinned")
    try:
        notes = [t for t in legend_texts(fig) if "thinned to" in t]
        assert notes == [f"6,000 moves,\nthinned to {points._count:,} points\n(extents exact)"]
    finally:
        plt.close(fig)


def test_a_rw_sympas_plot_under_its_cap_draws_every_move(tmp_path):
    """Under the cap nothing is thinned: the drawn line is the start and the end of every move, in order (the
    toolpath the recorder kept), and the legend has no note of thinning."""
    _, session = run_raster(tmp_path, 3, keep_toolpath=True)
    points = session.plot
    assert not points.thinned
    moves = session.recorder.arrays()
    [(style, line)] = points.drawn().items()
    assert style == (False, 0)
    path = line[:-(2 * len(points.extremes[style]))]  # the extreme points follow the line, each on its own
    assert np.isnan(path[0]).all()
    expected = np.vstack([moves["start"][:1], moves["end"]])
    np.testing.assert_array_equal(path[1:], expected)
    fig = figure(points)
    try:
        assert not any("thinned" in t for t in legend_texts(fig))
    finally:
        plt.close(fig)


def test_the_default_cap_is_read_when_the_plot_is_made():
    """A plot takes the module's cap when it is made (so the cap is one constant, documented in
    docs/decisions.md), or the one it is given."""
    rec = toolpath.ToolpathRecorder(keep=False)
    assert plot_module.PlotPoints(rec).max_points == plot_module.MAX_POINTS == 100_000
    assert plot_module.PlotPoints(rec, max_points=10).max_points == 10


def test_the_toolpath_is_left_out_of_the_drawings_that_place_the_3d_titles_and_drawn_after(tmp_path, monkeypatch):
    """Placing the 3-D axis titles draws the figure up to seven times to measure the text: the toolpath's lines
    are hidden then (the titles follow the axes' limits, not the lines) and visible again in the picture."""
    _, session = run_raster(tmp_path, 2)
    seen = []
    place = plotview._place_3d_titles

    def spy(fig, ax, tries):
        seen.append([line.get_visible() for view in fig.axes for line in view.lines])
        place(fig, ax, tries)

    monkeypatch.setattr(plotview, "_place_3d_titles", spy)
    fig = figure(session.plot)
    try:
        lines = [line for view in fig.axes for line in view.lines]
        drawn_paths = [line for line in lines if len(line.get_xdata()) > 2]
        assert len(drawn_paths) == 4  # the feed line in the three flat views and in the 3-D view
        assert len(seen) == 1
        hidden = [v for v, line in zip(seen[0], lines) if line in drawn_paths]
        assert hidden == [False] * 4
        assert all(line.get_visible() for line in lines)
    finally:
        plt.close(fig)
