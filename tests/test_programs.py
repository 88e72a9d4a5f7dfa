"""Golden programs, as data (like LinuxCNC's tests/interp).

``tests/programs/<dialect>/<case>.<ext>`` runs and is compared with
``<case>.expected.json``: only the keys that file holds are compared (numbers
to 1e-6), so a case states exactly what it is about. A ``machine.toml`` in the
folder is the machine for its cases. ``tests/programs/<dialect>/bad/<case>.<ext>``
must fail: the first line holding ``error <CODE>`` names the expected code,
reported by ``ncvm check`` or, for faults only a run can find, by the run.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

from ncvm.api import check, run
from ncvm.diagnostics import CompileFailed
from ncvm.dialects import EXTENSIONS
from ncvm.runtime.session import RunOptions

ROOT = Path(__file__).parent / "programs"


def _cases(bad: bool) -> list[Path]:
    out = []
    for dialect_dir in sorted(p for p in ROOT.iterdir() if p.is_dir()):
        folder = dialect_dir / "bad" if bad else dialect_dir
        if not folder.is_dir():
            continue
        for p in sorted(folder.iterdir()):
            if p.suffix.lower() in EXTENSIONS and (bad or p.with_suffix(".expected.json").exists()):
                out.append(p)
    return out


def _machine(folder: Path):
    m = folder / "machine.toml"
    return m if m.is_file() else None


def _compare(actual, expected, where: str) -> None:
    if isinstance(expected, dict):
        assert isinstance(actual, dict), f"{where}: expected an object, got {actual!r}"
        for k, v in expected.items():
            assert k in actual, f"{where}.{k} missing"
            _compare(actual[k], v, f"{where}.{k}")
    elif isinstance(expected, list):
        assert isinstance(actual, list) and len(actual) == len(expected), f"{where}: {actual!r} != {expected!r}"
        for i, (a, e) in enumerate(zip(actual, expected)):
            _compare(a, e, f"{where}[{i}]")
    elif isinstance(expected, float) and not isinstance(actual, bool):
        assert actual == pytest.approx(expected, abs=1e-6), f"{where}: {actual!r} != {expected!r}"
    else:
        assert actual == expected, f"{where}: {actual!r} != {expected!r}"


@pytest.mark.parametrize("program", _cases(bad=False), ids=lambda p: f"{p.parent.name}/{p.name}")
def test_golden_program(program: Path, tmp_path: Path):
    expected = json.loads(program.with_suffix(".expected.json").read_text())
    result, _ = run(program, machine=_machine(program.parent), options=RunOptions(state_dir=tmp_path))
    _compare(result, expected, program.name)


@pytest.mark.parametrize("program", _cases(bad=True), ids=lambda p: f"{p.parent.parent.name}/bad/{p.name}")
def test_bad_program(program: Path, tmp_path: Path):
    text = program.read_text(encoding="latin-1")
    m = re.search(r"error\s+([A-Z]*\d+[A-Z]*\w*)", text)
    assert m, f"{program}: no 'error CODE' line"
    code = m.group(1)
    machine = _machine(program.parent.parent)
    try:
        diags = check(program, machine=machine)
    except CompileFailed as e:
        diags = e.diagnostics
    codes = [d.code for d in diags if d.severity == "error"]
    if not codes:
        result, _ = run(program, machine=machine, options=RunOptions(state_dir=tmp_path))
        codes = [result["error"]["code"]] if result["error"] else []
    assert code in codes, f"{program.name}: expected error {code}, got {codes}"
