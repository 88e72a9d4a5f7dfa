"""S-profiles (MODEREG bit 1, L1392; qualifier jerkrel L1462) and NoTriangle (bit 6, L1397).

S-profile (ncvm's reading; the rw_SymPas manual gives no scale): jerkrel r in 0..1 is the fraction of each acceleration / braking ramp
that is jerk-limited; the peak acceleration stays TRAC (jac, sdec), so a ramp from va to vb lasts
(vb - va) / (a (1 - r/2)) and, its acceleration curve being symmetric, covers (va + vb) / 2 of it.

Reference move: MLR(A1 := 20) at TRVL 10, TRAC 100. With r = 1 a ramp lasts 10 / 50 = 0.2 s and
covers 1 mm; 18 mm cruise take 1.8 s: 2.2 s in all. Within the first ramp (jerk 100 / 0.1 = 1000
mm/s^3 for 0.1 s): v = 500 t^2, s = 500 t^3 / 3.
"""

from __future__ import annotations

import math

import pytest

SEC = 15625


def timed_move(sap, jerkrel: float, moderegs: str = "2", move: str = "MLRW(A1 := 20.0);", setup: str = ""):
    text = f"""program T;
var t0, t1: integer;
begin
  CL(A1, A2); TRVL := 10.0; TRAC := 100.0; MODEREG := {moderegs}; A1.jerkrel := {jerkrel}; {setup}
  t0 := CLOCK;
  {move}
  t1 := CLOCK - t0;
  writeln(t1, ' ', A1.dp);
end.
"""
    r = sap(text)
    assert r["status"] == "ok", r["error"]
    t1, x = r["output"][0].split()
    return int(t1), float(x)


@pytest.mark.parametrize("jerkrel, seconds", [
    (1.0, 2.2),  # ramps of 0.2 s over 1 mm: 0.4 + 18 / 10
    (0.5, 2.0 / 15.0 * 2 + (20.0 - 2 * 100.0 / 150.0) / 10.0),  # a (1 - r/2) = 75: ramps 2/15 s, 2/3 mm
    (0.0, 2.1),  # jerkrel 0: the trapezoid
])
def test_s_ramps_stretch_the_move(sap, jerkrel, seconds):
    t1, x = timed_move(sap, jerkrel)
    assert t1 == pytest.approx(seconds * SEC, abs=3)
    assert x == pytest.approx(20.0)


def test_without_the_moderegister_bit_jerkrel_does_nothing(sap):
    t1, _ = timed_move(sap, 1.0, moderegs="0")
    assert t1 == pytest.approx(2.1 * SEC, abs=3)


def test_the_ramp_is_s_shaped(sap):
    # the recording (LPR, 1.28 ms apart) of the first ramp: v = 500 t^2 up to 0.1 s, then 10 - 500 (0.2 - t)^2
    text = """program T;
var c0: integer;
begin
  CL(A1); TRVL := 10.0; TRAC := 100.0; MODEREG := 2; A1.jerkrel := 1.0; LST := 0.0; LET := 0.0;
  c0 := CLOCK;
  LPR(A1);
  MLRW(A1 := 20.0);
  writeln(c0);
end.
"""
    r = sap(text)
    assert r["status"] == "ok", r["error"]
    call, move = int(r["output"][0]) + 1, int(r["output"][0]) + 2
    first = math.ceil(call / 20) * 20
    samples = r["recordings"]["A1"]["samples"]
    for i in (10, 39, 40, 80, 150, 156):
        t = (first + 20 * i - move) / SEC
        if t < 0.1:
            v, s = 500.0 * t * t, 500.0 * t ** 3 / 3.0
        elif t < 0.2:
            rho = 0.2 - t
            v, s = 10.0 - 500.0 * rho * rho, 1.0 - (10.0 * rho - 500.0 * rho ** 3 / 3.0)
        else:
            v, s = 10.0, 1.0 + 10.0 * (t - 0.2)
        assert samples[i][3] == pytest.approx(v, abs=1e-9)
        assert samples[i][1] == pytest.approx(s, abs=1e-9)


def test_a_short_s_move_is_a_triangle_of_two_s_ramps(sap):
    # 0.5 mm cannot reach 10 mm/s: peak sqrt(50 * 0.5) = 5 mm/s, two ramps of 5 / 50 = 0.1 s
    t1, x = timed_move(sap, 1.0, move="MLRW(A1 := 0.5);")
    assert t1 == pytest.approx(0.2 * SEC, abs=3)
    assert x == pytest.approx(0.5)


