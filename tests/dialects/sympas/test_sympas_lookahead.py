"""Velocity chaining of spooled segments: TRTVL at the joints, LookAhead, ChkMaxVel (rw_SymPas manual L1391-1398).

All figures by hand: TRVL = 10 mm/s, TRAC = 100 mm/s^2 unless stated; 15625 ticks = 1 s. The
program's own statements add a few ticks around each measured motion (tolerance 8 ticks).
"""

from __future__ import annotations

import pytest

SEC = 15625


def prog(body: str) -> str:
    return f"program T;\nvar t0, t1: integer; x, y: double;\nbegin\nCL(A1, A2);\n{body}\nend.\n"


def timed(sap, setup: str, moves: str, axes: str = "A1"):
    r = sap(prog(f"{setup}\nt0 := CLOCK;\n{moves}\nSSMSW({axes});\nt1 := CLOCK - t0;\nwriteln(t1);"))
    assert r["status"] == "ok", r["error"]
    return int(r["output"][0])


def test_rest_to_rest_without_target_velocity(sap):
    # TRTVL = 0: each 10 mm segment accelerates 0.1 s (0.5 mm), cruises 0.9 s, brakes 0.1 s = 1.1 s
    t = timed(sap, "TRVL := 10.0; TRAC := 100.0;", "SMLR(A1 := 10.0); SMLR(A1 := 10.0);")
    assert t == pytest.approx(2.2 * SEC, abs=8)


def test_collinear_segments_join_at_target_velocity(sap):
    # TRTVL = 10: segment 1 accelerates 0.1 s then cruises 9.5 mm (0.95 s) = 1.05 s, segment 2 mirrors it
    t = timed(sap, "TRVL := 10.0; TRAC := 100.0; TRTVL := 10.0;", "SMLR(A1 := 10.0); SMLR(A1 := 10.0);")
    assert t == pytest.approx(2.1 * SEC, abs=8)


def test_axes_do_not_stop_at_the_joint(sap):
    # at 1.05 s (the joint) A1 stands at 10 mm moving at 10 mm/s
    r = sap(prog("TRVL := 10.0; TRAC := 100.0; TRTVL := 10.0;\nt0 := CLOCK;\n"
                 "SMLR(A1 := 10.0); SMLR(A1 := 10.0); SSMS(A1);\n"
                 "repeat until CLOCK - t0 >= 16406;\nx := A1.dp; y := A1.dv;\nSSMSW(A1);\n"
                 "writeln(x, ' ', y);"))
    x, v = (float(s) for s in r["output"][0].split())
    assert x == pytest.approx(10.0, abs=0.003)
    assert v == pytest.approx(10.0, abs=1e-6)
    assert r["position"]["A1"] == pytest.approx(20.0)


def test_target_velocity_limited_by_what_the_next_segment_can_brake(sap):
    # TRTVL = 10 but segment 2 is 0.125 mm: from v it brakes to 0 within 0.125 mm -> v = sqrt(2*100*0.125) = 5.
    # segment 1: 0 -> 10 in 0.1 s (0.5 mm), 10 -> 5 in 0.05 s (0.375 mm), cruise 9.125 mm (0.9125 s) = 1.0625 s;
    # segment 2: 5 -> 0 in 0.05 s.
    t = timed(sap, "TRVL := 10.0; TRAC := 100.0; TRTVL := 10.0;", "SMLR(A1 := 10.0); SMLR(A1 := 0.125);")
    assert t == pytest.approx(1.1125 * SEC, abs=8)


def test_lookahead_limits_the_corner_by_mdvel(sap):
    # 90 deg corner X then Y: each axis jumps by v at the joint; mdvel = 5 -> joint 5 mm/s.
    # each segment: 0.1 s (0.5 mm) + brake 10 -> 5: 0.05 s (0.375 mm) + cruise 9.125 mm (0.9125 s) = 1.0625 s
    t = timed(sap, "TRVL := 10.0; TRAC := 100.0; TRTVL := 10.0; MODEREG := 1; A1.mdvel := 5.0; A2.mdvel := 5.0;",
              "SMLR(A1 := 10.0); SMLR(A2 := 10.0);", "A1, A2")
    assert t == pytest.approx(2.125 * SEC, abs=8)


def test_without_lookahead_the_corner_runs_at_the_target_velocity(sap):
    # no LookAhead: the joint velocity is TRTVL itself, as on the collinear path: 2 x 1.05 s
    t = timed(sap, "TRVL := 10.0; TRAC := 100.0; TRTVL := 10.0; A1.mdvel := 5.0; A2.mdvel := 5.0;",
              "SMLR(A1 := 10.0); SMLR(A2 := 10.0);", "A1, A2")
    assert t == pytest.approx(2.1 * SEC, abs=8)


