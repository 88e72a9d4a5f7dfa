"""A spooled chain started (SSMS, AutoSpool) while an earlier chain of the same axes still runs joins it:
the spooler goes on without stopping, with the look-ahead's joint velocities (rw_SymPas manual L1391-1398).

By hand: TRVL = 10 mm/s, TRAC = 100 mm/s^2, TRTVL = 10 mm/s; 15625 ticks = 1 s. A 10 mm segment from rest
to 10 mm/s takes 0.1 s (0.5 mm) + 9.5 mm / 10 = 1.05 s; at 10 mm/s throughout 1.0 s; from 10 mm/s to rest
1.05 s; rest to rest 0.1 + 0.9 + 0.1 = 1.1 s. The program's own statements add a few ticks (tolerance 8).
"""

from __future__ import annotations

import pytest

SEC = 15625
SETUP = "TRVL := 10.0; TRAC := 100.0; TRTVL := 10.0;"


def prog(body: str) -> str:
    return f"program T;\nvar t0, t1, t2: integer; x, v: double;\nbegin\nCL(A1, A2);\n{SETUP}\n{body}\nend.\n"


def run(sap, body: str, machine: str | None = None):
    r = sap(prog(body), machine)
    assert r["status"] == "ok", r["error"]
    return r["output"][0].split(), r


def test_segment_spooled_during_the_cruise_continues_the_running_one(sap):
    # SSMS at 0.5 s: the running segment stands at 0.5 + 10 * 0.4 = 4.5 mm at 10 mm/s and is planned anew:
    # it no longer brakes, ends at 10 mm at 0.5 + 5.5 / 10 = 1.05 s with 10 mm/s, and the new one takes 1.05 s.
    # Together 2.1 s (two chains one after the other: 2 x 1.1 = 2.2 s). At 1.05 s A1 is at 10 mm, 10 mm/s.
    out, r = run(sap, """t0 := CLOCK;
SMLR(A1 := 10.0); SSMS(A1);
repeat until CLOCK - t0 >= 7812;
SMLR(A1 := 10.0); SSMS(A1);
repeat until CLOCK - t0 >= 16406;
x := A1.dp; v := A1.dv;
SSMSW(A1);
writeln(CLOCK - t0, ' ', x, ' ', v);""")
    assert int(out[0]) == pytest.approx(2.1 * SEC, abs=8)
    assert float(out[1]) == pytest.approx(10.0, abs=0.003)
    assert float(out[2]) == pytest.approx(10.0, abs=1e-6)
    assert r["position"]["A1"] == pytest.approx(20.0)
    assert r["motion"]["feed_moves"] == 2


def test_segment_spooled_during_the_final_ramp_starts_from_rest(sap):
    # SSMS at 1.05 s: the running segment brakes since 1.0 s and keeps its plan (rest at 1.1 s);
    # the new segment then runs rest to rest: 1.1 + 1.1 = 2.2 s. A1 is at 10 mm at rest at 1.1 s.
    out, r = run(sap, """t0 := CLOCK;
SMLR(A1 := 10.0); SSMS(A1);
repeat until CLOCK - t0 >= 16406;
SMLR(A1 := 10.0); SSMS(A1);
repeat until CLOCK - t0 >= 17188;
x := A1.dp; v := A1.dv;
SSMSW(A1);
writeln(CLOCK - t0, ' ', x, ' ', v);""")
    assert int(out[0]) == pytest.approx(2.2 * SEC, abs=8)
    # read a few ticks after 1.1 s: the new segment has just started from rest (100 mm/s^2 * 8 ticks = 0.05 mm/s)
    assert float(out[1]) == pytest.approx(10.0, abs=1e-4)
    assert 0.0 <= float(out[2]) <= 0.05
    assert r["position"]["A1"] == pytest.approx(20.0)


def test_waiting_segments_of_the_running_chain_are_planned_anew(sap):
    # chain 1 = two 10 mm segments (1.05 s + 1.05 s, the second braking to rest); at 0.5 s a third joins:
    # the second now runs through at 10 mm/s (1.0 s) and the third brakes: 1.05 + 1.0 + 1.05 = 3.1 s (not 3.2 s).
    out, _ = run(sap, """t0 := CLOCK;
SMLR(A1 := 10.0); SMLR(A1 := 10.0); SSMS(A1);
repeat until CLOCK - t0 >= 7812;
SMLR(A1 := 10.0); SSMS(A1);
repeat until CLOCK - t0 >= 32031;
x := A1.dp; v := A1.dv;
SSMSW(A1);
writeln(CLOCK - t0, ' ', x, ' ', v);""")
    assert int(out[0]) == pytest.approx(3.1 * SEC, abs=8)
    # at 2.05 s the axis passes 20 mm at 10 mm/s: the old second segment did not brake
    assert float(out[1]) == pytest.approx(20.0, abs=0.003)
    assert float(out[2]) == pytest.approx(10.0, abs=1e-6)


