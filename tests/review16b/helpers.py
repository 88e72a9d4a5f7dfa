"""Run `ncvm translate` as a user would (a real process, real files) and read its output back."""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path


def translate(tmp_path: Path, source: str, name: str, *args: str, out_name: str = "out.ngc") -> tuple[int, str, str]:
    """Write `source` to tmp_path/name, translate it; (exit code, output text or "", stderr)."""
    prog = tmp_path / name
    prog.write_text(source, encoding="latin-1")
    out = tmp_path / out_name
    r = subprocess.run(
        [sys.executable, "-m", "ncvm", "translate", str(prog), "-o", str(out), *args],
        capture_output=True, text=True, timeout=120, cwd=tmp_path,
    )
    return r.returncode, out.read_text() if out.exists() else "", r.stderr


def code_lines(text: str) -> list[str]:
    """The output's code lines with comments ( ) and ; stripped."""
    lines = []
    for line in text.splitlines():
        code = re.sub(r"\([^)]*\)", "", line).split(";")[0].strip()
        if code and code != "%":
            lines.append(code)
    return lines
