"""The spindle after a tool change: M6 stops it on the new control, so the translation turns it on again
before the next move, once: where the program restarts it itself, its own word is the only one written."""

from __future__ import annotations

import pytest

from tests.review16c.helpers import code_lines, translate
from tests.review16d.helpers import machine

MILL = machine("mill", "[[tool]]\nnumber = 1\nlength = 40.0\n[[tool]]\nnumber = 2\nlength = 50.0\n")

RESTARTED = """G21 G90 G94 G54
T1 M6
S2000 M3
G0 X0 Y0 Z10
T2 M6
S2000 M3
G0 X10 Y10 Z10
M30
"""

NOT_RESTARTED = RESTARTED.replace("T2 M6\nS2000 M3\n", "T2 M6\n")


def _lines(tmp_path, source, target):
    (tmp_path / "machine.toml").write_text(MILL)
    rc, out, err = translate(tmp_path, source, "spindle.din", "--target", target, "-m", "machine.toml",
                             out_name=f"out.{target}")
    assert rc == 0, err
    return code_lines(out)


@pytest.mark.parametrize("target", ["linuxcnc", "sinumerik840d"])
def test_program_restart_after_m6_is_written_once(tmp_path, target):
    lines = _lines(tmp_path, RESTARTED, target)
    after = lines[lines.index("T2 M6"):]
    assert after.count("M3 S2000") == 1, after


@pytest.mark.parametrize("target", ["linuxcnc", "sinumerik840d"])
def test_spindle_turned_on_again_after_m6_before_the_next_move(tmp_path, target):
    lines = _lines(tmp_path, NOT_RESTARTED, target)
    after = lines[lines.index("T2 M6"):]
    assert after.count("M3 S2000") == 1 and after.index("M3 S2000") < after.index("G0 X10 Y10 Z10"), after
