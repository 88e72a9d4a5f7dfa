"""``--gcode`` writes the run "as flat G-code for a modern control" (README). A thread (DIN G33, LinuxCNC's
spindle-synchronised motion, docs/din.md "Threads"; SINUMERIK G33, CL 800 manual L7397) must stay a
spindle-synchronised move there: written as a plain G1 at the mean feed, the modern control cuts it without
following the spindle, and the thread is scrap."""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

from review14_helpers import MACHINE


def _flat(tmp_path: Path, name: str, text: str) -> str:
    (tmp_path / "machine.toml").write_text(MACHINE)
    (tmp_path / name).write_text(text)
    out = tmp_path / "flat.ngc"
    proc = subprocess.run([sys.executable, "-m", "ncvm", "run", "--gcode", str(out), "--machine",
                           str(tmp_path / "machine.toml"), "--state", str(tmp_path / ".s"), str(tmp_path / name)],
                          capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr
    return out.read_text()


def test_din_g33_stays_a_thread_in_the_flat_gcode(tmp_path):
    """``G33 Z-12 K1.5`` at S600 (rs274 emits START_SPEED_FEED_SYNCH(1.5) around the move). ncvm writes
    ``G1 X0 Y0 Z-12 F900``. Expected: a G33 block with K1.5 to Z-12."""
    flat = _flat(tmp_path, "t.ngc", "G21 G17 G90 G94\nS600 M3\nG33 Z-12 K1.5\nM2\n")
    assert re.search(r"^G33\b.*Z-12\b.*K1\.5\b", flat, re.M), flat


def test_sin800_g33_stays_a_thread_in_the_flat_gcode(tmp_path):
    """SINUMERIK ``N40 G33 Z-20 K1.5`` at S600 (lead 1.5 mm along Z). ncvm writes ``G1 ... Z-20 F900``.
    Expected: a G33 block with K1.5 to Z-20."""
    flat = _flat(tmp_path, "t.mpf", "%MPF4\nN10 G71 G90 G94 G17\nN20 S600 M3\nN30 G0 X10 Z0\nN40 G33 Z-20 K1.5\n"
                 "N50 M30\n")
    assert re.search(r"^G33\b.*Z-20\b.*K1\.5\b", flat, re.M), flat
