"""Manual §4.6-4.8: COF, DPC, SCL and the G functions behind them (G60/G67, G37/G38/G39, G138).

The manual's examples with their stated results, and positions computed by hand: a programmed point p
reaches the machine at G138(scale(p + contour shift)) + offsets (docs/decisions.md).
"""

from __future__ import annotations

import math

import pytest

from ncvm.api import run as api_run
from ncvm.runtime.session import RunOptions


def ok(r) -> dict:
    assert r["status"] == "ok", r["error"]
    return r["variables"]


# -- the manual's examples -------------------------------------------------------------------------
def test_cof_examples_l1985(run):
    v = ok(run("N5 G60 X1.5 Y2.5 Z3.5\n10 A=COF(3)\n20 B=COF(\"X\")\n30 C=COF(2,0)\nM30\n"))
    # coordinate 3 is Z, "X" is X, physical axis 2 is Y (reference configuration, channel 1)
    assert (v["A"], v["B"], v["C"]) == (3.5, 1.5, 2.5)


def test_cof_0_is_a_runtime_error_l1988(run):
    r = run("N5 G60 X1\n100 C=COF(0)\nM30\n")
    assert r["status"] == "error" and r["error"]["code"] == "1938" and r["error"]["line"] == 2


def test_dpc_examples_l2013(run):
    text = ("N5 G138 X1.25 Y-2 Z4 R30\n10 A=DPC(1)\n15 B=DPC(\"X\")\n20 B2=DPC(2)\n25 B3=DPC(2,0)\n"
            "30 ANGLE=DPC(0)\nM30\n")
    v = ok(run(text))
    assert (v["A"], v["B"], v["B2"], v["B3"], v["ANGLE"]) == (1.25, 1.25, -2.0, -2.0, 30.0)


def test_dpc_9_is_a_runtime_error_l2018(run):
    # the reference configuration has 8 physical axes, channel 1 three coordinates
    r = run("N5 G138 X1\n100 C=DPC(9)\nM30\n")
    assert r["status"] == "error" and r["error"]["code"] == "1938"


def test_scl_examples_l2046(run):
    text = ("N5 G38 X10 Y20 Z30 I2 J0.5 K3 R45\n10 W=SCL(0)\n20 P=SCL(1,2)\n30 F=SCL(2,2,1)\n"
            "40 D=SCL(2,\"X\")\nM30\n")
    v = ok(run(text))
    assert (v["W"], v["P"], v["F"], v["D"]) == (45.0, 20.0, 0.5, 2.0)


def test_functions_refuse_a_coordinate_of_another_channel(run):
    # "an error message is issued if a coordinate not existing on this channel is selected" (L1975, L2026)
    for call in ('COF("X2")', "DPC(4,0)", 'SCL(1,"Y2")'):
        r = run(f"10 A={call}\nM30\n")
        assert r["status"] == "error" and r["error"]["code"] == "1970", call


def test_nothing_programmed_gives_neutral_values(run):
    v = ok(run('10 A=COF(1)\n20 B=DPC(0)\n30 C=SCL(0)\n40 D=SCL(2,1)\n50 E=SCL(1,3)\n60 G$=NCF("G37")\n'
               '70 H$=NCF("G60")\nM30\n'))
    assert (v["A"], v["B"], v["C"], v["D"], v["E"]) == (0.0, 0.0, 0.0, 1.0, 0.0)
    assert (v["G$"], v["H$"]) == ("G39", "G67")


# -- blocks after activation move to transformed positions -----------------------------------------
def test_scale_2_about_a_centre(run):
    text = "N10 G37 X10 Y20 I2 J2\nN20 G1 X15 Y25 F1000\n30 WAIT\n40 MX=MPOS(\"X\")\n50 MY=MPOS(2)\n" \
           "60 CX=CPOS(\"X\")\n70 WX=WPOS(\"X\")\nM30\n"
    v = ok(run(text))
    # X: 10 + 2 * (15 - 10) = 20; Y: 20 + 2 * (25 - 20) = 30. The WCS includes scaling (L1323).
    assert (v["MX"], v["MY"]) == (20.0, 30.0)
    assert (v["CX"], v["WX"]) == (15.0, 20.0)


