"""din G81-G89 follow LinuxCNC (issue 14 part 3, docs/din.md "Canned cycles": "The errors are rs274's, as
NC009"). rs274 stops at a cycle block that carries a word the cycle does not use; ncvm drills and drops it:
a G81 written for a peck (Q) or a dwell (P) silently drills without either."""

from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

import pytest

PROG = "G21 G17 G90\nS600 M3\nG0 X0 Y0 Z10\nG81 X5 Y5 Z-5 R2 F100 {word}\nG80\nM2\n"
CASES = [("Q3", "Q word with no G5, G10, G64, G73, G76, G83"),
         ("P1", "P word with no G2 G3 G4 G10 G64 G5 G5.2 G76 G82 G86 G88 G89"),
         ("K2", "K word with no G2, G3, G33, G33.1, G76, or G87 to use it")]


@pytest.mark.parametrize("word, rs274_says", CASES)
def test_g81_with_a_word_it_does_not_use_stops(ncvm_run, word, rs274_says):
    """``G81 ... Q3`` (Q belongs to G83/G73), ``P1`` (dwell: G82), ``K2`` (G87): rs274 stops with the message
    named; ncvm ends normally. Expected: NC009 at line 4 and no hole drilled."""
    result, rows, _ = ncvm_run("c.ngc", PROG.format(word=word))
    assert result["status"] == "error" and result["error"]["line"] == 4, (rs274_says, result)
    assert not [r for r in rows if r["call"] == "feed"]


@pytest.mark.skipif(shutil.which("rs274") is None, reason="LinuxCNC rs274 not installed")
@pytest.mark.parametrize("word, rs274_says", CASES)
def test_rs274_stops_at_the_same_blocks(tmp_path: Path, word, rs274_says):
    """The reference: rs274 prints the message and feeds no move."""
    prog = tmp_path / "c.ngc"
    prog.write_text(PROG.format(word=word))
    proc = subprocess.run(["rs274", "-g", str(prog), str(tmp_path / "out.txt")], stdin=subprocess.DEVNULL,
                          capture_output=True, text=True, timeout=60)
    assert rs274_says in proc.stdout + proc.stderr
    assert "STRAIGHT_FEED" not in (tmp_path / "out.txt").read_text()
