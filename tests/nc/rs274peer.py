"""Driving LinuxCNC's standalone interpreter ``rs274`` (tests that use it skip when it is absent)."""

from __future__ import annotations

import shutil
import subprocess

import pytest

RS274 = shutil.which("rs274")
needs_rs274 = pytest.mark.skipif(RS274 is None, reason="rs274 not installed (Debian package linuxcnc-uspace)")


def rs274(ngc, canon) -> subprocess.CompletedProcess:
    """``rs274 -g ngc canon``; the peer itself now and then dies of a signal on this machine: try it again then
    (and skip the test when it keeps dying)."""
    for _ in range(3):
        proc = subprocess.run([RS274, "-g", str(ngc), str(canon)], stdin=subprocess.DEVNULL, capture_output=True,
                              text=True, timeout=60)
        if proc.returncode >= 0:
            return proc
    pytest.skip(f"rs274 keeps crashing (signal {-proc.returncode}); the peer is not usable here")
