"""A thread (G33; SINUMERIK G33-G35) stays a spindle-synchronised move in a translation, or is refused (TRN001):
written as a plain G1 at its mean feed, the new control would cut it without following the spindle."""

from __future__ import annotations

from pathlib import Path

import pytest

from ncvm.runtime.session import RunOptions
from ncvm.translate import TranslationRefused, translate

DIN = "G21 G18 G90 G94\nS600 M3\nG0 X10 Z0\nG33 Z-12 K1.5\nG0 X20\nM2\n"
SIN_G34 = "%MPF4\nN10 G71 G90 G94 G18\nN20 S600 M3\nN30 G0 X10 Z0\nN40 G34 Z-20 K1 F0.1\nN50 M30\n"


def _translate(tmp_path: Path, name: str, text: str, target: str) -> str:
    program = tmp_path / name
    program.write_text(text)
    out = tmp_path / f"out.{target}"
    translate(program, out, target, options=RunOptions(state_dir=tmp_path / "st"))
    return out.read_text()


def test_linuxcnc_gets_g33_with_the_lead_as_k(tmp_path):
    """DIN ``G33 Z-12 K1.5`` (docs/din.md "Threads") becomes LinuxCNC's ``G33 Z-12 K1.5`` (the programmed axis
    alone), no G1."""
    lines = _translate(tmp_path, "t.ngc", DIN, "linuxcnc").splitlines()
    assert "G33 Z-12 K1.5" in lines, lines
    assert not any(line.startswith("G1 ") for line in lines), lines


@pytest.mark.parametrize("target", ["sinumerik840d", "iso"])
def test_targets_without_a_thread_word_refuse_at_the_block(tmp_path, target):
    with pytest.raises(TranslationRefused) as e:
        _translate(tmp_path, "t.ngc", DIN, target)
    d = e.value.diagnostic
    assert d.code == "TRN001" and d.span.line == 4 and "thread" in d.message, d


def test_a_thread_of_growing_lead_is_refused_for_linuxcnc(tmp_path):
    """SINUMERIK G34 (CL 800 manual L7397): LinuxCNC's G33 has one lead; refused, not written as a mean."""
    with pytest.raises(TranslationRefused) as e:
        _translate(tmp_path, "t.mpf", SIN_G34, "linuxcnc")
    d = e.value.diagnostic
    assert d.code == "TRN001" and d.span.line == 5 and "G34/G35" in d.message, d
