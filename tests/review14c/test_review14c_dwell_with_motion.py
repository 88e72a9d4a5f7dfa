"""din follows LinuxCNC (issue 14: "`iso` (din; LinuxCNC rs274 is the reference)"). In LinuxCNC's order of
execution a block does its dwell (G4) and then its motion, so ``G4 P1 G0 X5`` dwells one second and then
moves to X5, and ``G4 P1 X5`` does the same under the modal G0. ncvm dwells and drops the move without a
word: the run ends "normally" with the tool standing at X1 while the program and rs274 put it at X5.
docs/profiles.md lets din read X as the dwell time ("P seconds; X or F as DIN controls write it"); with P
in the block the X word is then neither a dwell nor a move, and with G0/G1 in the block it is plainly a move."""

from __future__ import annotations

from pathlib import Path

import pytest
from review14c_run import RS274, ncvm, reference


@pytest.mark.parametrize("block", ["G4 P1 G0 X5", "G4 P1 X5", "G4 X5 P1", "G4 P0.5 G1 X5 F100"])
def test_a_dwell_block_also_makes_its_move(tmp_path: Path, block: str) -> None:
    text = f"G21 G90\nG0 X1\n{block}\nM2\n"
    if RS274:   # the reference: the dwell, then the move to X5
        assert reference(tmp_path, text)[-1][1] == (5.0, 0.0, 0.0)
    result, moves = ncvm(tmp_path, text)
    # a clear refusal would be acceptable; a run that ends normally must have made the move
    assert result["status"] != "ok" or moves[-1][1] == (5.0, 0.0, 0.0), (result["status"], moves)
