"""Issue 16 item 4: "arcs stay arcs ... in the program's plane"; the brief: "plane changes with arcs after
them". SINUMERIK 8xx `G16` selects the plane from an axis list (CL 800 manual L2695-2699, L4146-4147: the
1st axis is the horizontal, the 2nd the vertical axis of the plane). `G16 X Z Y` is the X-Z plane; ncvm
maps only the axis pairs of G17/G18/G19 in their own order and otherwise leaves the old plane in force, so
`G2 X10 Z10 I5 K5` runs, and is translated, as an X-Y arc with a helix in Z (`G2 X10 Y0 Z10 I5 J0`): the
tool swings out in Y, where the program never goes. The arc must stay in the X-Z plane (G18, where it
turns the other way: X horizontal and Z vertical is G18's view mirrored) or be refused."""

from __future__ import annotations

import re

from tests.review16e.helpers import bare_machine, code_lines, translate, write

MACHINE = bare_machine("880 mill", """\
[sin800]
control = "880"
""")

PROGRAM = """%MPF107
N10 G17 G71 G90 G54 G94
N20 G0 X0 Y0 Z0
N30 G16 X Z Y
N40 G2 X10 Z10 I5 K5 F100
N50 M30
"""


def test_g16_x_z_arc_stays_in_the_x_z_plane_or_is_refused(tmp_path):
    write(tmp_path, {"machine.toml": MACHINE, "plane.mpf": PROGRAM})
    rc, out, err = translate(tmp_path, "plane.mpf", "-m", "machine.toml")
    if rc != 0:
        assert out == "" and re.search(r"plane\.mpf:[45]\b.*error", err), err  # refused, naming G16 or its arc
        return
    code = code_lines(out)
    arc = next(line for line in code if re.match(r"G[23]\b", line))
    assert "G18" in code[:code.index(arc)], out
    assert not re.search(r"\b[YJ]", arc), out  # no helix in Y, no centre offset in Y
    assert arc.startswith("G3 "), out  # G2 seen with X horizontal, Z vertical is G3 seen from G18's Z-X
