"""What a benchmark case is, and helpers the case modules share."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

HERE = Path(__file__).parent
PEERS = HERE / "peers"  # the LinuxCNC peer programs and the flat-program generator
WORK = HERE / ".work"
NCVM = [sys.executable, "-m", "ncvm"]  # the CLI as a user starts it (the console script adds nothing but a stub)
#: run the opt-in cases of 10,000,000 moves too (``run.py --large``: minutes each, a 340 MB DIN file)
LARGE = {"on": False}


def large() -> bool:
    return LARGE["on"]


@dataclass
class Case:
    run: Callable[[], dict | None]  # one measured run; may return figures of its own (cpu_s, peak_rss_mb, ...)
    count: int  # units of work per run (lines, iterations, moves, calls)
    unit: str  # e.g. "lines/s"
    setup: Callable[[], None] | None = None
    available: Callable[[], bool] | None = None
    why_unavailable: str = ""
    repeat: int = 0  # 0: the command line's --repeat
    in_process: bool = True  # the work runs in this process (its CPU time means something)
    figures: Callable[[], dict] | None = None  # figures of the work itself (a cycle time), computed once, untimed


def rs274() -> str | None:
    return shutil.which("rs274")


def rs274_case(ngc: Path, count: int, unit: str, setup=None) -> Case:
    """LinuxCNC's standalone interpreter on ``ngc`` (canon output to a scratch file)."""

    def run():
        out = WORK / (ngc.stem + ".rs274.txt")
        subprocess.run([rs274(), "-g", str(ngc), str(out)], check=True, stdout=subprocess.DEVNULL,
                       stderr=subprocess.DEVNULL, stdin=subprocess.DEVNULL)

    return Case(run, count, unit, setup=setup, available=lambda: rs274() is not None,
                why_unavailable="rs274 not installed (Debian package linuxcnc-uspace)", in_process=False)


@dataclass
class Usage:
    """What one child process cost: CPU (user + system) and wall seconds, peak resident memory."""

    cpu_s: float
    wall_s: float
    peak_rss_mb: float


# Started by a small launcher: a child forked from this (large) process would count this process's memory in
# its peak, since Linux keeps the peak across exec; one forked from a small process starts from its size.
LAUNCHER = """\
import json, os, sys, time
out = os.open(sys.argv[1], os.O_WRONLY | os.O_CREAT | os.O_TRUNC) if sys.argv[1] else os.open(os.devnull, os.O_WRONLY)
t0 = time.perf_counter()
pid = os.posix_spawn(sys.argv[2], sys.argv[2:], os.environ, file_actions=[(os.POSIX_SPAWN_DUP2, out, 1)])
_, status, ru = os.wait4(pid, 0)
print(json.dumps([os.waitstatus_to_exitcode(status), ru.ru_utime + ru.ru_stime, time.perf_counter() - t0,
                  ru.ru_maxrss]))
"""


PYCACHE = WORK / "pycache"


def child_env() -> dict[str, str]:
    """The environment of a measured child: Python's bytecode cache on, as in an installed ncvm (kept under
    bench/.work, so the source tree gets no __pycache__), whatever the calling shell says."""
    env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    env["PYTHONPYCACHEPREFIX"] = str(PYCACHE.resolve())
    return env


def warm_bytecode() -> None:
    """Compile ncvm into the bench's bytecode cache once, so no measured run pays for compiling."""
    import ncvm

    subprocess.run([sys.executable, "-m", "compileall", "-q", str(Path(ncvm.__file__).parent)], check=True,
                   env=child_env(), stdout=subprocess.DEVNULL)


def child(argv: list[str], stdout: Path | None = None) -> Usage:
    """Run ``argv`` to its end (stdout to the file ``stdout`` or discarded) and measure that one child with
    ``os.wait4``, its own rusage (RUSAGE_CHILDREN would mix in every earlier child's peak)."""
    argv = [shutil.which(argv[0]) or argv[0], *map(str, argv[1:])]
    for _attempt in range(3):  # rs274 dies of SIGBUS now and then while another rs274 runs on the machine
        got = subprocess.run([sys.executable, "-S", "-I", "-c", LAUNCHER, str(stdout or ""), *argv],
                             stdin=subprocess.DEVNULL, capture_output=True, text=True, env=child_env())
        if got.returncode != 0 or not got.stdout:
            raise RuntimeError(f"launcher for {' '.join(argv)} failed: {got.stderr[-2000:]}")
        code, cpu, wall, maxrss = json.loads(got.stdout.splitlines()[-1])
        if code >= 0:
            break
    if code != 0:
        raise RuntimeError(f"{' '.join(argv)} exited {code}: {got.stderr[-2000:]}")
    return Usage(cpu, wall, maxrss / 1024)


def rs274_argv(ngc: Path) -> list[str]:
    return [rs274(), "-g", str(ngc), str(WORK / (ngc.stem + ".rs274.txt"))]
