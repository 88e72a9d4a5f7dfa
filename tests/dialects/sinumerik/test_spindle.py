"""The spindle's actual values and setpoints: ACSP @363, ACSS @364, AGS @3e4, PRSS @342, PRVC @345.

Manual L2557-2569 (PRSS), L2648-2668 (ACSP/ACSS, STOP DEC before them), L3021-3032 (AGS), L4887 and
L6542 (PRVC, value 2 = 0: G96); spindle numbers per the ch.6 table L4907-4912 and ch.10 L6552-6553.
Expected values are computed by hand in each test: a spindle at S rev/min turns S/60 * 360 degrees a second.
"""

from __future__ import annotations

import math
from pathlib import Path

import pytest
from sin800_helpers import R, machine, run_mpf

from ncvm.api import check


def _run(tmp_path: Path, text: str, extra: str = "", control: str = "880"):
    return run_mpf(tmp_path, text, extra, machine_text=machine("XZ", control))


def _ok(tmp_path: Path, text: str, extra: str = "", control: str = "880"):
    return run_mpf(tmp_path, text, extra, machine_text=machine("XZ", control), ok=True)


def test_position_and_speed_after_a_dwell(tmp_path):
    # S600 = 10 rev/s; 0.25 s = 2.5 rev = 900 degrees -> 900 mod 360 = 180
    r = _ok(tmp_path, "%MPF1\nS600 M3\nG4 X0.25\n@714\n@363 R1 K0 @364 R2 K0 @363 R3 K1 @364 R4 K1\nM30\n")
    assert (R(r, 1), R(r, 2)) == (pytest.approx(180.0), 600.0)
    assert (R(r, 3), R(r, 4)) == (pytest.approx(180.0), 600.0)  # spindle 1 is the master spindle


def test_spindle_stands_before_start_and_after_m5(tmp_path):
    # before M3: 0 rev/min at 0 degrees; S600 M3 for 0.25 s (180 deg), M5, 1 s more: still 180 deg, 0 rev/min
    r = _ok(tmp_path, "%MPF1\nS600\nG4 X2\n@714\n@363 R1 K0 @364 R2 K0\nM3\nG4 X0.25\nM5\nG4 X1\n@714\n"
                      "@363 R3 K0 @364 R4 K0\nM30\n")
    assert (R(r, 1), R(r, 2)) == (0.0, 0.0)
    assert (R(r, 3), R(r, 4)) == (pytest.approx(180.0), 0.0)


def test_m4_turns_backwards_with_negative_speed(tmp_path):
    # S100 M4: 100/60 rev/s * 0.1 s * 360 = 60 degrees counter-clockwise -> -60 mod 360 = 300
    r = _ok(tmp_path, "%MPF1\nS100 M4\nG4 X0.1\n@714\n@363 R1 K0 @364 R2 K0\nM30\n")
    assert R(r, 1) == pytest.approx(300.0) and R(r, 2) == -100.0


def test_speed_change_keeps_the_angle_turned(tmp_path):
    # 600 rev/min for 0.25 s = 900 deg, then 1000 rev/min for 0.1 s = 600 deg: 1500 mod 360 = 60
    r = _ok(tmp_path, "%MPF1\nS600 M3\nG4 X0.25\nS1000\nG4 X0.1\n@714\n@363 R1 K0 @364 R2 K0\nM30\n")
    assert R(r, 1) == pytest.approx(60.0) and R(r, 2) == 1000.0


def test_spindle_turns_while_the_axes_move(tmp_path):
    # G1 X100 F6000 with the axis defaults (max_feed 5000 mm/min = 83.333 mm/s, accel 1000 mm/s^2):
    # t = 100 / 83.333 + 83.333 / 1000 = 1.28333 s; S60 = 360 deg/s -> 462 deg -> 102 deg
    r = _ok(tmp_path, "%MPF1\nS60 M3\nG1 X100 F6000\n@714\n@363 R1 K0\nM30\n")
    assert r["cycle_time_s"] == pytest.approx(1.283333, rel=1e-6)
    assert R(r, 1) == pytest.approx(102.0)


