"""Issue 16 item 1: "A header comment lists the offsets and tools the simulation used, so the user can set
up the new control"; docs/translate.md: "840D: per tool, `tool T2 edge D1`, since a D is an edge of the
active tool". A DIN program prepares T2, changes it with a bare M6 and selects G43 H2 in the next block:
the 840D output writes `T2 M6` then `D1` (the H1 length still in force at the change) then `D2`, but the
header lists only `tool T2 edge D2`. The 840D stops with an alarm at a D number its active tool does not
have (alarm 17180, illegal D number): every edge the output selects must be in the setup list."""

from __future__ import annotations

import re

from tests.review16e.helpers import bare_machine, code_lines, translate, write

MACHINE = bare_machine("two tools", """\
[[tool]]
number = 1
length = 50.0
[[tool]]
number = 2
length = 75.0
""")

PROGRAM = """N10 G21 G90 G17 G54
N20 T1 M6
N30 G43 H1 G0 X0 Y0 Z50
N40 T2
N50 G1 X10 F100
N60 M6
N70 G43 H2 G0 X20
N80 M30
"""


def test_every_edge_the_840d_output_selects_is_listed(tmp_path):
    write(tmp_path, {"machine.toml": MACHINE, "tools.din": PROGRAM})
    rc, out, err = translate(tmp_path, "tools.din", "-m", "machine.toml", "--target", "sinumerik840d")
    assert rc == 0, err
    listed = set(re.findall(r"tool T(\d+) edge D(\d+)", out))
    tool, selected = None, set()
    for line in code_lines(out):
        change = re.search(r"\bT(\d+) M6\b", line)
        if change:
            tool = change.group(1)
        for edge in re.findall(r"\bD(\d+)\b", line):
            if edge != "0":
                selected.add((tool, edge))
    assert selected <= listed, (selected - listed, out)
