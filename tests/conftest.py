"""Shared fixtures: write a program into a temporary folder and run it."""

from __future__ import annotations

from pathlib import Path

import pytest

from ncvm.api import run
from ncvm.runtime.session import RunOptions


@pytest.fixture
def run_text(tmp_path: Path):
    """run_text(text, name="prog.din", machine=None, **options) -> result dict."""

    def _run(text: str, name: str = "prog.din", machine=None, dialect=None, **opts):
        path = tmp_path / name
        path.write_text(text, encoding="latin-1")
        options = RunOptions(state_dir=tmp_path / ".ncvm", **opts)
        result, _session = run(path, dialect=dialect, machine=machine, options=options)
        return result

    return _run
