"""A translation reads the permanent data of the state directory and leaves it as it found it (issue 16,
"Say what was frozen"; docs/translate.md): SINUMERIK central R900-R999 and CPL permanent variables that a
translated program writes stay as the earlier runs left them, so translating twice gives the same file."""

from __future__ import annotations

import hashlib

from tests.review16c.helpers import code_lines, ncvm
from tests.review16d.helpers import machine

COUNTER = """%MPF5
N10 G17 G71 G90 G54 G94
N20 R900=R900+10
N30 G0 X=R900 Y0 Z50
N40 M30
"""


def _digest(folder) -> dict[str, str]:
    return {p.name: hashlib.sha256(p.read_bytes()).hexdigest() for p in sorted(folder.iterdir()) if p.is_file()}


def _moves(tmp_path) -> list[str]:
    r = ncvm(tmp_path, "translate", "count.mpf", "-m", "machine.toml", "--state", "st", "-o", "out.ngc")
    assert r.returncode == 0, r.stderr
    return [line.split()[1] for line in code_lines((tmp_path / "out.ngc").read_text()) if line.startswith("G0 X")]


def test_translations_leave_central_r_as_the_runs_left_it(tmp_path):
    (tmp_path / "machine.toml").write_text(machine("mill"))
    (tmp_path / "count.mpf").write_text(COUNTER)
    assert ncvm(tmp_path, "run", "count.mpf", "-m", "machine.toml", "--state", "st").returncode == 0
    before = _digest(tmp_path / "st")
    assert [_moves(tmp_path) for _ in range(3)] == [["X20"]] * 3
    assert _digest(tmp_path / "st") == before
    run = ncvm(tmp_path, "run", "count.mpf", "-m", "machine.toml", "--state", "st", "--json")
    assert '"R900": 20' in run.stdout.replace(".0", ""), run.stdout  # the second run counts on from the first


def test_a_translation_creates_no_store(tmp_path):
    (tmp_path / "machine.toml").write_text(machine("mill"))
    (tmp_path / "count.mpf").write_text(COUNTER)
    assert _moves(tmp_path) == ["X10"]
    assert not list((tmp_path / "st").glob("store*")), "the translation made a permanent store"
