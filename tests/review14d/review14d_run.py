"""What the review-14d tests share: ``ncvm run`` and ``ncvm check`` in real processes on programs written to a
folder, beside a fast X/Y/Z machine."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

from tests.review14.review14_helpers import MACHINE, make_runner


def write(tmp_path: Path, files: dict[str, str], machine: str = MACHINE) -> None:
    """The machine file and the programs, in tmp_path."""
    (tmp_path / "machine.toml").write_text(machine)
    for name, text in files.items():
        (tmp_path / name).write_text(text)


def check(tmp_path: Path, name: str, dialect: str) -> subprocess.CompletedProcess:
    """``ncvm check`` of tmp_path/name with the machine file beside it, in a process."""
    proc = subprocess.run([sys.executable, "-m", "ncvm", "check", "-d", dialect, "--machine",
                           str(tmp_path / "machine.toml"), str(tmp_path / name)],
                          capture_output=True, text=True, timeout=120)
    assert "Traceback" not in proc.stderr, proc.stderr
    return proc


def run(tmp_path: Path, name: str, text: str, files: dict | None = None, machine: str = MACHINE):
    """(JSON result, trace rows, stderr) of ``ncvm run --json --trace``, in a process."""
    return make_runner(tmp_path)(name, text, files, machine=machine)