def test_contour_shift_moves_and_ends_with_g67(run):
    text = ("N10 G60 X5 Y-3\nN20 G1 X10 Y10 F1000\n30 WAIT\n40 MX=MPOS(1)\n50 MY=MPOS(2)\n60 WX=WPOS(1)\n"
            "N70 G67\nN80 G1 X10 Y10\n90 WAIT\n100 NX=MPOS(1)\n110 C=COF(1)\nM30\n")
    v = ok(run(text))
    assert (v["MX"], v["MY"], v["WX"]) == (15.0, 7.0, 15.0)
    assert (v["NX"], v["C"]) == (10.0, 0.0)


def test_g60_keeps_the_shift_of_coordinates_it_does_not_name(run):
    v = ok(run("N10 G60 X5 Y6\nN20 G60 Y1\n30 A=COF(1)\n40 B=COF(2)\nM30\n"))
    assert (v["A"], v["B"]) == (5.0, 1.0)


def test_workpiece_position_compensation_rotates_and_shifts(run):
    text = ("N10 G138 X100 Y50 R90\nN20 G1 X10 Y0 F1000\n30 WAIT\n40 MX=MPOS(1)\n50 MY=MPOS(2)\n"
            "60 WX=WPOS(1)\n70 WY=WPOS(2)\n80 CX=CPOS(1)\nM30\n")
    v = ok(run(text))
    # (10, 0) turned 90 degrees counter-clockwise in G17 is (0, 10); plus the shift (100, 50)
    assert (v["MX"], v["MY"]) == (100.0, 60.0)
    # G138 is a coordinate transformation after the WCS (L1323, L1581): WPOS is before it
    assert (v["WX"], v["WY"], v["CX"]) == (10.0, 0.0, 10.0)


def test_the_chain_contour_shift_then_scaling_then_g138(run):
    text = "N10 G60 X1\nN20 G37 I2 J2\nN30 G138 X100\nN40 G1 X4 F1000\n50 WAIT\n60 MX=MPOS(1)\n70 WX=WPOS(1)\nM30\n"
    v = ok(run(text))
    # (4 + 1) * 2 = 10 in the WCS, + 100 from G138
    assert (v["MX"], v["WX"]) == (110.0, 10.0)


def test_g38_rotation_about_the_pole(run):
    text = "N10 G38 X5 Y0 I2 J2 R90\nN20 G1 X10 Y0 F1000\n30 WAIT\n40 MX=MPOS(1)\n50 MY=MPOS(2)\nM30\n"
    v = ok(run(text))
    # scaled about the pole: (5 + 2 * 5, 0) = (15, 0); turned 90 degrees about (5, 0): (5, 10)
    assert (v["MX"], v["MY"]) == (5.0, 10.0)


def test_g39_ends_scaling(run):
    text = ("N10 G37 I3\nN20 G1 X10 F1000\nN30 G39\nN40 G1 X4\n50 WAIT\n60 MX=MPOS(1)\n70 F=SCL(2,1)\n"
            '80 G$=NCF("G38")\nM30\n')
    v = ok(run(text))
    assert (v["MX"], v["F"], v["G$"]) == (4.0, 1.0, "G39")


def test_g138_without_values_ends_the_compensation(run):
    v = ok(run("N10 G138 X7 R10\nN20 G138\nN30 G1 X1 F1000\n40 WAIT\n50 MX=MPOS(1)\n60 A=DPC(0)\nM30\n"))
    assert (v["MX"], v["A"]) == (1.0, 0.0)


def test_incremental_moves_under_scaling(run):
    text = "N10 G37 I2\nN20 G91 G1 X5 F1000\nN30 X5\n40 WAIT\n50 MX=MPOS(1)\n60 CX=CPOS(1)\nM30\n"
    v = ok(run(text))
    assert (v["MX"], v["CX"]) == (20.0, 10.0)


