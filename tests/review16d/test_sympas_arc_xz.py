"""rw_SymPas circles in the X-Z plane (issue 16: "arcs stay arcs (I/J/K or the target's radius form), in the
program's plane"; "makes the same motions to the same end points").

`MCRW(A1 := 10.0, A3 := 0.0, PHI := 90.0)` is a quarter circle in the plane of axes 1 and 3 (X and Z),
counter-clockwise from axis 1 towards axis 3. That plane is G18's (Z-X, so the turn is a `G2` there). The
translation refuses it (TRN001 "an arc in the plane of X and Z, which has no G17/G18/G19") while the same
circle in the Y-Z plane is written `G19 G3`: a card program with a circle in X-Z cannot be moved at all.
"""

from __future__ import annotations

import re

from tests.review16c.helpers import code_lines, needs_rs274, rs274_canon, trace_work
from tests.review16d.helpers import machine, translated

MACHINE = machine("gantry")

PROGRAM = """program P;
begin
  TRVL := 50.0; TRAC := 500.0;
  MLAW(A1 := 50.0, A2 := 50.0, A3 := 0.0);
  MCRW(A1 := 10.0, A3 := 0.0, PHI := 90.0);
end.
"""


def test_xz_circle_is_a_g18_arc(tmp_path):
    lines = code_lines(translated(tmp_path, MACHINE, PROGRAM, "xz.sap"))
    arc = [i for i, line in enumerate(lines) if re.match(r"G[23]\b", line)]
    assert len(arc) == 1 and "G18" in lines[:arc[0]], lines
    assert lines[arc[0]].startswith("G2 "), f"counter-clockwise from X towards Z is G2 in G18: {lines[arc[0]]}"


@needs_rs274
def test_rs274_reads_the_same_quarter_circle(tmp_path):
    out = translated(tmp_path, MACHINE, PROGRAM, "xz.sap")
    rc, canon = rs274_canon(tmp_path, out)
    assert rc == 0, canon
    arcs = re.findall(r"ARC_FEED\(([^)]*)\)", canon)
    assert len(arcs) == 1
    z_end, x_end, z_c, x_c, rotation = (float(v) for v in arcs[0].split(",")[:5])
    work = [w for call, w in trace_work(tmp_path, "xz.sap", "-m", "machine.toml") if call == "arc"][0]
    assert (round(x_end, 4), round(z_end, 4)) == (round(work["X"], 4), round(work["Z"], 4)) == (60.0, -10.0)
    assert (x_c, z_c) == (60.0, 0.0) and rotation == -1  # a quarter turn, clockwise seen from +Y
