"""Refused profiles are not silent (manual L1415: a profile without travel or with velocity/acceleration 0
is discarded and a message is generated, unless MODEREG bit 29 InhibitProfileRefuse is set)."""

from __future__ import annotations

REFUSE = """program R;
begin
  TRVL := 0.0;
  MLAW(A1 := 10.0);
  TRVL := 100.0; TRAC := 0.0;
  MLAW(A1 := 10.0);
  TRAC := 1000.0;
  MLAW(A1 := 0.0);
  MLA(A1 := 10.0);
  MLA(A1 := 20.0);
  DTCA1 := 0.0; DTCA2 := 0.0;
  SMCR(A2 := 5.0, A3 := 5.0);
  SSMSW(A2, A3);
  MODEREG := MODEREG or $20000000;
  MLAW(A1 := 10.0);
  TRVL := 0.0;
  MLAW(A1 := 30.0);
end.
"""


def test_refused_profiles_give_a_message_L1415(sap):
    r = sap(REFUSE)
    assert r["error"] is None
    out = [line.split("prog.sap:", 1)[1] for line in r["output"]]
    assert out == ["4: profile refused: TRVL = 0 (A1)", "6: profile refused: TRAC = 0 (A1)",
                   "8: profile refused: no travel (A1)", "10: profile refused: axis A1 is still in a profile (A1)",
                   "12: profile refused: no travel (A2, A3)"]
    assert r["position"]["X"] == 10.0  # bit 29 suppresses the message only: line 16 is still refused


def test_refused_profile_sets_the_refused_bit_L1415(sap):
    r = sap("""program R;
var b: boolean;
begin
  TRVL := 0.0;
  MLA(A1 := 10.0);
  b := A1.axstb.15;  { axst bit 14: refused }
end.
""")
    assert r["variables"]["b"] is True and len(r["output"]) == 1
