"""Inch programs with a rotary axis (issue 16: "makes the same motions to the same end points (program
coordinates)"; "feed and spindle words as programmed").

In inch (CPL/SINUMERIK `G70`, DIN `G20`) the linear axes are in inches, the rotary axes stay in degrees (CPL
manual L1329-1337 "rotary axes use degrees"; L1975 "When working with rotary axes ...
the unit is always in degrees"; rs274/LinuxCNC likewise). ncvm multiplies a rotary axis word by 25.4 in inch:
`A90` is run and translated as `A2286` on every target, a rotary table turned six times and a quarter instead
of a quarter turn, with the fixture swinging through the spindle.
"""

from __future__ import annotations

import json
import re

import pytest

from tests.review16c.helpers import code_lines, ncvm
from tests.review16d.helpers import machine, translated

MACHINE = machine("4-axis mill", """
[[axis]]
name = "A"
kind = "rotary"
min = -720.0
max = 720.0
""")

PROGRAMS = {
    "inch.din": "G20 G90 G94 G54\nG0 X1 Y1 Z1 A90\nG1 X2 A180 F10\nM30\n",
    "inch.cpl": "N10 G70 G90 G54\nN20 G0 X1 Y1 Z1 A90\nN30 G1 X2 A180 F10\nN40 M30\n",
    "inch.mpf": "%MPF3\nN10 G70 G90 G94 G54\nN20 G0 X1 Y1 Z1 A90\nN30 G1 X2 A180 F10\nN40 M30\n",
}


@pytest.mark.parametrize("name", sorted(PROGRAMS))
def test_run_keeps_degrees(tmp_path, name):
    """The run's work end points: X in mm (1 inch = 25.4 mm), A in degrees as programmed."""
    (tmp_path / "machine.toml").write_text(MACHINE)
    (tmp_path / name).write_text(PROGRAMS[name])
    r = ncvm(tmp_path, "run", name, "-m", "machine.toml", "--trace", "t.jsonl")
    assert r.returncode == 0, r.stderr
    ends = [json.loads(line)["work"] for line in (tmp_path / "t.jsonl").read_text().splitlines()
            if json.loads(line)["call"] in ("rapid", "feed")]
    assert [round(e["X"], 4) for e in ends] == [25.4, 50.8]
    assert [round(e["A"], 4) for e in ends] == [90.0, 180.0], f"A in inch mode is scaled by 25.4: {ends}"


@pytest.mark.parametrize("target", ["linuxcnc", "sinumerik840d", "iso"])
@pytest.mark.parametrize("name", sorted(PROGRAMS))
def test_translation_keeps_degrees(tmp_path, name, target):
    """Every target: `A90` and `A180` as programmed, never `A2286`."""
    out = translated(tmp_path, MACHINE, PROGRAMS[name], name, target)
    a_words = [float(v) for line in code_lines(out) for v in re.findall(r"\bA(-?[\d.]+)", line)]
    assert a_words == [90.0, 180.0], f"rotary words {a_words}:\n{out}"
