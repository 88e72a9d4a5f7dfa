"""ISO: a feed move in machine coordinates (issue 16: "plain ISO/Fanuc style"; "feed and spindle words as
programmed"; "where ncvm cannot do what the control does, it refuses clearly").

On a Fanuc-style control `G53` is a one-shot positioning that always moves at rapid traverse, whatever the
motion mode (the G01 in force is taken up again after it). The DIN block `G53 G1 Z-20 F100` (a slow approach
in machine coordinates, e.g. to a tool setter) is written for ISO as `G53 G1 Z-20. F100`: the new control
rapids there. LinuxCNC's `G53 G1` feeds, so its output is right; the ISO output must refuse the move
(TRN001 naming the block) or write it as a feed move that the control makes at F100.
"""

from __future__ import annotations

import re

from tests.review16c.helpers import code_lines
from tests.review16d.helpers import machine, translation

MACHINE = machine("mill", """
[offsets]
G54 = [200.0, 150.0, -200.0]
""")

PROGRAM = """G21 G90 G94 G54
G0 X0 Y0 Z10
G53 G1 Z-20 F100
G53 G0 Z0
M30
"""


def test_iso_g53_feed_is_not_a_rapid(tmp_path):
    rc, out, err = translation(tmp_path, MACHINE, PROGRAM, "g53.din", "iso")
    if rc == 1:
        assert "TRN001" in err and "g53.din:3" in err, err
        return
    g53_feeds = [line for line in code_lines(out) if re.search(r"\bG53\b", line) and re.search(r"\bG0?1\b", line)]
    assert not g53_feeds, f"a Fanuc-style control moves {g53_feeds} at rapid traverse:\n{out}"
