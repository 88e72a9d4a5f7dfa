"""rw_SymPas: a circle while another task moves an axis (issue 16: "makes the same motions to the same end
points ... as ncvm's own run"; "arcs stay arcs"; "Trust first: a silently wrong answer is the worst defect").

Task 0 runs a quarter circle `MCRW(A1 := 20.0, A2 := 0.0, PHI := 90.0)` from X50 Y50 while task 1 jogs A3.
The run's trace starts the circle with a zero-length `arc` (its end 0.000004 mm from its start) and then
samples the combined motion as straight moves. Every target writes that zero-length arc as `G3 X50 Y50 I20
J0`: in G-code an arc whose end is its start is a FULL circle, 126 mm of cut around X70 Y50 that the card
never made, before the sampled quarter circle. The end points still agree (a full circle ends where it
began), so only the sweep shows it.
"""

from __future__ import annotations

import pytest

from tests.review16c.helpers import needs_rs274, rs274_canon
from tests.review16d.helpers import full_circles, machine, rs274_sweep, translated

MACHINE = machine("gantry")

PROGRAM = """{$TASK 0}
program T0;
begin
  TRVL := 50.0; TRAC := 500.0;
  MLAW(A1 := 50.0, A2 := 50.0);
  STARTCNCT(1);
  MCRW(A1 := 20.0, A2 := 0.0, PHI := 90.0);
  WT(15625);
end.

{$TASK 1}
program T1;
begin
  A3.jvl := 5.0; A3.jac := 100.0;
  JAW(A3 := -2.0);
end.
"""


@pytest.mark.parametrize("target", ["linuxcnc", "sinumerik840d", "iso"])
def test_no_arc_ends_where_it_starts(tmp_path, target):
    """No `G2`/`G3` of the output returns to its start point: the program made no full circle."""
    full = full_circles(translated(tmp_path, MACHINE, PROGRAM, "two.sap", target))
    assert not full, f"{target}: full circles the run never made: {full}"


@needs_rs274
def test_rs274_sweeps_no_more_than_the_quarter_circle(tmp_path):
    """rs274's reading of the LinuxCNC output: the arcs it makes sweep at most the programmed 90 degrees."""
    rc, canon = rs274_canon(tmp_path, translated(tmp_path, MACHINE, PROGRAM, "two.sap", "linuxcnc"))
    assert rc == 0, canon
    sweep = rs274_sweep(canon)
    assert sweep <= 90.001, f"rs274 sweeps {sweep:.1f} degrees of arc; the program turned 90"
