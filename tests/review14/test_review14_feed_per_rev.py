"""Feed per revolution (SINUMERIK group 11 G94-G97, CL 800 manual L7407; CPL L2817; din as LinuxCNC).
ncvm sets the feed to 0 when G94 and G95 change (docs/decisions.md, "so a number is never silently read
in the other unit"); the stop that follows must tell the user why the F they programmed is gone."""

from __future__ import annotations

import pytest

SIN = "%MPF5\nN10 G71 G90 G17\nN20 S1000 M3\nN30 G94 F100\nN40 G1 X5\nN50 G95\nN60 G1 X10\nN99 M30\n"
DIN = "G21 G17 G90\nS1000 M3\nG94 F100\nG1 X5\nG95\nG1 X10\nM2\n"


@pytest.mark.parametrize("name, text, line", [("p.mpf", SIN, 7), ("p.ngc", DIN, 6)])
def test_feed_cleared_by_g95_is_named_in_the_stop(ncvm_run, name, text, line):
    """F100 is programmed, X5 runs at 100 mm/min, then G95 without F and G1 X10: ncvm stops with
    "G1 with feed rate 0 (program an F word)" - the user sees F100 two blocks up and a claim that the feed
    is 0. Expected: the stop (NC006, at the G1 block) names G95 (the switch that asks for a new F)."""
    result, _, _ = ncvm_run(name, text)
    assert result["status"] == "error" and result["error"]["line"] == line, result
    assert "G95" in result["error"]["message"], result["error"]["message"]
