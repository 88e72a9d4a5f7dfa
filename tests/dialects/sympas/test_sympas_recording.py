"""LPR / LPRS data recording (manual §6.6.29-30, L1845-1859; LST/LET L1299-1300; PU/TU L1326-1351).

Recording starts LST s after the call, takes 1000 values k * T_A apart, k = ceil(LET / (1000 * T_A)),
T_A = 1.28 ms = 20 ticks; the card samples in its servo cycle (ticks that are multiples of 20).
Statements cost one tick each (Q = 1): a statement runs at the CLOCK it reads, the next one a tick later.

Reference move: MLR(A1 := 20) at TRVL 10, TRAC 100 from tick m: s = 50 t^2 up to 0.1 s (0.5 mm),
then 0.5 + 10 (t - 0.1) up to 1.95 mm ... 19.5 mm at 2.0 s, braking to 20 mm at 2.1 s.
"""

from __future__ import annotations

import math

import pytest

SEC = 15625


def ref_pos(t: float) -> float:
    """Position of the reference move t seconds after its start."""
    if t <= 0.0:
        return 0.0
    if t < 0.1:
        return 50.0 * t * t
    if t < 2.0:
        return 0.5 + 10.0 * (t - 0.1)
    if t < 2.1:
        r = 2.1 - t
        return 20.0 - 50.0 * r * r
    return 20.0


def record(sap, lst: float, let: float, body: str = "MLRW(A1 := 20.0);", setup: str = "",
           axes: str = "A1", cmd: str = "LPR"):
    text = f"""program T;
var c0: integer;
begin
  CL(A1, A2); TRVL := 10.0; TRAC := 100.0; LST := {lst}; LET := {let}; {setup}
  c0 := CLOCK;
  {cmd}({axes});
  {body}
  writeln(c0);
end.
"""
    r = sap(text)
    assert r["status"] == "ok", r["error"]
    return int(r["output"][0]), r


def first_tick(call: int, lst: float) -> int:
    return math.ceil((call + lst * SEC) / 20) * 20


def test_lpr_records_the_move_at_the_simulated_time(sap):
    c0, r = record(sap, 0.5, 1.0)
    call, move = c0 + 1, c0 + 2  # LPR one tick after c0 := CLOCK, MLRW one after LPR
    rec = r["recordings"]["A1"]
    assert rec["fields"] == ["t", "dp", "rp", "dv", "rv", "poserr"]
    samples = rec["samples"]
    assert len(samples) == 1000  # always 1000 values (L1299)
    assert rec["interval_s"] == pytest.approx(0.00128)  # LET 1.0 s rounds up to 1000 * 1.28 ms
    first = first_tick(call, 0.5)
    for i in (0, 1, 500, 999):
        tick = first + 20 * i
        t, dp, rp, dv, rv, perr = samples[i]
        assert t == pytest.approx((tick - call) / SEC)
        assert dp == pytest.approx(ref_pos((tick - move) / SEC), abs=1e-9)
        assert rp == pytest.approx(dp) and perr == 0.0
        assert dv == pytest.approx(10.0) and rv == pytest.approx(10.0)  # cruising from 0.1 s to 2.0 s
    # sample 500 is 500 x 20 ticks after sample 0, in the cruise: 0.5 mm + 10 mm/s * (time into the move - 0.1 s)
    assert samples[500][1] == pytest.approx(0.5 + 10.0 * ((first + 10000 - move) / SEC - 0.1), abs=1e-9)
    assert first % 20 == 0 and 0 <= first - (call + 0.5 * SEC) < 20  # first servo cycle after call + LST


def test_recording_goes_on_after_the_program_ends(sap):
    # MLR without wait: the program ends at once, the card records the move as it runs and then stands
    c0, r = record(sap, 0.0, 2.56, body="MLR(A1 := 20.0);")
    call, move = c0 + 1, c0 + 2
    rec = r["recordings"]["A1"]
    assert rec["interval_s"] == pytest.approx(0.00256)  # LET 2.56 s: exactly 2 x 1.28 s
    first = first_tick(call, 0.0)
    for i in (0, 10, 300, 800, 850, 999):
        tick = first + 40 * i
        assert rec["samples"][i][1] == pytest.approx(ref_pos((tick - move) / SEC), abs=1e-9)
    assert rec["samples"][999][1] == 20.0 and rec["samples"][999][3] == 0.0  # 2.56 s: at rest
    assert rec["samples"][10][3] == pytest.approx(100.0 * (first + 400 - move) / SEC)  # accelerating


