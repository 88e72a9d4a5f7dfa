"""The program's tool offset number is the one written (issue 16: "tool length as `G43 H<n>` (LinuxCNC/ISO) or
the target's equivalent"; "feed and spindle words as programmed").

A retrofitted machine has its own measured tool table, one entry per tool. A DIN program that applies tool 3's
length with tool 1 in the spindle (`T1 M6`, `G43 H3`), or a CPL program whose `H2` selects compensation
group 2, is written `G43 H1`: the new control applies tool 1's length where the old one applied another
(the header's "H1: length 65.5 mm" asks the user to enter a wrong length for tool 1, which every other
program on that machine then uses). A `G44` (length subtracted) becomes `G43` with the header asking for a
negative length: whoever enters the tool's measured length moves the tool twice the length off in Z.
"""

from __future__ import annotations

import re

import pytest

from tests.review16c.helpers import code_lines
from tests.review16d.helpers import machine, translated, translation

MILL = machine("mill", """
[[tool]]
number = 1
length = 40.0
[[tool]]
number = 2
length = 75.0
[[tool]]
number = 3
length = 65.5
""")

DIN_H3 = """G21 G90 G94 G54
T1 M6
G43 H3
S1000 M3
G0 X0 Y0 Z10
G1 Z-1 F300
G0 Z50
M30
"""

CPL_H2 = """N10 G90 G17 G54
N20 T1 M6 H2
N30 S2000 M3
N40 G0 X0 Y0 Z50
N50 G1 Z5 F100
N60 M30
"""

DIN_G44 = DIN_H3.replace("G43 H3", "G44 H1")


@pytest.mark.parametrize("target", ["linuxcnc", "iso"])
def test_din_g43_h3_with_tool_1_stays_h3(tmp_path, target):
    """`T1 M6` then `G43 H3`: the output applies H3, as programmed (the length is tool 3's 65.5 mm)."""
    out = translated(tmp_path, MILL, DIN_H3, "h3.din", target)
    words = [w for line in code_lines(out) for w in re.findall(r"H\d+", line)]
    assert words == ["H3"], f"the program's H3 is written as {words}:\n{out}"


@pytest.mark.parametrize("target", ["linuxcnc", "iso"])
def test_cpl_h2_stays_h2(tmp_path, target):
    """CPL `T1 M6 H2` (compensation group 2, 75 mm): the output applies H2, not H1 with a header asking tool
    1's entry to hold 75 mm."""
    out = translated(tmp_path, MILL, CPL_H2, "h2.cpl", target)
    words = [w for line in code_lines(out) for w in re.findall(r"H\d+", line)]
    assert words == ["H2"], f"the program's H2 is written as {words}:\n{out}"


def test_din_g44_is_not_written_as_g43_with_a_negative_length(tmp_path):
    """ISO has `G44`: `G44 H1` stays `G44 H1`, and the header asks for tool 1's length as measured (40 mm),
    never for a negative length under a `G43`."""
    out = translated(tmp_path, MILL, DIN_G44, "g44.din", "iso")
    assert "length -" not in out, f"the header asks for a negative tool length:\n{out}"
    assert any(line.startswith("G44") or " G44" in line for line in code_lines(out)), out


def test_din_g44_on_linuxcnc_is_refused(tmp_path):
    """LinuxCNC has no `G44`: the translation refuses it (TRN001) rather than ask for a negative tool length."""
    rc, out, err = translation(tmp_path, MILL, DIN_G44, "g44.din")
    assert rc == 1 and "TRN001" in err, f"written with a negative tool length in the header:\n{out}"
