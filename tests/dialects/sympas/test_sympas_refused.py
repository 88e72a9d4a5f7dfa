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
    assert r["position"]["A1"] == 10.0  # bit 29 suppresses the message only: line 16 is still refused


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


def test_a_profile_that_would_never_end_is_refused_L1415(sap):
    """TRVL = 1e-310 is > 0 but the move would take for ever: refused with a message, not a hold."""
    r = sap("program R;\nbegin\n  TRVL := 1.0e-310;\n  MLAW(A1 := 100.0);\nend.\n")
    assert r["error"] is None and r["position"]["A1"] == 0.0
    assert r["output"][0].endswith("prog.sap:4: profile refused: TRVL = 1e-310: the profile would never end (A1)")


def test_the_json_document_has_no_infinity(tmp_path):
    import json

    from ncvm.api import run_program
    from ncvm.runtime.session import RunOptions

    path = tmp_path / "p.sap"
    path.write_text("program R;\nvar d: double;\nbegin\n  d := 1.0e308 * 10.0;\nend.\n", encoding="latin-1")
    result = run_program(path, options=RunOptions(state_dir=tmp_path / ".ncvm"))
    result.cycle_time_s = float("inf")  # as an endless hold would give
    text = json.dumps(result.to_json(), allow_nan=False)
    assert "Infinity" not in text
