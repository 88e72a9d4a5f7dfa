"""Coordinate rotation (@437-@43a, L3242-3302, L4325-4334) and the programmed angle (PANG @447, L3342-3348).

Expected values are worked by hand: a point (h, v) of the program turns to
(h cos a - v sin a, h sin a + v cos a); the angle address completes a line
through the start point.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from sin800_helpers import run_mpf


def _run(tmp_path: Path, text: str, extra: str = "", ok: bool = True):
    return run_mpf(tmp_path, text, extra, ok=ok)


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


# -- MEAS M, INTA, PREP REF and INT SEC under a rotation: the program's frame --------------------------------
G54_30 = 'zero_offsets = { G54 = { coarse = [100.0, 50.0, 0.0], fine = [0.0, 0.0, 0.0] } }\n' \
         'rotation = { settable = [30.0, 0.0, 0.0, 0.0] }\n'


def _probe(position: str) -> str:
    return f'[[scenario]]\ntime = 0.0\nkind = "probe"\ninput = 1\nposition = {{ {position} }}\n'


def test_meas_m_under_rotation_measures_both_traversing_axes_and_stops_on_the_path(tmp_path):
    # G54 = (100, 50), 30 degrees. From the program point (0, 0) = machine (100, 50), X100 ends at the program
    # point (100, 0), turned (86.602540, 50), machine (186.602540, 100): both X and Y traverse. The probe
    # switches at machine Y = 80, 3/5 of the way: X = 100 + 0.6 * 86.602540 = 151.961524 (the program point
    # (60, 0)). R93/R94 = machine X/Y (L4362: referred to machine zero). G91 Y10 then goes to the program
    # point (60, 10) = turned (60 cos30 - 10 sin30, 60 sin30 + 10 cos30) = (46.961524, 38.660254), machine
    # (146.961524, 88.660254).
    r = _run(tmp_path, "%MPF1\nG54 G90 G1 X0 Y0 F1000\n@720 R93 K1 X100\n@714\n@361 R1 K1 @361 R2 K2\n"
                       "G91 Y10\n@714 @361 R3 K1 @361 R4 K2\n", G54_30 + _probe("Y = 80.0"))
    v = r["variables"]
    assert (v["R93"], v["R94"]) == pytest.approx((151.961524, 80.0))
    assert (v["R1"], v["R2"]) == pytest.approx((151.961524, 80.0))
    assert (v["R3"], v["R4"]) == pytest.approx((146.961524, 88.660254))


def test_incremental_meas_m_under_rotation(tmp_path):
    # G54 = (100, 50), 30 degrees. The program point (10, 0) is machine (108.660254, 55); G91 X50 ends at the
    # program point (60, 0) = machine (151.961524, 80). The probe switches at machine Y = 70, 0.6 of the way:
    # X = 108.660254 + 0.6 * 43.301270 = 134.641016, the program point (40, 0). G90 Y10 then goes to the
    # program point (40, 10) = turned (29.641016, 28.660254) = machine (129.641016, 78.660254).
    r = _run(tmp_path, "%MPF1\nG54 G90 G1 X10 Y0 F1000\n@720 R93 K1 G91 X50\n@714\nG90 Y10\n"
                       "@714 @361 R3 K1 @361 R4 K2\n", G54_30 + _probe("Y = 70.0"))
    v = r["variables"]
    assert (v["R93"], v["R94"]) == pytest.approx((134.641016, 70.0))
    assert (v["R3"], v["R4"]) == pytest.approx((129.641016, 78.660254))


def test_meas_m_under_rotation_counts_the_turned_axes(tmp_path):
    # X and Z programmed: under the rotation of the XY plane X, Y and Z traverse, more than 2 (L4396)
    r = _run(tmp_path, "%MPF1\nG54 G90 G1 X0 Y0 Z0 F1000\n@720 R93 K1 X100 Z-5\n", G54_30 + _probe("X = 120.0"),
             ok=False)
    assert r["error"]["code"] == "CL800" and "at most 2 axes" in r["error"]["message"]


def test_meas_m_probe_position_off_the_path(tmp_path):
    # the path runs from machine Y 50 to 100: a probe at Y = 120 never switches in this block
    r = _run(tmp_path, "%MPF1\nG54 G90 G1 X0 Y0 F1000\n@720 R93 K1 X100\n", G54_30 + _probe("Y = 120.0"), ok=False)
    assert r["error"]["code"] == "SIN007" and "not on the block's path" in r["error"]["message"]


def test_inta_under_rotation_cuts_the_path_in_the_program_frame(tmp_path):
    # 90 degrees: from the program point (10, 0) = machine (0, 10), X110 runs 100 mm along machine Y. F6000 is
    # limited to max_feed 5000 mm/min = 83.333 mm/s with 1000 mm/s^2: 0.083333 s and 3.472222 mm to speed
    # up. The input comes 0.5 s after the block starts: 3.472222 + 83.333 * (0.5 - 0.083333) = 38.194444 mm,
    # the program point (48.194444, 0) = machine (0, 48.194444). G91 X10 -> program (58.194444, 0) = machine
    # (0, 58.194444).
    first = 10 / (5000 / 60) + (5000 / 60) / 1000  # the move to (10, 0): 0.2 s
    event = f'[[scenario]]\ntime = {first + 0.5}\nkind = "input"\nbyte = 1\nbit = 3\nvalue = 1\n'
    r = _run(tmp_path, "%MPF1\nG54 G90 G1 X10 Y0 F6000\n@736 K0 K1 K3 X110\nG91 X10\n"
                       "@714 @361 R1 K1 @361 R2 K2\n", "rotation = { settable = [90.0, 0.0, 0.0, 0.0] }\n" + event)
    assert (r["variables"].get("R1", 0.0), r["variables"]["R2"]) == pytest.approx((0.0, 58.194444), abs=1e-6)


CONTOUR = "L20\nN5 X400 Y50 B100\nN10 X300 Y300\nN15 X100 Y400 M17\n"
INT_SEC_MAIN = ("%MPF30\nG54 G0 Y250 X750\nR50=20 R52=750 R51=50 R53=1 R70=0\n"
                "N3001 @131 R70 K0 K3002 @710 R54 R50\n@711 R70 R54 R62 Y250 X0 @100 K-3001\n"
                "N3002 @361 R1 K1 @361 R2 K2 M30\n")


def test_prep_ref_and_int_sec_manual_example_under_rotation(tmp_path):
    """L4212-4252 with ZOADW(0,1,1) = 30: contour, destination and result are program coordinates, so the
    intersection is X = 320, Y = 250 as without rotation, and PREP REF gives the contour as programmed."""
    (tmp_path / "L20.spf").write_text(CONTOUR)
    r = _run(tmp_path, INT_SEC_MAIN, G54_30)
    v = r["variables"]
    assert (v["R70"], v["R71"], v["R72"]) == pytest.approx((1.0, 250.0, 320.0))
    assert [v.get(f"R{n}", 0.0) for n in range(54, 62)] == pytest.approx(
        [112.860932, 374.855627, 300.0, 300.0, 0.0, 0.0, 1.0, 0.0])  # the line after the B100 rounding
    # the approach block itself is turned: (750, 250) -> (750 cos30 - 250 sin30, 750 sin30 + 250 cos30)
    # = (524.519053, 591.506351), plus G54 (100, 50)
    assert (v["R1"], v["R2"]) == pytest.approx((624.519053, 641.506351))


def test_int_sec_starts_at_the_current_point_of_the_program_frame(tmp_path):
    # contour L21 from (Y0, X0): the line to (Y100, X100). 30 degrees; the tool at the program point
    # (X0, Y50) after an incremental move. The path to (X100, Y50) meets the line Y = X at X = 50, Y = 50
    # (turned-frame coordinates of the start point, (-25, 43.30), would give another point).
    (tmp_path / "L21.spf").write_text("L21\nN5 X100 Y100 M17\n")
    r = _run(tmp_path, "%MPF1\nG54 G90 G0 X0 Y0\nG91 Y50\nG90\nR50=21 R51=0 R52=0 R53=1\n@710 R54 R50\n"
                       "@711 R70 R54 R62 X100 Y50\n", G54_30)
    v = r["variables"]
    assert (v["R70"], v["R71"], v["R72"]) == pytest.approx((1.0, 50.0, 50.0))


def test_the_rotation_is_the_kernels_transform_and_ends_with_the_angle(tmp_path):
    """A selected rotation is an Affine rotation set as the kernel's transform (straight moves leave the
    generated path); positions are shown turned; writing the angle back to 0 clears it."""
    from ncvm.nc.transform import Affine

    (tmp_path / "on").mkdir()
    r, session = run_mpf(tmp_path / "on", "%MPF1\n@437 K0 K1 K1 K90\nG54 G90 G1 X10 Y0 F1000\n", ok=True,
                         session=True)
    k = session.kernel
    assert k.transform.map.m == Affine.rotation(3, 0, 1, 90.0).m and k.linear is not k._fast_linear
    assert k.prog == pytest.approx([10.0, 0.0, 0.0], abs=1e-9)  # as programmed ...
    assert _xy(r) == pytest.approx((0.0, 10.0), abs=1e-9)  # ... shown turned
    (tmp_path / "off").mkdir()
    r, session = run_mpf(tmp_path / "off", "%MPF1\n@437 K0 K1 K1 K90\nG54 G90 G1 X10 Y0 F1000\n@437 K0 K1 K1 K0\n"
                         "X20\n", ok=True, session=True)
    assert session.kernel.transform is None and session.kernel.linear is session.kernel._fast_linear
    assert _xy(r) == pytest.approx((20.0, 10.0), abs=1e-9)


def test_a_plane_axis_missing_in_a_block_that_changes_the_zero_offset_stays_put(tmp_path):
    """As without a rotation (the kernel's rule): the axis a block does not program keeps its machine position
    through the zero offset change; under 90 degrees the program's Y is the machine's X (docs/decisions.md)."""
    extra = "rotation = { settable = [90.0, 90.0, 0.0, 0.0] }\n"
    machine_text = MACHINE_OFFSETS
    r = run_mpf(tmp_path, "%MPF1\nG54 G90 G1 X10 Y3 F1000\nG55 X20\n", extra, machine_text=machine_text, ok=True)
    # G54: (10, 3) turned = (-3, 10) at the machine; G55 (5, 7): the machine X stays -3, the program's X20
    # is the machine's Y 20 + 7; shown relative to G55: (-8, 20)
    assert _xy(r) == pytest.approx((-8.0, 20.0), abs=1e-9)


MACHINE_OFFSETS = ('[[axis]]\nname = "X"\n[[axis]]\nname = "Y"\n[[axis]]\nname = "Z"\n'
                   '[offsets]\nG54 = [0.0, 0.0, 0.0]\nG55 = [5.0, 7.0, 0.0]\n[sin800]\ncontrol = "880"\n')


def test_l2594_acpw_under_a_settable_rotation_is_the_dimension_from_the_workpiece_zero(tmp_path):
    """ACPW (@360) reads "the dimension between the workpiece zero W and tool starting position P" per axis
    (L2594). The settable rotation (ZOADW, L3247) turns the program about W and leaves W where G54 puts it,
    so after ``G54 X10 Y0`` under 30 degrees the tool stands at (10 cos30, 10 sin30) from W along axes 1
    and 2: ACPW = (8.660254, 5), ACPM (@361, L2605) that plus G54's shift (100, 0)."""
    r = _run(tmp_path, "%MPF1\n@437 K0 K1 K1 K30\nG54 G90 G0 X10 Y0\n"
                       "@714 @360 R1 K1 @360 R2 K2 @361 R3 K1 @361 R4 K2\nM30\n",
             "[offsets]\nG54 = [100.0, 0.0, 0.0]\n")
    v = r["variables"]
    assert (v["R1"], v["R2"]) == pytest.approx((8.660254, 5.0))
    assert (v["R3"], v["R4"]) == pytest.approx((108.660254, 5.0))
