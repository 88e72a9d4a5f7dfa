"""The toolpath plot as a user looks at it (issue 19): the examples rendered to PNG, and what can be asserted
of the pictures: the work frame, equal scales in every view, extents, the legend beside the views, depth
colours, one colour per rw_SymPas task, soft-limit marks, no approach rapid from the start position."""

from __future__ import annotations

from pathlib import Path

import matplotlib
import numpy as np
import pytest

from ncvm.api import run
from ncvm.runtime.session import RunOptions
from ncvm.sinks.plotview import figure, plot_run, plot_title

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

EXAMPLES = Path(__file__).parents[2] / "examples"
SHOWN = ["din/face_and_circle.din", "cpl/pocket.cpl", "cpl/flange.cpl", "cpl/measlog.cpl", "sin800/flange.mpf",
         "sympas/pick_place.sap", "sympas/two_tasks.sap", "sympas/contour.sap", "cl800/drill_hole_pattern.cl8",
         "cl800/deep_hole.cl8"]


def run_example(name: str, tmp_path: Path, frame: str = "work"):
    program = EXAMPLES / name
    machine = program.parent / "machine.toml"
    scenario = program.with_suffix(".scenario.toml")
    result, session = run(program, machine=machine if machine.is_file() else None,
                          options=RunOptions(state_dir=tmp_path / "state", plot=True, plot_frame=frame,
                                             scenario=scenario if scenario.is_file() else None))
    assert result["status"] == "ok", result["error"]
    return result, session


def run_text(tmp_path: Path, name: str, text: str, machine: str | None = None, frame: str = "work"):
    program = tmp_path / name
    program.write_text(text)
    if machine is not None:
        (tmp_path / "machine.toml").write_text(machine)
    return run(program, machine=tmp_path / "machine.toml" if machine else None,
               options=RunOptions(state_dir=tmp_path / "state", plot=True, plot_frame=frame))


def drawn_points(session) -> np.ndarray:
    pts = np.concatenate(list(session.plot.drawn().values()))
    return pts[np.isfinite(pts).all(axis=1)]


def assert_readable(fig) -> None:
    """Equal scales in the three flat views and in the 3-D box; the legend overlaps no view."""
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    for name in ("XY", "XZ", "YZ"):
        ax = fig.views[name]
        x0, x1 = ax.get_xlim()
        y0, y1 = ax.get_ylim()
        box = ax.get_window_extent(renderer)
        assert ax.get_aspect() == 1.0
        assert (x1 - x0) / (y1 - y0) == pytest.approx(box.width / box.height, rel=0.02), name
    ax3 = fig.views["3-D"]
    spans = np.array([np.ptp(ax3.get_xlim()), np.ptp(ax3.get_ylim()), np.ptp(ax3.get_zlim())])
    box = np.array(ax3.get_box_aspect())
    assert box / box.max() == pytest.approx(spans / spans.max(), rel=1e-6)
    legend = fig.legend_box.get_legend()
    assert legend is not None
    where = legend.get_window_extent(renderer)
    for name, ax in fig.views.items():
        assert not where.overlaps(ax.get_window_extent(renderer)), f"the legend covers the {name} view"


