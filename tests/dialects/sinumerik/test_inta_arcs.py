"""INTA @736 (manual L4417-4436, ch.10 L6799) on circular blocks: the arc is cut where the path is when
the input comes, the remaining travel is deleted and the next block starts at the point reached.

Times are worked by hand as the NC kernel times an arc: a straight move of the arc's length over the two
plane axes, each carrying a share of 1/sqrt(2). With the axis defaults (max_feed 5000 mm/min =
83.333 mm/s, accel 1000 mm/s^2) the path may run at up to 83.333 * sqrt(2) = 117.85 mm/s, so F6000
gives v = 100 mm/s, and accelerates at a = 1000 * sqrt(2) = 1414.214 mm/s^2: 0.1 s and
v^2 / 2a = 5.0 mm of ramp. Once at speed, t seconds into the block the path has covered
v t - v^2 / 2a; at t = 0.5 s that is 50 - 5.0 = 45.0 mm, on a radius of 50 an angle of
0.9 rad = 53.244 degrees.
"""

from __future__ import annotations

import math
from pathlib import Path

import pytest
from sin800_helpers import MACHINE, input_event, machine, run_mpf

from ncvm.api import run
from ncvm.runtime.session import RunOptions

V, A = 100.0, 1000.0  # an arc ramps at its plane axes' smallest acceleration (nc.dynamics.arc_limits)
RAMP = V * V / (2 * A)  # 5.0 mm
S_05 = V * 0.5 - RAMP  # the path covered 0.5 s into the block: 45.0 mm
PHI = S_05 / 50.0  # the angle reached on radius 50: 0.9 rad
# the quarter circle G3 X-50 Y50 I-50 J0 from (0, 0), centre (-50, 0), stopped at PHI
CUT = (-50.0 + 50.0 * math.cos(PHI), 50.0 * math.sin(PHI))


def _ok(tmp_path: Path, text: str, extra: str = ""):
    return run_mpf(tmp_path, text, extra, ok=True, session=True)


def _event(time: float) -> str:
    return input_event(time, 3)


def _xy(result):
    return result["position"]["X"], result["position"]["Y"]


def _arc(session, index: int = 0):
    """(start, end, ArcSpec) of the move ``index`` the canon output as an arc."""
    rec = session.recorder
    arrays = rec.arrays()
    assert arrays["kind"][index] == 2
    return tuple(arrays["start"][index]), tuple(arrays["end"][index]), rec.arcs[index]


def test_hand_computed_values():
    assert (RAMP, S_05, PHI) == (pytest.approx(5.0), pytest.approx(45.0), pytest.approx(0.9))
    assert math.degrees(PHI) == pytest.approx(51.5662, abs=1e-4)
    assert CUT == (pytest.approx(-18.919502), pytest.approx(39.166345))


def test_quarter_circle_is_cut_where_the_input_comes(tmp_path):
    r, s = _ok(tmp_path, "%MPF1\nG17 G90 F6000\n@736 K0 K1 K3 G3 X-50 Y50 I-50 J0\n@714 @361 R1 K1 @361 R2 K2\n"
                         "M30\n", _event(0.5))
    assert (r["variables"]["R1"], r["variables"]["R2"]) == pytest.approx(CUT)
    start, end, spec = _arc(s)
    # the canon output: an arc about the same centre, counter-clockwise, ending at the cut point
    assert start == (0.0, 0.0, 0.0) and end == pytest.approx((*CUT, 0.0))
    assert spec.center == pytest.approx((-50.0, 0.0)) and not spec.cw and spec.radius == pytest.approx(50.0)
    assert r["motion"]["arc_moves"] == 1 and r["motion"]["feed_length"] == pytest.approx(S_05)
    # the cut arc, timed rest to rest, takes 45.0 / 100 + 0.1 = 0.55 s (>= the input's 0.5 s)
    assert r["cycle_time_s"] == pytest.approx(S_05 / V + V / A)


def test_next_block_starts_at_the_point_reached(tmp_path):
    # G1 X0 keeps Y at the cut point: (0, 39.166345)
    r, s = _ok(tmp_path, "%MPF1\nG17 G90 F6000\n@736 K0 K1 K3 G3 X-50 Y50 I-50 J0\nG1 X0\nM30\n", _event(0.5))
    assert _xy(r) == pytest.approx((0.0, CUT[1]))
    assert tuple(s.recorder.arrays()["start"][1]) == pytest.approx((*CUT, 0.0))


