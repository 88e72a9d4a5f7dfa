"""A SINUMERIK T word without M6 is not dropped (issue 16: "tool length as `G43 H<n>` ... or the target's
equivalent"; "840D ... `T`/`D`"; docs/translate.md rule 7: what the old control handed to its PLC is written
as a comment and listed in the header).

On the SINUMERIK 800 the T word goes to the PLC, which selects (on many machines changes) the tool; `M6` is a
machine builder's M function. `N20 T1 D1` with no M6 is written as `D1` alone (840D: an edge of no tool, the
header "tool offset D1") and `G43 H1` (LinuxCNC): the program's tool selection is gone from the output, so
the user cannot tell which tool the program ran with.
"""

from __future__ import annotations

import re

import pytest

from tests.review16d.helpers import machine, translated

MACHINE = machine("mill", """
[[tool]]
number = 1
[sin800]
tool_offsets = [ { area = 0, d = 1, p = [1, 20, 85.0, 0.0, 4.25, 0.1] } ]
""")

PROGRAM = """%MPF7
N10 G17 G71 G90 G54 G94
N20 T1 D1
N30 S2000 M3
N40 G0 X0 Y0 Z50
N50 G1 Z5 F300
N60 M30
"""


@pytest.mark.parametrize("target", ["linuxcnc", "sinumerik840d", "iso"])
def test_t1_is_in_the_output(tmp_path, target):
    out = translated(tmp_path, MACHINE, PROGRAM, "t.mpf", target)
    assert re.search(r"\bT1\b", out), f"the program's T1 is nowhere in the output:\n{out}"
