"""INTA @736 (manual L4417-4436, ch.10 L6799) on circular blocks: the arc is cut where the path is when
the input comes, the remaining travel is deleted and the next block starts at the point reached.

Times are worked by hand as the NC kernel times an arc (nc.dynamics.arc_limits): at the quadrant points
one plane axis carries the whole path speed and ramp, so a flat arc runs at no more than the plane axes'
smallest maximum feed and ramps at their smallest acceleration. With the axis defaults (max_feed
5000 mm/min = 83.333 mm/s, accel 1000 mm/s^2) F4800 gives v = 80 mm/s, reached in 0.08 s over
v^2 / 2a = 3.2 mm of ramp. Once at speed, t seconds into the block the path has covered
v t - v^2 / 2a; at t = 0.5 s that is 40 - 3.2 = 36.8 mm, on a radius of 50 an angle of
0.736 rad = 42.170 degrees.
"""

from __future__ import annotations

import math
from pathlib import Path

import pytest
from sin800_helpers import MACHINE, input_event, machine, run_mpf

from ncvm.api import run
from ncvm.runtime.session import RunOptions

V, A = 80.0, 1000.0  # F4800; an arc ramps at its plane axes' smallest acceleration (nc.dynamics.arc_limits)
RAMP = V * V / (2 * A)  # 3.2 mm
S_05 = V * 0.5 - RAMP  # the path covered 0.5 s into the block: 36.8 mm
PHI = S_05 / 50.0  # the angle reached on radius 50: 0.736 rad
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
    assert (RAMP, S_05, PHI) == (pytest.approx(3.2), pytest.approx(36.8), pytest.approx(0.736))
    assert math.degrees(PHI) == pytest.approx(42.1697, abs=1e-4)
    assert CUT == (pytest.approx(-12.942010), pytest.approx(33.566433))


def test_quarter_circle_is_cut_where_the_input_comes(tmp_path):
    r, s = _ok(tmp_path, "%MPF1\nG17 G90 F4800\n@736 K0 K1 K3 G3 X-50 Y50 I-50 J0\n@714 @361 R1 K1 @361 R2 K2\n"
                         "M30\n", _event(0.5))
    assert (r["variables"]["R1"], r["variables"]["R2"]) == pytest.approx(CUT)
    start, end, spec = _arc(s)
    # the canon output: an arc about the same centre, counter-clockwise, ending at the cut point
    assert start == (0.0, 0.0, 0.0) and end == pytest.approx((*CUT, 0.0))
    assert spec.center == pytest.approx((-50.0, 0.0)) and not spec.cw and spec.radius == pytest.approx(50.0)
    assert r["motion"]["arc_moves"] == 1 and r["motion"]["feed_length"] == pytest.approx(S_05)
    # the cut arc, timed rest to rest, takes 36.8 / 80 + 0.08 = 0.54 s (>= the input's 0.5 s)
    assert r["cycle_time_s"] == pytest.approx(S_05 / V + V / A)


def test_next_block_starts_at_the_point_reached(tmp_path):
    # G1 X0 keeps Y at the cut point: (0, 33.566433)
    r, s = _ok(tmp_path, "%MPF1\nG17 G90 F4800\n@736 K0 K1 K3 G3 X-50 Y50 I-50 J0\nG1 X0\nM30\n", _event(0.5))
    assert _xy(r) == pytest.approx((0.0, CUT[1]))
    assert tuple(s.recorder.arrays()["start"][1]) == pytest.approx((*CUT, 0.0))


def test_position_reached_when_the_input_does_not_come(tmp_path):
    # the whole quarter circle: 25 pi = 78.539816 mm in 0.981748 + 0.08 = 1.061748 s (ramps at an axis's 1000 mm/s^2)
    r, s = _ok(tmp_path, "%MPF1\nG17 G90 F4800\n@736 K0 K1 K3 G3 X-50 Y50 I-50 J0\nM30\n")
    assert _xy(r) == pytest.approx((-50.0, 50.0))
    assert r["cycle_time_s"] == pytest.approx(1.061748, abs=1e-6)
    assert _arc(s)[2].center == pytest.approx((-50.0, 0.0))


