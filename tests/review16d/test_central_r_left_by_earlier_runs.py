"""SINUMERIK central R parameters left by earlier runs are input from outside the program (issue 16, "Say
what was frozen": "where the program's path depended on run-time input ..., the output marks the block with a
comment naming the decision and its source line").

Central R900-R999 survive power-off (docs/sin800.md, "The NC state": persisted in the state directory, as
CPL permanent variables are). A CPL program reading a permanent variable an earlier run left gets a
`FROZEN: permanent variable ...` mark (docs/translate.md, What is frozen); a SINUMERIK program whose move
is `X=R900` after `R900=R900+10` is written with the value the state directory happened to hold, without a
mark: translated three times it is `X10`, `X20`, `X30`, and nothing in the file says the position came from
the simulated NC's memory.
"""

from __future__ import annotations

from tests.review16c.helpers import code_lines, ncvm
from tests.review16d.helpers import machine

MACHINE = machine("mill")

PROGRAM = """%MPF5
N10 G17 G71 G90 G54 G94
N20 R900=R900+10
N30 G0 X=R900 Y0 Z50
N40 M30
"""


def test_r900_from_an_earlier_run_is_marked_frozen(tmp_path):
    (tmp_path / "machine.toml").write_text(MACHINE)
    (tmp_path / "count.mpf").write_text(PROGRAM)
    first = ncvm(tmp_path, "run", "count.mpf", "-m", "machine.toml", "--state", "st")
    assert first.returncode == 0, first.stderr
    r = ncvm(tmp_path, "translate", "count.mpf", "-m", "machine.toml", "--state", "st", "-o", "out.ngc")
    assert r.returncode == 0, r.stderr
    out = (tmp_path / "out.ngc").read_text()
    assert any(line.startswith("G0 X20") for line in code_lines(out))  # the earlier run's 10 plus this run's
    assert "FROZEN" in out and "R900" in out, (
        f"the move's X comes from R900 left by an earlier run, and nothing marks it:\n{out}")
