"""Lines the target can read: a source reference never shares a line with a message, a long message or
comment is split below rs274ngc's 252 characters, and a refusal names its block (issue 16, rule 4)."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

EX = Path(__file__).parents[2] / "examples"


def _translate(tmp_path: Path, name: str, source: str, *args: str) -> tuple[subprocess.CompletedProcess, str]:
    (tmp_path / name).write_text(source)
    out = tmp_path / "out.txt"
    r = subprocess.run([sys.executable, "-m", "ncvm", "translate", str(tmp_path / name), "-o", str(out), *args],
                       capture_output=True, text=True, timeout=300, cwd=tmp_path)
    return r, out.read_text() if out.exists() else ""


def test_source_reference_on_its_own_line_before_a_message(tmp_path):
    r, text = _translate(tmp_path, "m.din", "G90 G54\n(MSG, turn the part)\nG0 X1\nM2\n", "--source-comments")
    assert r.returncode == 0, r.stderr
    lines = text.splitlines()
    msg = next(i for i, ln in enumerate(lines) if ln.startswith("(MSG,"))
    assert lines[msg] == "(MSG, turn the part)", text
    assert lines[msg - 1] == "(m.din:2)", text


@pytest.mark.parametrize("target", ["linuxcnc", "sinumerik840d", "iso"])
def test_long_message_split_into_readable_lines(tmp_path, target):
    words = " ".join(f"word{i}" for i in range(80))
    r, text = _translate(tmp_path, "l.din", f"G90 G54\n(MSG, {words})\nG0 X1\nM2\n", "--target", target)
    assert r.returncode == 0, r.stderr
    assert max(len(ln) for ln in text.splitlines()) <= 252, text
    assert "word0 " in text and "word79" in text and text.count("word") >= 80, text


def test_modal_g53_refusal_names_the_block_that_moves(tmp_path):
    source = "N10 G90 G17 G54 T1 M6\nN20 G0 X0 Y0 Z5\nN25 G1 X1 F100\nN30 G53 G0 X10 Y10\nM30\n"
    r, _ = _translate(tmp_path, "a.cpl", source, "--machine", str(EX / "cpl" / "machine.toml"))
    assert r.returncode == 1 and "TRN001" in r.stderr, r.stderr
    assert "a.cpl:4:" in r.stderr, r.stderr