def test_input_already_at_the_level_moves_nothing(tmp_path):
    r, _s = _ok(tmp_path, "%MPF1\nG17 G90 F4800\n@736 K0 K1 K3 G3 X-50 Y50 I-50 J0\nM30\n",
                'inputs = { "1" = "00001000" }\n')
    assert _xy(r) == (0.0, 0.0) and r["motion"]["arc_moves"] == 0


def test_radius_word_and_incremental_words(tmp_path):
    # G91 G2 X50 Y-50 B50: clockwise quarter circle of the short way, centre (0, -50), from 90 to 0 degrees.
    # Stopped at 90 degrees - PHI: (50 sin PHI, -50 + 50 cos PHI) = (33.566433, -12.942010); G1 X10 then
    # goes on from there.
    r, s = _ok(tmp_path, "%MPF1\nG17 G91 F4800\n@736 K1 K1 K3 G2 X50 Y-50 B50\nG1 X10\nM30\n", _event(0.5))
    assert _xy(r) == pytest.approx((CUT[1] + 10.0, CUT[0]))
    _start, end, spec = _arc(s)
    assert end == pytest.approx((CUT[1], CUT[0], 0.0))
    assert spec.center == pytest.approx((0.0, -50.0)) and spec.cw


def test_axis_not_programmed_but_interpolating_stops_the_arc(tmp_path):
    # G2 X-100 I-50: half circle clockwise about (-50, 0) through (-50, -50); Y has no word but moves with X,
    # so INTA for Y (axis 2) cuts it at -PHI: (-50 + 50 cos PHI, -50 sin PHI)
    r, _s = _ok(tmp_path, "%MPF1\nG17 G90 F4800\n@736 K2 K1 K3 G2 X-100 I-50\nM30\n", _event(0.5))
    assert _xy(r) == pytest.approx((CUT[0], -CUT[1]))


def test_axis_outside_the_arc_does_not_stop_it(tmp_path):
    r, _s = _ok(tmp_path, "%MPF1\nG17 G90 F4800\n@736 K3 K1 K3 G3 X-50 Y50 I-50 J0\nM30\n", _event(0.5))
    assert _xy(r) == pytest.approx((-50.0, 50.0))


def test_helix_stops_at_the_same_fraction_of_angle_and_height(tmp_path):
    # G3 X-50 Y50 Z30 I-50 J0: length hypot(25 pi, 30) = 84.074388 mm, of which the plane's share is
    # p = 25 pi / 84.074388 = 0.934171 (a helix has a constant pitch). X and Y then carry p of the path's
    # speed and ramp at most: v = 80 mm/s stays under 83.333 / p, the ramp is 1000 / p = 1070.468 mm/s^2
    # (Z's share 30 / 84.074388 lets it 2802 mm/s^2). At 0.5 s the path has covered 40 - 80^2 / (2 * 1070.468)
    # = 37.010654 mm, the fraction f = 0.440213 of it: angle f pi / 2, Z = 30 f
    length = math.hypot(25.0 * math.pi, 30.0)
    f = (V * 0.5 - V * V / (2 * A * length / (25.0 * math.pi))) / length
    assert (length, f) == (pytest.approx(84.074388), pytest.approx(0.440213))
    r, s = _ok(tmp_path, "%MPF1\nG17 G90 F4800\n@736 K0 K1 K3 G3 X-50 Y50 Z30 I-50 J0\nM30\n", _event(0.5))
    angle = f * math.pi / 2
    expected = (-50.0 + 50.0 * math.cos(angle), 50.0 * math.sin(angle), 30.0 * f)
    assert (r["position"]["X"], r["position"]["Y"], r["position"]["Z"]) == pytest.approx(expected)
    assert _arc(s)[2].center == pytest.approx((-50.0, 0.0))


