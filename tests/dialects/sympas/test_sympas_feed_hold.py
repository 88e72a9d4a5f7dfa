"""TROVR = 0 as a feed hold (UTROVR L2183-2189, TROVR/TROVRST L1314-1315).

The override scales ds/dt and reaches its new value linearly over TROVRST seconds; a factor of 0
brings the path to a stand (decelerating over TROVRST) and keeps it there, not at profile end, with
simulated time passing, until a UTROVR raises it again. Figures by hand; 15625 ticks = 1 s.

Reference move: MLR(A1 := 20) at TRVL 10, TRAC 100: 0.1 s up (0.5 mm), cruise, 0.1 s down: 2.1 s.
A ramp 1 -> 0 over 0.2 s covers 0.5 * 0.2 = 0.1 s of profile time (1 mm at 10 mm/s), and so does
the ramp 0 -> 1 back.
"""

from __future__ import annotations

import pytest

SEC = 15625


HOLD = """program T;
var t0, t1, t2: integer; v, x1, x2: double; pe: boolean;
begin
  CL(A1); TRVL := 10.0; TRAC := 100.0;
  t0 := CLOCK;
  MLR(A1 := 20.0);
  repeat until CLOCK - t0 >= 15625;
  TROVR := 0.0; TROVRST := 0.2; UTROVR(A1);
  repeat until CLOCK - t0 >= 17187;
  v := A1.dv;
  repeat until CLOCK - t0 >= 31250;
  x1 := A1.dp; pe := A1.axstb.1;
  WT(15625);
  x2 := A1.dp;
  TROVR := 1.0; UTROVR(A1);
  repeat until A1.axstb.1;
  t1 := CLOCK - t0;
  writeln(v, ' ', x1, ' ', x2, ' ', pe, ' ', t1, ' ', A1.dp);
end.
"""


def test_feed_hold_stops_the_path_and_resumes(sap):
    r = sap(HOLD)
    assert r["status"] == "ok", r["error"]
    v, x1, x2, pe, t1, x = r["output"][0].split()
    # 0.1 s into the 0.2 s ramp down the factor is 0.5: 5 mm/s
    assert float(v) == pytest.approx(5.0, abs=0.01)
    # held from 1.2 s at 9.5 mm (1.0 s) + 1 mm (the ramp): 10.5 mm, not at profile end
    assert float(x1) == pytest.approx(10.5, abs=2e-3)
    assert pe == "FALSE"
    # one more second later it still stands there
    assert float(x2) == float(x1)
    # raised at 3.0 s (+ a few statements): the ramp up covers 0.1 s profile, then 0.9 s of profile left:
    # 3.0 + 0.2 + 0.9 = 4.1 s
    assert int(t1) == pytest.approx(4.1 * SEC, abs=12)
    assert float(x) == pytest.approx(20.0)


def test_feed_hold_without_settling_time_stands_at_once(sap):
    text = HOLD.replace("TROVRST := 0.2", "TROVRST := 0.0")
    r = sap(text)
    assert r["status"] == "ok", r["error"]
    v, x1, x2, _, t1, _ = r["output"][0].split()
    # no ramp: the path stands at once at 9.5 mm; going on at 3 s the 1.1 s of profile left end at 4.1 s
    assert float(v) == 0.0
    assert float(x1) == pytest.approx(9.5, abs=2e-3) and x2 == x1
    assert int(t1) == pytest.approx(4.1 * SEC, abs=12)


RELEASED_BY_TASK_1 = """{$TASK 0}
program Main;
var t0, t1: integer;
begin
  CL(A1); TRVL := 10.0; TRAC := 100.0;
  STARTCNCT(1);
  t0 := CLOCK;
  MLRW(A1 := 20.0);
  t1 := CLOCK - t0;
  writeln(t1, ' ', A1.dp);
end.
{$TASK 1}
program Operator;
begin
  repeat until CI2 = 1;
  TROVR := 0.0; TROVRST := 0.2; UTROVR(A1);
  repeat until CI1 = 1;
  TROVR := 1.0; UTROVR(A1);
end.
"""

CI2_AT_1S = """
[[scenario]]
time = 1.0
kind = "ci"
index = 2
value = 1
"""
CI_AT = CI2_AT_1S + """
[[scenario]]
time = 3.0
kind = "ci"
index = 1
value = 1
"""


