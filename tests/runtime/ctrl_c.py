"""Ctrl-C sent to a real ncvm process as a terminal sends it (SIGINT), once the process has got going.

The tests that interrupt a run wait for a sign of work (a trace file that grows, a pool at work), send the
signal, and collect what the process wrote; a process that outlives the test is killed, never left behind.
"""

from __future__ import annotations

import os
import signal
import subprocess
import time
from collections.abc import Callable
from pathlib import Path


def wait_until(ready: Callable[[], bool], what: str, timeout: float = 180.0) -> None:
    """Poll ``ready`` until it holds; fail naming ``what`` after ``timeout`` seconds."""
    end = time.monotonic() + timeout
    while not ready():
        if time.monotonic() > end:
            raise AssertionError(f"gave up after {timeout:g} s waiting for {what}")
        time.sleep(0.05)


def grown_past(path: Path, size: int) -> Callable[[], bool]:
    """True once the file at ``path`` holds more than ``size`` bytes (a run's trace: it is moving)."""
    return lambda: path.exists() and path.stat().st_size > size


def ctrl_c(proc: subprocess.Popen, ready: Callable[[], bool] | None = None, what: str = "the run to start",
           *, settle: float = 0.0, group: bool = False, timeout: float = 120.0):
    """Once ``ready`` holds (and ``settle`` seconds more), interrupt ``proc`` -- its whole process group
    with ``group``, as the terminal does -- and return its ``(stdout, stderr)``."""
    try:
        if ready is not None:
            wait_until(ready, what)
        time.sleep(settle)
        if group:
            os.killpg(proc.pid, signal.SIGINT)
        else:
            proc.send_signal(signal.SIGINT)
        return proc.communicate(timeout=timeout)
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.communicate()
