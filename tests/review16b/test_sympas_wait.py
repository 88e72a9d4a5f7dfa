"""Issue 16 rule 4 "Program order kept" and the brief's list of what a translation must keep: "dwell".

rw_SymPas `WT(n)` makes the task sleep n x 64 us (manual L2228-2233); after a `MLAW` (which
waits for the motion's end) the axes stand still that long: here 2 s at the bottom of a plunge (the run's
cycle time includes it). The translation writes the plunge and the retract back to back: the new control
does not wait at Z-5 and nothing in the output says a wait was left out.
"""

import re

import pytest

from .helpers import code_lines, translate

PLUNGE_AND_WAIT = """program Wt;
begin
  TRVL := 50.0; TRAC := 500.0;
  MLAW(A1 := 10.0, A2 := 10.0);
  MLAW(A3 := -5.0);
  WT(31250);
  MLAW(A3 := 5.0);
end.
"""

DWELL = {"linuxcnc": r"G4 P2(\.0*)?\b", "sinumerik840d": r"G4 F2(\.0*)?\b", "iso": r"G4 X2(\.0*)?\b"}


@pytest.mark.parametrize("target", sorted(DWELL))
def test_a_sympas_wait_between_moves_is_written_as_a_dwell(tmp_path, target):
    rc, text, err = translate(tmp_path, PLUNGE_AND_WAIT, "wait.sap", "--target", target)
    assert rc == 0, err
    lines = code_lines(text)
    plunge = next(i for i, line in enumerate(lines) if "Z-5" in line)
    retract = next(i for i, line in enumerate(lines) if i > plunge and "Z5" in line)
    between = lines[plunge + 1:retract]
    assert any(re.search(DWELL[target], line) for line in between), (
        f"the 2 s WT at the bottom of the plunge is lost:\n{text}")
