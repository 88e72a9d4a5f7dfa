"""din follows LinuxCNC (issue 14: "`iso` (din; LinuxCNC rs274 is the reference)"; "never silently ignore a
word"). rs274 refuses a D word in a block without G41/G42 ("D word with no G41, G41.1, G42, G42.1 ... to
use it"). ncvm ignores it without a word: ``G1 Y20 D0`` under active G41 keeps cutting with radius 2.54
although the program asks for radius 0, and ``G1 Y5 D2`` keeps tool 1's radius instead of tool 2's."""

from __future__ import annotations

from pathlib import Path

import pytest
from review14c_run import RS274, ncvm, reference


@pytest.mark.parametrize("text", [
    "G21 G90\nT1 M6\nG1 X5 D1 F100\nM2\n",
    "G21 G90\nT1 M6\nG41 D1 G1 X5 F100\nG1 Y5 D2\nM2\n",
    "G21 G90\nT1 M6\nG0 X-10 Y-10\nG41 D1 G1 X0 Y0 F100\nG1 X20\nG1 Y20 D0\nG1 X0\nG40 G1 X-10 Y-10\nM2\n",
])
def test_a_d_word_without_g41_g42_in_its_block_is_refused(tmp_path: Path, text: str) -> None:
    if RS274:   # the reference stops at the block with the lone D word
        ref = reference(tmp_path, text)
        assert len(ref) < text.count("X") + text.count("Y")
    result, _ = ncvm(tmp_path, text)
    assert result["status"] == "error", result["status"]
