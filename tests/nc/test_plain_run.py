"""Plain runs executed column-wise give the results of executing their blocks one by one.

Each program runs twice: as usual (plain runs go through :mod:`ncvm.nc.plainrun`)
and with a step hook attached, which sends every block through
``NcKernel.execute`` on its own. Moves, arcs, positions, cycle time, steps and
faults must agree.
"""

from __future__ import annotations

import json
import math
import random

import numpy as np
import pytest

from ncvm.api import run
from ncvm.nc.block import PlainRun, read_din_program, read_din_segments
from ncvm.runtime.session import RunOptions


def _both(tmp_path, text, name="p.ngc"):
    tmp_path.mkdir(parents=True, exist_ok=True)
    path = tmp_path / name
    path.write_text(text)
    plain, s1 = run(path, dialect="din", options=RunOptions(keep_toolpath=True, state_dir=tmp_path / ".a"))
    stepped, s2 = run(path, dialect="din", options=RunOptions(keep_toolpath=True, state_dir=tmp_path / ".b", hook=lambda *a: None))
    return (plain, s1), (stepped, s2)


def _same(a, b):
    assert type(a) is type(b) or isinstance(a, float | int) and isinstance(b, float | int)
    if isinstance(a, dict):
        assert a.keys() == b.keys()
        for k in a:
            _same(a[k], b[k])
    elif isinstance(a, list):
        assert len(a) == len(b)
        for x, y in zip(a, b):
            _same(x, y)
    elif isinstance(a, float):
        assert a == pytest.approx(b, rel=1e-9, abs=1e-9)
    else:
        assert a == b


def _same_recordings(r1, r2):
    a1, a2 = r1.arrays(), r2.arrays()
    assert np.array_equal(a1["kind"], a2["kind"])
    assert np.array_equal(a1["line"], a2["line"])
    assert np.array_equal(a1["tool"], a2["tool"])
    np.testing.assert_allclose(a1["end"], a2["end"], rtol=0, atol=1e-9)
    assert r1.arcs.keys() == r2.arcs.keys()
    for k, spec in r1.arcs.items():
        other = r2.arcs[k]
        assert (spec.a, spec.b, spec.cw, spec.turns) == (other.a, other.b, other.cw, other.turns)
        assert spec.center == pytest.approx(other.center, abs=1e-9)
        assert spec.radius == pytest.approx(other.radius, abs=1e-9)
    reach = []
    for rec, arr in ((r1, a1), (r2, a2)):  # where every move reaches, arcs widened in their plane
        lo, hi = arr["end"].copy(), arr["end"].copy()
        rec.arc_reach(lo, hi)
        reach.append((lo, hi))
    np.testing.assert_allclose(reach[0][0], reach[1][0], rtol=0, atol=1e-9)
    np.testing.assert_allclose(reach[0][1], reach[1][1], rtol=0, atol=1e-9)
    assert r1.arc_length == pytest.approx(r2.arc_length, rel=1e-12)
    for k in list(r1.arcs)[:20]:  # what a plot draws
        start, end = a1["start"][k], a1["end"][k]
        np.testing.assert_allclose(np.array(r1.polyline(k, start, end), dtype=float),
                                   np.array(r2.polyline(k, start, end), dtype=float), rtol=0, atol=1e-9)
    assert [r1.src(i) for i in range(len(r1))] == [r2.src(i) for i in range(len(r2))]


@pytest.mark.parametrize("seed", range(12))
def test_columns_match_block_by_block(tmp_path, random_din, seed):
    text = random_din(seed)
    segments, diags = read_din_segments("p.ngc", text)
    assert not diags and any(isinstance(s, PlainRun) for s in segments)
    (plain, s1), (stepped, s2) = _both(tmp_path, text)
    assert plain["status"] == "ok", plain["error"]
    assert plain["motion"]["arc_moves"] > 0
    _same(plain, stepped)
    _same_recordings(s1.recorder, s2.recorder)
    assert s1.machine.clock.now == pytest.approx(s2.machine.clock.now, rel=1e-12)


def test_trace_of_a_batch_replays_every_move(tmp_path, random_din):
    """Sinks that take single moves (here the JSONL trace) get every move of a plain run, in order."""
    path = tmp_path / "p.ngc"
    path.write_text(random_din(3))
    traces = []
    for name, hook in (("a", None), ("b", lambda *a: None)):
        trace = tmp_path / f"{name}.jsonl"
        run(path, dialect="din", options=RunOptions(keep_toolpath=True, state_dir=tmp_path / name, trace=trace, hook=hook))
        traces.append([json.loads(line) for line in trace.read_text().splitlines()])
    assert len(traces[0]) == len(traces[1]) > 100
    _same(traces[0], traces[1])


