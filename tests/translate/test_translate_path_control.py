"""The path control reaches every translation in the target's words (docs/translate.md "What each target
keeps"): DIN G61 / G64 P / G09, SINUMERIK G60 (its power-on state) / G64 / G9, CPL G61 / G62. A corner
tolerance the target's G64 cannot take is written without it, with a comment and a TRN003 warning."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from ncvm.runtime.session import RunOptions
from ncvm.translate import translate


def _code(text: str) -> list[str]:
    """The output's program lines, ISO's decimal point of whole numbers taken off."""
    lines = (re.sub(r"\b([XYZ]-?\d+)\.(?!\d)", r"\1", line.split("(")[0].split(";")[0].strip())
             for line in text.splitlines())
    return [line for line in lines if line and line != "%"]

AXES = '[[axis]]\nname = "X"\n[[axis]]\nname = "Y"\n[[axis]]\nname = "Z"\n'
DIN = "N10 G21 G90 G17 G54\nN20 G0 X0 Y0 Z5\nN30 G1 Z-1 F500\nN40 G9 X50\nN50 Y50\nN60 X0\nN70 M30\n"


def _translated(tmp_path: Path, name: str, text: str, target: str, machine: str = AXES):
    (tmp_path / "machine.toml").write_text(machine)
    program = tmp_path / name
    program.write_text(text)
    out = tmp_path / "out"
    done = translate(program, out, target, machine=tmp_path / "machine.toml",
                     options=RunOptions(state_dir=tmp_path / "st"))
    return _code(out.read_text()), out.read_text(), done


@pytest.mark.parametrize(("target", "expected"), [
    ("linuxcnc", ["G1 Z-1 F500", "G61", "G1 X50", "G64", "G1 Y50"]),  # no G9: the modal exact stop around it
    ("sinumerik840d", ["G1 Z-1 F500", "G9 G1 X50", "G1 Y50"]),
    ("iso", ["G1 Z-1 F500", "G09 G1 X50", "G1 Y50"]),
])
def test_exact_stop_of_one_block(tmp_path, target, expected):
    code, _, _ = _translated(tmp_path, "g9.din", DIN, target)
    start = code.index("G1 Z-1 F500")
    assert code[start:start + len(expected)] == expected, code


@pytest.mark.parametrize("target", ["sinumerik840d", "iso"])
def test_a_tolerance_the_target_cannot_take_is_said(tmp_path, target):
    code, text, done = _translated(tmp_path, "p.din", DIN.replace("N50 Y50", "N50 G64 P0.05 Y50"), target)
    assert "G64" in code and not any("P0.05" in line for line in code), code
    assert "corner tolerance P0.05 is not written" in text
    assert [(d.code, d.span.line) for d in done.diagnostics] == [("TRN003", 5)]


def test_sinumerik_power_on_exact_stop_and_g64(tmp_path):
    """The 8xx powers on in G60 (exact stop); LinuxCNC in G64: the translation says G61 first."""
    machine = AXES + '[sin800]\ncontrol = "880"\n'
    program = "%MPF5\nN10 G17 G71 G90 G54 G94 G0 X0 Y0 Z5\nN20 G1 X50 F500\nN30 G64 Y50\nN40 M30\n"
    code, _, _ = _translated(tmp_path, "p.mpf", program, "linuxcnc", machine)
    assert code[code.index("G61"):][:4] == ["G61", "G0 X0 Y0 Z5", "G1 X50 F500", "G64"], code


def test_cpl_continuous_path(tmp_path):
    code, _, _ = _translated(tmp_path, "p.cpl", "N10 G90 G17 G54 G61 G0 X0 Y0 Z5\nN20 G1 X5 F100\nN30 G62 X9\nN40 M30\n",
                             "sinumerik840d")
    assert code.index("G60") < code.index("G1 X5 F100") < code.index("G64", 1) < code.index("G1 X9"), code
