"""SINUMERIK H words: auxiliary functions output to the PLC (machine data bit 5400.0 "defines whether
auxiliary functions are to be output to the PLC", CL 800 planning guide L3072). ncvm hands them on as it
does a machine-specific M function: a canon ``aux`` call in the trace, no motion of their own, and no
NC007 stop (docs/decisions.md, "Issue 14: the H word")."""

from __future__ import annotations

import json
import subprocess
import sys

from sin800_helpers import machine, run_mpf

from ncvm.api import check


def _trace_run(tmp_path, text: str):
    (tmp_path / "m.toml").write_text(machine())
    (tmp_path / "p.mpf").write_text(text)
    trace = tmp_path / "t.jsonl"
    proc = subprocess.run([sys.executable, "-m", "ncvm", "run", "--json", "--dialect", "sin800", "--machine",
                           str(tmp_path / "m.toml"), "--trace", str(trace), str(tmp_path / "p.mpf")],
                          capture_output=True, text=True, timeout=120)
    return proc, [json.loads(line) for line in trace.read_text().splitlines()]


def test_l3072_h_word_goes_to_the_plc_in_order(tmp_path):
    """H12 on a move block and H3 alone: both reach the trace as auxiliary functions, at their lines; the
    move still runs, the H3 block does not move."""
    proc, rows = _trace_run(tmp_path, "%MPF1\nG1 F100 X10 H12\nH3\nX20\nM30\n")
    assert proc.returncode == 0, proc.stderr
    aux = [(r["code"], r["line"]) for r in rows if r["call"] == "aux"]
    assert aux == [("H12", 2), ("H3", 3)]
    moves = [r["line"] for r in rows if r["call"] in ("feed", "rapid")]
    assert moves == [2, 4]
    assert json.loads(proc.stdout)["position"]["X"] == 20.0


def test_h_word_is_no_refused_address_in_check(tmp_path):
    """ncvm check no longer warns of H (NC007): a clean check, and the run ends normally."""
    (tmp_path / "m.toml").write_text(machine())
    path = tmp_path / "p.mpf"
    path.write_text("%MPF1\nG0 X1 H7\nM30\n")
    assert [d.code for d in check(path, dialect="sin800", machine=tmp_path / "m.toml")] == []
    assert run_mpf(tmp_path, "%MPF1\nG0 X1 H7\nM30\n")["status"] == "ok"


def test_l3072_every_h_word_of_a_block_goes_to_the_plc_in_the_blocks_order(tmp_path):
    """Several H words in one block: each is an auxiliary function output to the PLC (L3072), as each M word
    of a block is, in the order the block writes them; constant values (a plain block) and values read from R
    parameters (``H=R1``) alike, and on a block that moves."""
    proc, rows = _trace_run(tmp_path, "%MPF1\nH12 H13 H2\nR1=5 R2=6\nG1 F100 X10 H=R1 H7 H=R2\nM30\n")
    assert proc.returncode == 0, proc.stderr
    aux = [(r["code"], r["line"]) for r in rows if r["call"] == "aux"]
    assert aux == [("H12", 2), ("H13", 2), ("H2", 2), ("H5", 4), ("H7", 4), ("H6", 4)]
    assert json.loads(proc.stdout)["position"]["X"] == 10.0