def test_constant_cutting_speed_sets_the_spindle_every_block(tmp_path):
    """Under G96 each block sets the spindle speed for its start radius: the trace shows it as block by block."""
    path = tmp_path / "p.ngc"
    path.write_text("G0 X40 Z2\nG96 S200 M3\n" + "".join(f"G1 X{40 - i} Z-{i} F300\n" for i in range(1, 30))
                    + "G97\nM30\n")
    traces = []
    for name, hook in (("a", None), ("b", lambda *a: None)):
        trace = tmp_path / f"{name}.jsonl"
        run(path, dialect="din", options=RunOptions(keep_toolpath=True, state_dir=tmp_path / name, trace=trace, hook=hook))
        traces.append([json.loads(line) for line in trace.read_text().splitlines()])
    assert sum(1 for t in traces[0] if t.get("call") == "spindle") > 20
    _same(traces[0], traces[1])


@pytest.mark.parametrize("bad, code, line", [
    ("N40 G1 X5 Y5", "NC006", 5),  # G1 without any feed yet
    ("N40 G2 X5 Y5 I1 J0 F100", "NC002", 5),  # end point on another radius
    ("N40 G3 X5 Y5 F100", "NC003", 5),  # arc without centre words
])
def test_fault_inside_a_run(tmp_path, bad, code, line):
    """The moves before the faulting block are kept; the fault names the kernel's code and the block's line."""
    text = f"G0 X1 Y1\nN10 G0 X2\nN20 Y3\nN30 Z-1\n{bad}\nN50 G1 X9 F100\nM30\n"
    (plain, _), (stepped, _) = _both(tmp_path, text)
    assert plain["status"] == "error"
    assert (plain["error"]["code"], plain["error"]["line"]) == (code, line)
    assert plain["motion"]["rapid_moves"] == 4
    assert plain["position"] == {"X": 2.0, "Y": 3.0, "Z": -1.0}
    _same(plain, stepped)


def test_step_limit_inside_a_run(tmp_path):
    path = tmp_path / "p.ngc"
    path.write_text("".join(f"G1 X{i} F500\n" for i in range(1, 101)))
    result, _ = run(path, dialect="din", options=RunOptions(keep_toolpath=True, state_dir=tmp_path / ".n", max_steps=40))
    assert result["status"] == "error"
    assert result["error"]["line"] == 41
    assert result["steps"] == 40
    assert result["position"]["X"] == 40.0
    assert result["motion"]["feed_moves"] == 40


def test_hand_computed_run(tmp_path):
    """A quarter circle and two lines in one run: length, bounds and time by hand."""
    path = tmp_path / "p.ngc"
    # machine default: feed limits well above F600 (10 mm/s); acceleration from the default machine
    path.write_text("G1 X10 F600\nG3 X0 Y10 I-10 J0\nG1 X0 Y0\nM2\n")
    # timed from rest to rest (the corners are blended otherwise: tests/nc/test_planner.py)
    result, session = run(path, dialect="din", options=RunOptions(keep_toolpath=True, state_dir=tmp_path / ".n",
                                                                  time_model="rest-to-rest"))
    arc = math.pi * 10 / 2
    assert result["motion"]["feed_length"] == pytest.approx(10 + arc + 10)
    assert result["motion"]["bounds"]["X"] == pytest.approx([0.0, 10.0])
    assert result["motion"]["bounds"]["Y"] == pytest.approx([0.0, 10.0])
    acc = min(ax.accel for ax in session.machine.axes[:2])
    v = 10.0

    def trapezoid(length, a):
        return length / v + v / a if length * a >= v * v else 2 * math.sqrt(length / a)

    # the lines move one axis each; the arc ramps at the plane axes' smallest acceleration (nc.dynamics.arc_limits)
    expected = trapezoid(10, acc) + trapezoid(arc, acc) + trapezoid(10, acc)
    assert result["cycle_time_s"] == pytest.approx(expected)


