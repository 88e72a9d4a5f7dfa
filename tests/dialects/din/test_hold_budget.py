"""What a DIN run holds of the program it reads (issue 18, "memory bounded by design"): the leading stretches
read are held while they cost at most ``din.HOLD_BYTES`` together (a program that fits is read once); the rest
is read again as it runs, from the first stretch not held on. Either way the run, its errors and its refusals
are the same."""

from __future__ import annotations

import gc
import json
import math
import subprocess
import sys
import tracemalloc
from pathlib import Path

import pytest

import ncvm.dialects.din as din
from ncvm.api import run
from ncvm.nc import block
from ncvm.nc.block import COLUMNS_FROM
from ncvm.runtime.session import RunOptions
from tests.conftest import fifo_with


def bolt_circle(holes: int, tail: str = "") -> str:
    """A drilling program as CAM output writes it: per hole a positioning, a plunge, a dwell and a retract
    (every dwell cuts the plain runs short), then ``tail`` and M2."""
    lines = ["G17 G21 G90 G94", "G0 X0 Y0 Z50"]
    for i in range(holes):
        a = 2 * math.pi * i / holes
        lines += [f"G0 X{40 * math.cos(a):.4f} Y{40 * math.sin(a):.4f}", "G0 Z2", "G1 Z-12 F150", "G4 P0.5", "G0 Z2"]
    return "\n".join(lines) + "\n" + tail + "M2\n"


def stretch_costs(path: Path) -> list[tuple[int, int, int]]:
    """(first line, characters, what holding it costs: ``din.held_bytes``) of each stretch of the program."""
    with din.ProgramStretches(str(path), None) as program:
        return [(s.first, s.chars, din.held_bytes(s)) for s in program(COLUMNS_FROM)]


@pytest.fixture
def stretched(monkeypatch, reads):
    """The pieces read (``reads``), in stretches of about 4,096 characters (about 370 lines: read as columns,
    nc.block.COLUMNS_FROM)."""
    monkeypatch.setattr(block, "CHUNK_CHARS", 4096)
    return reads


def run_with_budget(monkeypatch, path: Path, budget: int) -> dict:
    with monkeypatch.context() as m:
        m.setattr(din, "HOLD_BYTES", budget)
        result, _ = run(path, dialect="din", options=RunOptions(state_dir=path.parent / ".ncvm"))
    return result


@pytest.mark.parametrize("tail, outcome", [
    ("", ("ok", None, None)),
    ("G1 X1 B5\n", ("error", "NC011", 2003)),  # an axis the machine lacks: the blocks before it run
    ("G1 X1 Y\n", ("error", "NC001", 2003)),  # a syntax error: stops the run before any move
])
def test_a_program_that_fits_is_read_once_one_just_past_the_budget_again_from_its_last_stretch(
        tmp_path, monkeypatch, stretched, tail, outcome):
    """A bolt circle of 400 holes in stretches of about 4,096 characters, with a late refusal or error: at the
    budget that just holds it the file is read once; one byte under it its last stretch is read again if it
    runs, and at nothing held the whole file; the JSON summary (status, error and its line, steps, moves,
    position, cycle time) is the same each way, and that of the default budget."""
    path = tmp_path / "drill.ngc"
    text = bolt_circle(400, tail)
    path.write_text(text)
    costs = stretch_costs(path)
    fits = sum(cost for _, _, cost in costs)
    assert len(costs) > 4  # read in several stretches
    last = text[len(text) - costs[-1][1]:]
    results = {}
    runs = outcome[1] != "NC001"  # a program with errors does not run: it is not read again
    for budget, again in ((fits, ""), (fits - 1, last * runs), (0, text * runs), (din.HOLD_BYTES, "")):
        stretched.clear()
        results[budget] = run_with_budget(monkeypatch, path, budget)
        assert "".join(stretched) == text + again, f"budget {budget}: read {len(''.join(stretched))} characters"
    once = results[fits]
    assert results[fits - 1] == once == results[0] == results[din.HOLD_BYTES]
    error = once["error"] or {}
    assert (once["status"], error.get("code"), error.get("line")) == outcome
    assert once["motion"]["feed_moves"] == (0 if outcome[1] == "NC001" else 400)


def test_a_long_program_holds_its_leading_stretches_and_reads_the_rest_again(tmp_path, monkeypatch, stretched):
    """A budget that holds three stretches of a longer program: the run holds those three (each costed once,
    and the fourth, which passes the budget), reads the rest again from the fourth stretch's first character
    as it runs, and runs every hole as when it holds the whole."""
    path = tmp_path / "drill.ngc"
    text = bolt_circle(400)
    path.write_text(text)
    costs = stretch_costs(path)
    assert len(costs) > 5
    costed = []
    real = din.held_bytes
    monkeypatch.setattr(din, "held_bytes", lambda stretch: costed.append(stretch.first) or real(stretch))
    stretched.clear()
    r = run_with_budget(monkeypatch, path, sum(cost for _, _, cost in costs[:3]))
    assert r["status"] == "ok" and r["motion"]["feed_moves"] == 400, r["error"]
    assert costed == [first for first, _, _ in costs[:4]]
    assert "".join(stretched) == text + text[sum(chars for _, chars, _ in costs[:3]):]
    assert r == run_with_budget(monkeypatch, path, math.inf)


