"""SINUMERIK 810–880: the manual's dwell is ``G4 F=R27`` (CL 800 manual L5465, L5530: "Dwell time at
drilling depth"), a block of its own. Issue 14: "For each function: implement it, or refuse it with a clear
'not supported by ncvm' (never silently ignore a word)". ncvm runs ``N2 G4 F2 Y5`` as a two-second dwell and
drops ``Y5`` without a word: the run ends normally with Y at 0. Either the move (as LinuxCNC does for a dwell
block with axis words) or a clear error is expected, not a lost axis word."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

MACHINE = "".join(f'[[axis]]\nname = "{a}"\nmin = -1000.0\nmax = 1000.0\nrapid = 60000.0\nmax_feed = 60000.0\n'
                  f'accel = 100000000.0\n' for a in "XYZ") + '[sin800]\ncontrol = "880"\n'


def test_a_dwell_block_does_not_drop_its_axis_word(tmp_path: Path) -> None:
    (tmp_path / "machine.toml").write_text(MACHINE)
    (tmp_path / "dwell.mpf").write_text("%MPF1\nN1 G1 X10 F100\nN2 G4 F2 Y5\nN3 M30\n")
    trace = tmp_path / "trace.jsonl"
    proc = subprocess.run([sys.executable, "-m", "ncvm", "run", "--json", "--trace", str(trace), "--machine",
                           str(tmp_path / "machine.toml"), "--state", str(tmp_path / ".state"),
                           str(tmp_path / "dwell.mpf")], capture_output=True, text=True, timeout=120)
    assert "Traceback" not in proc.stderr, proc.stderr
    result = json.loads(proc.stdout)
    rows = [json.loads(line) for line in trace.read_text().splitlines()] if trace.exists() else []
    ends = [r["end"]["Y"] for r in rows if r["call"] in ("rapid", "feed", "arc")]
    assert result["status"] == "error" or ends[-1] == 5.0, (result["status"], ends)