def test_bad_spindle_numbers_are_the_cl800_error(tmp_path):
    # 880: spindle numbers 0-6, but this machine has only spindle 1
    r = _run(tmp_path, "%MPF1\n@363 R1 K2\nM30\n")
    assert r["error"]["code"] == "CL800" and "spindle 2 does not exist" in r["error"]["message"]
    r = _run(tmp_path, "%MPF1\n@364 R1 K7\nM30\n")
    assert r["error"]["code"] == "CL800" and "outside 0-6" in r["error"]["message"]
    # 810/820/850: 0-4 (ch.6 table)
    r = _run(tmp_path, "%MPF1\n@364 R1 K5\nM30\n", control="850")
    assert r["error"]["code"] == "CL800" and "outside 0-4" in r["error"]["message"]
    # AGS on the 810/820: spindle 0 or 1
    r = _run(tmp_path, "%MPF1\n@3e4 R1 K2\nM30\n", control="810")
    assert r["error"]["code"] == "CL800" and "outside 0-1" in r["error"]["message"]


def test_gear_stage_from_machine_file_and_m41_m45(tmp_path):
    r = _ok(tmp_path, "%MPF1\n@3e4 R1 K0\nM42\n@714\n@3e4 R2 K0\nM45\n@714\n@3e4 R3 K1\nM30\n")
    assert (R(r, 1), R(r, 2), R(r, 3)) == (1.0, 2.0, 5.0)
    r = _ok(tmp_path, "%MPF1\n@3e4 R1 K0\nM30\n", extra="gear = 3\n")
    assert R(r, 1) == 3.0


def test_manual_ags_example(tmp_path):
    # L3031-3032: R65 = 1; R60 = AGS (R65);  (spindle 1, here in gear stage 2)
    r = _ok(tmp_path, "%MPF1\nR65=1 @3e4 R60 R65\nM30\n", extra="gear = 2\n", control="810")
    assert R(r, 60) == 2.0


def test_m40_selects_the_gear_stage_from_the_speed(tmp_path):
    # stages up to 500, 1500, 4000 rev/min: S1000 needs stage 2, S3000 stage 3, S200 stage 1
    extra = "gears = [500, 1500, 4000]\n"
    r = _ok(tmp_path, "%MPF1\nM40 S1000 M3\n@714 @3e4 R1 K0\nS3000\n@714 @3e4 R2 K0\nS200\n@714 @3e4 R3 K0\n"
                      "M41\n@714 @3e4 R4 K0\nM30\n", extra=extra)
    assert (R(r, 1), R(r, 2), R(r, 3), R(r, 4)) == (2.0, 3.0, 1.0, 1.0)
    r = _run(tmp_path, "%MPF1\nM44\nM30\n", extra=extra)
    assert r["error"]["code"] == "CL800" and "gear stage 4" in r["error"]["message"]


def test_prvc_is_the_g96_cutting_speed(tmp_path):
    # PRVC(0, 0): 0 before G96, the cutting speed S180 while G96 is on, 0 again after G97
    r = _ok(tmp_path, "%MPF1\n@345 R1 K0 K0\nG0 X50\nG96 S180 M3\n@345 R2 K1 K0\nG97\n@345 R3 K0 K0\nM30\n")
    assert (R(r, 1), R(r, 2), R(r, 3)) == (0.0, 180.0, 0.0)
    r = _run(tmp_path, "%MPF1\n@345 R1 K0 K1\nM30\n")
    assert r["error"]["code"] == "CL800"
    r = _run(tmp_path, "%MPF1\n@345 R1 K2 K0\nM30\n")
    assert r["error"]["code"] == "CL800" and "channel 2" in r["error"]["message"]
    # 810/820: PRVC channel 1 only (ch.6 table, L4887-4889)
    r = _run(tmp_path, "%MPF1\n@345 R1 K2 K0\nM30\n", control="810")
    assert r["error"]["code"] == "CL800" and "outside 0-1" in r["error"]["message"]


