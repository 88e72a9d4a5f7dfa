"""What the review-14 tests share: a fast machine, a run of ``ncvm run`` in a process, the moves of a trace."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

# An X/Y/Z machine with fast axes (acceleration and rapid so high that a time computed by hand from
# path / feed holds to a millisecond), SINUMERIK data for the sin800 runs.
MACHINE = "".join(f'[[axis]]\nname = "{a}"\nmin = -1000.0\nmax = 1000.0\nrapid = 60000.0\nmax_feed = 60000.0\n'
                  f'accel = 100000000.0\n' for a in "XYZ") + '[sin800]\ncontrol = "880"\n'


def make_runner(tmp_path: Path):
    """ncvm_run(name, text, files={}) -> (JSON result, trace rows, stderr) of ``ncvm run`` in a process."""

    def _run(name: str, text: str, files: dict | None = None, machine: str = MACHINE):
        (tmp_path / "machine.toml").write_text(machine)
        for fname, body in (files or {}).items():
            (tmp_path / fname).write_text(body)
        (tmp_path / name).write_text(text)
        trace = tmp_path / "trace.jsonl"
        proc = subprocess.run([sys.executable, "-m", "ncvm", "run", "--json", "--trace", str(trace),
                               "--machine", str(tmp_path / "machine.toml"), "--state", str(tmp_path / ".state"),
                               str(tmp_path / name)], capture_output=True, text=True, timeout=120)
        assert "Traceback" not in proc.stderr, proc.stderr
        result = json.loads(proc.stdout)
        rows = [json.loads(line) for line in trace.read_text().splitlines()] if trace.exists() else []
        return result, rows, proc.stderr

    return _run


def moves(rows: list[dict]) -> list[tuple]:
    """(call, X, Y, Z, file name, line) of every move of a trace."""
    return [(r["call"], round(r["end"]["X"], 4), round(r["end"]["Y"], 4), round(r["end"]["Z"], 4),
             Path(r["file"]).name, r["line"]) for r in rows if r["call"] in ("rapid", "feed", "arc")]
