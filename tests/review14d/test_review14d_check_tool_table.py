"""A tool change to a tool the machine file does not have: ``ncvm check`` is clean, ``ncvm run`` stops
(NC008 "tool 1 is not in the tool table") at the first block, in every dialect with NC blocks.

Issue 14 §5 asks check to report "every axis word for an axis the machine lacks" so that a clean check means
the run does not stop on what the machine lacks; a tool the machine lacks stops the run the same way, at a
literal T word the check reads (the machine file is given to both commands)."""

from __future__ import annotations

import pytest
from review14d_run import check, run, write

PROGRAMS = {
    "cpl": ("p.cpl", "N10 T1 M6\nN20 G0 X0 Y0 Z0\nN90 M30\n"),
    "din": ("p.ngc", "T1 M6\nG0 X0 Y0 Z0\nM2\n"),
    "sin800": ("p.mpf", "%MPF1\nN10 T1 M6\nN20 G0 X0\nN30 M30\n"),
}


@pytest.mark.parametrize("dialect", sorted(PROGRAMS))
def test_check_sees_the_tool_the_run_stops_on(tmp_path, dialect):
    name, text = PROGRAMS[dialect]
    write(tmp_path, {name: text})  # the review machine: X Y Z, no [[tool]]
    result, _rows, _stderr = run(tmp_path, name, text)
    assert result["error"]["code"] == "NC008", result["error"]
    proc = check(tmp_path, name, dialect)
    assert " 0 diagnostic(s)" not in proc.stderr, f"check is clean; the run stops: {result['error']['message']}"
