"""Review of issue 14 part 3 (cycles, threads, feed per revolution) and the SINUMERIK radius address: each
test runs ncvm as a user does, as a real process (``python -m ncvm run --json --trace``), on programs
written from the manuals."""

from __future__ import annotations

from pathlib import Path

import pytest
from review14_helpers import make_runner


@pytest.fixture
def ncvm_run(tmp_path: Path):
    """ncvm_run(name, text, files={}) -> (JSON result, trace rows, stderr) of ``ncvm run`` in a process."""
    return make_runner(tmp_path)
