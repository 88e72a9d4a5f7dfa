"""Issue 16: anything a target cannot say "stops with a clear error naming the block"; the quality bar: "Bad
input gives `file:line:col: error CODE: message` with the source line".

CPL `G53` is the modal "axis zero shift off" (docs/profiles.md, L2302). The translation refuses it (no
zero offset to select on the new control), but its message names no block at all: `error TRN001:
translation ... refused: the program selects no zero offset ...` — in a long program the user cannot find
which block to change.
"""

from pathlib import Path

from .helpers import translate

MACHINE = Path(__file__).parents[2] / "examples" / "cpl" / "machine.toml"

PROGRAM = """(G53: zero shift off)
N10 G90 G17 G54 T1 M6
N20 G0 X0 Y0 Z5
N30 G53 G0 X10 Y10
N40 G1 X20 F100
N60 G54 G0 X0
M30
"""


def test_zero_offset_refusal_names_the_block(tmp_path):
    rc, text, err = translate(tmp_path, PROGRAM, "g53.cpl", "--machine", str(MACHINE))
    assert rc == 1 and "TRN001" in err, err
    assert err.startswith(str(tmp_path / "g53.cpl") + ":4") or "g53.cpl:4" in err, (
        "the refusal does not name the G53 block (line 4):\n" + err)