def test_a_stop_brakes_s_shaped(sap):
    # JSW at 1.0 s (9 mm: 1 mm ramp + 0.8 s at 10 mm/s) with sdec 100: 10 / 50 = 0.2 s over 1 mm -> 10 mm
    t1, x = timed_move(sap, 1.0, move="MLR(A1 := 20.0); repeat until CLOCK - t0 >= 15625; JSW(A1);",
                       setup="A1.sdec := 100.0;")
    assert x == pytest.approx(10.0, abs=2e-3)
    assert t1 == pytest.approx(1.2 * SEC, abs=4)


def test_jogs_ramp_s_shaped_too(sap):
    t1, x = timed_move(sap, 1.0, move="JRW(A1 := 20.0);", setup="A1.jvl := 10.0; A1.jac := 100.0;")
    assert t1 == pytest.approx(2.2 * SEC, abs=3)
    assert x == pytest.approx(20.0)


def test_a_spooled_chain_ramps_s_shaped(sap):
    # two 10 mm segments joined at TRTVL 10: a 0.2 s ramp up, 18 mm at 10 mm/s, a 0.2 s ramp down: 2.2 s
    t1, x = timed_move(sap, 1.0, move="SMLR(A1 := 10.0); SMLR(A1 := 10.0); SSMSW(A1);", setup="TRTVL := 10.0;")
    assert t1 == pytest.approx(2.2 * SEC, abs=5)
    assert x == pytest.approx(20.0)


# -- NoTriangle --------------------------------------------------------------------------------------
# A zigzag of four 1 mm segments X, Y, X, Y (each of both axes, so they share one spooler order) at TRVL 100, TRAC 1000, TRTVL 100 with LookAhead and
# mdvel 20: each 90 degree joint is limited to 20 mm/s (one axis stops, the other starts).
# Segment 1 from rest: up to sqrt(1000 + 200) = 34.64 and down to 20: 0.034641 + 0.014641 s.
# Without NoTriangle the middle segments are triangles 20 -> sqrt(1400) = 37.42 -> 20: 2 x 0.0174166 s
# each, and the last 20 -> 34.64 -> 0: 0.014641 + 0.034641 s. With it the middle ones keep 20 mm/s
# (1 / 20 = 0.05 s each) and the last one cruises at 20 and brakes over 0.2 mm: 0.04 + 0.02 s.
SEG1 = math.sqrt(1200.0) / 1000.0 + (math.sqrt(1200.0) - 20.0) / 1000.0
TRIANGLES = SEG1 + 2 * 2 * (math.sqrt(1400.0) - 20.0) / 1000.0 + SEG1
NO_TRIANGLES = SEG1 + 0.05 + 0.05 + 0.06

ZIGZAG = """program T;
var c0, t1: integer;
begin
  CL(A1, A2); TRVL := 100.0; TRAC := 1000.0; TRTVL := 100.0; A1.mdvel := 20.0; A2.mdvel := 20.0;
  MODEREG := {mode}; LST := 0.0; LET := 0.0;
  SMLR(A1 := 1.0, A2 := 0.0); SMLR(A1 := 0.0, A2 := 1.0); SMLR(A1 := 1.0, A2 := 0.0); SMLR(A1 := 0.0, A2 := 1.0);
  c0 := CLOCK;
  LPRS(A1, A2);
  SSMSW(A1, A2);
  t1 := CLOCK - c0;
  writeln(c0, ' ', t1, ' ', A1.dp, ' ', A2.dp);
end.
"""


@pytest.mark.parametrize("mode, seconds", [(0x1, TRIANGLES), (0x41, NO_TRIANGLES)])
def test_notriangle_keeps_the_start_velocity_of_short_segments(sap, mode, seconds):
    r = sap(ZIGZAG.format(mode=mode))
    assert r["status"] == "ok", r["error"]
    c0, t1, x, y = r["output"][0].split()
    assert int(t1) - 2 == pytest.approx(seconds * SEC, abs=2)  # SSMSW 2 ticks after c0 := CLOCK
    assert (float(x), float(y)) == (2.0, 2.0)
    if mode & 0x40:
        # all through segment 2 (A2 from 1 mm on, 0.0493 s .. 0.0993 s after the start) A2 runs at 20 mm/s
        start = int(c0) + 2
        call = int(c0) + 1
        first = math.ceil(call / 20) * 20
        a2 = r["recordings"]["A2"]["samples"]
        inside = [s for i, s in enumerate(a2) if SEG1 + 0.001 < (first + 20 * i - start) / SEC < SEG1 + 0.049]
        assert len(inside) > 30
        assert all(s[3] == pytest.approx(20.0) for s in inside)


def test_notriangle_needs_the_lookahead_mode(sap):
    # bit 6 alone: LookAhead is off, the joints are not limited by mdvel and NoTriangle does nothing
    r_plain = sap(ZIGZAG.format(mode=0))
    r_nt = sap(ZIGZAG.format(mode=0x40))
    assert r_plain["output"][0].split()[1] == r_nt["output"][0].split()[1]