def test_activation_keeps_the_tool_where_it_is(run):
    # like G92, a new transformation moves no axis: the programmed position is what makes the
    # machine position under it. Machine X 10, scaling 2 about 0: CPOS 5
    text = "N10 G1 X10 F1000\nN20 G37 I2\n30 WAIT\n40 MX=MPOS(1)\n50 CX=CPOS(1)\nM30\n"
    v = ok(run(text))
    assert (v["MX"], v["CX"]) == (10.0, 5.0)


def test_values_in_inch_under_g70(run):
    text = "N10 G70\nN20 G60 X1\nN30 G1 X1 F10\n40 WAIT\n50 C=COF(1)\n60 MX=MPOS(1)\nN70 G71\n75 WAIT\n80 MM=MPOS(1)\nM30\n"
    v = ok(run(text))
    # the shift is 1 inch = 25.4 mm; X1 in inch ends at 2 inch = 50.8 mm
    assert v["C"] == 1.0 and v["MX"] == pytest.approx(2.0) and v["MM"] == pytest.approx(50.8)


def test_prepared_values_are_read_before_execution(run):
    # COF reads the last *programmed* shift (block preparation), MPOS the executed position
    v = ok(run("N10 G60 X5\nN20 G1 X1 F1000\n30 C=COF(1)\n40 M=MPOS(1)\nM30\n"))
    assert (v["C"], v["M"]) == (5.0, 0.0)


def test_g92_under_scaling(run):
    text = "N10 G37 I2\nN20 G0 X10\nN30 G92 X0\nN40 G1 X5 F1000\n50 WAIT\n60 MX=MPOS(1)\n70 A=AXO(1)\nM30\n"
    v = ok(run(text))
    # machine 20 after N20; G92 X0 keeps it there (G92 shift 20); X5 -> 2 * 5 + 20 = 30
    assert (v["MX"], v["A"]) == (30.0, 20.0)


def test_zero_factor_is_an_error(run):
    r = run("N10 G37 I0\nM30\n")
    assert r["status"] == "error" and r["error"]["code"] == "NC009" and r["error"]["line"] == 1


def test_ppos_keeps_scaling_cprobe_removes_it(run_text, reference):
    # PPOS does not consider scaling (L1582); CPROBE uses every transformation (L1430)
    m = reference(1, scenario=[{"time": 0.0, "kind": "probe", "X": 40.0}])
    text = "N10 G37 I2\nN20 G75 X50 F500\n30 PP=PPOS(1)\n40 CP=CPROBE(1)\n50 MX=MPOS(1)\nM30\n"
    v = ok(run_text(text, name="p.cpl", machine=m))
    assert (v["PP"], v["CP"], v["MX"]) == (40.0, 20.0, 40.0)


# -- circles -------------------------------------------------------------------------------------
def test_arc_under_uniform_scaling_and_rotation(run):
    text = "N5 G1 X0 Y20 F1000\nN10 G38 I2 J2 R90\nN20 G1 X10 Y0\nN30 G3 X0 Y10 I-10 J0\nM30\n"
    r = run(text)
    assert r["status"] == "ok", r["error"]
    m = r["motion"]
    # T(p) = rot90(2 p): (10, 0) -> (0, 20) (the tool is already there), (0, 10) -> (-20, 0), centre 0;
    # a counter-clockwise quarter of radius 20 from (0, 20) to (-20, 0)
    assert m["arc_moves"] == 1
    assert m["feed_length"] == pytest.approx(20.0 + math.pi * 20 / 2)
    assert m["bounds"]["X"] == pytest.approx([-20.0, 0.0]) and m["bounds"]["Y"] == pytest.approx([0.0, 20.0])
    assert r["position"] == pytest.approx({"X": 0.0, "Y": 10.0, "Z": 0.0})


