"""A rw_SymPas circle in axes 1 and 3 (X and Z) is G18's arc on every target (issue 16: "arcs stay arcs ...
in the program's plane"): G18's plane is Z-X, so a turn from X towards Z is clockwise there (`G2`), with the
centre as `I` (X) and `K` (Z) from the start point."""

from __future__ import annotations

import re

import pytest

from tests.review16c.helpers import code_lines, translate
from tests.review16d.helpers import machine

START = "MLAW(A1 := 50.0, A2 := 50.0, A3 := 0.0);"


def _arc(tmp_path, target: str, circle: str) -> tuple[list[str], dict[str, float]]:
    program = f"program P;\nbegin\n  TRVL := 50.0; TRAC := 500.0;\n  {START}\n  {circle}\nend.\n"
    (tmp_path / "machine.toml").write_text(machine("gantry"))
    rc, out, err = translate(tmp_path, program, "xz.sap", "--target", target, "-m", "machine.toml",
                             out_name=f"out.{target}")
    assert rc == 0, err
    lines = code_lines(out)
    arcs = [i for i, line in enumerate(lines) if re.match(r"G[23]\b", line)]
    assert len(arcs) == 1, lines
    words = {w: float(v.rstrip(".")) for w, v in re.findall(r"\b([XYZIJK])(-?[\d.]+)", lines[arcs[0]])}
    return lines[:arcs[0] + 1], words


@pytest.mark.parametrize("target", ["linuxcnc", "sinumerik840d", "iso"])
def test_counter_clockwise_from_x_towards_z_is_g2_in_g18(tmp_path, target):
    lines, words = _arc(tmp_path, target, "MCRW(A1 := 10.0, A3 := 0.0, PHI := 90.0);")
    assert "G18" in lines and lines[-1].startswith("G2 "), lines
    assert words == {"X": 60.0, "Z": -10.0, "I": 10.0, "K": 0.0}


@pytest.mark.parametrize("target", ["linuxcnc", "sinumerik840d", "iso"])
def test_clockwise_from_x_towards_z_is_g3_in_g18(tmp_path, target):
    lines, words = _arc(tmp_path, target, "MCRW(A1 := 10.0, A3 := 0.0, PHI := -90.0);")
    assert "G18" in lines and lines[-1].startswith("G3 "), lines
    assert words == {"X": 60.0, "Z": 10.0, "I": 10.0, "K": 0.0}