def test_lookahead_mdvel_zero_stops_at_a_corner(sap):
    t = timed(sap, "TRVL := 10.0; TRAC := 100.0; TRTVL := 10.0; MODEREG := 1; A1.mdvel := 0.0; A2.mdvel := 0.0;",
              "SMLR(A1 := 10.0); SMLR(A2 := 10.0);", "A1, A2")
    assert t == pytest.approx(2.2 * SEC, abs=8)


def test_lookahead_limits_circle_velocity(sap):
    # full circle R = 1 (PHI = 360): v <= sqrt(R * maxacc) = sqrt(1 * 25) = 5 mm/s; length 2*pi.
    # TRAC = 100: 0.05 s up (0.125 mm), 0.05 s down, cruise (2*pi - 0.25) / 5
    import math
    t = timed(sap, "TRVL := 10.0; TRAC := 100.0; PHI := 360.0; MODEREG := 1; A1.maxacc := 25.0; A2.maxacc := 25.0;",
              "SMCR(A1 := 1.0, A2 := 0.0);", "A1, A2")
    assert t == pytest.approx((0.1 + (2 * math.pi - 0.25) / 5.0) * SEC, abs=8)


def test_chkmaxvel_scales_velocity_and_acceleration(sap):
    # TRVL 100, TRAC 1000 would take 0.2 s for 10 mm; maxvel 10, maxacc 100 make it 1.1 s
    fast = timed(sap, "TRVL := 100.0; TRAC := 1000.0; A1.maxvel := 10.0; A1.maxacc := 100.0;", "SMLR(A1 := 10.0);")
    slow = timed(sap, "TRVL := 100.0; TRAC := 1000.0; A1.maxvel := 10.0; A1.maxacc := 100.0; MODEREG := $80;",
                 "SMLR(A1 := 10.0);")
    assert fast == pytest.approx(0.2 * SEC, abs=8)
    assert slow == pytest.approx(1.1 * SEC, abs=8)


def test_chkmaxvel_on_a_diagonal_uses_the_axis_share(sap):
    # 30/40 mm diagonal (length 50): A2 carries 0.8 of the path -> v <= 10 / 0.8 = 12.5, a <= 100 / 0.8 = 125.
    # 50 mm: 0.1 s up (0.625 mm), cruise 48.75 / 12.5 = 3.9 s, 0.1 s down -> 4.1 s
    t = timed(sap, "TRVL := 100.0; TRAC := 1000.0; A1.maxvel := 100.0; A1.maxacc := 1000.0;"
                   "A2.maxvel := 10.0; A2.maxacc := 100.0; MODEREG := $80;",
              "SMLR(A1 := 30.0, A2 := 40.0);", "A1, A2")
    assert t == pytest.approx(4.1 * SEC, abs=8)


def test_ms_stops_a_chain_in_its_running_segment(sap):
    # MS at 0.5 s (in segment 1 at 10 mm/s, s = 4.5 mm), sdec = 100: brakes 0.5 mm -> stands at 5.0 mm
    r = sap(prog("TRVL := 10.0; TRAC := 100.0; TRTVL := 10.0; A1.sdec := 100.0;\nt0 := CLOCK;\n"
                 "SMLR(A1 := 10.0); SMLR(A1 := 10.0); SSMS(A1);\n"
                 "repeat until CLOCK - t0 >= 7812;\nMSW(A1);\nwriteln(A1.dp);"))
    assert float(r["output"][0]) == pytest.approx(5.0, abs=0.01)
    assert r["position"]["A1"] == pytest.approx(5.0, abs=0.01)
    assert r["motion"]["feed_moves"] == 1


def test_line_circle_line_chain_with_ssf_between(sap):
    # X 10 mm, quarter circle R 5 (tangent at both joints, 7.854 mm), Y 10 mm, TRTVL 10 throughout:
    # 1.05 s + 0.7854 s + 1.05 s = 2.8854 s. The SSF after segment 1 writes CI1 when segment 1 ends (1.05 s).
    text = prog("""TRVL := 10.0; TRAC := 100.0; TRTVL := 10.0; PHI := 90.0;
t0 := CLOCK;
SMLR(A1 := 10.0); SSF(A1 := 42, SSFP = 1); SMCR(A1 := 0.0, A2 := 5.0); SMLR(A2 := 10.0);
SSMS(A1, A2);
repeat until CI1 = 42;
t1 := CLOCK - t0; x := A1.dp;
SSMSW(A1, A2);
writeln(t1, ' ', x, ' ', CLOCK - t0);""")
    r = sap(text)
    assert r["status"] == "ok", r["error"]
    t1, x, t2 = r["output"][0].split()
    assert int(t1) == pytest.approx(1.05 * SEC, abs=12)
    assert float(x) == pytest.approx(10.0, abs=0.005)
    assert int(t2) == pytest.approx((2.1 + 0.7854) * SEC, abs=8)
    assert (r["position"]["A1"], r["position"]["A2"]) == (pytest.approx(15.0), pytest.approx(15.0))
    assert (r["motion"]["feed_moves"], r["motion"]["arc_moves"]) == (2, 1)
