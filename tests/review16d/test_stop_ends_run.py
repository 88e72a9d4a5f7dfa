"""A run that ends at a programmed stop is no complete program (issue 16: "Always a complete file: the
output is written to a temporary file and moved into place only when the run ended normally; it always ends
with the target's program end"; "a failed run leaves no output and says why").

With the SINUMERIK machine setting `m0 = "stop"` (docs/machine-file.md: "M0 ends the run") the run stops at
N60 `M0`. `translate` writes what ran up to there and then the program end `M2`: the cut after the stop
(N70) and the retract (N80) are gone without a word, and on the new control the operator's cycle start after
M0 ends the program with the tool in the part. The translation must run on past the stop (as if start were
pressed, the M0 written) or refuse; never write the part before the stop as the whole program.
"""

from __future__ import annotations

from tests.review16c.helpers import code_lines
from tests.review16d.helpers import machine, translation

MACHINE = machine("mill", """
[sin800]
m0 = "stop"
""")

PROGRAM = """%MPF4
N10 G17 G71 G90 G54 G94
N40 G0 X0 Y0 Z50
N50 G1 Z5 F300
N60 M0
N70 G1 X50
N80 G0 Z50
N90 M30
"""


def test_stop_does_not_cut_the_program_short(tmp_path):
    rc, out, err = translation(tmp_path, MACHINE, PROGRAM, "m0.mpf")
    if rc == 1:  # a refusal is safe: it must say why and leave no file
        assert "M0" in err and out == "", err
        return
    lines = code_lines(out)
    assert "G1 X50" in lines and lines.index("M0") < lines.index("G1 X50"), (
        f"the program after M0 (N70 cut, N80 retract) is missing; the file ends right after the stop:\n{out}")
