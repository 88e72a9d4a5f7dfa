"""din follows LinuxCNC (issue 14: "`iso` (din; LinuxCNC rs274 is the reference)"; "never silently ignore a
word"). rs274 refuses a block with two G codes of one modal group ("Two g codes used from same modal group")
or two M codes of one group ("Two m codes used from same modal group"): the block's meaning is undefined.
ncvm runs such a block without a word, keeping one of the two codes: ``G90 G91 X5`` moves, ``G43 G49`` runs
without a length, ``M3 M5`` with a spindle that may or may not turn. A clear error is expected."""

from __future__ import annotations

from pathlib import Path

import pytest
from review14c_run import RS274, ncvm, reference


@pytest.mark.parametrize("block", ["G0 G1 X5 F100", "G90 G91 G0 X5", "G91 G90 G0 X5", "G20 G21 G0 X5",
                                   "G54 G55 G0 X5", "G17 G18 G0 X5", "G43 G49 G0 Z5", "M3 M5 S100 G0 X1",
                                   "T1 M6 M6 G0 X1"])
def test_two_codes_of_one_modal_group_are_refused(tmp_path: Path, block: str) -> None:
    text = f"G21 G90\nT1 M6\n{block}\nM2\n"
    if RS274:   # the reference refuses the block: no move at all
        assert reference(tmp_path, text) == []
    result, moves = ncvm(tmp_path, text)
    assert result["status"] == "error" and moves == [], (result["status"], moves)
