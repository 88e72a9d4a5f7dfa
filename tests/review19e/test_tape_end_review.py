"""Review of the DIN program end (fix19): nothing after the first block with M2/M30 is read, by run and check
alike (docs/din.md, "Which files run"; decision "tape marks and the first reading"). Each test is one defect
found; its docstring says what is expected and why.

The commands run ``python -m ncvm`` in a temporary folder.
"""

from __future__ import annotations

import subprocess
import sys

import pytest

NCVM = [sys.executable, "-m", "ncvm"]


def _ncvm(tmp_path, command: str, text: str) -> subprocess.CompletedProcess:
    (tmp_path / "part.ngc").write_text(text)
    return subprocess.run(NCVM + [command, "-d", "din", "part.ngc"], cwd=tmp_path, capture_output=True, text=True,
                          timeout=120)


@pytest.mark.parametrize("after", ["G1 A5", "G1 G0 X5"], ids=["axis-the-machine-lacks", "two-motion-codes"])
def test_check_does_not_refuse_lines_after_m30_that_the_run_never_reads(tmp_path, after):
    """docs/din.md: "Nothing after the first block with M2/M30 is read", as rs274 reads no line after it; the
    run does so (it ends normally, exit 0). ``ncvm check`` of the same file still reads the blocks after M30 for
    the machine's axes (NC011 for ``A5`` on an X Y Z machine) and the block rules (NC015 for G1 with G0) and
    fails with exit 1: check says the program has an error where run and rs274 run it to its end. Syntax errors
    there are already dropped by the fix; the other checks must be too (a warning would be acceptable, an error
    is not). Expected: check exits 0, as for a syntax error after M30."""
    text = f"G1 X1 F100\nM30\n{after}\n"
    ran = _ncvm(tmp_path, "run", text)
    assert ran.returncode == 0, ran.stderr
    checked = _ncvm(tmp_path, "check", text)
    assert checked.returncode == 0, checked.stdout + checked.stderr
