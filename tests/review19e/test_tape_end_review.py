"""Review of the DIN program end (fix19): nothing after the first block with M2/M30 is read, by run and check
alike (docs/din.md, "Which files run"; decision "tape marks and the first reading"). Each test is one defect
found; its docstring says what is expected and why.

The commands run ``python -m ncvm`` in a temporary folder.
"""

from __future__ import annotations

import re
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


def _x_range(stderr: str) -> tuple[float, float] | None:
    found = re.search(r"program X\[([-\d.,]+),([-\d.,]+)\]", stderr)
    return None if found is None else (float(found[1].replace(",", "")), float(found[2].replace(",", "")))


@pytest.mark.parametrize("start, end", [("% (START)", "% (END)"), ("%O1000", "%O1000")],
                         ids=["tape-marks-with-comments", "tape-marks-with-a-program-number"])
def test_a_tape_mark_with_text_after_it_does_not_let_the_trailer_run(tmp_path, start, end):
    """The fix refuses a ``%`` line in a program that does not open with ``%`` (NC016), because the lines after a
    closing mark would otherwise run: a tape after a comment header ran its trailer. The block reader drops
    *every* line whose text begins with ``%`` (``% (END)``, ``%O1000``), but the tape marks are only the lines
    that are ``%`` alone (``tape.is_percent``): so the same file with a comment or a program number after its
    marks is neither refused nor cut, and the move to X99 after the closing mark runs, "ended normally". rs274
    refuses both files ("Bad character '%' used": its tape mark is ``%`` alone, any other ``%`` is a bad
    character). Expected: refused (exit != 0), or at the very least nothing after the closing mark runs."""
    done = _ncvm(tmp_path, "run", f"(PART 4711)\n{start}\nG1 X10 F100\nG1 X20\n{end}\nG1 X99\n")
    assert done.returncode != 0 or _x_range(done.stderr) == (10.0, 20.0), done.stderr


def test_a_block_after_a_percent_sign_is_not_dropped_silently(tmp_path):
    """A line ``%G1 X50`` (a tape mark and a block run together, as a hand edit or a bad join of two files
    leaves it) is dropped whole by the block reader: the move to X50 silently does not happen and the run
    "ended normally" at X20. rs274 refuses the line ("Bad character '%' used"); ncvm reads it neither as a tape
    mark (it is not ``%`` alone) nor as a block. Expected: refused (exit != 0) or the move made; never a run
    that skips a motion block and says it ended normally."""
    done = _ncvm(tmp_path, "run", "G1 X10 F100\n%G1 X50\nG1 X20\nM30\n")
    assert done.returncode != 0 or _x_range(done.stderr) == (10.0, 50.0), done.stderr
