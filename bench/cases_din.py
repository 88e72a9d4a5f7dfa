"""DIN cases: din_flat_50k, the 50,000-block plain program of the peer set, through ncvm and rs274."""

from __future__ import annotations

import subprocess
import sys

from benchlib import PEERS, WORK, Case, rs274_case

from ncvm.api import run
from ncvm.runtime.session import RunOptions

FLAT = WORK / "flat_50k.ngc"
LINES = 50_000


def make_flat() -> None:
    WORK.mkdir(exist_ok=True)
    if not FLAT.exists():
        subprocess.run([sys.executable, str(PEERS / "gen_flat.py"), "-n", str(LINES), "-o", str(FLAT)], check=True)


def run_flat() -> None:
    result, _ = run(FLAT, dialect="din", options=RunOptions(state_dir=WORK / ".ncvm"))
    assert result["status"] == "ok", result["error"]


def cases() -> dict[str, Case]:
    return {
        "din_flat_50k": Case(run_flat, LINES, "lines/s", setup=make_flat),
        "rs274_din_flat_50k": rs274_case(FLAT, LINES, "lines/s", setup=make_flat),
    }