@pytest.mark.parametrize("name", SHOWN)
def test_every_example_renders_a_readable_picture(name: str, tmp_path: Path):
    result, session = run_example(name, tmp_path)
    png = tmp_path / "plot.png"
    plot_run(png, EXAMPLES / name, result, session)
    pixels = plt.imread(png)
    assert pixels.shape[:2] == (1000, 1500)
    assert (pixels[:, :, :3] < 0.9).any(axis=2).mean() > 0.01  # not a blank page: lines, labels, marks
    fig = figure(session.plot, plot_title(EXAMPLES / name, result, session.machine.name))
    try:
        assert_readable(fig)
        for view in ("XZ", "YZ", "3-D"):  # the path itself is in every view (the top view of drilling: rings)
            assert sum(np.isfinite(np.asarray(line.get_xdata(), dtype=float)).sum()
                       for line in fig.views[view].lines) >= 4, view
        lo, hi = drawn_points(session).min(axis=0), drawn_points(session).max(axis=0)
        for view, (a, b) in {"XY": (0, 1), "XZ": (0, 2), "YZ": (1, 2)}.items():
            ax = fig.views[view]
            assert ax.get_xlim()[0] <= lo[a] and hi[a] <= ax.get_xlim()[1], view
            assert ax.get_ylim()[0] <= lo[b] and hi[b] <= ax.get_ylim()[1], view
            assert ax.get_xlabel().endswith("(work)")
        title = fig._suptitle.get_text()
        assert f"({result['dialect']})" in title and session.machine.name in title and "cycle time" in title
    finally:
        plt.close(fig)


def test_pick_and_place_is_drawn_where_the_program_says(tmp_path: Path):
    """The program picks at X50 Y40 (its coordinates, after homing to REF -5): the plot shows 50,40, not the
    machine's 45,35; the machine frame is drawn on request and says so."""
    _, session = run_example("sympas/pick_place.sap", tmp_path)
    pts = drawn_points(session)
    xy = {(round(x, 3), round(y, 3)) for x, y in pts[:, :2]}
    assert {(50.0, 40.0), (140.0, 40.0), (250.0, 150.0), (290.0, 190.0)} <= xy
    assert (45.0, 35.0) not in xy
    _, machine = run_example("sympas/pick_place.sap", tmp_path / "m", frame="machine")
    xy = {(round(x, 3), round(y, 3)) for x, y in drawn_points(machine)[:, :2]}
    assert (45.0, 35.0) in xy and (50.0, 40.0) not in xy
    fig = figure(machine.plot)
    try:
        assert fig.views["XY"].get_xlabel() == "X (machine)"
    finally:
        plt.close(fig)


def test_no_rapid_from_the_machine_start_position(tmp_path: Path):
    """SINUMERIK flange: G54 is X150 Y100; the run starts at machine zero (work X-150 Y-100), which the
    program never named: the drawing starts at its first programmed point over the part."""
    _, session = run_example("sin800/flange.mpf", tmp_path)
    pts = drawn_points(session)
    assert pts[:, 0].min() > -45 and pts[:, 1].min() > -45
    assert session.plot.approach >= 1
    assert session.plot.first[2] == pytest.approx(50.0)  # N40 G0 X0 Y0 Z50 is where it begins


def test_a_program_that_never_cuts_draws_its_rapids(tmp_path: Path):
    _, session = run_text(tmp_path, "r.din", "G0 X10 Y10\nG0 X20\nM2\n")
    pts = drawn_points(session)
    assert pts[:, 0].max() == 20.0 and len(pts) >= 3


def test_offsets_changed_by_the_program_keep_the_drawing_in_its_coordinates(tmp_path: Path):
    """The same square under G54 (X0) and under G55 (X200, set by G10 L2): both cuts drawn on the same spot;
    each move in the frame in force for it (the rapid to the second part comes from X-200 of G55)."""
    square = "G1 X10 Y0 F500\nG1 X10 Y10\nG1 X0 Y10\nG1 X0 Y0\n"
    text = f"G10 L2 P2 X200 Y0 Z0\nG54 G0 X0 Y0 Z0\n{square}G55 G0 X0 Y0\n{square}M2\n"
    _, session = run_text(tmp_path, "two.din", text)
    feed = session.plot.drawn()[(False, 0)]
    feed = feed[np.isfinite(feed).all(axis=1)]
    assert feed[:, 0].min() == 0.0 and feed[:, 0].max() == 10.0 and feed[:, 1].max() == 10.0
    rapid = session.plot.drawn()[(True, 0)]
    assert np.nanmin(rapid[:, 0]) == -200.0
    (tmp_path / "m").mkdir()
    _, machine = run_text(tmp_path / "m", "two.din", text, frame="machine")
    assert drawn_points(machine)[:, 0].max() == 210.0


