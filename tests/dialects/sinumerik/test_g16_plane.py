"""SINUMERIK 8xx ``G16`` selects the plane from its axis list (CL 800 manual L2679-2680: the 1st axis is the
horizontal, the 2nd the vertical axis of the plane; L4146-4147). Axes in G17-G19's order are that plane;
in the other order the same plane seen mirrored (``G16 X Z``: G18's Z-X plane, where G2 turns as G3); a
plane of other axes has no circles in ncvm, and its arc is refused (docs/decisions.md)."""

from __future__ import annotations

import json

import pytest

from ncvm.api import run
from ncvm.runtime.session import RunOptions


def _arc(tmp_path, g16: str, arc: str, axes: str = "XYZ"):
    """The run's result and its first arc's trace record, after ``G16 <g16>`` and the block ``arc``."""
    (tmp_path / "machine.toml").write_text("".join(f'[[axis]]\nname = "{a}"\n' for a in axes)
                                           + '[sin800]\ncontrol = "880"\n')
    prog = tmp_path / "plane.mpf"
    prog.write_text(f"%MPF107\nN10 G17 G71 G90 G54 G94\nN20 G0 X0 Y0 Z0\nN30 G16 {g16}\nN40 {arc} F100\nN50 M30\n")
    trace = tmp_path / "t.jsonl"
    result, _ = run(prog, dialect="sin800", machine=tmp_path / "machine.toml",
                    options=RunOptions(state_dir=tmp_path / "st", trace=trace))
    records = [json.loads(line) for line in trace.read_text().splitlines()] if trace.exists() else []
    return result, next((r for r in records if r["call"] == "arc"), None)


@pytest.mark.parametrize(("g16", "arc", "plane", "cw"), [
    ("X Y Z", "G2 X10 Y10 I5 J5", ["X", "Y"], True),  # G17's order
    ("Z X Y", "G2 Z10 X10 K5 I5", ["Z", "X"], True),  # G18's order
    ("X Z Y", "G2 X10 Z10 I5 K5", ["Z", "X"], False),  # G18 mirrored: X horizontal, Z vertical
    ("Y X Z", "G2 X10 Y10 I5 J5", ["X", "Y"], False),  # G17 mirrored
    ("Z Y X", "G2 Y10 Z10 J5 K5", ["Y", "Z"], False),  # G19 mirrored
], ids=["xy", "zx", "xz", "yx", "zy"])
def test_g16_plane_and_turn(tmp_path, g16, arc, plane, cw):
    result, rec = _arc(tmp_path, g16, arc)
    assert result["status"] == "ok", result["error"]
    assert rec["plane"] == plane and rec["cw"] is cw
    assert all(v == 0.0 for n, v in rec["end"].items() if n not in plane)  # no helix in the third axis


def test_g16_plane_of_other_axes_refuses_its_arc(tmp_path):
    result, rec = _arc(tmp_path, "X A Z", "G2 X10 A10 I5", axes="XYZA")
    assert result["status"] != "ok" and rec is None
    assert result["error"]["code"] == "NC004" and "G16 X A" in result["error"]["message"]
    assert result["error"]["line"] == 5


def test_g17_after_g16_ends_the_mirrored_plane(tmp_path):
    result, rec = _arc(tmp_path, "X Z Y", "G17 G2 X10 Y10 I5 J5")
    assert result["status"] == "ok", result["error"]
    assert rec["plane"] == ["X", "Y"] and rec["cw"] is True
