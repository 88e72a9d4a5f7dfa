"""dp is rounded to whole counts at the end of every profile that ends at rest (manual L1399, MODEREG bit 8
ExactTargetPos switches it off), stops (MS, JS) and home searches included; a home search's latch is seen
together with its profile end."""

from __future__ import annotations

STOPS = """program J;
begin
  TRVL := 100.0; TRAC := 1000.0;
  {MODE}
  MLA(A1 := 100.0);
  WT(7777);
  MSW(A1);
  writeln(A1.dp);
  JA(A1 := 0.0);
  WT(3333);
  JSW(A1);
  writeln(A1.dp);
end.
"""


def test_dp_is_whole_counts_after_ms_and_js_L1399(sap):
    r = sap(STOPS.replace("{MODE}", ""))
    assert r["output"] == ["49.786", "14.213"]


def test_exact_target_pos_keeps_the_stop_position_L1399(sap):
    r = sap(STOPS.replace("{MODE}", "MODEREG := MODEREG or $100;"))
    assert r["output"] == ["49.7856", "14.21226667"]


def test_jhi_dp_is_0_when_the_profile_end_bit_is_seen_L1399(sap):
    r = sap("""program H;
var d: double;
begin
  JHI(A1 := 5.0);
  repeat until A1.axstb.1;
  d := A1.dp;
  writeln(d, ' ', A1.axstb.4);
end.
""")
    assert r["output"] == ["0 TRUE"]