def test_autospool_keeps_the_axes_moving_across_spooler_refills(sap):
    # spool_capacity = 2: the spooler starts at every second SMLR (AutoSpool), the second start a few ticks
    # into the first segment's acceleration. Four 10 mm segments as one chain: 1.05 + 1.0 + 1.0 + 1.05 = 4.1 s
    # (two chains one after the other would take 2 x 2.1 = 4.2 s).
    out, r = run(sap, """MODEREG := $20; t0 := CLOCK;
SMLR(A1 := 10.0); SMLR(A1 := 10.0); SMLR(A1 := 10.0); SMLR(A1 := 10.0);
SSMSW(A1);
writeln(CLOCK - t0);""", "[sympas]\nspool_capacity = 2\n")
    assert int(out[0]) == pytest.approx(4.1 * SEC, abs=8)
    assert r["position"]["A1"] == pytest.approx(40.0)


def test_ssf_after_a_replanned_segment_acts_at_its_new_end(sap):
    # the SSF after segment 2 was due when segment 2 stopped (2.1 s); once segment 3 joins it runs through
    # and ends at 2.05 s, when CI1 becomes 42.
    out, _ = run(sap, """t0 := CLOCK;
SMLR(A1 := 10.0); SMLR(A1 := 10.0); SSF(A1 := 42, SSFP = 1); SSMS(A1);
repeat until CLOCK - t0 >= 7812;
SMLR(A1 := 10.0); SSMS(A1);
repeat until CI1 = 42;
t1 := CLOCK - t0;
SSMSW(A1);
writeln(t1, ' ', CLOCK - t0);""")
    assert int(out[0]) == pytest.approx(2.05 * SEC, abs=12)
    assert int(out[1]) == pytest.approx(3.1 * SEC, abs=8)


def test_a_stopped_chain_is_not_joined(sap):
    # MS at 0.5 s (sdec 100: stands at 5.0 mm at 0.6 s); the next SSMS starts a new chain from rest there:
    # 10 mm rest to rest, 1.1 s -> ends at 15 mm.
    out, r = run(sap, """A1.sdec := 100.0; t0 := CLOCK;
SMLR(A1 := 10.0); SSMS(A1);
repeat until CLOCK - t0 >= 7812;
MS(A1);
SMLR(A1 := 10.0); SSMSW(A1);
writeln(CLOCK - t0);""")
    assert int(out[0]) == pytest.approx(1.7 * SEC, abs=8)
    assert r["position"]["A1"] == pytest.approx(15.0, abs=0.01)


def test_s_profile_chain_joins_while_cruising(sap):
    # MODEREG bit 1, jerkrel 1: ramps plan with 100 * (1 - 1/2) = 50 mm/s^2: 0 -> 10 mm/s in 0.2 s over 1 mm.
    # Joined at 0.5 s (cruising): 0.2 + 9 / 10 = 1.1 s, then 1.1 s back to rest: 2.2 s (2 x 1.2 s apart).
    out, _ = run(sap, """MODEREG := 2; A1.jerkrel := 1.0; t0 := CLOCK;
SMLR(A1 := 10.0); SSMS(A1);
repeat until CLOCK - t0 >= 7812;
SMLR(A1 := 10.0); SSMSW(A1);
writeln(CLOCK - t0);""")
    assert int(out[0]) == pytest.approx(2.2 * SEC, abs=8)


def test_s_profile_segment_in_its_first_ramp_keeps_its_plan(sap):
    # joined at 0.1 s, inside the S-shaped ramp: the running segment keeps its plan (rest at 1.2 s), so the
    # acceleration does not jump; the new one runs rest to rest after it: 2.4 s.
    out, _ = run(sap, """MODEREG := 2; A1.jerkrel := 1.0; t0 := CLOCK;
SMLR(A1 := 10.0); SSMS(A1);
repeat until CLOCK - t0 >= 1562;
SMLR(A1 := 10.0); SSMSW(A1);
writeln(CLOCK - t0);""")
    assert int(out[0]) == pytest.approx(2.4 * SEC, abs=8)