@pytest.mark.parametrize("seed,as_rows", [(0, False), (1, False), (2, True), (3, True)])
def test_queued_blocks_as_segments(tmp_path, random_din, seed, as_rows):
    """A motion queue (as CPL drains it) executed as segments gives the moves of executing it block by block,
    whether its plain blocks are Blocks or plain rows (the tuples CPL code queues)."""
    from ncvm.machine.config import load_machine
    from ncvm.nc.block import block_row, row_block
    from ncvm.nc.canon import Src
    from ncvm.nc.plainrun import execute_segments, plain_segments
    from ncvm.runtime.session import Session

    blocks = [blk for blk, _skip in read_din_program("p.ngc", random_din(seed))[0]]
    # blocks from a second file in the middle, as a called sub-program adds them
    for blk in blocks[40:60]:
        blk.src = Src("sub.cpl", blk.src.line)
    sessions = [Session(load_machine(), RunOptions(keep_toolpath=True, state_dir=tmp_path / name)) for name in "ab"]
    queue = blocks
    if as_rows:
        queue = [block_row(b) or b for b in blocks]
        rows = [(b, r) for b, r in zip(blocks, queue) if r.__class__ is tuple]
        assert len(rows) > len(blocks) // 2
        for b, r in rows:  # a row is its block again
            back = row_block(r)
            assert (back.g, back.m, back.words, back.n, back.src) == (b.g, b.m, b.words, b.n, b.src)
    segments = plain_segments(queue)
    runs = [s for s in segments if isinstance(s, PlainRun)]
    assert len(runs) >= 3 and {r.file for r in runs} == {"p.ngc", "sub.cpl"}
    execute_segments(sessions[0].kernel, segments)
    for blk in blocks:
        if sessions[1].kernel.ended:
            break
        sessions[1].kernel.execute(blk)
    _same_recordings(sessions[0].recorder, sessions[1].recorder)
    assert sessions[0].machine.clock.now == pytest.approx(sessions[1].machine.clock.now, rel=1e-12)
    assert sessions[0].kernel.prog == pytest.approx(sessions[1].kernel.prog, abs=1e-9)


MIXED_G = ["G0", "G1", "G2", "G3", "G17", "G18", "G19", "G90", "G91", "G20", "G21", "G70", "G71", "G54", "G55",
           "G53", "G92", "G92.1", "G40", "G43", "G49", "G4", "G94", "G80", "G64", "G96", "G97", "G10 L2 P2"]


def _mixed_program(rnd) -> str:
    """Random blocks of every kind the kernel knows, with faults (no feed, bad arcs) among them."""
    def word():
        r = rnd.random()
        if r < 0.4:
            return rnd.choice("XYZ") + f"{rnd.uniform(-50, 50):.3f}"
        if r < 0.55:
            return rnd.choice("IJK") + f"{rnd.uniform(-20, 20):.3f}"
        if r < 0.6:
            return "R" + f"{rnd.uniform(-30, 30):.3f}"
        if r < 0.7:
            return "F" + str(rnd.randint(0, 3000))
        if r < 0.8:
            return rnd.choice(("S", "T", "H", "P")) + str(rnd.randint(0, 3))
        return rnd.choice(("M3", "M4", "M5", "M6", "M8", "M9", "M0", "M1", "M7"))
    lines = []
    for _ in range(rnd.randint(5, 60)):
        ws = ([rnd.choice(MIXED_G)] if rnd.random() < 0.6 else []) + [word() for _ in range(rnd.randint(0, 4))]
        lines.append(("/" if rnd.random() < 0.03 else "") + " ".join(ws))
    return "\n".join(lines) + "\n"


def test_mixed_programs_columns_and_blocks_agree(tmp_path):
    """Programs of all block kinds, most ending in a fault: both paths give the same document."""
    rnd = random.Random("mixed")
    for k in range(40):
        (plain, _), (stepped, _) = _both(tmp_path / str(k), _mixed_program(rnd))
        for key in ("status", "error", "position", "motion", "cycle_time_s", "steps"):
            _same(plain[key], stepped[key])


def test_a_plain_row_names_its_fields_and_round_trips_a_compiled_block():
    from ncvm.nc.block import PLAIN_WORDS, PlainRow, plain_row, row_block
    from ncvm.nc.canon import Src

    assert PlainRow._fields[1:8] == tuple(PLAIN_WORDS)
    row = PlainRow._make(plain_row((1, 2.0, math.nan, math.nan, math.nan, math.nan, math.nan, 100.0, 7, 30), "p.cpl"))
    assert (row.g, row.X, row.F, row.line, row.n, row.src) == (1, 2.0, 100.0, 7, 30, Src("p.cpl", 7))
    blk = row_block(row)
    assert (blk.g, blk.words, blk.n, blk.src) == ((1,), {"X": 2.0, "F": 100.0}, 30, Src("p.cpl", 7))