def test_g96_speed_follows_the_radius(tmp_path):
    # 180 m/min at radius 50 mm: 180000 / (2 pi 50) = 572.958 rev/min; at radius 20: 1432.39 -> limit 1000
    r = _ok(tmp_path, "%MPF1\nG0 X50\nG96 S180 M3\n@714 @364 R1 K0\nG0 X20\n@714 @364 R2 K0\n"
                      "G97\nG0 X50\n@714 @364 R3 K0 @342 R4 K0 K0\nM30\n", extra="gears = [1000]\n")
    assert R(r, 1) == pytest.approx(180000.0 / (2 * math.pi * 50))
    assert R(r, 2) == 1000.0
    assert R(r, 3) == 1000.0 and R(r, 4) == 1000.0  # G97 keeps the speed the spindle has


def test_g96_at_radius_zero_needs_a_limit(tmp_path):
    r = _run(tmp_path, "%MPF1\nG0 X0\nG96 S100 M3\nM30\n")
    assert r["error"]["code"] == "NC010" and r["error"]["line"] == 3
    # a standing spindle needs no speed: G96 at X0, then away from the axis and start there
    # (180 m/min at radius 50 mm: 572.958 rev/min)
    r = _ok(tmp_path, "%MPF1\nG0 X0\nG96 S180\nG0 X50\nM3\n@714 @364 R1 K0\nM30\n")
    assert R(r, 1) == pytest.approx(180000.0 / (2 * math.pi * 50))
    r = _run(tmp_path, "%MPF1\nG0 X0\nG96 S180\nM4\nM30\n")
    assert r["error"]["code"] == "NC010" and r["error"]["line"] == 4
    # at radius 0 the spindle runs at the limit of its gear stage (stage 2: 2500 rev/min)
    r = _ok(tmp_path, "%MPF1\nG0 X0\nG96 S100 M3\n@714 @364 R1 K0\nM30\n", extra="gears = [800, 2500]\ngear = 2\n")
    assert R(r, 1) == 2500.0


def test_prss_reads_the_programmed_speed(tmp_path):
    # L2569: R55 = PRSS (1,0); the programmed speed of the master spindle in channel 1
    r = _ok(tmp_path, "%MPF1\nS850\n@342 R55 K1 K0\nM30\n")
    assert R(r, 55) == 850.0


def test_decode_ahead_actual_values_need_stop_dec(tmp_path):
    # with 2 blocks decoded ahead, S600 M3 and the dwell still wait: ACSS sees the standing spindle
    extra = "decode_ahead = 2\n"
    r = _ok(tmp_path, "%MPF1\nS600 M3\nG4 X0.25\n@364 R1 K0 @363 R2 K0\n@714\n@364 R3 K0 @363 R4 K0\nM30\n",
            extra=extra)
    assert (R(r, 1), R(r, 2)) == (0.0, 0.0)
    assert (R(r, 3), R(r, 4)) == (600.0, pytest.approx(180.0))


def test_decode_ahead_setpoints_are_the_decoded_ones(tmp_path):
    # PRVC and PRSS read what decoding has programmed, also while those blocks wait in the buffer
    r = _ok(tmp_path, "%MPF1\nS700\nG0 X50\nG96 S200\n@342 R1 K0 K0 @345 R2 K0 K0\nM30\n",
            extra="decode_ahead = 3\n")
    assert (R(r, 1), R(r, 2)) == (700.0, 200.0)


def _lint(tmp_path: Path, text: str):
    path = tmp_path / "prog.mpf"
    path.write_text(text)
    return check(path, dialect="sin800")


def test_lint_warns_for_spindle_read_after_spindle_block(tmp_path):
    diags = _lint(tmp_path, "%MPF1\nS600 M3\nG4 X0.25\n@363 R1 K0\n@714\n@363 R2 K0 @3e4 R3 K0\n")
    assert [(d.code, d.span.line) for d in diags] == [("SIN010", 4)]
    assert "ACSP" in diags[0].message and "spindle block in line 3" in diags[0].message
    # axis reads do not go stale by a spindle block, nor by a dwell (the X of G04 is a time)
    assert _lint(tmp_path, "%MPF1\nS600 M3\n@361 R1 K1\n") == []
    assert _lint(tmp_path, "%MPF1\nG04 X2\n@361 R1 K1\n") == []
    diags = _lint(tmp_path, "%MPF1\nM42\n@3e4 R1 K0\n")
    assert [(d.code, d.span.line) for d in diags] == [("SIN010", 3)] and "AGS" in diags[0].message