def test_position_reached_when_the_input_does_not_come(tmp_path):
    # the whole quarter circle: 25 pi = 78.539816 mm in 0.785398 + 0.1 = 0.885398 s (ramps at an axis's 1000 mm/s^2)
    r, s = _ok(tmp_path, "%MPF1\nG17 G90 F6000\n@736 K0 K1 K3 G3 X-50 Y50 I-50 J0\nM30\n")
    assert _xy(r) == pytest.approx((-50.0, 50.0))
    assert r["cycle_time_s"] == pytest.approx(0.885398, abs=1e-6)
    assert _arc(s)[2].center == pytest.approx((-50.0, 0.0))


def test_input_already_at_the_level_moves_nothing(tmp_path):
    r, _s = _ok(tmp_path, "%MPF1\nG17 G90 F6000\n@736 K0 K1 K3 G3 X-50 Y50 I-50 J0\nM30\n",
                'inputs = { "1" = "00001000" }\n')
    assert _xy(r) == (0.0, 0.0) and r["motion"]["arc_moves"] == 0


def test_radius_word_and_incremental_words(tmp_path):
    # G91 G2 X50 Y-50 B50: clockwise quarter circle of the short way, centre (0, -50), from 90 to 0 degrees.
    # Stopped at 90 degrees - PHI: (50 sin PHI, -50 + 50 cos PHI) = (39.166345, -18.919502); G1 X10 then
    # goes on from there.
    r, s = _ok(tmp_path, "%MPF1\nG17 G91 F6000\n@736 K1 K1 K3 G2 X50 Y-50 B50\nG1 X10\nM30\n", _event(0.5))
    assert _xy(r) == pytest.approx((CUT[1] + 10.0, CUT[0]))
    _start, end, spec = _arc(s)
    assert end == pytest.approx((CUT[1], CUT[0], 0.0))
    assert spec.center == pytest.approx((0.0, -50.0)) and spec.cw


def test_axis_not_programmed_but_interpolating_stops_the_arc(tmp_path):
    # G2 X-100 I-50: half circle clockwise about (-50, 0) through (-50, -50); Y has no word but moves with X,
    # so INTA for Y (axis 2) cuts it at -PHI: (-50 + 50 cos PHI, -50 sin PHI)
    r, _s = _ok(tmp_path, "%MPF1\nG17 G90 F6000\n@736 K2 K1 K3 G2 X-100 I-50\nM30\n", _event(0.5))
    assert _xy(r) == pytest.approx((CUT[0], -CUT[1]))


def test_axis_outside_the_arc_does_not_stop_it(tmp_path):
    r, _s = _ok(tmp_path, "%MPF1\nG17 G90 F6000\n@736 K3 K1 K3 G3 X-50 Y50 I-50 J0\nM30\n", _event(0.5))
    assert _xy(r) == pytest.approx((-50.0, 50.0))


def test_helix_stops_at_the_same_fraction_of_angle_and_height(tmp_path):
    # G3 X-50 Y50 Z30 I-50 J0: length hypot(25 pi, 30) = 84.074388 mm, timed as above (the kernel caps a helix
    # by its plane axes); 45.0 mm are the fraction f = 0.535240 of it: angle f pi / 2, Z = 30 f
    length = math.hypot(25.0 * math.pi, 30.0)
    f = S_05 / length
    assert (length, f) == (pytest.approx(84.074388), pytest.approx(0.535240))
    r, s = _ok(tmp_path, "%MPF1\nG17 G90 F6000\n@736 K0 K1 K3 G3 X-50 Y50 Z30 I-50 J0\nM30\n", _event(0.5))
    angle = f * math.pi / 2
    expected = (-50.0 + 50.0 * math.cos(angle), 50.0 * math.sin(angle), 30.0 * f)
    assert (r["position"]["X"], r["position"]["Y"], r["position"]["Z"]) == pytest.approx(expected)
    assert _arc(s)[2].center == pytest.approx((-50.0, 0.0))


def test_other_plane_g18(tmp_path):
    # G18: the plane Z (first), X (second), centre words K, I. G3 Z-50 X50 K-50 I0 is the same quarter circle
    # with Z for X and X for Y
    r, s = _ok(tmp_path, "%MPF1\nG18 G90 F6000\n@736 K1 K1 K3 G3 Z-50 X50 K-50 I0\nM30\n", _event(0.5))
    assert (r["position"]["Z"], r["position"]["X"]) == pytest.approx(CUT)
    assert _arc(s)[2].center == pytest.approx((-50.0, 0.0))


