"""``[din] profile`` (issue 14 §1: "a machine file may choose one for din"): a plain DIN program read with
another control's G table. The AXP example's blocks (CPL manual L2372: G20 is the plane switchover) cut
the half circle of 31.42 mm under typ3osa and 797.96 mm under iso (G20 = inch)."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from ncvm.api import check, run
from ncvm.runtime.session import RunOptions

AXES = '[[axis]]\nname = "X"\n[[axis]]\nname = "Y"\n[[axis]]\nname = "Z"\n'
HALF_CIRCLE = "G0 X0 Y0\nG20 X0 Y0\nG2 X20 Y0 R10 F1000\nM30\n"


def _run(tmp_path: Path, text: str, profile: str | None):
    section = f'[din]\nprofile = "{profile}"\n' if profile else ""
    (tmp_path / "machine.toml").write_text(AXES + section)
    prog = tmp_path / "p.ngc"
    prog.write_text(text)
    result, _ = run(prog, dialect="din", machine=tmp_path / "machine.toml", options=RunOptions(state_dir=tmp_path / ".s"))
    return result, check(prog, dialect="din", machine=tmp_path / "machine.toml")


def test_typ3osa_profile_reads_g20_as_the_plane_switchover_l2372(tmp_path):
    result, diags = _run(tmp_path, HALF_CIRCLE, "typ3osa")
    assert result["status"] == "ok", result["error"]
    assert result["motion"]["feed_length"] == pytest.approx(10 * math.pi, abs=1e-9) and diags == []


def test_iso_profile_reads_g20_as_inch(tmp_path):
    result, _ = _run(tmp_path, "G0 X0 Y0\nG20\nG2 X20 Y0 R10 F1000\nM30\n", None)
    assert result["motion"]["feed_length"] == pytest.approx(10 * math.pi * 25.4, abs=1e-6)


@pytest.mark.parametrize(("profile", "g", "code"), [("typ3osa", "G63", "NC004"), ("typ3osa", "G160", "NC004"),
                                                    ("typ3osa", "G63", "NC004"), ("sinumerik8xx", "G10", "NC004"),
                                                    ("sinumerik8xx", "G81", "NC004"), ("sinumerik8xx", "G21", "NC004")])
def test_check_warns_of_what_the_profile_refuses_and_the_run_stops_there(tmp_path, profile, g, code):
    """G160 is run by the CPL front end, which a din program does not have; G81 under sinumerik8xx calls L81
    (issue 14 §3), not LinuxCNC's cycle."""
    result, diags = _run(tmp_path, f"G0 X0 Y0\n{g} X10 Y10 Z-1 R1 F100\nM30\n", profile)
    assert result["error"]["code"] == code and result["error"]["line"] == 2, result["error"]
    assert [(d.code, d.span.line, d.severity) for d in diags] == [(code, 2, "warning")], diags
    assert "not supported by ncvm" in diags[0].message
