"""Rotary axes in translational interpolations (effradius, MODEREG bit 10 RotatoricUnit, L1401, L1450) and
JA the shorter way round (bit 9 ShortestRotatoricDistance, L1400).

By hand: A4 is a rotary axis (deg), A4.effradius = 10 mm; TRVL 10 mm/s, TRAC 100 mm/s^2, PU = mm. A path of
L mm from rest to rest takes 0.1 s + (L - 1) / 10 s + 0.1 s. Statements add a few ticks (tolerance 8).
"""

from __future__ import annotations

import math

import pytest

SEC = 15625
ROTARY = '[[axis]]\nname = "C"\nkind = "rotary"\nmin = -100000.0\nmax = 100000.0\n'
HEAD = "CL(A1, A2, A4); TRVL := 10.0; TRAC := 100.0; A4.effradius := 10.0;"


def run(sap, body: str):
    r = sap(f"program T;\nvar t0: integer; x, v: double;\nbegin\n{HEAD}\n{body}\nend.\n", ROTARY)
    assert r["status"] == "ok", r["error"]
    return r["output"], r


def test_rotary_travel_is_a_length_on_the_surface(sap):
    # A4 := 40 mm on a radius of 10 mm: 4 rad = 229.183 deg; the path is sqrt(30^2 + 40^2) = 50 mm: 5.1 s.
    # While cruising A4 turns at 10 mm/s * (229.183 deg / 50 mm) = 45.837 deg/s.
    out, r = run(sap, """t0 := CLOCK; MLR(A1 := 30.0, A4 := 40.0);
repeat until CLOCK - t0 >= 31250;
v := A4.dv;
repeat until A1.axstb.1 and A4.axstb.1;
writeln(CLOCK - t0, ' ', v, ' ', A4.dp);""")
    t, v, c = out[0].split()
    deg = math.degrees(40.0 / 10.0)
    assert int(t) == pytest.approx(5.1 * SEC, abs=8)
    assert float(v) == pytest.approx(10.0 * deg / 50.0, rel=1e-6)
    assert float(c) == pytest.approx(deg, abs=0.001)


def test_rotatoric_unit_takes_the_rotary_axis_in_degrees(sap):
    # MODEREG bit 10: A4 := 180 is 180 deg; the path still counts its surface, 10 mm * pi = 31.416 mm:
    # L = sqrt(30^2 + (10 pi)^2) = 43.439 mm
    out, r = run(sap, """MODEREG := $400; t0 := CLOCK; MLRW(A1 := 30.0, A4 := 180.0);
writeln(CLOCK - t0, ' ', A4.dp);""")
    t, c = out[0].split()
    L = math.hypot(30.0, 10.0 * math.pi)
    assert int(t) == pytest.approx((0.2 + (L - 1.0) / 10.0) * SEC, abs=8)
    assert float(c) == pytest.approx(180.0)


def test_absolute_rotary_target_under_a_length_unit(sap):
    # MLA: A4 := 10 mm on the surface = 1 rad from the zero point
    out, _ = run(sap, "MLAW(A1 := 0.0, A4 := 10.0);\nwriteln(A4.dp);")
    assert float(out[0]) == pytest.approx(math.degrees(1.0), abs=0.001)


def test_rotary_unit_pu_is_not_converted(sap):
    # PU = 4 (deg): not a translational interpolation, A4 := 90 deg at 10 deg/s: 0.1 + 8.9 + 0.1 = 9.1 s
    out, _ = run(sap, "PU := 4; t0 := CLOCK; MLRW(A4 := 90.0);\nwriteln(CLOCK - t0, ' ', A4.dp);")
    t, c = out[0].split()
    assert int(t) == pytest.approx(9.1 * SEC, abs=8)
    assert float(c) == pytest.approx(90.0)


def test_effradius_zero_is_a_wrong_parameter(sap):
    r = sap("program T;\nbegin\nA4.effradius := 0.0;\nMLRW(A1 := 1.0, A4 := 1.0);\nend.\n", ROTARY)
    assert r["status"] == "error"
    assert r["error"]["code"] == "256"


def test_shortest_rotatoric_distance(sap):
    # from 0 deg, JA to 350 deg: the long way without bit 9; with it -10 deg (20 deg travel instead of 350)
    out, _ = run(sap, """A4.jvl := 100.0; A4.jac := 1000.0;
JAW(A4 := 350.0); x := A4.dp; JAW(A4 := 0.0);
MODEREG := $200; JAW(A4 := 350.0); v := A4.dp; JAW(A4 := 20.0);
writeln(x, ' ', v, ' ', A4.dp);""")
    assert [float(s) for s in out[0].split()] == pytest.approx([350.0, -10.0, 20.0])


def test_nfrax_axis_velocity_is_its_share_of_the_path(sap):
    # NFRAX bit 1 leaves A2 out of the path: L = 30 mm (A1); cruising at 10 mm/s, A2 covers 40 mm meanwhile:
    # A1.dv = 10, A2.dv = 10 * 40 / 30
    out, _ = run(sap, """NFRAX := 2; t0 := CLOCK; MLR(A1 := 30.0, A2 := 40.0);
repeat until CLOCK - t0 >= 15625;
writeln(A1.dv, ' ', A2.dv);""")
    assert [float(s) for s in out[0].split()] == pytest.approx([10.0, 40.0 / 3.0])


def test_circle_on_the_surface_of_a_rotary_axis(sap):
    # MCR(A1 := 0, A4 := 5) with PHI 90: the centre lies 5 mm along the surface of A4 (effradius 10 mm);
    # the quarter circle of R = 5 mm ends at A1 = 5 mm, A4 = 5 mm on the surface = 0.5 rad = 28.648 deg.
    # Length 5 * pi / 2 = 7.854 mm: 0.1 + (7.854 - 1) / 10 + 0.1 s. Reported as 18 feeds of 5 degrees.
    out, r = run(sap, """PHI := 90.0; t0 := CLOCK; MCRW(A1 := 0.0, A4 := 5.0);
writeln(CLOCK - t0, ' ', A1.dp, ' ', A4.dp);""")
    t, x, c = out[0].split()
    assert int(t) == pytest.approx((0.2 + (2.5 * math.pi - 1.0) / 10.0) * SEC, abs=8)
    assert float(x) == pytest.approx(5.0)
    assert float(c) == pytest.approx(math.degrees(0.5), abs=0.001)
    assert (r["motion"]["arc_moves"], r["motion"]["feed_moves"]) == (0, 18)


def test_lookahead_circle_limit_on_a_surface_uses_the_rotary_acceleration_there(sap):
    # spooled full circle R = 1 mm in the A1/A4 surface plane, LookAhead: v <= sqrt(R * a) with a the smaller of
    # A1.maxacc = 1000 mm/s^2 and A4.maxacc = 90 deg/s^2 * (10 mm * pi / 180 per deg) = 15.708 mm/s^2:
    # v = 3.963 mm/s; TRAC 100: 2 ramps of v / 100 s, cruise (2 pi - v^2 / 100) / v
    out, _ = run(sap, """PHI := 360.0; MODEREG := 1; A1.maxacc := 1000.0; A4.maxacc := 90.0; t0 := CLOCK;
SMCR(A1 := 1.0, A4 := 0.0); SSMSW(A1, A4);
writeln(CLOCK - t0);""")
    v = math.sqrt(1.0 * 90.0 * 10.0 * math.pi / 180.0)
    assert int(out[0]) == pytest.approx((2 * v / 100.0 + (2 * math.pi - v * v / 100.0) / v) * SEC, abs=8)
