"""The examples of docs/api.md run as they are written (from a copy of the project's examples/), so the
documentation cannot drift from the API."""

from __future__ import annotations

import re
import shutil
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
DOC = ROOT / "docs" / "api.md"
BLOCKS = re.findall(r"```python\n(.*?)```", DOC.read_text(encoding="utf-8"), re.S)


def test_the_document_has_its_worked_example():
    assert len(BLOCKS) >= 5
    assert any("ncvm.batch(" in b and "DataFrame" in b and "savefig" in b for b in BLOCKS)


@pytest.mark.parametrize("index", range(len(BLOCKS)))
def test_example_runs(index, tmp_path, monkeypatch, capsys):
    """Block ``index`` of docs/api.md runs without an error (its own asserts included)."""
    pytest.importorskip("pandas")
    work = tmp_path / "project"
    shutil.copytree(ROOT / "examples", work / "examples")
    scratch = tmp_path / "scratch"
    scratch.mkdir()
    monkeypatch.chdir(work)
    exec(compile(BLOCKS[index], f"{DOC}:block{index + 1}", "exec"), {"scratch": scratch, "__name__": "__doc__"})
    if "print(" in BLOCKS[index]:
        assert capsys.readouterr().out
    if "savefig" in BLOCKS[index]:
        assert [p for p in scratch.iterdir() if p.suffix == ".png" and p.stat().st_size > 1000]