def test_w_wait_on_a_held_axis_goes_on_when_another_task_raises_the_override(sap):
    # task 1 holds the move at 1.0 s and releases it at 3.0 s (the scenario's CI2 and CI1): the MLRW of
    # task 0 waits through the hold; its move ends at 4.1 s after its start, as in the first test
    r = sap(RELEASED_BY_TASK_1, machine_toml=CI_AT)
    assert r["status"] == "ok", r["error"]
    t1, x = r["output"][0].split()
    assert int(t1) == pytest.approx(4.1 * SEC, abs=12)
    assert float(x) == pytest.approx(20.0)
    assert r["cycle_time_s"] == pytest.approx(4.1, abs=2e-3)


def test_a_move_started_under_a_hold_waits_at_its_start(sap):
    # TROVR 0 before the move: it does not start; raised at 1 s it runs its 2.1 s: 3.1 s
    text = """program T;
var t0, t1: integer; x: double;
begin
  CL(A1); TRVL := 10.0; TRAC := 100.0; TROVR := 0.0; UTROVR(A1);
  t0 := CLOCK;
  MLR(A1 := 20.0);
  WT(15625);
  x := A1.dp;
  TROVR := 1.0; UTROVR(A1);
  repeat until A1.axstb.1;
  t1 := CLOCK - t0;
  writeln(x, ' ', t1);
end.
"""
    r = sap(text)
    assert r["status"] == "ok", r["error"]
    x, t1 = r["output"][0].split()
    assert float(x) == 0.0
    assert int(t1) == pytest.approx(3.1 * SEC, abs=12)


def test_feed_hold_on_a_spooled_chain_keeps_its_ssf_for_after(sap):
    # two 10 mm segments joined at TRTVL 10 (2.1 s of profile); SSF between them writes CI1 := 42 when
    # segment 1 ends (1.05 s of profile). Held at once at 0.5 s, raised at 2.5 s: segment 1 ends at 3.05 s
    text = """program T;
var t0, t1, t2: integer;
begin
  CL(A1); TRVL := 10.0; TRAC := 100.0; TRTVL := 10.0; TROVRST := 0.0;
  t0 := CLOCK;
  SMLR(A1 := 10.0); SSF(A1 := 42, SSFP = 1); SMLR(A1 := 10.0); SSMS(A1);
  repeat until CLOCK - t0 >= 7812;
  TROVR := 0.0; UTROVR(A1);
  WT(31250);
  TROVR := 1.0; UTROVR(A1);
  repeat until CI1 = 42;
  t1 := CLOCK - t0;
  repeat until A1.axstb.1;
  t2 := CLOCK - t0;
  writeln(t1, ' ', t2, ' ', A1.dp);
end.
"""
    r = sap(text)
    assert r["status"] == "ok", r["error"]
    t1, t2, x = r["output"][0].split()
    assert int(t1) == pytest.approx(3.05 * SEC, abs=12)
    assert int(t2) == pytest.approx(4.1 * SEC, abs=12)
    assert float(x) == pytest.approx(20.0)


def test_the_recording_shows_the_hold(sap):
    # LPR from 0.9 s, one sample per 2.56 ms: 10 mm/s before the hold at 1.0 s, 5 mm/s halfway down the
    # ramp (1.1 s, sample 78 = 0.19968 s on), 0 while held (1.2 s .. 3.0 s = samples 118 .. 820)
    text = HOLD.replace("t0 := CLOCK;", "t0 := CLOCK; LST := 0.9; LET := 2.56; LPR(A1);")
    r = sap(text)
    assert r["status"] == "ok", r["error"]
    samples = r["recordings"]["A1"]["samples"]
    speeds = [s[3] for s in samples]
    assert speeds[0] == pytest.approx(10.0, abs=0.02)
    assert speeds[78] == pytest.approx(5.0, abs=0.05)
    assert all(v == 0.0 for v in speeds[120:815])
    assert speeds[950] == pytest.approx(10.0)
    assert samples[400][1] == pytest.approx(10.5, abs=2e-3)


def test_a_wait_nothing_can_release_is_reported(sap):
    r = sap("""program T;
begin
  CL(A1); TROVR := 0.0; UTROVR(A1);
  MLRW(A1 := 20.0);
end.
""")
    assert r["status"] == "error"
    assert r["error"]["code"] == "RUN005" and r["error"]["line"] == 4


