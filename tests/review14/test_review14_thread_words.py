"""A word a thread block does not use is never silently ignored (issue 14 part 1: "never silently ignore a
word"). din: LinuxCNC's rs274 (the reference, docs/din.md "Threads") stops at such a G33 block; SINUMERIK:
the radius address on a straight block rounds a corner (CL 800 manual L4237, docs/sin800.md), which a
thread cannot do, so it must be refused as ncvm refuses it on G0."""

from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

import pytest

DIN = "G21 G18 G90\nS600 M3\nG0 X10 Z0\nG33 Z-5 K1 {word}\nM2\n"


@pytest.mark.parametrize("word, rs274_says", [("R5", "R word with no g code that uses it"),
                                              ("I3", "I word with no G2, G3"),
                                              ("Q3", "Q word with no G5")])
def test_din_g33_with_a_word_it_does_not_use_stops(ncvm_run, word, rs274_says):
    """rs274 stops at ``G33 Z-5 K1 R5`` ("R word with no g code that uses it"), likewise for I3 and Q3;
    ncvm cuts the thread and ends normally, the word dropped. Expected: NC009 at line 4."""
    result, _, _ = ncvm_run("t.ngc", DIN.format(word=word))
    assert result["status"] == "error" and result["error"]["line"] == 4, (rs274_says, result)


@pytest.mark.skipif(shutil.which("rs274") is None, reason="LinuxCNC rs274 not installed")
def test_rs274_itself_stops_at_g33_with_r(tmp_path: Path):
    """The reference the din test above follows: rs274 prints the error and emits no move for the block."""
    prog = tmp_path / "t.ngc"
    prog.write_text(DIN.format(word="R5"))
    proc = subprocess.run(["rs274", "-g", str(prog), str(tmp_path / "out.txt")], stdin=subprocess.DEVNULL,
                          capture_output=True, text=True, timeout=60)
    assert "R word with no g code that uses it" in proc.stdout + proc.stderr
    assert "START_SPEED_FEED_SYNCH" not in (tmp_path / "out.txt").read_text()


@pytest.mark.parametrize("block", ["N40 G33 Z-20 K1.5 B5", "N40 G34 Z-20 K1 F0.1 B5"])
def test_sin800_thread_with_the_radius_address_is_refused(ncvm_run, block):
    """``G33 Z-20 K1.5 B5``: B is the radius address (machine data, default B); on a straight block it asks
    for a rounding to the next block, which a thread cannot make. ncvm cuts the thread and drops B5 without
    a word. Expected: a refusal (NC009) at the block, line 5."""
    result, _, _ = ncvm_run("t.mpf", f"%MPF11\nN10 G71 G90 G94 G18\nN20 S600 M3\nN30 G0 X10 Z0\n{block}\nN99 M30\n")
    assert result["status"] == "error" and result["error"]["line"] == 5, result
