"""DIN 66025 as rs274 reads it: G96's D word is the spindle speed limit, G92 without axes is refused.

rs274 (LinuxCNC 2.9): ``G96 D2000 S200`` caps the spindle at 2000 rev/min; ``G92 S3000`` stops with "All
axes missing with g92". The spindle speeds are read from the run's trace (the ``spindle`` calls).
"""

from __future__ import annotations

import json

import pytest

from ncvm.api import run
from ncvm.runtime.session import RunOptions


def _run(tmp_path, text):
    path = tmp_path / "p.ngc"
    path.write_text(text)
    trace = tmp_path / "t.jsonl"
    result, _state = run(path, dialect="din", options=RunOptions(state_dir=tmp_path / "s", trace=trace))
    calls = [json.loads(line) for line in trace.read_text().splitlines()] if trace.exists() else []
    return result, [c for c in calls if c.get("call") == "spindle"]


def _speeds(calls):
    return [abs(c["speed"]) for c in calls]


def test_g96_d_caps_the_spindle_speed(tmp_path):
    """200 m/min at X1 would be 31,831 rev/min; D2000 holds it at 2000 (X10: 3183 -> 2000 as well)."""
    result, calls = _run(tmp_path, "G90 G21\nS500 M3\nG0 X20 Z0\nG96 D2000 S200\nG1 X10 F100\nX1\nM2\n")
    assert result["status"] == "ok", result["error"]
    assert max(_speeds(calls)) == pytest.approx(2000.0)
    assert any(s == pytest.approx(1591.549, rel=1e-4) for s in _speeds(calls))  # X20: below the limit


def test_g96_without_d_has_no_limit_as_in_rs274(tmp_path):
    """A later G96 without D drops an earlier D: rs274 reads D in the G96 block only."""
    result, calls = _run(tmp_path, "G90 G21\nS500 M3\nG0 X10 Z0\nG96 D2000 S200\nG97\nG96 S200\nG1 X1 F100\nX2\nM2\n")
    assert result["status"] == "ok", result["error"]
    assert max(_speeds(calls)) == pytest.approx(31830.9886, rel=1e-6)


@pytest.mark.parametrize("block", ["G96 D0 S200", "G96 D-100 S200"])
def test_g96_d_must_be_positive(tmp_path, block):
    result, _ = _run(tmp_path, f"G90 G21\nG0 X10 Z0\n{block}\nM2\n")
    assert result["status"] == "error"
    assert (result["error"]["code"], result["error"]["line"]) == ("NC009", 3)


def test_g92_without_axis_words_is_refused_like_rs274(tmp_path):
    """rs274: "All axes missing with g92"; the S word is not taken as a new cutting speed or a limit."""
    result, _ = _run(tmp_path, "G90 G21\nS500 M3\nG0 X10 Z0\nG96 S200\nG92 S3000\nG1 X20 F100\nM2\n")
    assert result["status"] == "error"
    assert (result["error"]["code"], result["error"]["line"]) == ("NC009", 5)
    assert "G92" in result["error"]["message"] and "axes missing" in result["error"]["message"]


def test_g92_with_axis_words_still_sets_the_position(tmp_path):
    result, _ = _run(tmp_path, "G90 G21\nG0 X10 Z0\nG92 X0\nG0 X5\nM2\n")
    assert result["status"] == "ok", result["error"]
