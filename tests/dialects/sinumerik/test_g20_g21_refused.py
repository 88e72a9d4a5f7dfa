"""G20/G21 are not in the SINUMERIK 810-880 G groups (CL 800 manual L7392-7410; the units are G70/G71): a
block with them stops with NC004 instead of being read as LinuxCNC's inch/mm (issue 14)."""

from __future__ import annotations

import pytest
from sin800_helpers import run_mpf


@pytest.mark.parametrize("g", [20, 21])
def test_g20_and_g21_are_refused_not_read_as_inch_or_mm(tmp_path, g):
    result = run_mpf(tmp_path, f"%MPF1\nN10 G0 X0 Y0\nN20 G{g} G1 X10 F100\nN30 M30\n")
    assert result["error"]["code"] == "NC004" and result["error"]["line"] == 3, result["error"]
    assert "G70/G71" in result["error"]["message"]
