"""Second review of issue 18 (performance): the defects found, one failing test each.

No test here times anything: the figures checked are step counts, variables and cycle times.
"""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

LOOP = """\
%MPF9001
N10 G71 G90 G17 R1=0 R2=0
N20 @135 R1 K5 K30
R2=R2+1
R3=R2*2
@620 R1 @100 K-20
N30 M30
"""

RUNAWAY = """\
%MPF9003
N10 R1=0
N20 R1=R1+1
R2=R1*2
@100 K-20
N30 M30
"""


def _run(tmp_path: Path, text: str, *extra: str) -> dict:
    program = tmp_path / "p.mpf"
    program.write_text(text)
    done = subprocess.run([sys.executable, "-m", "ncvm", "run", "-d", "sin800", "--state", str(tmp_path / "st"),
                           "--json", *extra, str(program)], capture_output=True, text=True, timeout=120)
    return json.loads(done.stdout)


def test_sin800_loop_counts_every_block(tmp_path):
    """The count itself is exact: N10, five passes of N20 and its three blocks, the last N20 and N30."""
    assert _run(tmp_path, LOOP)["steps"] == 1 + 5 * 4 + 1 + 1


def test_sin800_step_limit_below_a_programs_steps_stops_it(tmp_path):
    """``--max-steps`` "stops a runaway program after this many statements and blocks" and docs/sin800.md
    says the step limit counts every block. A program of 23 blocks under ``--max-steps 22`` (or 21) ends
    normally reporting 23 steps, more than the limit: the limit is tested only where a loop jumps back. CPL
    stops at exactly the limit (docs/decisions.md, "Steps after a fault (CPL)")."""
    result = _run(tmp_path, LOOP, "--max-steps", "22")
    assert result["steps"] <= 22, f"ran {result['steps']} steps under a limit of 22, status {result['status']}"
    assert result["error"] and result["error"]["code"] == "RUN001"


def test_sin800_runaway_reports_the_variables_of_the_steps_it_reports(tmp_path):
    """A runaway loop of three blocks a pass (N20, R2, @100) after N10: 1,000 steps are N10 and 333 whole
    passes, so R1 = 333 and R2 = 666 when the limit is reached. The run reports 1,000 steps but R1 = 334,
    R2 = 668: the variables of blocks beyond the reported count (a silently inconsistent report)."""
    result = _run(tmp_path, RUNAWAY, "--max-steps", "1000")
    assert result["error"]["code"] == "RUN001"
    assert result["steps"] == 1000
    assert result["variables"]["R1"] == 333.0, result["variables"]
    assert result["variables"]["R2"] == 666.0, result["variables"]