def test_ms_stops_a_joined_chain_in_its_running_segment(sap):
    # joined at 0.5 s; at 1.2 s the second segment cruises at 10 mm/s through 10 + 1.5 = 11.5 mm;
    # MS with sdec 100 brakes over 0.5 mm: stands at 12.0 mm.
    out, r = run(sap, """A1.sdec := 100.0; t0 := CLOCK;
SMLR(A1 := 10.0); SSMS(A1);
repeat until CLOCK - t0 >= 7812;
SMLR(A1 := 10.0); SSMS(A1);
repeat until CLOCK - t0 >= 18750;
MSW(A1);
writeln(A1.dp);""")
    assert float(out[0]) == pytest.approx(12.0, abs=0.01)
    assert r["position"]["A1"] == pytest.approx(12.0, abs=0.01)


def test_a_fault_while_joining_leaves_the_running_chain(sap):
    # the second segment was spooled under PU = 9 (no position unit): error 256 at the SSMS that joins it;
    # the running segment still ends at 10 mm.
    r = sap(prog("""t0 := CLOCK;
SMLR(A1 := 10.0); SSMS(A1);
repeat until CLOCK - t0 >= 7812;
PU := 9; SMLR(A1 := 10.0); SSMS(A1);"""))
    assert r["status"] == "error"
    assert r["error"]["code"] == "256"
    assert r["position"]["A1"] == pytest.approx(10.0)
    assert r["motion"]["feed_moves"] == 1  # the running segment is reported


def test_chain_under_a_settled_override_is_joined(sap):
    # TROVR 0.5 from 0.2 s (TROVRST 0): the segment, at 1.5 mm, goes on at 5 mm/s (its profile time at half
    # rate). Joined at 0.5 s (at 3.0 mm): it runs its last 7 mm at 5 mm/s (1.4 s, to 1.9 s) into the new
    # segment, planned at TRVL * 0.5 = 5 mm/s with the joint TRTVL * 0.5 = 5 mm/s: 9.875 mm at 5 mm/s
    # (1.975 s) and 0.05 s braking with TRAC: ends at 1.9 + 2.025 = 3.925 s (from rest it would be 4.05 s).
    out, r = run(sap, """t0 := CLOCK;
SMLR(A1 := 10.0); SSMS(A1);
repeat until CLOCK - t0 >= 3125;
TROVR := 0.5; TROVRST := 0.0; UTROVR(A1);
repeat until CLOCK - t0 >= 7812;
SMLR(A1 := 10.0); SSMS(A1);
repeat until CLOCK - t0 >= 29688;
x := A1.dp; v := A1.dv;
SSMSW(A1);
writeln(CLOCK - t0, ' ', x, ' ', v);""")
    assert int(out[0]) == pytest.approx(3.925 * SEC, abs=8)
    assert float(out[1]) == pytest.approx(10.0, abs=0.003)  # at 1.9 s
    assert float(out[2]) == pytest.approx(5.0, abs=1e-6)
    assert r["position"]["A1"] == pytest.approx(20.0)


def test_chain_during_an_override_ramp_is_not_joined(sap):
    # TROVRST 1 s from 0.2 s: the override ramp still runs at 0.5 s, so the new segment starts after the
    # chain, from rest. Segment 1 (1.1 s of profile time, braking from 1.0 s): its profile time reaches
    # 0.2 + (1 - 0.25) = 0.95 s at 1.2 s (rate 1 -> 0.5 linearly), then 1.1 s at 1.2 + 0.15 / 0.5 = 1.5 s.
    # Segment 2, planned at 5 mm/s: 0.05 + 9.75 / 5 + 0.05 = 2.05 s -> 3.55 s.
    out, r = run(sap, """t0 := CLOCK;
SMLR(A1 := 10.0); SSMS(A1);
repeat until CLOCK - t0 >= 3125;
TROVR := 0.5; TROVRST := 1.0; UTROVR(A1);
repeat until CLOCK - t0 >= 7812;
SMLR(A1 := 10.0); SSMSW(A1);
writeln(CLOCK - t0);""")
    assert int(out[0]) == pytest.approx(3.55 * SEC, abs=8)
    assert r["position"]["A1"] == pytest.approx(20.0)


