"""What a benchmark case is, and helpers the case modules share."""

from __future__ import annotations

import shutil
import subprocess
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

HERE = Path(__file__).parent
PEERS = HERE / "peers"  # the LinuxCNC peer programs and the flat-program generator
WORK = HERE / ".work"


@dataclass
class Case:
    run: Callable[[], None]  # one measured run
    count: int  # units of work per run (lines, iterations, moves, calls)
    unit: str  # e.g. "lines/s"
    setup: Callable[[], None] | None = None
    available: Callable[[], bool] | None = None
    why_unavailable: str = ""
    repeat: int = 0  # 0: the command line's --repeat


def rs274() -> str | None:
    return shutil.which("rs274")


def rs274_case(ngc: Path, count: int, unit: str, setup=None) -> Case:
    """LinuxCNC's standalone interpreter on ``ngc`` (canon output to a scratch file)."""

    def run():
        out = WORK / (ngc.stem + ".rs274.txt")
        subprocess.run([rs274(), "-g", str(ngc), str(out)], check=True, stdout=subprocess.DEVNULL,
                       stderr=subprocess.DEVNULL, stdin=subprocess.DEVNULL)

    return Case(run, count, unit, setup=setup, available=lambda: rs274() is not None,
                why_unavailable="rs274 not installed (Debian package linuxcnc-uspace)")
