"""rw_SymPas moves keep the axes they program (issue 16: "only programmed axes written" fix of an earlier
review; docs/translate.md rule 1: "The axes the block programs are written ..., also one whose value equals
where the axis stands, e.g. the `Y0` of a first move").

`MLAW(A1 := 20.0, A2 := 0.0, A3 := 0.0)` (a straight move of three axes to X20 Y0 Z0) is written `G1 X20`: the
program's A2 := 0 and A3 := 0 are dropped because the simulated axes stood at 0. On the new control Y and Z
stay wherever they are, and the next move (`MLAW(A3 := -1.0)`) plunges there.
"""

from __future__ import annotations

import re

from tests.review16c.helpers import code_lines
from tests.review16d.helpers import machine, translated

MACHINE = machine("gantry")

PROGRAM = """program P;
begin
  TRVL := 50.0; TRAC := 500.0;
  MLAW(A1 := 20.0, A2 := 0.0, A3 := 0.0);
  MLAW(A3 := -1.0);
end.
"""


def test_all_three_programmed_axes_are_written(tmp_path):
    out = translated(tmp_path, MACHINE, PROGRAM, "p.sap")
    first = next(line for line in code_lines(out) if re.match(r"G[01]\b", line))
    assert re.search(r"\bX20\b", first) and re.search(r"\bY0\b", first) and re.search(r"\bZ0\b", first), (
        f"the first move programs A1 A2 A3, written as {first!r}:\n{out}")
