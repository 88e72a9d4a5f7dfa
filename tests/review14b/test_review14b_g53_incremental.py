"""G53 under G91: the block's target "in machine coordinates" is an absolute position; a program in
incremental mode means a distance. ncvm reads the word as an absolute machine position anyway and moves the
slide there without a word, a crash-sized move the program never asked for."""

from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

import pytest
from review14b_run import SIN800_MACHINE, moves, run


def test_sin800_g53_under_g91_is_not_silently_absolute(tmp_path: Path) -> None:
    """SINUMERIK: G53 suppresses the zero offsets for its block (CL 800 manual L7396, group 4; as POS MSYS,
    L4083, "effective only blockwise"); G91 (group 10, L7404) keeps the block incremental. ``G91 G53 Z10``
    from the slide at machine Z170 must either go 10 mm up (Z180) or stop with an error: ncvm moves it
    110 mm DOWN to machine Z60 (Z10 + the tool length) and reports the run ok."""
    result, rows, _ = run(tmp_path, "g53inc.mpf",
                          "%MPF1\nN1 G54 G0 X0 Y0 Z100 D1\nN2 G91 G53 Z10\nN3 M30\n", SIN800_MACHINE)
    assert moves(rows)[0] == (2, 100.0, 10.0, 170.0)   # G54 Z100 + offset 20 + length 50
    if result["status"] == "ok":
        assert moves(rows)[1][3] == 180.0, moves(rows)
    else:
        assert result["error"]["line"] == 3


def test_din_g53_under_g91_is_an_error_as_linuxcnc(tmp_path: Path) -> None:
    """din follows LinuxCNC (docs/din.md; issue 14: "`iso` (din; LinuxCNC rs274 is the reference)"): rs274
    stops ``G91 G53 G0 Z10`` with "Cannot use g53 incremental". ncvm runs it as an absolute machine move
    (from Z1 to Z10) and reports the run ok."""
    text = "G21 G90\nG0 X1 Y1 Z1\nG91 G53 G0 Z10\nM2\n"
    rs274 = shutil.which("rs274")
    if rs274:   # the reference really refuses it (when installed)
        (tmp_path / "ref.ngc").write_text(text)
        ref = subprocess.run([rs274, "-g", str(tmp_path / "ref.ngc")], capture_output=True, text=True,
                             input="", timeout=60)
        assert "cannot use g53 incremental" in (ref.stdout + ref.stderr).lower()
    result, rows, stderr = run(tmp_path, "g53inc.ngc", text)
    assert result["status"] != "ok", (moves(rows), stderr)
    assert result["error"]["line"] == 3


@pytest.mark.parametrize("block", ["G91 G53 Z10", "G53 G91 Z10"])
def test_sin800_g53_g91_either_order(tmp_path: Path, block: str) -> None:
    """The order of the words in the block does not matter (the same block, CL 800 manual L7392-7410)."""
    result, rows, _ = run(tmp_path, "g53inc.mpf",
                          f"%MPF1\nN1 G54 G0 X0 Y0 Z100 D1\nN2 {block}\nN3 M30\n", SIN800_MACHINE)
    assert result["status"] != "ok" or moves(rows)[1][3] == 180.0, moves(rows)
