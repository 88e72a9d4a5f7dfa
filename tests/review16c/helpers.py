"""Run `ncvm translate` and `ncvm run` as a user would (real processes, real files); read LinuxCNC output
back with rs274 where it is installed."""

from __future__ import annotations

import json
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from tests.review16b.helpers import code_lines  # noqa: F401  (the tests import it from here)

RS274 = shutil.which("rs274")
needs_rs274 = pytest.mark.skipif(RS274 is None, reason="rs274 not installed (Debian package linuxcnc-uspace)")


def ncvm(cwd: Path, *args: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "ncvm", *args], capture_output=True, text=True, timeout=300,
                          cwd=cwd)


def translate(tmp_path: Path, source: str, name: str, *args: str, out_name: str = "out.ngc") -> tuple[int, str, str]:
    """Write `source` (latin-1, as the old controls' files) to tmp_path/name and translate it;
    (exit code, output text or "", stderr)."""
    prog = tmp_path / name
    prog.write_text(source, encoding="latin-1")
    out = tmp_path / out_name
    r = ncvm(tmp_path, "translate", str(prog), "-o", str(out), *args)
    return r.returncode, out.read_text() if out.exists() else "", r.stderr


def rs274_canon(tmp_path: Path, ngc_text: str) -> tuple[int, str]:
    """``rs274 -g`` of ``ngc_text``: (exit code, canon text)."""
    ngc, canon = tmp_path / "readback.ngc", tmp_path / "readback.canon"
    ngc.write_text(ngc_text)
    p = subprocess.run([RS274, "-g", str(ngc), str(canon)], stdin=subprocess.DEVNULL, capture_output=True,
                       text=True, timeout=60)
    return p.returncode, (canon.read_text() if canon.exists() else "") + p.stdout + p.stderr


def rs274_moves_with_spindle(canon: str) -> list[tuple[str, bool]]:
    """(canon line, spindle turning) of every move in rs274's canon text."""
    turning, moves = False, []
    for line in canon.splitlines():
        if re.search(r"START_SPINDLE_(COUNTER)?CLOCKWISE", line):
            turning = True
        elif "STOP_SPINDLE_TURNING" in line:
            turning = False
        elif re.search(r"STRAIGHT_TRAVERSE|STRAIGHT_FEED|ARC_FEED", line):
            moves.append((line.strip(), turning))
    return moves


def trace_work(tmp_path: Path, name: str, *args: str) -> list[tuple[str, dict]]:
    """(call, work end point) of every motion of ``ncvm run NAME --trace``."""
    trace = tmp_path / "run.jsonl"
    r = ncvm(tmp_path, "run", str(tmp_path / name), "--trace", str(trace), *args)
    assert r.returncode == 0, r.stderr
    out = []
    for line in trace.read_text().splitlines():
        rec = json.loads(line)
        if rec["call"] in ("rapid", "feed", "arc"):
            out.append((rec["call"], rec.get("work", rec["end"])))
    return out
