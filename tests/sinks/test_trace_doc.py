"""docs/trace.md describes the trace as it is: every call the trace writes has its row, and the example
lines are those of a real run of the example program."""

from __future__ import annotations

import json
import re
from pathlib import Path

from ncvm.api import run
from ncvm.nc.canon import CanonSink
from ncvm.runtime.session import RunOptions
from ncvm.sinks.trace import JsonlTrace

DOC = (Path(__file__).parents[2] / "docs" / "trace.md").read_text()
PROGRAM = "G10 L2 P1 X10 Y0 Z0\nG54 T1 M6\nG43 H1\nS1000 M3 M8\nG0 X0 Y0 Z5\nG1 Z-1 F300\nG2 X10 Y0 I5 J0\n" \
          "G4 P0.5\n(MSG, done)\nM5 M9\nM30\n"
MACHINE = """[[axis]]
name = "X"
[[axis]]
name = "Y"
[[axis]]
name = "Z"
[[tool]]
number = 1
length = 50.0
"""


def test_every_call_the_trace_writes_is_documented():
    documented = set(re.findall(r"^\| `(\w+)` \|", DOC, re.M)) - {"call"}  # the table's rows, not its header
    written = {name for name in vars(JsonlTrace) if not name.startswith("_") and hasattr(CanonSink, name)
               and name not in ("end", "timing", "frame")}  # these two add fields to the move lines
    assert documented == written


def test_the_example_is_a_real_trace(tmp_path: Path, monkeypatch):
    (tmp_path / "t.din").write_text(PROGRAM)
    (tmp_path / "m.toml").write_text(MACHINE)
    trace = tmp_path / "t.jsonl"
    monkeypatch.chdir(tmp_path)  # the trace names the file as the run was given it: t.din
    result, _ = run("t.din", machine="m.toml", options=RunOptions(state_dir=tmp_path / "s", trace=trace))
    assert result["status"] == "ok", result["error"]
    lines = [json.loads(line) for line in trace.read_text().splitlines()]
    example = DOC.split("```\n")[1]
    shown = [json.loads(line) for line in example.splitlines() if line.startswith("{")]
    assert len(shown) == 7 and all(record in lines for record in shown)
