"""The DIN 66025 kernel: arcs in every plane, offsets, G91, units, faults (values computed by hand)."""

from __future__ import annotations

import math

import pytest

from ncvm.machine.config import machine_from_dict

AXES = [{"name": n, "min": -1000.0, "max": 1000.0} for n in "XYZ"]


def machine(**extra):
    return machine_from_dict({"axis": AXES, **extra})


def test_quarter_arc_xy_length_and_bounds(run_text):
    r = run_text("G17 G90 G1 X10 Y0 F100\nG3 X0 Y10 I-10 J0\nM2\n")
    m = r["motion"]
    assert m["arc_moves"] == 1 and m["feed_moves"] == 1
    assert m["feed_length"] == pytest.approx(10 + math.pi * 10 / 2)
    assert m["bounds"]["X"] == pytest.approx([0, 10]) and m["bounds"]["Y"] == pytest.approx([0, 10])
    assert r["position"] == pytest.approx({"X": 0.0, "Y": 10.0, "Z": 0.0})


def test_cw_arc_passes_three_quadrants(run_text):
    # clockwise from (10,0) to (0,10) around the origin sweeps 270 degrees through (0,-10) and (-10,0)
    r = run_text("G1 X10 F100\nG2 X0 Y10 I-10 J0\n")
    assert r["motion"]["feed_length"] == pytest.approx(10 + 1.5 * math.pi * 10)
    assert r["motion"]["bounds"]["X"] == pytest.approx([-10, 10])
    assert r["motion"]["bounds"]["Y"] == pytest.approx([-10, 10])


def test_arc_xz_plane_g18(run_text):
    # G18: plane Z-X, centre words K (Z) and I (X); CCW half circle from (X0,Z0) to (X0,Z10)... radius 5
    r = run_text("G18 G1 X0 Z0 F100\nG3 X0 Z10 K5 I0\n")
    m = r["motion"]
    assert m["feed_length"] == pytest.approx(math.pi * 5)
    # (Z, X) is right-handed about +Y: CCW from angle 180 deg to 360 deg passes 270 deg, i.e. X = -5
    assert m["bounds"]["X"] == pytest.approx([-5, 0])
    assert m["bounds"]["Z"] == pytest.approx([0, 10])


def test_arc_yz_plane_g19_radius_form(run_text):
    r = run_text("G19 G1 Y10 Z0 F100\nG2 Y0 Z10 R10\n")
    # R10 from (Y10,Z0) to (Y0,Z10): quarter circle, centre (Y0,Z0) for CW seen from +X
    assert r["motion"]["feed_length"] == pytest.approx(10 + math.pi * 10 / 2)
    assert r["motion"]["bounds"]["Y"] == pytest.approx([0, 10])
    assert r["motion"]["bounds"]["Z"] == pytest.approx([0, 10])


def test_negative_radius_takes_long_arc(run_text):
    r = run_text("G1 X10 F100\nG3 X0 Y10 R-10\n")
    assert r["motion"]["feed_length"] == pytest.approx(10 + 1.5 * math.pi * 10)


def test_full_circle_and_helix(run_text):
    r = run_text("G1 X10 F100\nG3 X10 Y0 Z-2 I-10 J0\n")
    assert r["motion"]["feed_length"] == pytest.approx(10 + math.hypot(2 * math.pi * 10, 2))
    assert r["position"]["Z"] == pytest.approx(-2)
    assert r["motion"]["bounds"]["X"] == pytest.approx([-10, 10])


def test_radius_mismatch_faults_with_line(run_text):
    r = run_text("G1 X10 F100\nG3 X0 Y11 I-10 J0\n")
    assert r["status"] == "error"
    assert r["error"]["code"] == "NC002" and r["error"]["line"] == 2
    assert r["motion"]["feed_moves"] == 1  # everything before the fault is reported


def test_incremental_moves(run_text):
    r = run_text("G91 G1 X5 Y5 F100\nX5\nY-2\nG90 X0\n")
    assert r["position"] == pytest.approx({"X": 0.0, "Y": 3.0, "Z": 0.0})
    assert r["motion"]["feed_length"] == pytest.approx(math.hypot(5, 5) + 5 + 2 + 10)


def test_work_offset_moves_machine_but_not_program_position(run_text, tmp_path):
    m = machine(offsets={"G55": [100.0, 50.0, -10.0]})
    r = run_text("G55 G0 X1 Y2 Z3\n", machine=m)
    assert r["position"] == pytest.approx({"X": 1.0, "Y": 2.0, "Z": 3.0})
    # toolpath extents are in machine coordinates
    assert r["motion"]["bounds"]["X"] == pytest.approx([0, 101])
    assert r["motion"]["bounds"]["Z"] == pytest.approx([-7, 0])


