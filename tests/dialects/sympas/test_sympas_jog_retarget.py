"""A new JA/JR on a jogging axis re-targets it on the fly (ncvm's reading; the rw_SymPas manual gives JA's parameters only): it goes on from where it is
with the velocity it has, brakes with jac and turns back for a target behind its braking distance, and
slows down with jac to a lowered jvl.

By hand: jvl = 10 mm/s, jac = 100 mm/s^2, jtv = 0; 15625 ticks = 1 s. JA(A1 := 10) from 0: 0.1 s up (0.5 mm),
cruise 9 mm (0.9 s), 0.1 s down = 1.1 s; at 0.5 s it is at 4.5 mm with 10 mm/s. The statements of the
program add a few ticks after each "repeat until" (tolerance 8 ticks).
"""

from __future__ import annotations

import pytest

SEC = 15625
HEAD = "CL(A1, A2); A1.jvl := 10.0; A1.jac := 100.0; A1.sdec := 100.0;"


def run(sap, body: str):
    r = sap(f"program T;\nvar t0: integer; x, v: double;\nbegin\n{HEAD}\n{body}\nend.\n")
    assert r["status"] == "ok", r["error"]
    return r["output"], r


def test_farther_target_continues_without_stopping(sap):
    # at 0.5 s JA(A1 := 20): 15.5 mm left at 10 mm/s: cruise 15 mm (1.5 s) + 0.1 s braking -> ends at 2.1 s.
    # At 1.2 s (past the old target's stop) it moves at 10 mm/s through 11.5 mm.
    out, r = run(sap, """t0 := CLOCK; JA(A1 := 10.0);
repeat until CLOCK - t0 >= 7812;
JA(A1 := 20.0);
repeat until CLOCK - t0 >= 18750;
x := A1.dp; v := A1.dv;
JSW(A1); JAW(A1 := 20.0);
writeln(x, ' ', v);""")
    x, v = (float(s) for s in out[0].split())
    assert x == pytest.approx(11.5, abs=0.01)
    assert v == pytest.approx(10.0, abs=1e-6)
    assert r["position"]["A1"] == pytest.approx(20.0)


def test_retargeted_jog_ends_when_planned(sap):
    out, r = run(sap, """t0 := CLOCK; JA(A1 := 10.0);
repeat until CLOCK - t0 >= 7812;
JAW(A1 := 20.0);
writeln(CLOCK - t0);""")
    assert int(out[0]) == pytest.approx(2.1 * SEC, abs=8)
    assert r["position"]["A1"] == pytest.approx(20.0)


def test_jr_on_a_jogging_axis_counts_from_its_target(sap):
    # JR(A1 := 5) at 0.5 s: the new target is 10 + 5 = 15; 10.5 mm left: 1.0 s cruise + 0.1 s -> 1.6 s
    out, r = run(sap, """t0 := CLOCK; JA(A1 := 10.0);
repeat until CLOCK - t0 >= 7812;
JRW(A1 := 5.0);
writeln(CLOCK - t0);""")
    assert int(out[0]) == pytest.approx(1.6 * SEC, abs=8)
    assert r["position"]["A1"] == pytest.approx(15.0)


def test_target_behind_brakes_and_turns_back(sap):
    # JA(A1 := 0) at 0.5 s: it brakes from 10 mm/s with jac over 0.5 mm (0.1 s) and stands at 5.0 mm at 0.6 s,
    # then jogs back 5 mm rest to rest: 0.1 + 0.4 + 0.1 = 0.6 s -> at 0 after 1.2 s. At 0.55 s: +5 mm/s.
    out, r = run(sap, """t0 := CLOCK; JA(A1 := 10.0);
repeat until CLOCK - t0 >= 7812;
JA(A1 := 0.0);
repeat until CLOCK - t0 >= 8594;
v := A1.dv;
repeat until CLOCK - t0 >= 9375;
x := A1.dp;
repeat until A1.axstb.1;
writeln(x, ' ', v, ' ', CLOCK - t0);""")
    x, v, t = out[0].split()
    assert float(x) == pytest.approx(5.0, abs=0.005)
    assert float(v) == pytest.approx(5.0, abs=0.05)
    assert int(t) == pytest.approx(1.2 * SEC, abs=8)
    assert r["position"]["A1"] == pytest.approx(0.0)
    assert r["motion"]["rapid_moves"] == 3  # 0 -> 4.5, 4.5 -> 5.0, 5.0 -> 0


def test_lowered_jvl_slows_down_with_jac(sap):
    # at 0.5 s jvl := 5 and JA(A1 := 10) again: 10 -> 5 mm/s in 0.05 s over 0.375 mm (at 4.875 mm), then 5.125 mm:
    # cruise 5.0 mm (1.0 s) + 0.05 s braking -> 0.5 + 0.05 + 1.0 + 0.05 = 1.6 s
    out, _ = run(sap, """t0 := CLOCK; JA(A1 := 10.0);
repeat until CLOCK - t0 >= 7812;
A1.jvl := 5.0; JAW(A1 := 10.0);
writeln(CLOCK - t0);""")
    assert int(out[0]) == pytest.approx(1.6 * SEC, abs=8)


def test_a_home_search_is_not_retargeted(sap):
    # JHL runs toward the REF switch; a JA meanwhile is refused (axst bit 14, qualifier bit 15)
    r = sap("program T;\nbegin\nCL(A1);\nJHL(A1);\nJA(A1 := 5.0);\nwriteln(A1.axstb.15);\nJHLW(A1);\nend.\n",
            '[sympas]\nref_positions = { A1 = -5.0 }\n')
    assert r["status"] == "ok", r["error"]
    assert r["output"][0].endswith("prog.sap:5: profile refused: axis A1 is still in a profile (A1)")  # L1415
    assert r["output"][1] == "TRUE"
