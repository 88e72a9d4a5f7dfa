"""Issue 16 rule 3: "`translate` without the scenario/keys that a run needs refuses with a clear message."
docs/translate.md rule 4 does so for a probe: "A probe that did not switch because the run had no
`--scenario` is refused (TRN001): the run never measured."

A branch on a digital input (rw_SymPas `A2.digib.enable`) read with no `--scenario` is the same case: no
one said what the input is, the simulation took 0, and the translation writes the `else` path for good
(a FROZEN mark says "read as 0x0", but nothing was ever read). The translation should refuse and name
`--scenario`, as it does for the probe and for missing `--keys`.
"""

from .helpers import translate

BRANCH_ON_INPUT = """program Dg;
const enable = 1;
var ok: boolean;
begin
  TRVL := 50.0; TRAC := 500.0;
  MLAW(A1 := 10.0, A2 := 10.0);
  ok := A2.digib.enable;
  if ok then
    MLAW(A1 := 50.0)
  else
    MLAW(A2 := 50.0);
end.
"""


def test_a_branch_on_a_digital_input_without_a_scenario_is_refused(tmp_path):
    rc, text, err = translate(tmp_path, BRANCH_ON_INPUT, "input.sap")
    assert rc != 0 and not text, f"translated a branch on an input no scenario gave:\n{text}"
    assert "--scenario" in err, err
