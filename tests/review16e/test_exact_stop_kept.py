"""Issue 16 item 4 "Program order kept ... as programmed" and the trust rule (a silently wrong answer is the
worst defect): a DIN program that selects exact stop (`G61`, docs/din.md: G61 modal exact stop, `G64 P`
path tolerance) for sharp pocket corners is translated without it, so the new control blends the corners
(LinuxCNC's power-on G64 without a tolerance rounds them as fast as it can) and cuts them off. Each target
has the function: LinuxCNC `G61` / `G64 P<tol>`, SINUMERIK 840D `G60` (exact stop) / `G64`, Fanuc-style
`G61` / `G64`."""

from __future__ import annotations

import pytest

from tests.review16e.helpers import code_lines, translate, write

PROGRAM = """N10 G21 G90 G17 G54
N20 G61
N30 G0 X0 Y0 Z5
N40 G1 Z-1 F500
N50 X50
N60 Y50
N70 G64 P0.01
N80 X0
N90 M30
"""

EXACT = {"linuxcnc": "G61", "sinumerik840d": "G60", "iso": "G61"}
FIRST_CORNER = {"linuxcnc": "G1 X50", "sinumerik840d": "G1 X50", "iso": "G1 X50."}


@pytest.mark.parametrize("target", ["linuxcnc", "sinumerik840d", "iso"])
def test_exact_stop_reaches_the_translation(tmp_path, target):
    write(tmp_path, {"pocket.din": PROGRAM})
    rc, out, err = translate(tmp_path, "pocket.din", "--target", target)
    assert rc == 0, err
    code = code_lines(out)
    before = code[:code.index(FIRST_CORNER[target])]
    assert any(EXACT[target] in line.split() for line in before), out


def test_path_tolerance_reaches_the_linuxcnc_translation(tmp_path):
    write(tmp_path, {"pocket.din": PROGRAM})
    rc, out, err = translate(tmp_path, "pocket.din")
    assert rc == 0, err
    code = code_lines(out)
    assert any("G64 P0.01" in line for line in code[:code.index("G1 X0")]), out


def test_sinumerik_exact_stop_reaches_the_linuxcnc_translation(tmp_path):
    """SINUMERIK 8xx `G60` (exact stop, docs/sin800.md "G60/G64") is LinuxCNC's `G61`."""
    program = "%MPF110\nN10 G17 G71 G90 G54 G94 G60\nN20 G0 X0 Y0 Z5\nN30 G1 X50 F500\nN40 Y50\nN50 M30\n"
    write(tmp_path, {"corner.mpf": program})
    rc, out, err = translate(tmp_path, "corner.mpf")
    assert rc == 0, err
    code = code_lines(out)
    assert any("G61" in line.split() for line in code[:code.index("G1 X50 F500")]), out
