"""Non-ASCII text of a program in its translation: UTF-8 for LinuxCNC (rs274 reads UTF-8 comments and
messages: tried), ASCII for the 840D and ISO targets with umlauts transliterated and any other character
written as <U+XXXX>; never a silent "?" (docs/translate.md). Programs are read as latin-1."""

from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

import pytest

from ncvm.runtime.session import RunOptions
from ncvm.translate import translate
from ncvm.translate.targets import ascii_text

RS274 = shutil.which("rs274")

def _translate(tmp_path: Path, target: str = "linuxcnc") -> str:
    program = tmp_path / "p.din"
    program.write_text(PROGRAM, encoding="latin-1")  # as the old controls' files
    out = tmp_path / f"p.{target}"
    translate(program, out, target, options=RunOptions(state_dir=tmp_path / "st"))
    return out.read_bytes().decode("utf-8")


PROGRAM = "%\nN10 G90 G71 G54\nN20 (MSG, Wärme Größe café)\nN30 G0 X10 Y0 Z0\nN40 M30\n"


def test_ascii_text_transliterates_and_marks_the_rest():
    assert ascii_text("Wärme Größe ÄÖÜ") == "Waerme Groesse AeOeUe"
    assert ascii_text("café") == "cafe"
    assert ascii_text("日") == "<U+65E5>"


def test_linuxcnc_target_keeps_utf8_text(tmp_path):
    text = _translate(tmp_path)
    assert "Wärme Größe café" in text and "?" not in text


@pytest.mark.skipif(RS274 is None, reason="rs274 not installed (Debian package linuxcnc-uspace)")
def test_linuxcnc_message_reads_back_in_rs274(tmp_path):
    ngc = tmp_path / "out.ngc"
    ngc.write_text(_translate(tmp_path), encoding="utf-8")
    p = subprocess.run([RS274, "-g", str(ngc)], stdin=subprocess.DEVNULL, capture_output=True, timeout=60)
    assert "Wärme Größe café" in p.stdout.decode("utf-8"), p.stdout


@pytest.mark.parametrize("target", ["sinumerik840d", "iso"])
def test_ascii_targets_transliterate(tmp_path, target):
    text = _translate(tmp_path, target)
    assert text.isascii()
    assert "Waerme Groesse cafe" in text and "?" not in text
