"""A block that does not move (a point written twice, a block whose axis words go to where the tool is) is
not planned: its trace line says ``time`` 0 and, as every move's line, ``v_entry`` and ``v_exit`` the path
speed there (docs/trace.md): the speed the path passes that point at, the exit speed of the move before
it; 0 where the path stands (the program start, after an exact stop)."""

from __future__ import annotations

import json


def _speeds(run_text, tmp_path, text: str, name: str = "p.ngc", **opts) -> list[tuple]:
    trace = tmp_path / "t.jsonl"
    result = run_text(text, name=name, trace=trace, **opts)
    moves = [r for r in map(json.loads, trace.read_text().splitlines()) if r["call"] in ("feed", "rapid", "arc")]
    return result, [(r["time"] == 0.0, r.get("v_entry"), r.get("v_exit")) for r in moves]


def test_points_repeated_inside_a_contour_pass_at_the_junction_speed(run_text, tmp_path):
    _, speeds = _speeds(run_text, tmp_path, "G90 G64 F3000\nG1 X10\nG1 X10\nX10\nG1 X20\nM2\n")
    assert speeds == [(False, 0.0, 3000.0), (True, 3000.0, 3000.0), (True, 3000.0, 3000.0), (False, 3000.0, 0.0)]


def test_a_point_repeated_at_rest_stands(run_text, tmp_path):
    """At the start, after an exact stop (G61) and at the end the path stands: speed 0."""
    _, speeds = _speeds(run_text, tmp_path, "G90 G61 F3000\nG1 X0\nG1 X10\nG1 X10\nG1 X20\nG1 X20\nM2\n")
    assert speeds == [(True, 0.0, 0.0), (False, 0.0, 0.0), (True, 0.0, 0.0), (False, 0.0, 0.0), (True, 0.0, 0.0)]


def test_a_cpl_loop_repeating_its_point(run_text, tmp_path):
    """CPL's rows (the block buffer, column-wise execution) report the same as DIN's blocks."""
    text = "N1 G71 G90 G17 F3000\n10 I% = 0\n20 WHILE I% < 4 DO\nG1 X[INT(I% / 2) * 10 + 10]\n30 I% = I% + 1\n" \
           "40 END\nM30\n"
    _, speeds = _speeds(run_text, tmp_path, text, name="p.cpl")
    assert speeds == [(False, 0.0, 3000.0), (True, 3000.0, 3000.0), (False, 3000.0, 0.0), (True, 0.0, 0.0)]


def test_a_run_stopped_by_a_fault_ends_at_rest(run_text, tmp_path):
    """A fault ends the run: the moves still waiting are timed to rest, the point repeated after them too."""
    result, speeds = _speeds(run_text, tmp_path, "G90 G64 F3000\nG1 X10\nG1 X10\nG1 X20\nM2\n", max_steps=3)
    assert result["error"]["code"] == "RUN001"
    assert speeds == [(False, 0.0, 0.0), (True, 0.0, 0.0)]
