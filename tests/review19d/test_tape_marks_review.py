"""Review of the DIN tape marks (pct19): a program opened with ``%``, cut short or followed by other text, run
as a user of LinuxCNC's rs274 would run it. Each test is one defect found; its docstring says what is expected
and why (the rs274 rules: its interpreter's ``open`` and ``read_text``).

The commands run ``python -m ncvm`` in a temporary folder.
"""

from __future__ import annotations

import re
import subprocess
import sys

NCVM = [sys.executable, "-m", "ncvm"]


def _run(tmp_path, text: str) -> subprocess.CompletedProcess:
    (tmp_path / "part.ngc").write_text(text)
    return subprocess.run(NCVM + ["run", "-d", "din", "part.ngc"], cwd=tmp_path, capture_output=True, text=True,
                          timeout=120)


def _x_range(stderr: str) -> tuple[float, float] | None:
    found = re.search(r"program X\[([-\d.,]+),([-\d.,]+)\]", stderr)
    return None if found is None else (float(found[1].replace(",", "")), float(found[2].replace(",", "")))


def test_a_percent_tape_after_a_comment_header_does_not_run_its_trailer(tmp_path):
    """A CAM file with a comment line put before its ``%`` tape start (a header an operator or a DNC program
    added) and a trailer after the closing ``%``: rs274 opens it as a file that does not use percents (the first
    non-blank line is not ``%`` alone) and then refuses its ``%`` line 2 ("Bad character '%' used"), so nothing
    of it runs. ncvm ignores both ``%`` lines (no tape mark in a file not opened with ``%``) and runs the trailer
    after the closing ``%`` too: line 6's move to X99 is made and the run "ended normally" -- exactly the
    silently wrong run pct19 removed for files that open with ``%``. Expected: the file is refused, or at the
    very least nothing after the closing ``%`` runs."""
    done = _run(tmp_path, "(PART 4711 from the DNC)\n%\nG1 X10 F100\nG1 X20\n%\nG1 X99\n")
    assert done.returncode != 0 or _x_range(done.stderr) == (10.0, 20.0), done.stderr


def test_text_after_m30_in_a_percent_program_is_not_read(tmp_path):
    """rs274 reads no line after the block with M2/M30 that ends the program (the docs of pct19 say so: "reach
    a block with M2/M30, after which rs274 reads no more"), so a ``%`` program whose M30 is followed by text that
    is not G-code (a post-processor's trailer, a second program's garbage, a file cut mid-copy after M30) runs
    to its M30 and ends normally. ncvm reads on past M30 and refuses the whole program with NC001 at line 4:
    the program rs274 runs is refused. Expected: it runs to M30 (exit 0, the move to X10 made); ``ncvm check``
    may warn about the lines after M30."""
    done = _run(tmp_path, "%\nG1 X10 F100\nM30\nG1 X20 Q$$\n")
    assert done.returncode == 0, done.stderr
    assert _x_range(done.stderr) == (10.0, 10.0), done.stderr
