"""Bosch Typ3 osa and SINUMERIK 810–880 name their G groups (CPL manual's group table L2302–2306, "Index /
G functions": 0-3 ... one group, 90, 91 ... another; CL 800 manual §11.5 L7392–7410: group 0 G00 G01 ...,
group 10 G90 G91): only one function of a group is active. Issue 14: "never silently ignore a word"; the
project itself makes two additive shifts of one group in a Typ3 block CPL040 (docs/decisions.md, G154-G159).
ncvm runs ``G0 G1 X5`` and ``G90 G91 X5`` in both dialects without a word, silently keeping the last word of
the group (``G90 G91 X5`` moves incrementally), and ``G54 G55`` in a Typ3 block. A clear error is expected."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

AXES = "".join(f'[[axis]]\nname = "{a}"\nmin = -1000.0\nmax = 1000.0\nrapid = 60000.0\nmax_feed = 60000.0\n'
               f'accel = 100000000.0\n' for a in "XYZ")
SIN800 = AXES + '[sin800]\ncontrol = "880"\n'


def _status(tmp_path: Path, name: str, text: str, machine: str) -> str:
    (tmp_path / "machine.toml").write_text(machine)
    (tmp_path / name).write_text(text)
    proc = subprocess.run([sys.executable, "-m", "ncvm", "run", "--json", "--machine",
                           str(tmp_path / "machine.toml"), "--state", str(tmp_path / ".state"),
                           str(tmp_path / name)], capture_output=True, text=True, timeout=120)
    assert "Traceback" not in proc.stderr, proc.stderr
    return json.loads(proc.stdout)["status"]


@pytest.mark.parametrize("block", ["G0 G1 X5 F100", "G90 G91 X5", "G54 G55 G0 X5"])
def test_typ3_refuses_two_functions_of_one_group(tmp_path: Path, block: str) -> None:
    assert _status(tmp_path, "prog.cpl", f"N10 G0 X5\nN20 {block}\nN30 M30\n", AXES) == "error"


@pytest.mark.parametrize("block", ["G0 G1 X5 F100", "G90 G91 X5"])
def test_sinumerik_refuses_two_functions_of_one_group(tmp_path: Path, block: str) -> None:
    assert _status(tmp_path, "prog.mpf", f"%MPF1\nN10 G0 X5\nN20 {block}\nN30 M30\n", SIN800) == "error"