def test_a_held_move_at_the_end_of_the_run_stands_where_it_is(sap):
    text = """program T;
var t0: integer;
begin
  CL(A1); TRVL := 10.0; TRAC := 100.0; TROVRST := 0.2;
  t0 := CLOCK;
  MLR(A1 := 20.0);
  repeat until CLOCK - t0 >= 15625;
  TROVR := 0.0; UTROVR(A1);
end.
"""
    r = sap(text)
    assert r["status"] == "ok", r["error"]
    assert list(r["position"].values())[0] == pytest.approx(10.5, abs=2e-3)
    assert r["cycle_time_s"] == pytest.approx(1.2, abs=1e-3)  # the path stands 0.2 s after the UTROVR


def test_js_ends_a_held_move_where_it_stands(sap):
    # held at once at 1.0 s (9.5 mm); JSW ends the profile there, and a new move starts from 9.5 mm
    text = """program T;
var t0: integer; x: double;
begin
  CL(A1); TRVL := 10.0; TRAC := 100.0;
  t0 := CLOCK;
  MLR(A1 := 20.0);
  repeat until CLOCK - t0 >= 15625;
  TROVR := 0.0; UTROVR(A1);
  JSW(A1);
  x := A1.dp;
  TROVR := 1.0; UTROVR(A1);
  MLRW(A1 := 1.0);
  writeln(x, ' ', A1.axstb.1, ' ', A1.dp);
end.
"""
    r = sap(text)
    assert r["status"] == "ok", r["error"]
    x, pe, x2 = r["output"][0].split()
    assert float(x) == pytest.approx(9.5, abs=2e-3)
    assert pe == "TRUE"
    assert float(x2) == pytest.approx(float(x) + 1.0, abs=1e-3)


def test_two_tasks_waiting_on_held_axes_are_reported(sap):
    # both tasks wait on their own held axis: nothing runs any more, no scenario event is ahead
    r = sap("""{$TASK 0}
program Main;
begin
  CL(A1, A2);
  STARTCNCT(1);
  TROVR := 0.0; UTROVR(A1);
  MLRW(A1 := 5.0);
  writeln('never');
end.
{$TASK 1}
program Other;
begin
  TROVR := 0.0; UTROVR(A2);
  MLRW(A2 := 5.0);
  writeln('never either');
end.
""")
    assert r["status"] == "error" and r["error"]["code"] == "RUN005"
    assert r["output"] == []


def test_the_override_belongs_to_the_axes_not_to_the_task(sap):
    # L2189: "reduzierte Bahngeschwindigkeit für Achsen A1 und A2". Task 0 holds A1 and starts a move
    # (it waits at its start); task 1 raises A1's override at 1.0 s (scenario CI2): the move runs its 2.1 s
    # and task 0's next move on A1 runs at full speed too (another 2.1 s): 1.0 + 2.1 + 2.1 = 5.2 s
    text = """{$TASK 0}
program Main;
var t0, t1: integer;
begin
  CL(A1); TRVL := 10.0; TRAC := 100.0;
  STARTCNCT(1);
  TROVR := 0.0; UTROVR(A1);
  t0 := CLOCK;
  MLRW(A1 := 20.0);
  MLRW(A1 := 20.0);
  t1 := CLOCK - t0;
  writeln(t1, ' ', A1.dp);
end.
{$TASK 1}
program Operator;
begin
  repeat until CI2 = 1;
  TROVR := 1.0; UTROVR(A1);
end.
"""
    r = sap(text, machine_toml=CI2_AT_1S)
    assert r["status"] == "ok", r["error"]
    t1, x = r["output"][0].split()
    assert int(t1) == pytest.approx(5.2 * SEC, abs=12)
    assert float(x) == pytest.approx(40.0)


def test_a_group_runs_with_the_smallest_override_of_its_axes(sap):
    # UTROVR(A2) at 0.5 before a move of A1 and A2: 20 mm at v 5, a 100: 0.05 s x 2 + 19.75 / 5 = 4.05 s
    text = """program T;
var t0, t1: integer;
begin
  CL(A1, A2); TRVL := 10.0; TRAC := 100.0; TROVR := 0.5; UTROVR(A2);
  t0 := CLOCK;
  MLRW(A1 := 20.0, A2 := 0.0);
  t1 := CLOCK - t0;
  MLRW(A1 := 20.0);
  writeln(t1, ' ', CLOCK - t0 - t1);
end.
"""
    r = sap(text)
    assert r["status"] == "ok", r["error"]
    t1, t2 = r["output"][0].split()
    assert int(t1) == pytest.approx(4.05 * SEC, abs=8)
    assert int(t2) == pytest.approx(2.1 * SEC, abs=8)  # A1 alone is not reduced
