"""Issue 16 rule 4 "feed and spindle words as programmed" and the brief: "canned cycles (written as cycles
or expanded - either is fine if said)"; docs/translate.md rule 4 for the same kind of move: "never a plain
move".

DIN `G84` (tapping) is written as `G1 Z-10 F500`, `M5`, `M4`, `G4 P0`, `G1 Z2`: a plain feed into the hole
with the tap, open to feed override and not tied to the spindle (LinuxCNC `G33.1`/`G84`, 840D `G331`/
`CYCLE84` would be), and neither the header nor docs/translate.md says that any canned cycle was expanded.
"""

import re

import pytest

from .helpers import translate

TAP = """%
N10 G90 G17 G71 G54
N20 T1 M6
N30 S500 M3
N40 G0 X10 Y10 Z5
N50 G84 Z-10 R2 F500
N60 G80
N70 G0 Z50
N80 M30
"""

TAPPING_WORDS = r"G84|G33\.1|G331|G332|CYCLE84|CYCLE840"


@pytest.mark.parametrize("target", ["linuxcnc", "sinumerik840d", "iso"])
def test_a_tapping_cycle_is_a_tapping_move_or_said_or_refused(tmp_path, target):
    rc, text, err = translate(tmp_path, TAP, "tap.din", "--target", target)
    if rc != 0:
        assert "TRN001" in err and not text, err
        return
    said = any(re.search(r"\btap|expanded", line, re.IGNORECASE)
               for line in text.splitlines() if line.startswith(("(", ";")) and "written by ncvm" not in line)
    assert re.search(TAPPING_WORDS, text) or said, (
        f"G84 became plain G1 feeds with M5/M4 and not a word about it:\n{text}")
