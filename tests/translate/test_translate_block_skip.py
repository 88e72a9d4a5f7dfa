"""The block skip ``/`` is the operator's switch (``[setting_data] block_skip``): a translation writes the
path of its simulated setting and marks each ``/`` block FROZEN with that setting, before the move it
leads to (docs/translate.md "What is frozen"), in DIN, CPL (also DIN blocks a CPL program runs
unlinked) and SINUMERIK programs alike."""

from __future__ import annotations

from pathlib import Path

import pytest

from ncvm.runtime.session import RunOptions
from ncvm.translate import translate

MACHINE = '[[axis]]\nname = "X"\n[[axis]]\nname = "Y"\n[[axis]]\nname = "Z"\n{extra}[setting_data]\nblock_skip = {on}\n'
PROGRAMS = {
    "skip.din": "N10 G21 G90 G17 G54\nN20 G0 X0 Y0 Z5\n/N30 G0 X100\nN40 G1 Z-1 F100\nN50 M30\n",
    "skip.mpf": "%MPF12\nN10 G17 G71 G90 G54 G94 G0 X0 Y0 Z5\n/N30 G0 X100\nN40 G1 Z-1 F100\nN50 M30\n",
}


def _translated(tmp_path: Path, name: str, on: bool) -> list[str]:
    extra = '[sin800]\ncontrol = "880"\n' if name.endswith(".mpf") else ""
    (tmp_path / "machine.toml").write_text(MACHINE.format(extra=extra, on=str(on).lower()))
    program = tmp_path / name
    program.write_text(PROGRAMS[name])
    out = tmp_path / "out.ngc"
    translate(program, out, machine=tmp_path / "machine.toml", options=RunOptions(state_dir=tmp_path / "st"))
    return out.read_text().splitlines()


@pytest.mark.parametrize("name", PROGRAMS)
@pytest.mark.parametrize("on", [True, False], ids=["on", "off"])
def test_skip_block_marked_with_the_switch_setting(tmp_path, name, on):
    lines = _translated(tmp_path, name, on)
    mark = next(i for i, text in enumerate(lines) if text.startswith("(FROZEN: block skip"))
    assert f"block_skip = {str(on).lower()}" in lines[mark] and f"{name}:3" in lines[mark], lines
    following = lines[mark + 1]
    assert following == ("G1 Z-1 F100" if on else "G0 X100"), lines  # the mark stands before what it decided
    assert any("X100" in text for text in lines if not text.startswith("(")) is not on, lines


def test_cpl_unlinked_din_blocks_marked(tmp_path):
    """A CPL program's DIN sub-program run unlinked (CALL of a plain DIN file) reads the same switch."""
    (tmp_path / "machine.toml").write_text(MACHINE.format(extra="", on="true"))
    (tmp_path / "part.din").write_text("N10 G0 X5\n/N20 G0 X100\nN30 G1 Y7 F100\nN40 M30\n")
    program = tmp_path / "main.cpl"
    program.write_text("N10 G90 G17 G54 G0 X0 Y0 Z5\n20 CALL part.din\nN30 M30\n")
    out = tmp_path / "out.ngc"
    translate(program, out, machine=tmp_path / "machine.toml", options=RunOptions(state_dir=tmp_path / "st"))
    lines = out.read_text().splitlines()
    assert any(text.startswith("(FROZEN: block skip") and "part.din:2" in text for text in lines), lines
