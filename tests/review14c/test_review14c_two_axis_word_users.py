"""din follows LinuxCNC (issue 14: "`iso` (din; LinuxCNC rs274 is the reference)"; "never silently ignore a
word"). rs274 refuses a block in which two G codes both want the axis words ("Cannot use two g codes that
both use axis values": ``G92 X0 G0``), two codes of the non-modal group (``G53 G92 X0``: "Two g codes used
from same modal group") and G53 with an arc ("Must use g0 or g1 with g53"). ncvm runs each of them without
a word, choosing one reading: ``G92 X0 G0`` sets the origin and drops the move, ``G2 G53`` cuts an arc."""

from __future__ import annotations

from pathlib import Path

import pytest
from review14c_run import RS274, ncvm, reference


@pytest.mark.parametrize("block", ["G92 X0 G0", "G0 G92 X0", "G53 G92 X0", "G2 G53 X0 I-2.5 F100"])
def test_a_block_rs274_cannot_read_is_refused(tmp_path: Path, block: str) -> None:
    text = f"G21 G90\nG0 X5\n{block}\nG0 X1\nM2\n"
    if RS274:   # the reference stops at the block: the first move only
        assert [end for _, end in reference(tmp_path, text)] == [(5.0, 0.0, 0.0)]
    result, moves = ncvm(tmp_path, text)
    assert result["status"] == "error", (result["status"], moves)
