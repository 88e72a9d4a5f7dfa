"""Issue 16 rule 1: "the output keeps the program's frame"; rule 4: "arcs ... feed and spindle words as
programmed". docs/translate.md rule 1: "Only the axes that move are written: an axis the block did not
move is left out".

A programmed absolute position whose value happens to equal the simulated machine's start position is not
"an axis the block did not move" on the new control: there the axis stands wherever the operator left it.
examples/din/face_and_circle.din programs `N40 G0 X-5 Y0 Z5`; the translation writes `G0 X-5 Z5` and the
whole facing pass (N50..N60) runs at whatever Y the new machine happens to stand on: a silent wrong path.
"""

import subprocess
import sys
from pathlib import Path

import pytest

from .helpers import code_lines, translate

FIRST_MOVE = """%
N10 G90 G17 G71 G54
N20 T1 M6
N30 S2500 M3
N40 G0 X-5 Y0 Z5
N50 G1 Z-0.5 F400
N60 X65 F800
N70 G0 Z20
N80 M30
"""


@pytest.mark.parametrize("target", ["linuxcnc", "sinumerik840d", "iso"])
def test_a_programmed_absolute_axis_equal_to_the_simulated_start_is_written(tmp_path, target):
    rc, text, err = translate(tmp_path, FIRST_MOVE, "first.din", "--target", target)
    assert rc == 0, err
    first = next(line for line in code_lines(text) if line.startswith("G0 ") and "X" in line)
    # the program's own block positions X, Y and Z; the receiving control must get all three
    assert "Y0" in first.replace("Y0.", "Y0"), f"the programmed Y0 of N40 is lost: {first!r}\n{text}"


def test_the_cpl_flange_examples_first_hole_keeps_its_y(tmp_path):
    """examples/cpl/flange.cpl: BOLTCIRC's `N90 G0 X[XH!] Y[YH!]` positions the first hole at X40 Y0; the
    translation writes `G0 X40` (Y never moved in the simulation) and the first hole is drilled at the Y
    where the new machine happens to stand."""
    examples = Path(__file__).parents[2] / "examples" / "cpl"
    out = tmp_path / "flange.ngc"
    r = subprocess.run([sys.executable, "-m", "ncvm", "translate", str(examples / "flange.cpl"), "-o", str(out),
                        "--machine", str(examples / "machine.toml")], capture_output=True, text=True, timeout=120,
                       cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    first_xy = next(line for line in code_lines(out.read_text()) if line.startswith("G0 X"))
    assert "Y" in first_xy, f"the first hole's programmed Y0 is lost: {first_xy!r}"
