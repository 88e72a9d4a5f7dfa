"""The toolpath recorder without keep: a window of moves, running totals, watchers; the thinned plot."""

from __future__ import annotations

import math

import numpy as np
import pytest

from ncvm.machine.model import Axis
from ncvm.nc.canon import ArcSpec, Src
from ncvm.sinks import toolpath
from ncvm.sinks.areas import DEAD, zone_check
from ncvm.sinks.limits import LimitCheck
from ncvm.sinks.plot import PlotPoints, draw
from ncvm.sinks.toolpath import ToolpathRecorder

NAMES = ("X", "Y", "Z")


def moves(n: int):
    """A zig-zag with arcs and rapids and spikes: (kind, end, spec) on lines 1..n."""
    rnd = np.random.default_rng(7)
    here = (0.0, 0.0, 0.0)
    out = []
    for i in range(n):
        if i % 97 == 50:
            r = 2.0
            end = here  # a full circle about a centre r to the left
            out.append(("arc", end, ArcSpec(0, 1, (here[0] - r, here[1]), bool(i % 2), r)))
        elif i % 31 == 0:
            end = (here[0], here[1], 5.0 + float(rnd.uniform(0, 3)))
            out.append(("rapid", end, None))
        else:
            end = (float(i % 400) * 0.25, float(i // 400) * 0.1 + float(rnd.uniform(-1, 1)) * (i % 1013 == 7), -1.0)
            out.append(("feed", end, None))
        here = end
    return out


def record(rec: ToolpathRecorder, ms) -> ToolpathRecorder:
    rec.begin(NAMES, (0.0, 0.0, 0.0))
    here = (0.0, 0.0, 0.0)
    for line, (kind, end, spec) in enumerate(ms, 1):
        if kind == "arc":
            rec.arc(here, end, spec, 1000.0, Src("p", line))
        elif kind == "rapid":
            rec.rapid(here, end, Src("p", line))
        else:
            rec.feed(here, end, 1000.0, Src("p", line))
        here = end
    return rec


@pytest.fixture
def small_window(monkeypatch):
    monkeypatch.setattr(toolpath, "WINDOW", 1000)


def test_totals_of_a_forgetting_recorder_are_those_of_the_whole_toolpath(small_window):
    ms = moves(20_000)
    kept, window = ToolpathRecorder(keep=True), ToolpathRecorder(keep=False)
    record(kept, ms)
    record(window, ms)
    assert window._held() < 1000 and window.base > 0  # the moves before the window are forgotten
    a, b = kept.summary(), window.summary()
    assert (a.rapid_moves, a.feed_moves, a.arc_moves) == (b.rapid_moves, b.feed_moves, b.arc_moves)
    assert a.bounds == b.bounds  # exact, arcs' quadrant points included
    assert b.rapid_length == pytest.approx(a.rapid_length, rel=1e-12)
    assert b.feed_length == pytest.approx(a.feed_length, rel=1e-12)
    assert len(window) == len(kept) == 20_000
    with pytest.raises(RuntimeError, match="keep_toolpath"):
        window.arrays()


def test_checks_find_the_first_violation_in_a_later_window(small_window):
    ms = moves(5000)
    ms[3500] = ("feed", (ms[3499][1][0], ms[3499][1][1], 12.0), None)  # the one move above Z 10
    axes = [Axis("X", min=-1.0, max=99.0), Axis("Y", min=-10.0, max=100.0), Axis("Z", min=-2.0, max=10.0)]
    found = {}
    for keep in (True, False):
        rec = ToolpathRecorder(keep=keep)
        limits = LimitCheck(axes, rec)
        zones = zone_check([(1, DEAD, ("X", "Y"), (58.75, 2.85), (1.0, 0.2))], NAMES, rec)  # by an arc
        record(rec, ms)
        found[keep] = ({v.axis: v.line for v in limits.first()}, [v.line for v in zones.first()])
    assert found[True] == found[False]
    lines, zone_lines = found[False]
    assert lines["X"] == next(i for i, (_, end, _) in enumerate(ms, 1) if end[0] > 99.0 + 1e-9)
    assert lines["Z"] == 3501  # in a later window
    assert len(zone_lines) == 1 and zone_lines[0] > 1000 and ms[zone_lines[0] - 1][0] == "arc"


def test_plot_thinning_keeps_the_extents_and_bounds_the_points(small_window, tmp_path):
    ms = moves(60_000)
    rec = ToolpathRecorder(keep=False)
    full = PlotPoints(rec, max_points=10**9)
    plot = PlotPoints(rec, max_points=2000)
    record(rec, ms)
    summary = rec.summary()
    every = np.concatenate(list(full.drawn().values()))
    drawn = np.concatenate(list(plot.drawn().values()))
    assert len(every) > 60_000 and len(drawn) <= 2000
    for col, name in enumerate(NAMES):
        # the extents of every drawn point (arcs as sampled), and of the motion within an arc's sampling
        assert np.nanmin(drawn[:, col]) == np.nanmin(every[:, col])
        assert np.nanmax(drawn[:, col]) == np.nanmax(every[:, col])
        assert np.nanmin(drawn[:, col]) == pytest.approx(summary.bounds[name][0], abs=0.01)
        assert np.nanmax(drawn[:, col]) == pytest.approx(summary.bounds[name][1], abs=0.01)
    # the first move, a rapid from the start position, is the approach: the drawing starts where it ends
    assert ms[0][0] == "rapid" and plot.approach == 1
    assert plot.first == list(ms[0][1]) and plot.last == list(ms[-1][1])
    # the early moves were thinned no more than the late ones: Y grows with the move number
    feed = plot.drawn()[(False, 0)]
    early = np.count_nonzero(feed[:, 1] < 7.5)  # the first half of the rows of the zig-zag
    assert 0.6 < early / np.count_nonzero(feed[:, 1] >= 7.5) < 1.6
    draw(plot, tmp_path / "p.png", "thinned")
    assert (tmp_path / "p.png").read_bytes()[:4] == b"\x89PNG"


def test_plot_of_many_short_lines_stays_bounded(small_window):
    rec = ToolpathRecorder(keep=False)
    plot = PlotPoints(rec, max_points=1000)
    rec.begin(NAMES, (0.0, 0.0, 0.0))
    here = (0.0, 0.0, 0.0)
    for i in range(20_000):  # drilling: a rapid over the hole, a plunge, a rapid out: short lines of two styles
        x, y = float(i % 200), float(i // 200)
        for kind, end in (("rapid", (x, y, 2.0)), ("feed", (x, y, -3.0)), ("rapid", (x, y, 2.0))):
            (rec.rapid(here, end, Src("p", i)) if kind == "rapid" else rec.feed(here, end, 100.0, Src("p", i)))
            here = end
    rec.settle()
    drawn = np.concatenate(list(plot.drawn().values()))
    assert len(drawn) <= 1000
    assert np.nanmin(drawn[:, 0]) == 0.0 and np.nanmax(drawn[:, 0]) == 199.0
    assert np.nanmax(drawn[:, 1]) == 99.0 and np.nanmin(drawn[:, 2]) == -3.0
    marks = np.concatenate(plot.plunges)
    assert len(marks) <= 1000 and marks[:, 0].max() == 199.0 and marks[:, 1].max() == 99.0


def test_arcs_are_drawn_along_their_curve():
    rec = ToolpathRecorder(keep=False)
    plot = PlotPoints(rec)
    rec.begin(NAMES, (10.0, 0.0, 0.0))
    rec.arc((10.0, 0.0, 0.0), (10.0, 0.0, 0.0), ArcSpec(0, 1, (0.0, 0.0), False, 10.0), 100.0, Src("p", 1))
    rec.settle()
    (pts,) = plot.drawn().values()
    radius = np.hypot(pts[1:, 0], pts[1:, 1])
    assert np.allclose(radius[~np.isnan(radius)], 10.0) and len(pts) > 20
    assert math.isclose(np.nanmin(pts[:, 1]), -10.0, abs_tol=0.01)


def test_a_thinned_curve_stays_close_to_the_path():
    """100,000 moves along a 10-turn spiral in a plot of 5,000 points: the drawn chords stay within 0.1 mm of
    the spiral (a bucket of 32 points thinned a curve to its two ends: chords 0.4 mm inside, visible)."""
    n, turns, pitch = 100_000, 10, 0.4
    a = np.arange(1, n + 1) * (2 * math.pi * turns / n)
    path = np.column_stack(((10 + pitch * a) * np.cos(a), (10 + pitch * a) * np.sin(a), np.zeros(n)))
    rec = ToolpathRecorder(keep=False)
    plot = PlotPoints(rec, max_points=5000)
    rec.begin(NAMES, (10.0, 0.0, 0.0))
    here = (10.0, 0.0, 0.0)
    for i, end in enumerate(map(tuple, path.tolist()), 1):
        rec.feed(here, end, 1000.0, Src("p", i))
        here = end
    rec.settle()
    drawn = plot.drawn()[(False, 0)]
    drawn = drawn[~np.isnan(drawn[:, 0])]
    assert len(drawn) <= 5000
    mid = (drawn[1:] + drawn[:-1]) / 2  # the middle of each drawn chord, against the spiral's turn nearest to it
    angle = np.mod(np.arctan2(mid[:, 1], mid[:, 0]), 2 * math.pi)
    radius = np.hypot(mid[:, 0], mid[:, 1])
    turn = np.round(((radius - 10) / pitch - angle) / (2 * math.pi))
    off = np.abs(radius - (10 + pitch * (angle + 2 * math.pi * turn)))
    assert np.percentile(off, 99) < 0.1, np.percentile(off, 99)


def test_a_thinned_plot_says_so_in_its_legend(small_window, tmp_path):
    import matplotlib

    rec = ToolpathRecorder(keep=False)
    thinned, whole = PlotPoints(rec, max_points=2000), PlotPoints(rec, max_points=10**9)
    record(rec, moves(30_000))
    rec.summary()
    assert thinned.thinned and not whole.thinned
    assert thinned.moves == whole.moves == 30_000
    assert thinned.note().startswith("30,000 moves,\nthinned to ")  # wrapped: the legend column is narrow
    with matplotlib.rc_context({"svg.fonttype": "none"}):  # text as text, not as outlines
        draw(thinned, tmp_path / "thin.svg")
        draw(whole, tmp_path / "whole.svg")
    svg = (tmp_path / "thin.svg").read_text()
    assert "30,000 moves," in svg and "thinned to" in svg
    assert "thinned" not in (tmp_path / "whole.svg").read_text()


def test_held_moves_are_left_alone_by_the_garbage_collector():
    """A move held as a row keeps its file and line, not its Src (a named tuple the collector never stops
    tracking): after two collections the rows are untracked, so the window of up to WINDOW rows costs the
    full collections nothing (issue 18: a drilling program's 300,000 moves made a full collection every
    few thousand moves go over all of them). ``src`` gives the same place back."""
    import gc

    rec = ToolpathRecorder(keep=True)
    rec.begin(NAMES, (0.0, 0.0, 0.0))
    here = (0.0, 0.0, 0.0)
    for i in range(50):
        end = (float(i), 1.0, -1.0)
        if i % 2:
            rec.rapid(here, end, Src("a.ngc", i + 1))
        else:
            rec.feed(here, end, 100.0, Src("b.spf", i + 1))
        here = end
    gc.collect()  # the end points (tuples of floats), then the rows that hold them
    gc.collect()
    assert rec._rows and not any(gc.is_tracked(row) for row in rec._rows)
    assert [rec.src(i) for i in (0, 1, 49)] == [Src("b.spf", 1), Src("a.ngc", 2), Src("a.ngc", 50)]
    rec._flush(settle=False)  # the rows as a chunk of columns: the same places
    assert [rec.src(i) for i in (0, 1, 49)] == [Src("b.spf", 1), Src("a.ngc", 2), Src("a.ngc", 50)]
