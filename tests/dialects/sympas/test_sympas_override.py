"""UTROVR with the TROVRST ramp (rw_SymPas manual L2183-2189): the override scales ds/dt of the running
path moves and reaches the new TROVR linearly over TROVRST seconds. Figures by hand; 15625 ticks = 1 s.

Reference move: 20 mm at TRVL 10, TRAC 100 lasts 0.1 + 1.9 + 0.1 = 2.1 s of profile time.
"""

from __future__ import annotations

import pytest

SEC = 15625


def run_override(sap, ovr: float, ramp: float, at_ticks: int, moves: str = "MLR(A1 := 20.0);",
                 extra: str = "") -> int:
    text = f"""program T;
var t0, t1: integer;
begin
  CL(A1); TRVL := 10.0; TRAC := 100.0; {extra}
  t0 := CLOCK;
  {moves}
  repeat until CLOCK - t0 >= {at_ticks};
  TROVR := {ovr}; TROVRST := {ramp}; UTROVR(A1);
  repeat until A1.axstb.1;
  t1 := CLOCK - t0;
  writeln(t1, ' ', A1.dp);
end.
"""
    r = sap(text)
    assert r["status"] == "ok", r["error"]
    t, x = r["output"][0].split()
    assert float(x) == pytest.approx(20.0)
    return int(t)


def test_override_at_once_without_settling_time(sap):
    # at 1 s, 1.1 s of profile left at half rate: 2.2 s -> 3.2 s in all
    assert run_override(sap, 0.5, 0.0, SEC) == pytest.approx(3.2 * SEC, abs=8)


def test_override_ramps_over_trovrst(sap):
    # ramp 1 -> 0.5 over 0.2 s covers 0.2 - 0.05 = 0.15 s of profile; 0.95 s left at 0.5 = 1.9 s -> 3.1 s
    assert run_override(sap, 0.5, 0.2, SEC) == pytest.approx(3.1 * SEC, abs=8)


def test_override_ramp_up(sap):
    # TROVR 2 over 0.4 s from 1 s: covers 0.4 + 0.5 * 1 * 0.4 = 0.6 s of profile; 0.5 s left at 2 = 0.25 s -> 1.65 s
    assert run_override(sap, 2.0, 0.4, SEC) == pytest.approx(1.65 * SEC, abs=8)


def test_velocity_during_the_ramp(sap):
    # halfway through the 0.2 s ramp the factor is 0.75: dv = 7.5 mm/s
    text = """program T;
var t0: integer; v: double;
begin
  CL(A1); TRVL := 10.0; TRAC := 100.0;
  t0 := CLOCK;
  MLR(A1 := 20.0);
  repeat until CLOCK - t0 >= 15625;
  TROVR := 0.5; TROVRST := 0.2; UTROVR(A1);
  t0 := CLOCK;
  repeat until CLOCK - t0 >= 1562;
  v := A1.dv;
  writeln(v);
end.
"""
    r = sap(text)
    assert float(r["output"][0]) == pytest.approx(7.5, abs=0.01)


def test_override_on_a_spooled_chain(sap):
    # two 10 mm segments joined at TRTVL 10: 2.1 s of profile. At 0.5 s, half rate at once: 1.6 s left -> 3.2 s
    t = run_override(sap, 0.5, 0.0, SEC // 2, "SMLR(A1 := 10.0); SMLR(A1 := 10.0); SSMS(A1);", "TRTVL := 10.0;")
    assert t == pytest.approx(3.7 * SEC, abs=8)


def test_later_moves_are_planned_with_the_override(sap):
    # TROVR 0.5 before the move: v = 5, a = 100: 0.05 s up (0.125 mm) x2, 19.75 mm / 5 = 3.95 s -> 4.05 s
    text = """program T;
var t0, t1: integer;
begin
  CL(A1); TRVL := 10.0; TRAC := 100.0; TROVR := 0.5; UTROVR(A1);
  t0 := CLOCK;
  MLRW(A1 := 20.0);
  t1 := CLOCK - t0;
  writeln(t1);
end.
"""
    assert int(sap(text)["output"][0]) == pytest.approx(4.05 * SEC, abs=8)


def test_ssf_in_a_chain_follows_the_override(sap):
    # segment 1 (10 mm, joint at TRTVL 10) ends at 1.05 s; half rate from 0.5 s: 0.55 s left -> 1.1 s -> 1.6 s.
    # MS before the end of segment 1 of a second chain drops its SSF.
    text = """program T;
var t0, t1, c: integer;
begin
  CL(A1); TRVL := 10.0; TRAC := 100.0; TRTVL := 10.0; A1.sdec := 1000.0;
  t0 := CLOCK;
  SMLR(A1 := 10.0); SSF(A1 := 42, SSFP = 1); SMLR(A1 := 10.0); SSMS(A1);
  repeat until CLOCK - t0 >= 7812;
  TROVR := 0.5; TROVRST := 0.0; UTROVR(A1);
  repeat until CI1 = 42;
  t1 := CLOCK - t0;
  SSMSW(A1);
  TROVR := 1.0; UTROVR(A1); CI1 := 0;
  SMLR(A1 := 10.0); SSF(A1 := 7, SSFP = 1); SMLR(A1 := 10.0); SSMS(A1);
  MSW(A1);
  WT(30000);
  c := CI1;
  writeln(t1, ' ', c);
end.
"""
    r = sap(text)
    assert r["status"] == "ok", r["error"]
    t1, c = r["output"][0].split()
    assert int(t1) == pytest.approx(1.6 * SEC, abs=12)
    assert c == "0"
