"""Review of issue 16 (`ncvm translate`) as a retrofitter would use it: each test cites the issue's rule."""

import subprocess
import sys
from pathlib import Path

import pytest


def translate(tmp_path: Path, source: str, name: str = "prog.din", *args: str) -> tuple[int, str, str]:
    prog = tmp_path / name
    prog.write_text(source)
    out = tmp_path / "out.ngc"
    r = subprocess.run(
        [sys.executable, "-m", "ncvm", "translate", str(prog), "-o", str(out), "--source-comments", *args],
        capture_output=True, text=True, timeout=120,
    )
    return r.returncode, out.read_text() if out.exists() else "", r.stderr


def body(text: str) -> list[str]:
    """The output's code lines, comments stripped."""
    lines = []
    for line in text.splitlines():
        code = line.split("(")[0].split(";")[0].strip()
        if code and code != "%":
            lines.append(code)
    return lines


# Issue 16, rule 4 "Program order kept: spindle and coolant functions where the program put them".
# docs/translate.md rule 6: "M5 and M9 of a block are written after that block's move".
# Block N80 stops the spindle with its feed move; block N90 is the retract with M9. The M5 of N80
# belongs right after N80's move, before N90's retract; ncvm held it back past the retract
# (the pending list is flushed only when *no* pending entry comes from the moving block).
PLANE_AND_ORDER = """%
N10 G90 G17 G71 G54
N20 T1 M6
N30 S1000 M3 M8
N40 G0 X10 Y0 Z0
N80 G1 X20 F100 M5
N90 G0 Z50 M9
N100 M30
"""


@pytest.mark.parametrize("target", ["linuxcnc", "sinumerik840d", "iso"])
def test_m5_of_a_block_is_written_before_the_next_blocks_move_issue16_rule4(tmp_path, target):
    rc, text, err = translate(tmp_path, PLANE_AND_ORDER, "order.din", "--target", target)
    assert rc == 0, err
    code = body(text)
    feed = next(i for i, c in enumerate(code) if c.startswith("G1 X20"))
    retract = next(i for i, c in enumerate(code) if c.startswith("G0") and "Z50" in c)
    m5 = code.index("M5")
    assert feed < m5 < retract, f"M5 of N80 must follow N80's move and precede N90's retract: {code}"


# Same rule: an M5 alone in its block, then a retract block with M9: the program stops the spindle
# BEFORE the retract; ncvm wrote the M5 after it.
M5_ALONE = """%
N10 G90 G17 G71 G54
N20 T1 M6
N30 S1000 M3 M8
N40 G0 X10 Y0 Z0
N50 G1 X20 F100
N60 M5
N70 G0 Z50 M9
N80 M30
"""


def test_m5_alone_in_its_block_stays_before_the_retract_issue16_rule4(tmp_path):
    rc, text, err = translate(tmp_path, M5_ALONE, "alone.din")
    assert rc == 0, err
    code = body(text)
    retract = next(i for i, c in enumerate(code) if c.startswith("G0") and "Z50" in c)
    assert code.index("M5") < retract, f"the program stopped the spindle before the retract: {code}"