def test_feed_moves_are_coloured_by_depth_only_when_the_depth_varies(tmp_path: Path):
    _, pocket = run_example("cpl/pocket.cpl", tmp_path)
    fig = figure(pocket.plot)
    try:
        [depths] = [c for c in fig.views["XY"].collections if c.get_array() is not None]
        assert depths.get_array().min() == pytest.approx(-12.0) and depths.get_array().max() < 0
    finally:
        plt.close(fig)
    (tmp_path / "f").mkdir()
    _, flat = run_text(tmp_path / "f", "flat.din", "G0 X0 Y0 Z-1\nG1 X50 F500\nG1 Y30\nG2 X0 Y30 I-25 J0\nG1 Y0\nM2\n")
    fig = figure(flat.plot)
    try:
        assert not [c for c in fig.views["XY"].collections if c.get_array() is not None]
        ax3 = fig.views["3-D"]
        assert list(ax3.get_zticks()) == [-1.0]  # one depth, no meaningless Z scale
        spans = np.array([np.ptp(ax3.get_xlim()), np.ptp(ax3.get_ylim()), np.ptp(ax3.get_zlim())])
        assert spans[2] < 0.15 * spans.max()  # a thin slab, with the path's proportions
        assert_readable(fig)
    finally:
        plt.close(fig)


TWO_MOVING_TASKS = """{$TASK 0}
program Mover;
begin
  TRVL := 100.0; TRAC := 1000.0;
  STARTCNCT(1);
  MLAW(A1 := 100.0);
  WT(15625);
end.

{$TASK 1}
program Other;
begin
  TRVL := 100.0; TRAC := 1000.0;
  MLAW(A2 := 50.0);
end.
"""

CARD = """[[axis]]
name = "X"
min = -10.0
max = 400.0
[[axis]]
name = "Y"
min = -10.0
max = 300.0
[[axis]]
name = "Z"
min = -100.0
max = 10.0
"""


def test_the_plot_tells_rw_sympas_tasks_apart(tmp_path: Path):
    """Issue 15 (rw_SymPas 1): task 0 moves A1, task 1 moves A2: two colours, each named in the legend."""
    result, session = run_text(tmp_path, "tasks.sap", TWO_MOVING_TASKS, machine=CARD)
    assert result["status"] == "ok", result["error"]
    owners = {owner for _, owner in session.plot.drawn()}
    assert owners == {0, 1}
    fig = figure(session.plot)
    try:
        labels = [t.get_text() for t in fig.legend_box.get_legend().get_texts()]
        assert any(t.startswith("task 0 ") for t in labels) and any(t.startswith("task 1 ") for t in labels)
        colours = {tuple(line.get_color()) if not isinstance(line.get_color(), str) else line.get_color()
                   for line in fig.views["XZ"].lines if line.get_linestyle() == "-"}
        assert len(colours) >= 2
    finally:
        plt.close(fig)


def test_a_soft_limit_violation_is_marked_where_it_happens(tmp_path: Path):
    machine = "[[axis]]\nname = \"X\"\nmin = 0.0\nmax = 100.0\n[[axis]]\nname = \"Y\"\nmin = 0.0\nmax = 100.0\n" \
              "[[axis]]\nname = \"Z\"\nmin = -50.0\nmax = 50.0\n[offsets]\nG54 = [10.0, 0.0, 0.0]\n"
    result, session = run_text(tmp_path, "far.din", "G54 G0 X0 Y0 Z5\nG1 Z0 F300\nG1 X120 Y20\nM2\n",
                               machine=machine)
    [violation] = session.checks.violations()
    assert violation.axis == "X" and violation.point[0] == pytest.approx(130.0)  # machine
    png = tmp_path / "far.png"
    plot_run(png, tmp_path / "far.din", result, session)
    fig = figure(session.plot, violations=session.checks.violations())
    try:
        labels = [t.get_text() for t in fig.legend_box.get_legend().get_texts()]
        assert any(t.startswith("soft limit X 100 passed") for t in labels)
        marks = [line for line in fig.views["XY"].lines if line.get_marker() == "X"]
        assert [(line.get_xdata()[0], line.get_ydata()[0]) for line in marks] == [(120.0, 20.0)]  # work frame
    finally:
        plt.close(fig)


