"""A tool length rewritten after moves with it (issue 16: "tool length as `G43 H<n>` ... never writes offset
tables"; "The header lists the offsets and tools the simulation used, so the user can set up the new control").

One `H1` of the new control's tool table holds one length. A SINUMERIK program that rewrites its D1 length
(`@420`, TOS) after moves with D1 is written as `G43 H1` twice with the header "length 85.1 then 95.1 mm":
whatever the user sets, one half of the program runs 10 mm off in Z on the new machine. The zero offset's
case is refused (TRN001, docs/translate.md rule 2: "a G54 of the new control holds one value"); the tool
length's must be too, or written so that the new control follows it.
"""

from __future__ import annotations

import json
import re

from tests.review16c.helpers import ncvm
from tests.review16d.helpers import machine, translation

MACHINE = machine("mill", """
[[tool]]
number = 1
[sin800]
tool_offsets = [ { area = 0, d = 1, p = [1, 20, 85.0, 0.0, 4.25, 0.1] } ]
""")

PROGRAM = """%MPF1
N10 G17 G71 G90 G54 G94
N20 T1 M6 D1
N30 S2000 M3
N40 G0 X0 Y0 Z50
N50 G1 Z5 F300
N60 @420 K0 K1 K2 K95
N70 G0 Z50
N80 G1 Z5
N90 M30
"""


def test_the_simulation_ran_two_lengths(tmp_path):
    """The run itself: the second plunge stands 10 mm higher in the machine (D1 is 95.1 mm then)."""
    (tmp_path / "machine.toml").write_text(MACHINE)
    (tmp_path / "tos.mpf").write_text(PROGRAM)
    r = ncvm(tmp_path, "run", "tos.mpf", "--trace", "t.jsonl", "-m", "machine.toml")
    assert r.returncode == 0, r.stderr
    calls = [json.loads(line) for line in (tmp_path / "t.jsonl").read_text().splitlines()]
    assert [c["length"] for c in calls if c["call"] == "tool_offset"] == [85.1, 95.1]


def test_linuxcnc_h1_cannot_hold_both_lengths(tmp_path):
    """Refused (TRN001 at N60) or written with a length the new control applies: never `G43 H1` twice under
    a header that asks the user to set H1 to 85.1 and 95.1 at once."""
    rc, out, err = translation(tmp_path, MACHINE, PROGRAM, "tos.mpf", "linuxcnc")
    if rc == 1:
        assert "TRN001" in err and "N60" in err, err
        assert out == ""
        return
    header_lengths = re.findall(r"H1: length ([^)]*) mm", out)
    assert header_lengths and " then " not in header_lengths[0], (
        f"one tool table entry H1 is asked to hold two lengths ({header_lengths}); the moves after N60 run "
        f"10 mm off on the new control:\n{out}")


def test_840d_d1_cannot_hold_both_lengths(tmp_path):
    """The same on the 840D: edge D1 of T1 holds one length."""
    rc, out, err = translation(tmp_path, MACHINE, PROGRAM, "tos.mpf", "sinumerik840d")
    if rc == 1:
        assert "TRN001" in err, err
        return
    assert " then " not in out, f"D1 of T1 is asked to hold two lengths:\n{out}"