@pytest.mark.parametrize("let, every", [(0.0, 1), (1.28, 1), (1.2801, 2), (2.0, 2), (5.0, 4)])
def test_let_rounds_up_to_whole_multiples_of_1000_ta(sap, let, every):
    _, r = record(sap, 0.0, let, body="")
    assert r["recordings"]["A1"]["interval_s"] == pytest.approx(every * 0.00128)


def test_positions_in_pu_and_velocities_in_pu_per_tu(sap):
    # PU 2 = m, TU 1 = min: the same move in m and m/min (TRVL 0.6 m/min = 10 mm/s, TRAC 360 m/min^2)
    setup = "PU := 2; TU := 1; TRVL := 0.6; TRAC := 360.0;"
    c0, r = record(sap, 1.0, 1.0, body="MLRW(A1 := 0.02);", setup=setup)
    call, move = c0 + 1, c0 + 2
    t, dp, _, dv, _, _ = r["recordings"]["A1"]["samples"][0]
    tick = first_tick(call, 1.0)
    assert t == pytest.approx((tick - call) / SEC)  # times stay in seconds, like LST and LET
    assert dp == pytest.approx(ref_pos((tick - move) / SEC) / 1000.0, abs=1e-12)
    assert dv == pytest.approx(0.6)


def test_lprs_records_several_axes_on_one_grid(sap):
    # A1 and A2 move together 20 and 10 mm: path 22.36 mm at 10 mm/s; A2 runs at 10/sqrt(5) mm/s
    c0, r = record(sap, 0.3, 0.0, body="MLRW(A1 := 20.0, A2 := 10.0);", axes="A1, A2", cmd="LPRS")
    recs = r["recordings"]
    assert set(recs) == {"A1", "A2"}
    s1, s2 = recs["A1"]["samples"], recs["A2"]["samples"]
    assert [s[0] for s in s1] == [s[0] for s in s2]
    call, move = c0 + 1, c0 + 2
    tick = first_tick(call, 0.3) + 20 * 100
    path = 0.5 + 10.0 * ((tick - move) / SEC - 0.1)
    assert s1[100][1] == pytest.approx(path * 2 / math.sqrt(5), abs=1e-9)
    assert s2[100][1] == pytest.approx(path / math.sqrt(5), abs=1e-9)
    assert s2[100][3] == pytest.approx(10.0 / math.sqrt(5))


def test_a_new_lpr_replaces_the_axis_recording(sap):
    text = """program T;
var c0: integer;
begin
  CL(A1); LST := 5.0; LPR(A1);
  WT(15625);
  c0 := CLOCK;
  LST := 0.0; LPR(A1);
  JRW(A1 := 1.0);
  writeln(c0);
end.
"""
    r = sap(text)
    assert r["status"] == "ok", r["error"]
    call = int(r["output"][0]) + 2  # LST := 0.0 one tick after c0 := CLOCK, LPR one after that
    rec = r["recordings"]["A1"]
    assert rec["samples"][0][0] == pytest.approx((first_tick(call, 0.0) - call) / SEC)
    assert len(rec["samples"]) == 1000


def test_lpr_takes_exactly_one_axis(sap_check):
    assert sap_check("program T;\nbegin\n  LPR(A1, A2);\nend.\n") == [("SP005", 3)]


def test_negative_latch_times_are_wrong_parameters(sap):
    r = sap("program T;\nbegin\n  LST := -1.0;\n  LPR(A1);\nend.\n")
    assert r["status"] == "error" and r["error"]["code"] == "256" and r["error"]["line"] == 4


def test_no_recording_no_recordings_key(sap):
    r = sap("program T;\nbegin\n  CL(A1);\nend.\n")
    assert "recordings" not in r