def test_g92_and_tool_length(run_text):
    m = machine(tool=[{"number": 2, "length": 30.0}])
    r = run_text("G0 X10\nG92 X0\nG0 X5\nT2 M6\nG43 H2\nG0 Z0\n", machine=m)
    assert r["position"]["X"] == pytest.approx(5)
    assert r["motion"]["bounds"]["X"] == pytest.approx([0, 15])
    assert r["motion"]["bounds"]["Z"] == pytest.approx([0, 30])


def test_inch_units(run_text):
    r = run_text("G70 G1 X1 F10\n")
    assert r["motion"]["feed_length"] == pytest.approx(25.4)
    assert r["position"]["X"] == pytest.approx(1.0)


def test_dwell_adds_time_and_block_skip(run_text):
    r = run_text("G4 P2.5\n/G0 X100\nM30\n")
    assert r["cycle_time_s"] == pytest.approx(2.5)
    assert r["motion"]["rapid_moves"] == 0


def test_trapezoidal_cycle_time(run_text):
    # X: max_feed 5000 mm/min, accel 1000 mm/s^2 (default machine). 100 mm at F600 = 10 mm/s:
    # reaches speed (100*1000 >= 100): t = 100/10 + 10/1000
    r = run_text("G1 X100 F600\n")
    assert r["cycle_time_s"] == pytest.approx(10.01)
    # a short move never reaches speed: 2*sqrt(L/a)
    r = run_text("G1 X0.001 F6000\n")
    assert r["cycle_time_s"] == pytest.approx(2 * math.sqrt(0.001 / 1000))


def test_feed_without_f_faults(run_text):
    r = run_text("G1 X10\n")
    assert r["error"]["code"] == "NC006"


def test_syntax_error_has_column(run_text):
    r = run_text("G1 X10 F100\nG1 X1 Y2 ?? \n")
    assert r["error"]["code"] == "NC001" and r["error"]["line"] == 2 and r["error"]["column"] == 10


def test_g10_l2_sets_a_zero_offset_table_and_g92_1_cancels_g92(run_text):
    # G10 L2 P2 writes G55; selecting it moves the program origin, not the tool
    r = run_text("G10 L2 P2 X100 Y-20\nG55 G0 X1 Y1\nG92 X0\nG0 X5\nG92.1\nG0 X5\n")
    assert r["status"] == "ok"
    # machine X: 101 after line 2; G92 X0 there makes X5 -> 106; after G92.1, X5 in G55 -> 105
    assert r["motion"]["bounds"]["X"] == pytest.approx([0, 106])
    assert r["position"]["X"] == pytest.approx(5.0)
    assert r["motion"]["bounds"]["Y"] == pytest.approx([-19, 0])


def test_g10_other_forms_fault(run_text):
    r = run_text("G10 L1 P1 X3\n")
    assert r["error"]["code"] == "NC004" and "G10 L2" in r["error"]["message"]


def test_repeated_address_reports_the_second_word(run_text):
    r = run_text("(set up) G1 X10 (again) X20 F100\n")
    assert r["error"]["code"] == "NC001" and r["error"]["column"] == 25
    assert "address X twice" in r["error"]["message"]


@pytest.mark.parametrize("text, message", [
    ("G1 F-5 X10\n", "G1 with a negative feed rate F-5"),
    ("G1 X10\n", "G1 with feed rate 0"),
    ("G1 F100 X10\nF-2 G3 X0 Y10 I-10\n", "G3 with a negative feed rate F-2"),
])
def test_feed_rate_faults_name_the_feed(run_text, text, message):
    r = run_text(text, name="p.din")
    assert r["error"]["code"] == "NC006" and message in r["error"]["message"]


def test_tool_change_comes_before_tool_length_offset_in_one_block(run_text):
    """LinuxCNC's order of execution (the iso profile's reference): "change tool" (M6) runs before "tool
    length offset" (G43), so ``T2 M6 G43`` takes tool 2's length, not the length of the tool it replaces."""
    m = machine(tool=[{"number": 1, "length": 10.0}, {"number": 2, "length": 30.0}])
    r = run_text("T1 M6\nG43\nG0 Z0\nT2 M6 G43\nG0 Z0\n", machine=m)
    assert r["motion"]["bounds"]["Z"] == pytest.approx([0, 30])