def test_other_plane_g18(tmp_path):
    # G18: the plane Z (first), X (second), centre words K, I. G3 Z-50 X50 K-50 I0 is the same quarter circle
    # with Z for X and X for Y
    r, s = _ok(tmp_path, "%MPF1\nG18 G90 F4800\n@736 K1 K1 K3 G3 Z-50 X50 K-50 I0\nM30\n", _event(0.5))
    assert (r["position"]["Z"], r["position"]["X"]) == pytest.approx(CUT)
    assert _arc(s)[2].center == pytest.approx((-50.0, 0.0))


def test_full_circle_is_cut(tmp_path):
    # G3 I-50 J0: the full circle about (-50, 0) from (0, 0), 100 pi mm; at 0.5 s it is where the quarter
    # circle was
    r, s = _ok(tmp_path, "%MPF1\nG17 G90 F4800\n@736 K0 K1 K3 G3 I-50 J0\nM30\n", _event(0.5))
    assert _xy(r) == pytest.approx(CUT)
    assert _arc(s)[2].turns == 0


def test_cut_in_the_second_pass_of_a_multi_turn_circle(tmp_path):
    # G3 I-50 J0 P2 (two full circles as the kernel reads P): at 5 s the path has covered 400 - 3.2 =
    # 396.8 mm = 2 pi + 1.652815 rad; the cut arc keeps one full turn
    phi = (V * 5.0 - RAMP) / 50.0
    assert phi - 2 * math.pi == pytest.approx(1.652815, abs=1e-6)
    r, s = _ok(tmp_path, "%MPF1\nG17 G90 F4800\n@736 K0 K1 K3 G3 I-50 J0 P2\nM30\n", _event(5.0))
    assert _xy(r) == pytest.approx((-50.0 + 50.0 * math.cos(phi), 50.0 * math.sin(phi)))
    assert _arc(s)[2].turns == 1
    assert r["motion"]["feed_length"] == pytest.approx(V * 5.0 - RAMP)


ROT_90 = "rotation = { settable = [90.0, 0.0, 0.0, 0.0] }\n"


def test_arc_under_a_coordinate_rotation(tmp_path):
    # G54 turned by 90 degrees: the program's quarter circle about (-50, 0) runs about the machine point
    # (0, -50), from (0, 0) to (-50, -50). The cut point is CUT in the program's frame, turned:
    # (-33.566433, -12.942010). G91 X10 in the program's frame then gives the program point
    # (-2.942010, 33.566433) = machine (-33.566433, -2.942010).
    r, s = _ok(tmp_path, "%MPF1\nG54 G17 G90 F4800\n@736 K0 K1 K3 G3 X-50 Y50 I-50 J0\n@714 @361 R1 K1 "
                         "@361 R2 K2\nG1 G91 X10\nM30\n", ROT_90 + _event(0.5))
    assert (r["variables"]["R1"], r["variables"]["R2"]) == pytest.approx((-CUT[1], CUT[0]))
    assert _xy(r) == pytest.approx((-CUT[1], CUT[0] + 10.0))
    _start, end, spec = _arc(s)
    assert end == pytest.approx((-CUT[1], CUT[0], 0.0))
    assert spec.center == pytest.approx((0.0, -50.0)) and not spec.cw


def test_incremental_arc_under_a_coordinate_rotation(tmp_path):
    # the same arc as increments and a centre vector in the program's frame: the cut block's increments
    # and centre are turned back into that frame before the kernel turns them again
    r, s = _ok(tmp_path, "%MPF1\nG54 G17 G91 F4800\n@736 K0 K1 K3 G3 X-50 Y50 I-50 J0\nM30\n",
               ROT_90 + _event(0.5))
    assert _xy(r) == pytest.approx((-CUT[1], CUT[0]))
    assert _arc(s)[2].center == pytest.approx((0.0, -50.0))


XZ_MACHINE = machine("XZ")


@pytest.mark.parametrize("machine, text, code", [
    (XZ_MACHINE, "G17 G90 F4800\n@736 K1 K1 K3 G2 X10 Z10 I5 K5", "NC004"),  # G17 on a machine without Y
    (MACHINE, "G17 G90 F4800\n@736 K1 K1 K3 G2 X100 Y0 B10", "NC002"),  # radius too short for the chord
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
