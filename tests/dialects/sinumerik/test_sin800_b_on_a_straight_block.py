"""`B` on a straight block of a SINUMERIK contour is not silently ignored.

CL 800 planning guide L4214-4218, the contour sub-program of the INT SEC example: `N5 X400 Y50 B100`.
Issue 14 §1: "B on a straight block of a contour ... implement what it shows (a rounding between the
elements, counted by PREP REF), or refuse it clearly; do not ignore it." Today the block runs as if B were
not there: a sharp corner, path 200 mm, "ended normally".
"""

from __future__ import annotations

import math
from pathlib import Path

from ncvm.api import run
from ncvm.runtime.session import RunOptions

MACHINE = '[[axis]]\nname = "X"\n[[axis]]\nname = "Y"\n[[axis]]\nname = "Z"\n'


def test_b_radius_on_a_straight_block_rounds_the_corner_or_is_refused_l4216(tmp_path: Path):
    (tmp_path / "machine.toml").write_text(MACHINE)
    prog = tmp_path / "b.mpf"
    prog.write_text("%MPF1\nN1 G0 X0 Y0\nN5 G1 X100 Y0 B10 F100\nN6 X100 Y100\nN30 M30\n")
    result, _ = run(prog, dialect="sin800", machine=tmp_path / "machine.toml",
                    options=RunOptions(state_dir=tmp_path / ".s"))
    if result["error"] is not None:
        assert result["error"]["line"] == 3, result["error"]
        return
    rounded = 200.0 - 2 * 10.0 + math.pi * 10.0 / 2  # a 10 mm rounding between the two lines
    assert abs(result["motion"]["feed_length"] - rounded) < 1e-3, result["motion"]