@pytest.mark.parametrize("frame", ["work", "machine"])
def test_the_command_line_draws_in_the_frame_asked_for(tmp_path: Path, frame: str, monkeypatch):
    from click.testing import CliRunner

    from ncvm import cli
    from ncvm.sinks import plotview

    seen = []
    real = plotview.figure
    monkeypatch.setattr(plotview, "figure", lambda points, *a, **k: seen.append(points.in_work_frame) or real(
        points, *a, **k))
    program = tmp_path / "p.din"
    program.write_text("G10 L2 P1 X100 Y0 Z0\nG54 G0 X0 Y0 Z2\nG1 Z-1 F300\nG1 X20\nM2\n")
    r = CliRunner().invoke(cli.cli, ["run", str(program), "--state", str(tmp_path / "s"), "--plot",
                                     str(tmp_path / "p.png"), "--plot-frame", frame])
    assert r.exit_code == 0, r.output
    assert (tmp_path / "p.png").read_bytes()[:4] == b"\x89PNG" and seen == [frame == "work"]


def test_only_the_rapid_from_the_power_on_position_is_left_out(tmp_path: Path):
    """The second rapid leaves from X5 Y0 Z30, a point the program reached (Y0 is also where the run began):
    it is drawn; only the first, from the simulator's start position, is the approach."""
    _, session = run_text(tmp_path, "a.din", "G90 G0 X5 Y0 Z30\nG0 Y0 Z1\nG1 Z-2 F100\nG0 Z30\nM2\n")
    assert session.plot.approach == 1
    assert session.plot.first == pytest.approx([5.0, 0.0, 30.0])


def test_start_and_end_are_both_visible_where_they_coincide(tmp_path: Path):
    """A program that ends where it began: the end is an open square larger than the start's filled dot."""
    result, session = run_text(tmp_path, "loop.din", "G90 G0 X0 Y0 Z10\nG1 X10 F500\nG1 X0\nM2\n")
    fig = figure(session.plot, plot_title(tmp_path / "loop.din", result, "test"), [])
    marks = {line.get_color(): line for line in fig.views["XY"].lines if line.get_color() in ("green", "red")}
    assert marks["green"].get_markersize() < marks["red"].get_markersize()
    assert marks["red"].get_markerfacecolor() == "none" and marks["green"].get_zorder() > marks["red"].get_zorder()
    plt.close(fig)


def test_3d_titles_of_a_needle_shaped_path_are_clear_of_other_text(tmp_path: Path):
    """A drilled hole 100 mm deep at one XY point: the 3-D box is a needle; its axis titles cover neither
    each other nor a visible tick number."""
    result, session = run_text(tmp_path, "needle.din", "G90 G0 X40 Y30 Z50\nG1 Z-60 F100\nG0 Z50\nM2\n")
    fig = figure(session.plot, plot_title(tmp_path / "needle.din", result, "test"), [])
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    axes = [fig.views["3-D"].xaxis, fig.views["3-D"].yaxis, fig.views["3-D"].zaxis]
    titles = [a.label.get_window_extent(renderer) for a in axes]
    ticks = [t.get_window_extent(renderer) for a in axes for t in a.get_ticklabels() if t.get_visible() and t.get_text()]
    assert not any(a.overlaps(b) for i, a in enumerate(titles) for b in titles[i + 1:])
    assert not any(a.overlaps(t) for a in titles for t in ticks)
    plt.close(fig)