def test_override_ramp_across_segments_planned_under_different_overrides(sap):
    # as above (joined at 0.5 s under TROVR 0.5: at 1.5 s A1 is at 3.0 + 5 * 1.0 = 8.0 mm at 5 mm/s), then
    # TROVR 1 over TROVRST 1 s from 1.5 s: the override is 0.5 + 0.5 * tau on both segments (the first was
    # planned at 1, the second at 0.5), so the path runs at 10 * (0.5 + 0.5 * tau) mm/s across the joint:
    # at 2.5 s A1 is at 8 + 5 + 2.5 = 15.5 mm with 10 mm/s. The rest, 4.5 mm: 0.125 mm of braking from
    # profile velocity 5 at twice the rate (0.025 s) and 4.375 mm at 10 mm/s (0.4375 s) -> ends at 2.9625 s.
    out, _ = run(sap, """t0 := CLOCK;
SMLR(A1 := 10.0); SSMS(A1);
repeat until CLOCK - t0 >= 3125;
TROVR := 0.5; TROVRST := 0.0; UTROVR(A1);
repeat until CLOCK - t0 >= 7812;
SMLR(A1 := 10.0); SSMS(A1);
repeat until CLOCK - t0 >= 23438;
TROVR := 1.0; TROVRST := 1.0; UTROVR(A1);
repeat until CLOCK - t0 >= 39062;
x := A1.dp; v := A1.dv;
SSMSW(A1);
writeln(CLOCK - t0, ' ', x, ' ', v);""")
    t, x, v = out
    assert float(x) == pytest.approx(15.5, abs=0.01)
    assert float(v) == pytest.approx(10.0, abs=0.01)
    assert int(t) == pytest.approx(2.9625 * SEC, abs=8)


def test_autospool_enters_further_profiles_when_memory_is_free(sap):
    # spool_capacity = 4 (L1396: "Weitere Profile werden nur eingetragen, wenn wieder Speicherplatz frei ist"):
    # the 4th SMLR fills the spooler and starts it; the 5th waits until segment 1 is done (1.05 s), the 6th
    # until segment 2 is done (2.05 s); each joins the running chain. Then segments 3..6 hold the spooler:
    # lsm = 0, mcis = 4. All six as one chain: 1.05 + 4 * 1.0 + 1.05 = 6.1 s.
    r = sap(prog("""MODEREG := $20; t0 := CLOCK;
SMLR(A1 := 10.0); SMLR(A1 := 10.0); SMLR(A1 := 10.0); SMLR(A1 := 10.0);
t1 := CLOCK - t0;
SMLR(A1 := 10.0);
t2 := CLOCK - t0;
SMLR(A1 := 10.0);
writeln(t1, ' ', t2, ' ', CLOCK - t0, ' ', A1.lsm, ' ', A1.mcis);
SSMSW(A1);
writeln(CLOCK - t0, ' ', A1.lsm, ' ', A1.mcis);"""), "[sympas]\nspool_capacity = 4\n")
    assert r["status"] == "ok", r["error"]
    t1, t2, t3, lsm, mcis = (int(x) for x in r["output"][0].split())
    assert t1 < 8
    assert t2 == pytest.approx(1.05 * SEC, abs=8)
    assert t3 == pytest.approx(2.05 * SEC, abs=8)
    assert (lsm, mcis) == (0, 4)
    t, lsm, mcis = (int(x) for x in r["output"][1].split())
    assert t == pytest.approx(6.1 * SEC, abs=8)
    assert (lsm, mcis) == (4 * 64, 0)
    assert r["position"]["A1"] == pytest.approx(60.0)


def test_autospool_refills_run_as_one_chain(sap):
    # eight 1 mm segments through a spooler of 4: each refill joins while the chain cruises, so the path is the
    # one of a single 8 mm chain: 0.1 s up (0.5 mm), 7 mm at 10 mm/s (0.7 s), 0.1 s down = 0.9 s.
    # (the 4th SMLR fills the spooler and starts it: the clock is read right after it)
    r = sap(prog("""MODEREG := $20;
SMLR(A1 := 1.0); SMLR(A1 := 1.0); SMLR(A1 := 1.0); SMLR(A1 := 1.0); t0 := CLOCK;
for t1 := 1 to 4 do SMLR(A1 := 1.0);
SSMSW(A1);
writeln(CLOCK - t0);"""), "[sympas]\nspool_capacity = 4\n")
    assert r["status"] == "ok", r["error"]
    assert int(r["output"][0]) == pytest.approx(0.9 * SEC, abs=8)
    assert r["position"]["A1"] == pytest.approx(8.0)
    assert r["motion"]["feed_moves"] == 8