def test_mirrored_arc_turns_the_other_way(run):
    text = "N5 G1 X-10 Y0 F1000\nN10 G37 I-1\nN20 G3 X0 Y10 I-10 J0\nM30\n"
    r = run(text)
    assert r["status"] == "ok", r["error"]
    m = r["motion"]
    # mirrored in X: (10, 0) -> (0, 10) counter-clockwise about 0 becomes (-10, 0) -> (0, 10)
    # clockwise, a quarter circle (not three quarters)
    assert m["feed_length"] == pytest.approx(10.0 + math.pi * 10 / 2)
    assert m["bounds"]["X"] == pytest.approx([-10.0, 0.0]) and m["bounds"]["Y"] == pytest.approx([0.0, 10.0])


def test_arc_with_unequal_factors_is_refused(run):
    r = run("N10 G37 I2 J3\nN20 G2 X10 Y0 I5 J0 F100\nM30\n")
    assert r["status"] == "error" and r["error"]["code"] == "NC004" and r["error"]["line"] == 2


# -- the straight-move fast path --------------------------------------------------------------------
def test_plain_straight_moves_leave_the_fast_path_while_a_transformation_is_active(tmp_path, reference):
    """Plain G0/G1 blocks normally run through the generated fast path; it knows no transformation,
    so a transformation must send them the general way, and ending it must bring the fast path back."""
    path = tmp_path / "p.cpl"
    path.write_text("N10 G0 X1 Y1\nN20 G37 I2 J2\nN30 G0 X3 Y4\nN40 G1 X5 F1000\nN50 G39\n"
                    "N60 G1 X7 Y2\nM30\n", encoding="latin-1")
    result, session = api_run(path, machine=reference(1), options=RunOptions(keep_toolpath=True, state_dir=tmp_path / ".s"))
    assert result["status"] == "ok", result["error"]
    ends = [tuple(e[:2]) for e in session.recorder.arrays()["end"]]
    assert ends == [(1.0, 1.0), (6.0, 8.0), (10.0, 8.0), (7.0, 2.0)]
    assert session.kernel.linear is session.kernel._fast_linear


# -- the rest of the control sees them ---------------------------------------------------------------
def test_the_functions_are_read_only(run):
    # the manual gives COF, DPC and SCL only as functions that "supply" values
    for text in ("10 COF(1)=5\nM30\n", "10 DPC(0)=5\nM30\n", "10 SCL(2,1)=3\nM30\n"):
        r = run(text)
        assert r["status"] == "error" and r["error"]["code"] == "CPL001", text


def test_sd1_groups_18_and_19(run):
    text = "N10 G60 X1\nN20 G38 R5\n30 WAIT\n40 A%=SD(1,18,1)\n50 B%=SD(1,19,1)\nN60 G67 G39\n70 WAIT\n" \
           "80 C%=SD(1,18,1)\n90 D%=SD(1,19,1)\nM30\n"
    v = ok(run(text))
    assert (v["A%"], v["B%"], v["C%"], v["D%"]) == (60, 38, 67, 39)


def test_a_shift_block_does_not_repeat_a_modal_cycle(run, tmp_path):
    (tmp_path / "CYC81").write_text("N1 G1 Z[P1]\nN2 G0 Z10\n10 #HOLES% = #HOLES% + 1\n", encoding="latin-1")
    calls = {"calls": {"G81": {"program": "CYC81", "modal": True}}}
    text = "1 #HOLES% = 0\nN5 G1 F1000\nN10 G81 [-5]\nN20 X10\nN30 G60 X5\nN40 X20\nN50 G80\n60 H%=#HOLES%\nM30\n"
    v = ok(run(text, cpl=calls))
    assert v["H%"] == 3  # after N10, N20 and N40: G60 X5 travels nowhere


def test_mcods_wcs_and_bcs_differ_by_g138(run):
    # MCODS 71 gives WCS coordinates, 72 BCS set points; G138 lies between them (L1323)
    text = ("10 DIM W(3)\n20 DIM B(3)\nN30 G138 X100 R90\nN40 G1 X10 Y0 F1000\n50 WAIT\n60 V=0\n"
            "70 E%=MCODS(71,1,V,W,3)\n80 V=0\n90 E%=MCODS(72,1,V,B,3)\nM30\n")
    v = ok(run(text))
    assert v["W"] == [None, 10.0, 0.0, 0.0] and v["B"] == [None, 100.0, 10.0, 0.0]
