"""SSMSW waits until all spooled profiles are done, also behind a spooler halt (SSF 1000; manual L2086-2091,
L2101-2108)."""

from __future__ import annotations

HALT = """{$TASK 0}
program Main;
begin
  STARTCNCT(1);
  TRVL := 100.0; TRAC := 1000.0;
  SMLR(A1 := 100.0);
  SSF(A1 := 0, SSFP := 1000);
  SMLR(A1 := 50.0);
  SSMSW(A1);
  writeln('back at ', CLOCK / 15625.0, ' A1 ', A1.dp);
end.

{$TASK 1}
program Go;
begin
  WT(3 * 15625);
  SSMS(A1);
end.
"""


def test_ssmsw_waits_for_the_profiles_behind_a_spooler_halt_L2101(sap):
    """The halt stops the spooler after 100 mm; task 1 starts it again at 3 s; SSMSW returns when the
    last 50 mm are done (0.6 s later), not at the halt."""
    r = sap(HALT)
    assert r["error"] is None
    assert r["output"] == ["back at 3.600256 A1 150"]


def test_ssmsw_behind_a_halt_nothing_restarts_is_a_deadlock_L2101(sap):
    r = sap(HALT.replace("  SSMS(A1);", "  WT(1);"))
    assert r["error"]["code"] == "RUN005" and r["error"]["line"] == 9
    assert r["position"]["X"] == 100.0
