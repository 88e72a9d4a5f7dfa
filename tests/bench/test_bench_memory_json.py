"""The bench's memory cases put their figures in ``bench/run.py --json`` (issue 18, "Done means"): the peak
resident memory of the child that ran the program, not only a printed line. Run here on a small program
(the cases' own are a million moves), through the same child launcher and the same ``run.measure``."""

from __future__ import annotations

import importlib.util
import json
import sys
from pathlib import Path

import pytest

BENCH = Path(__file__).resolve().parents[2] / "bench"


def _module(name: str):
    sys.path.insert(0, str(BENCH))
    try:
        spec = importlib.util.spec_from_file_location(f"bench_{name}", BENCH / f"{name}.py")
        module = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(module)
        return module
    finally:
        sys.path.remove(str(BENCH))


@pytest.mark.parametrize("dialect, text, moves", [
    ("din", "G21 G90 G17 F6000\n" + "".join(f"G1 X{i % 10} Y{i // 10}\n" for i in range(300)) + "M30\n", 300),
    ("cpl_output", "10 I% = 0\n20 WHILE I% < 50 DO\n30 I% = I% + 1\n40 PRN#(0, \"LINE \", I%)\n50 END\nM30\n", 0),
])
def test_a_memory_case_gives_its_peak_rss_to_the_json_document(tmp_path, monkeypatch, dialect, text, moves):
    memory = _module("cases_memory")
    run = _module("run")
    program = tmp_path / ("p.ngc" if dialect == "din" else "p.cpl")
    program.write_text(text)
    monkeypatch.setattr(memory, "MOVES", moves)
    monkeypatch.setattr(memory, "PROGRAMS", {dialect: program})
    monkeypatch.setattr(memory, "WORK", tmp_path)
    case = memory.Case(memory.runner(dialect), max(moves, 1), "G1/s", repeat=1, in_process=False)
    figures = json.loads(json.dumps(run.measure(case, 1)))
    assert figures["clock"] == "cpu"
    assert 5.0 < figures["ncvm_peak_rss_mb"] < 1000.0  # a Python process's own peak, in MB
    assert figures["ncvm_cpu_s"] > 0.0 and figures["median_s"] == figures["ncvm_cpu_s"]
    assert "peak" in run.details(figures)
