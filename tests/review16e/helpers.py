"""Translate programs as a user would: real files in a folder, `ncvm translate` / `ncvm run` as real
processes; rs274 (where installed) reads LinuxCNC translations back."""

from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

import pytest

RS274 = shutil.which("rs274")
needs_rs274 = pytest.mark.skipif(RS274 is None, reason="rs274 not installed (LinuxCNC)")

MILL = """[machine]
name = "review mill"
units = "mm"
{axes}
[offsets]
G54 = [10.0, 20.0, 30.0]
G55 = [100.0, 50.0, 5.0]

[[tool]]
number = 1
length = 50.0
radius = 5.0

[paths]
program_path = ["."]
file_root = "files"
"""


def mill(extra: str = "") -> str:
    """A metric 3-axis mill (X Y Z, -500..500 mm), G54/G55 set, tool 1, controller files in ``files``."""
    axes = "".join(f'[[axis]]\nname = "{a}"\nmin = -500.0\nmax = 500.0\n' for a in "XYZ")
    return MILL.format(axes=axes) + extra


def bare_machine(name: str, extra: str = "") -> str:
    """A machine file of three axes X Y Z without limits, named ``name``, ``extra`` (TOML) after them."""
    axes = "".join(f'[[axis]]\nname = "{a}"\n' for a in "XYZ")
    return f'[machine]\nname = "{name}"\n{axes}{extra}'


def ncvm(cwd: Path, *args: str) -> subprocess.CompletedProcess:
    """``ncvm ARGS`` run in ``cwd`` as a separate process."""
    return subprocess.run([sys.executable, "-m", "ncvm", *args], capture_output=True, text=True, timeout=600,
                          cwd=cwd)


def write(folder: Path, files: dict[str, str]) -> None:
    """Write each named file (latin-1, as the old controls keep them) into ``folder``."""
    for name, text in files.items():
        path = folder / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text, encoding="latin-1")


def translate(folder: Path, program: str, *args: str, out: str = "out.ngc") -> tuple[int, str, str]:
    """``ncvm translate PROGRAM -o OUT ARGS`` in ``folder``: (exit code, OUT's text or "", stderr)."""
    target = folder / out
    r = ncvm(folder, "translate", program, "-o", str(target), *args)
    return r.returncode, target.read_text() if target.exists() else "", r.stderr


def code_lines(text: str) -> list[str]:
    """The lines of a LinuxCNC / ISO translation that are not comments or the ``%`` wrapper."""
    lines = (line.strip() for line in text.splitlines())
    return [line for line in lines if line and not line.startswith(("(", ";", "%"))]


def rs274_canon(folder: Path, ngc_text: str) -> tuple[int, str]:
    """``rs274 -g`` of ``ngc_text``: (exit code, canon calls and messages)."""
    ngc, canon = folder / "readback.ngc", folder / "readback.canon"
    ngc.write_text(ngc_text)
    p = subprocess.run([RS274, "-g", str(ngc), str(canon)], stdin=subprocess.DEVNULL, capture_output=True,
                       text=True, timeout=120)
    return p.returncode, (canon.read_text() if canon.exists() else "") + p.stdout + p.stderr