PIPE_RUN = ("import json, sys\nfrom pathlib import Path\nimport ncvm.dialects.din as din\nfrom ncvm.api import run\n"
            "from ncvm.runtime.session import RunOptions\n"
            "din.HOLD_BYTES = 0  # nothing fits: a file would be read twice\n"
            "r, _ = run(sys.argv[1], options=RunOptions(state_dir=Path(sys.argv[2])))\n"
            "print(json.dumps([r['status'], r['steps'], r['motion']['feed_moves'], r['position']]))\n")


@pytest.mark.parametrize("name", ["p.ngc", "p"])
def test_a_program_from_a_pipe_runs_whole_past_the_budget(tmp_path, name):
    """A named pipe can be read once: opened as a .ngc file it is held whatever the budget (read again, it
    would give nothing and the run would silently make no move); told by its content (no extension) its text
    is read again. Either way every block runs, as from a regular file."""
    text = bolt_circle(30)
    fifo = fifo_with(tmp_path / name, text)
    done = subprocess.run([sys.executable, "-c", PIPE_RUN, str(fifo), str(tmp_path / "s")], capture_output=True,
                          text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    status, steps, moves, position = json.loads(done.stdout)
    assert (status, steps, moves) == ("ok", 2 + 5 * 30 + 1, 30)
    last = 2 * math.pi * 29 / 30  # the last hole, written to 4 decimals
    assert position == {"X": round(40 * math.cos(last), 4), "Y": round(40 * math.sin(last), 4), "Z": 2.0}


def held_measured(path: Path) -> tuple[int, int]:
    """(what the program's segments take when held, as tracemalloc counts it; what din.held_bytes says)."""
    with din.ProgramStretches(str(path), None) as program:
        list(program(COLUMNS_FROM))  # numpy, the regexes and the reader's caches: not the segments' cost
        gc.collect()
        tracemalloc.start()
        try:
            stretches = list(program(COLUMNS_FROM))
            for s in stretches:  # what a run holds: the segments (their PlainRuns keep the stretch's lines)
                s.diags.clear()
            gc.collect()
            taken = tracemalloc.get_traced_memory()[0]
        finally:
            tracemalloc.stop()
        return taken, sum(map(din.held_bytes, stretches))


@pytest.mark.parametrize("shape", ["drilling", "flat", "comments"])
def test_the_estimate_of_held_segments_is_what_they_take(tmp_path, shape):
    """din.held_bytes (RUN_BYTES, BLOCK_BYTES, LINE_BYTES) against tracemalloc: within 15 % for a drilling
    program (short runs cut by dwells), flat CAM output (long runs) and a comment between moves (runs of
    one block), so the budget bounds what a run really holds."""
    holes = 400
    text = {
        "drilling": bolt_circle(holes),
        "flat": "G21 G90 F800\n" + "".join(f"N{10 * i} G1 X{i * 0.37 % 90:.4f} Y{i * 0.11 % 60:.4f} Z-1.0000\n"
                                         for i in range(12_000)) + "M2\n",
        "comments": "G21 G90 F500\n" + "".join(f"(pass {i}: finishing the outer contour)\nG1 X{i % 100}.5\n"
                                             for i in range(3_000)) + "M2\n",
    }[shape]
    path = tmp_path / f"{shape}.ngc"
    path.write_text(text)
    taken, estimated = held_measured(path)
    assert 0.85 * taken < estimated < 1.15 * taken, f"held {taken:,} B, estimated {estimated:,} B"


def run_partly_held(monkeypatch, path: Path, tmp_path: Path, **options) -> dict:
    """The run of ``path`` with the whole program held, with nothing held and with its first three stretches
    held (the rest read again): {budget: (JSON summary, the trace's lines)}; each from a fresh state."""
    costs = stretch_costs(path)
    out = {}
    for budget in (math.inf, 0, sum(cost for _, _, cost in costs[:3])):
        trace = tmp_path / f"trace-{len(out)}.jsonl"
        with monkeypatch.context() as m:
            m.setattr(din, "HOLD_BYTES", budget)
            result, _ = run(path, dialect="din", options=RunOptions(state_dir=tmp_path / f"s{len(out)}", trace=trace,
                                                                   **options))
        out[budget] = (result, trace.read_text())
    return out


@pytest.mark.parametrize("case", ["fault", "step limit"])
def test_a_stop_past_the_held_stretches_is_the_stop_of_a_program_held_whole(tmp_path, monkeypatch, stretched, case):
    """An arc whose end lies off its circle (NC002, a fault the kernel finds as it runs the block) near the end of
    a bolt circle, or the step limit reached there: with the first three stretches held and the rest read again
    as it runs, and with nothing held, the run stops at the same block with the same summary and trace as a run
    that holds the whole program."""
    path = tmp_path / "drill.ngc"
    lines = bolt_circle(400).splitlines()
    options = {}
    if case == "fault":
        lines.insert(1800, "G2 X10 Y0 I1 J0")
    else:
        options["max_steps"] = 1800  # the blocks of lines 1..1800 (every line of a bolt circle is one)
    line = 1801
    path.write_text("\n".join(lines) + "\n")
    assert sum(chars for _, chars, _ in stretch_costs(path)[:3]) < sum(map(len, lines[:1800]))  # past them
    runs = run_partly_held(monkeypatch, path, tmp_path, **options)
    whole = runs[math.inf]
    assert whole[0]["status"] == "error" and whole[0]["error"]["line"] == line, whole[0]["error"]
    assert whole[0]["error"]["code"] == ("NC002" if case == "fault" else "RUN001")
    assert whole[1].count("\n") > 1000  # the moves up to the stop
    assert all(other == whole for other in runs.values())
