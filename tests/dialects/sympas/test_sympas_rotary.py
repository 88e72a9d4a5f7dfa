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