def test_full_circle_is_cut(tmp_path):
    # G3 I-50 J0: the full circle about (-50, 0) from (0, 0), 100 pi mm; at 0.5 s it is where the quarter
    # circle was
    r, s = _ok(tmp_path, "%MPF1\nG17 G90 F6000\n@736 K0 K1 K3 G3 I-50 J0\nM30\n", _event(0.5))
    assert _xy(r) == pytest.approx(CUT)
    assert _arc(s)[2].turns == 0


def test_cut_in_the_second_pass_of_a_multi_turn_circle(tmp_path):
    # G3 I-50 J0 P2 (two full circles as the kernel reads P): at 4 s the path has covered 400 - 5.0 =
    # 395 mm = 2 pi + 1.616815 rad; the cut arc keeps one full turn
    phi = (V * 4.0 - RAMP) / 50.0
    assert phi - 2 * math.pi == pytest.approx(1.616815, abs=1e-6)
    r, s = _ok(tmp_path, "%MPF1\nG17 G90 F6000\n@736 K0 K1 K3 G3 I-50 J0 P2\nM30\n", _event(4.0))
    assert _xy(r) == pytest.approx((-50.0 + 50.0 * math.cos(phi), 50.0 * math.sin(phi)))
    assert _arc(s)[2].turns == 1
    assert r["motion"]["feed_length"] == pytest.approx(V * 4.0 - RAMP)


ROT_90 = "rotation = { settable = [90.0, 0.0, 0.0, 0.0] }\n"


def test_arc_under_a_coordinate_rotation(tmp_path):
    # G54 turned by 90 degrees: the program's quarter circle about (-50, 0) runs about the machine point
    # (0, -50), from (0, 0) to (-50, -50). The cut point is CUT in the program's frame, turned:
    # (-39.166345, -18.919502). G91 X10 in the program's frame then gives the program point
    # (-10.079824, 39.166345) = machine (-39.166345, -10.079824).
    r, s = _ok(tmp_path, "%MPF1\nG54 G17 G90 F6000\n@736 K0 K1 K3 G3 X-50 Y50 I-50 J0\n@714 @361 R1 K1 "
                         "@361 R2 K2\nG1 G91 X10\nM30\n", ROT_90 + _event(0.5))
    assert (r["variables"]["R1"], r["variables"]["R2"]) == pytest.approx((-CUT[1], CUT[0]))
    assert _xy(r) == pytest.approx((-CUT[1], CUT[0] + 10.0))
    _start, end, spec = _arc(s)
    assert end == pytest.approx((-CUT[1], CUT[0], 0.0))
    assert spec.center == pytest.approx((0.0, -50.0)) and not spec.cw


def test_incremental_arc_under_a_coordinate_rotation(tmp_path):
    # the same arc as increments and a centre vector in the program's frame: the cut block's increments
    # and centre are turned back into that frame before the kernel turns them again
    r, s = _ok(tmp_path, "%MPF1\nG54 G17 G91 F6000\n@736 K0 K1 K3 G3 X-50 Y50 I-50 J0\nM30\n",
               ROT_90 + _event(0.5))
    assert _xy(r) == pytest.approx((-CUT[1], CUT[0]))
    assert _arc(s)[2].center == pytest.approx((0.0, -50.0))


XZ_MACHINE = machine("XZ")


@pytest.mark.parametrize("machine, text, code", [
    (XZ_MACHINE, "G17 G90 F6000\n@736 K1 K1 K3 G2 X10 Z10 I5 K5", "NC004"),  # G17 on a machine without Y
    (MACHINE, "G17 G90 F6000\n@736 K1 K1 K3 G2 X100 Y0 B10", "NC002"),  # radius too short for the chord
    (MACHINE, "G17 G90\n@736 K1 K1 K3 G3 X-50 Y50 I-50 J0", "NC006"),  # no feed rate
    (MACHINE, "G17 G90\n@736 K1 K1 K3 G1 X50", "NC006"),  # no feed rate on a straight block either
])
def test_arc_the_kernel_rejects_keeps_the_kernel_fault(tmp_path, machine, text, code):
    (tmp_path / "machine.toml").write_text(machine + _event(0.5))
    path = tmp_path / "prog.mpf"
    path.write_text(f"%MPF1\n{text}\nM30\n")
    r, _s = run(path, dialect="sin800", machine=tmp_path / "machine.toml",
                options=RunOptions(keep_toolpath=True, state_dir=tmp_path / ".ncvm"))
    assert r["error"]["code"] == code and r["error"]["line"] == 3
