"""Review of issue 18 (performance): the defects found, one failing test each.

Each test names the issue item it holds the project to; it fails on the branch as reviewed. No test here
times anything: the figures checked are cycle times, counts and memory.
"""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def test_done_means_bench_json_runs_the_collinear_case_and_includes_its_cycle_time(tmp_path):
    """Issue 18 "Done means": bench/ prints every figure of the table and ``python bench/run.py --json``
    includes them. The din_collinear_1000 case returns the run's result dict, which run.measure takes for a
    whole-process case's figures: the bench dies (KeyError ncvm_cpu_s, or a TypeError sorting None in summarise), so the
    whole ``bench/run.py --json`` never writes its JSON (cases_din comes before cases_process). The cycle time
    (20.05 s goal) is only printed in setup, never put in the JSON."""
    out = tmp_path / "bench.json"
    done = subprocess.run([sys.executable, str(ROOT / "bench" / "run.py"), "--only", "din_collinear_1000",
                           "--repeat", "1", "--json", str(out)], cwd=ROOT, capture_output=True, text=True,
                          timeout=600)
    assert done.returncode == 0, done.stderr[-2000:]
    case = json.loads(out.read_text())["cases"]["din_collinear_1000"]
    assert any("cycle" in key for key in case), f"no cycle-time figure in the JSON: {sorted(case)}"
