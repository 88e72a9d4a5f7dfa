"""Coordinate rotation (@437-@43a, L3242-3302, L4325-4334) and the programmed angle (PANG @447, L3342-3348).

Expected values are worked by hand: a point (h, v) of the program turns to
(h cos a - v sin a, h sin a + v cos a); the angle address completes a line
through the start point.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from ncvm.api import run
from ncvm.runtime.session import RunOptions

MACHINE = """
[[axis]]
name = "X"
[[axis]]
name = "Y"
[[axis]]
name = "Z"
[sin800]
control = "880"
"""


def _run(tmp_path: Path, text: str, extra: str = "", ok: bool = True):
    (tmp_path / "machine.toml").write_text(MACHINE + extra)
    path = tmp_path / "prog.mpf"
    path.write_text(text)
    result, _ = run(path, dialect="sin800", machine=tmp_path / "machine.toml",
                    options=RunOptions(state_dir=tmp_path / ".ncvm"))
    if ok:
        assert result["status"] == "ok", result["error"]
    return result


def _xy(result):
    return result["position"]["X"], result["position"]["Y"]


def test_settable_rotation_turns_points_about_the_workpiece_zero(tmp_path):
    # ZOADW(0,1,1) = 30 for G54: (10, 0) -> (8.660254, 5); then Y5 alone: the program point is (10, 5)
    # -> (10 cos30 - 5 sin30, 10 sin30 + 5 cos30) = (6.160254, 9.330127)
    r = _run(tmp_path, "%MPF1\n@437 K0 K1 K1 K30\nG54 G90 G1 X10 Y0 F1000\n@361 R1 K1 @361 R2 K2\nY5\n")
    assert (r["variables"]["R1"], r["variables"]["R2"]) == pytest.approx((8.660254, 5.0))
    assert _xy(r) == pytest.approx((6.160254, 9.330127))


def test_incremental_words_turn_as_vectors(tmp_path):
    r = _run(tmp_path, "%MPF1\n@437 K0 K1 K1 K90\nG54 G91 G1 X10 F1000\nX5 Y0\n")
    assert _xy(r) == pytest.approx((0.0, 15.0), abs=1e-9)


def test_settable_and_programmable_angles_add(tmp_path):
    # machine file: settable G54 45 degrees; program: ZOPRDW(0,1,1) = 45 -> 90 degrees in all
    r = _run(tmp_path, "%MPF1\nG54 G1 X10 F1000\n@361 R1 K1 @361 R2 K2\n@439 K0 K1 K1 K45\nX10\n",
             "rotation = { settable = [45.0, 0.0, 0.0, 0.0] }\n")
    assert (r["variables"]["R1"], r["variables"]["R2"]) == pytest.approx((7.0710678, 7.0710678))
    # in the frame turned by 90 degrees the current point (7.07, 7.07) is (7.07, -7.07); X10 keeps that Y:
    # (10, -7.07) turned by 90 degrees = (7.07, 10)
    assert _xy(r) == pytest.approx((7.0710678, 10.0))


def test_rotation_of_another_zero_offset_group_is_not_selected(tmp_path):
    r = _run(tmp_path, "%MPF1\nG55 G1 X10 Y2 F1000\n", "rotation = { settable = [90.0, 0.0, 0.0, 0.0] }\n")
    assert _xy(r) == (10.0, 2.0)


def test_arc_centre_turns_with_the_end_point(tmp_path):
    # 90 degrees: start (10, 0) -> (0, 10); G3 to (-10, 0) about I-10 -> end (0, -10), centre vector (0, -10)
    r = _run(tmp_path, "%MPF1\n@437 K0 K1 K1 K90\nG54 G90 G1 X10 Y0 F1000\nG3 X-10 Y0 I-10 J0\n")
    assert _xy(r) == pytest.approx((0.0, -10.0), abs=1e-9)


def test_rotation_write_acts_on_blocks_already_decoded(tmp_path):
    """L4325-4334: with decode-ahead the new angle also turns blocks in the buffer; STOP DEC1 prevents it."""
    extra = "decode_ahead = 3\nrotation = { settable = [90.0, 0.0, 0.0, 0.0] }\n"
    text = "%MPF1\nG54 G90 G1 X10 Y0 F1000\n{stop}@437 K0 K1 K1 K0\nX20\n"
    # (separate state directories: the angle written by a run is kept for the next one)
    # without STOP DEC1 the first block runs after the write, unrotated: (10, 0) then (20, 0)
    (tmp_path / "a").mkdir()
    (tmp_path / "b").mkdir()
    assert _xy(_run(tmp_path / "a", text.format(stop=""), extra)) == pytest.approx((20.0, 0.0))
    # with STOP DEC1 it runs at 90 degrees: (0, 10); X20 at 0 degrees keeps Y10
    assert _xy(_run(tmp_path / "b", text.format(stop="@715\n"), extra)) == pytest.approx((20.0, 10.0), abs=1e-9)


def test_lockstep_rotation_write_acts_from_the_next_block(tmp_path):
    extra = "rotation = { settable = [90.0, 0.0, 0.0, 0.0] }\n"
    r = _run(tmp_path, "%MPF1\nG54 G90 G1 X10 Y0 F1000\n@437 K0 K1 K1 K0\nX20\n", extra)
    assert _xy(r) == pytest.approx((20.0, 10.0), abs=1e-9)


def test_pang_completes_a_line_from_its_start_point(tmp_path):
    # from (10, 0) at 45 degrees to X20: Y = (20 - 10) tan 45 = 10
    r = _run(tmp_path, "%MPF1\nG90 G1 X10 Y0 F1000\n@447 K45 X20\n")
    assert _xy(r) == pytest.approx((20.0, 10.0))


def test_pang_from_r_parameter_with_the_second_axis(tmp_path):
    # manual example PANG () = R60; from (0, 0) at 30 degrees to Y5: X = 5 / tan 30 = 8.660254
    r = _run(tmp_path, "%MPF1\nG90 G1 F1000\nR60=30 @447 R60 Y5\n")
    assert _xy(r) == pytest.approx((8.660254, 5.0))


def test_angle_address_word_and_incremental(tmp_path):
    # A is not an axis of this machine: A45 is the angle; G91 X-5 at 135 degrees: dY = -5 tan 135 = 5
    r = _run(tmp_path, "%MPF1\nG90 G1 X10 A45 F1000\nG91 X-5 A135\n")
    assert _xy(r) == pytest.approx((5.0, 15.0))


def test_pang_inside_a_rotated_frame(tmp_path):
    # program point (10, 10) turned by 90 degrees = (-10, 10)
    r = _run(tmp_path, "%MPF1\n@437 K0 K1 K1 K90\nG54 G90 G1 X0 Y0 F1000\n@447 K45 X10\n")
    assert _xy(r) == pytest.approx((-10.0, 10.0), abs=1e-9)


def test_pang_parallel_to_the_other_axis_is_a_cl800_error(tmp_path):
    r = _run(tmp_path, "%MPF1\nG90 G1 X0 Y0 F1000\n@447 K90 X10\n", ok=False)
    assert r["error"]["code"] == "CL800" and r["error"]["line"] == 3 and "parallel to Y" in r["error"]["message"]
