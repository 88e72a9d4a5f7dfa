"""`ncvm check` of a CPL program with G41/G42 must say that the run will refuse it.

Issue 14 §5: "ncvm check reports every G/M function and address the profile refuses ... so that a clean
check means the run will not stop on an unsupported function". For CPL, G41/G42 stop every run with NC005
(docs/decisions.md, "CPL ... G41/G42 stop with NC005 naming the missing source"), yet check is clean:
check green, run red -- the very defect issue 14 opens with. The din profile warns (NC004/NC005) as asked.
"""

from __future__ import annotations

from pathlib import Path

from ncvm.api import check, run
from ncvm.runtime.session import RunOptions

PROGRAM = "N10 G0 X0 Y0\nN20 G41 G1 X10 Y10 F100\nN30 G40 X0\nM30\n"


def test_check_warns_of_g41_that_the_cpl_run_refuses(tmp_path: Path):
    (tmp_path / "machine.toml").write_text('[[axis]]\nname = "X"\n[[axis]]\nname = "Y"\n[[axis]]\nname = "Z"\n')
    prog = tmp_path / "g41.cpl"
    prog.write_text(PROGRAM)
    result, _ = run(prog, dialect="cpl", machine=tmp_path / "machine.toml",
                    options=RunOptions(state_dir=tmp_path / ".s"))
    assert result["error"]["code"] == "NC005" and result["error"]["line"] == 2
    diags = check(prog, dialect="cpl", machine=tmp_path / "machine.toml")
    assert [(d.code, d.span.line) for d in diags] == [("NC005", 2)], diags
