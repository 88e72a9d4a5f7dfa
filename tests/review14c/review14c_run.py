"""What the review-14c tests share: ``ncvm run`` in a real process and ``rs274 -g`` on the same program, both
reduced to the machine position (slide) of every move, so the two can be compared move by move."""

from __future__ import annotations

import re
import shutil
import subprocess
from pathlib import Path

import pytest

from tests.review14.review14_helpers import make_runner

RS274 = shutil.which("rs274")
needs_rs274 = pytest.mark.skipif(RS274 is None, reason="rs274 not installed (Debian package linuxcnc-uspace)")
AXES = "XYZ"
MACHINE = "".join(f'[[axis]]\nname = "{a}"\nmin = -1000.0\nmax = 1000.0\nrapid = 60000.0\nmax_feed = 60000.0\n'
                  f'accel = 100000000.0\n' for a in AXES)
MACHINE += "[[tool]]\nnumber = 1\nlength = 25.4\nradius = 2.54\n"
TOOL_TABLE = "T1 P1 D0.2 Z1.0 ;\n"   # the same tool for rs274, which reads the table in inches
CALL = re.compile(r"(STRAIGHT_TRAVERSE|STRAIGHT_FEED|ARC_FEED|SET_G5X_OFFSET|SET_G92_OFFSET|"
                  r"USE_TOOL_LENGTH_OFFSET)\((.*)\)")


def ncvm(tmp_path: Path, text: str, name: str = "prog.ngc") -> tuple[dict, list[tuple]]:
    """(JSON result, [(kind, (X, Y, Z))] machine end point of each move) of ``ncvm run``."""
    result, rows, _stderr = make_runner(tmp_path)(name, text, machine=MACHINE)
    moves = [(r["call"], tuple(round(r["end"][a], 4) for a in AXES))
             for r in rows if r["call"] in ("rapid", "feed", "arc")]
    return result, moves


def reference(tmp_path: Path, text: str) -> list[tuple]:
    """[(kind, (X, Y, Z))] machine end point of each move of ``rs274 -g`` (offsets and tool length added back)."""
    (tmp_path / "ref.ngc").write_text(text)
    (tmp_path / "tool.tbl").write_text(TOOL_TABLE)
    proc = subprocess.run([RS274, "-t", str(tmp_path / "tool.tbl"), "-g", str(tmp_path / "ref.ngc")],
                          capture_output=True, text=True, input="", timeout=60)
    g5x, g92, tlo, moves = [0.0] * 3, [0.0] * 3, [0.0] * 3, []
    for line in proc.stdout.splitlines():
        m = CALL.search(line)
        if not m:
            continue
        name, args = m.groups()
        nums = [float(x) for x in args.replace(",", " ").split()]
        if name == "SET_G5X_OFFSET":
            g5x = nums[1:4]
        elif name == "SET_G92_OFFSET":
            g92 = nums[0:3]
        elif name == "USE_TOOL_LENGTH_OFFSET":
            tlo = nums[0:3]
        else:
            end = (nums[0], nums[1], nums[5]) if name == "ARC_FEED" else tuple(nums[0:3])
            kind = {"STRAIGHT_TRAVERSE": "rapid", "STRAIGHT_FEED": "feed", "ARC_FEED": "arc"}[name]
            moves.append((kind, tuple(round(end[i] + g5x[i] + g92[i] + tlo[i], 4) for i in range(3))))
    return moves
