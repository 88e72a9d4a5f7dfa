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
    assert r["position"]["A1"] == 100.0


def test_axst_bits_12_and_13_spooler_running_and_halted(sap):
    """axst bit 12 while the spooler works off its profiles, bit 13 while it is halted (SSF 1000, L2091)
    with profiles behind the halt (docs/sympas.md: the provisional axst layout)."""
    r = sap("""program B;
var run1, halt1, run2, halt2, run3, halt3: boolean;
begin
  TRVL := 100.0; TRAC := 1000.0;
  SMLR(A1 := 100.0);
  SSF(A1 := 0, SSFP := 1000);
  SMLR(A1 := 50.0);
  SSMS(A1);
  WT(100);
  run1 := A1.axstb.13; halt1 := A1.axstb.14;
  WT(3 * 15625);
  run2 := A1.axstb.13; halt2 := A1.axstb.14;
  SSMSW(A1);
  run3 := A1.axstb.13; halt3 := A1.axstb.14;
end.
""")
    v = r["variables"]
    assert (v["run1"], v["halt1"]) == (True, False)
    assert (v["run2"], v["halt2"]) == (False, True)
    assert (v["run3"], v["halt3"]) == (False, False)
    assert r["position"]["A1"] == 150.0


FULL = """program F;
var k: integer;
begin
  TRVL := 100.0; TRAC := 1000.0;
  {MODE}
  for k := 1 to 6 do
    SMLR(A1 := 10.0);
  SSMSW(A1);
end.
"""


def test_a_full_spooler_starts_itself_only_with_autospool_L1396(sap):
    r = sap(FULL.replace("{MODE}", "MODEREG := MODEREG or $20;"), machine_toml="[sympas]\nspool_capacity = 4\n")
    assert r["error"] is None and r["position"]["A1"] == 60.0


def test_without_autospool_a_full_spooler_waits_for_an_ssms_L1396(sap):
    """Without MODEREG bit 5 nothing starts the full spooler: the 5th SMLR waits for ever (RUN005 at
    once, with its line)."""
    r = sap(FULL.replace("{MODE}", ""), machine_toml="[sympas]\nspool_capacity = 4\n")
    assert r["error"]["code"] == "RUN005" and r["error"]["line"] == 7
    assert r["position"]["A1"] == 0.0
