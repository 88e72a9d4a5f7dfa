"""840D: the tool length after a tool change (issue 16: "SINUMERIK 840D (G-code in 840D syntax: ... `T`/`D`
...)"; "tool length as `G43 H<n>` (LinuxCNC/ISO) or the target's equivalent"; docs/translate.md: "a D is an
edge of the active tool").

On the 840D a D number is an edge of the tool in the spindle, and a tool change activates the new tool's
default edge (D1 unless the machine data say otherwise). The translation writes `T<n> M6` with no `D`
whenever its frame did not change:

- a program with no tool length compensation at all gets `T1 M6` and no `D0`: the 840D applies T1's D1,
  which the run never did (the header says "no tool length compensation was used");
- a DIN program keeps `G43 H1` (tool 1's 40 mm) through `T3 M6`, as DIN and LinuxCNC do; the run moves tool
  3 with 40 mm. The 840D output writes `T3 M6` and no D, and its header lists only "tool T1 edge D1": T3's
  edge is whatever the new control holds (0 when the user set up only what the header lists), and tool 3
  plunges up to 40 mm deeper than the simulated run.
"""

from __future__ import annotations

import re

from tests.review16c.helpers import code_lines
from tests.review16d.helpers import machine, translated

MILL = machine("mill", """
[[tool]]
number = 1
length = 40.0
[[tool]]
number = 3
length = 65.5
""")

NO_LENGTH = """G21 G90 G94 G54
T1 M6
S1000 M3
G0 X0 Y0 Z10
G1 Z-1 F300
G0 Z50
M30
"""

H1_KEPT = """G21 G90 G94 G54
T1 M6
G43 H1
S1000 M3
G0 X0 Y0 Z10
G1 Z-1 F300
G0 Z50
T3 M6
G0 X10 Y10 Z10
G1 Z-1
G0 Z50
M30
"""


def _d_before_first_move_after(lines, tool_change):
    i = lines.index(tool_change)
    for line in lines[i + 1:]:
        if re.match(r"G[0-3]\b", line):
            return None
        if re.search(r"\bD\d+", line):
            return re.search(r"\bD(\d+)", line).group(1)
    return None


def test_no_length_is_d0_after_the_tool_change(tmp_path):
    """No tool length in the run: `D0` after `T1 M6`, before the first move."""
    lines = code_lines(translated(tmp_path, MILL, NO_LENGTH, "nolen.din", "sinumerik840d"))
    assert _d_before_first_move_after(lines, "T1 M6") == "0", (
        f"T1 M6 without D0: the 840D applies T1's default edge, the run applied no length:\n{lines}")


def test_length_kept_through_the_tool_change_is_an_edge_of_the_new_tool(tmp_path):
    """The 40 mm the run kept through `T3 M6` is an edge of T3 in the output, listed in the header."""
    out = translated(tmp_path, MILL, H1_KEPT, "kept.din", "sinumerik840d")
    lines = code_lines(out)
    d = _d_before_first_move_after(lines, "T3 M6")
    assert d is not None and d != "0", f"T3 M6 and no D: the 840D moves T3 with its own default edge:\n{out}"
    assert re.search(rf"tool T3 edge D{d}: length 40 mm", out), f"the header lists no length for T3:\n{out}"


def test_frame_machine_keeps_d0_after_each_tool_change(tmp_path):
    """`--frame machine` includes every tool length in the positions and selects `G500 D0`; the `T1 M6` and
    `T3 M6` after it activate each tool's default edge on the 840D, adding the length a second time. A `D0`
    must follow each tool change before the next move."""
    out = translated(tmp_path, MILL, H1_KEPT, "kept.din", "sinumerik840d", "--frame", "machine")
    lines = code_lines(out)
    for change in ("T1 M6", "T3 M6"):
        assert _d_before_first_move_after(lines, change) == "0", f"no D0 after {change}:\n{out}"
