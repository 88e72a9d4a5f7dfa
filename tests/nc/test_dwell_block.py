"""Issue 14: a dwell block (G4) never drops a word of its block.

``din`` follows rs274 (LinuxCNC's order of execution: the dwell is step 10, the motion step 21): ``G4 P1 G0 X5``
dwells one second, then moves; its F is a feed. Without P, DIN controls write the time as X or F: the block is
then the dwell alone, and another axis word or a motion G code in it is refused (NC009). The controls' manuals
write the dwell in a block of its own (CL 800 ``G4 F=R27``, L5465; CPL's dwell of MCODS 39, L2949): an axis
word beside the time is refused there too, by run and check alike (docs/decisions.md, "Issue 14: in-block
order and modal groups")."""

from __future__ import annotations

import json
import subprocess
import sys

import pytest


def _run(tmp_path, name: str, text: str, command: str = "run", *more: str) -> subprocess.CompletedProcess:
    (tmp_path / name).write_text(text)
    return subprocess.run([sys.executable, "-m", "ncvm", command, *more, str(tmp_path / name)], capture_output=True,
                          text=True, timeout=120, cwd=tmp_path)


def _trace(tmp_path, text: str) -> list[dict]:
    proc = _run(tmp_path, "p.ngc", text, "run", "--trace", str(tmp_path / "t.jsonl"))
    assert proc.returncode == 0, proc.stderr
    return [json.loads(line) for line in (tmp_path / "t.jsonl").read_text().splitlines()]


def test_din_dwells_then_moves_as_rs274_orders_a_block(tmp_path):
    rows = _trace(tmp_path, "G21 G90\nG0 X1\nG4 P1.5 G0 X5\nM2\n")
    calls = [r["call"] for r in rows if r["call"] in ("dwell", "rapid")]
    assert calls == ["rapid", "dwell", "rapid"]
    move = [r for r in rows if r["call"] == "rapid"][-1]
    assert move["end"]["X"] == 5.0


def test_din_dwell_block_under_modal_motion_moves_and_its_f_is_the_feed(tmp_path):
    rows = _trace(tmp_path, "G21 G90\nG1 X1 F100\nG4 P1 X5 F50\nM2\n")
    feed = [r for r in rows if r["call"] == "feed"][-1]
    assert feed["end"]["X"] == 5.0
    assert feed["feed"] == 50.0


@pytest.mark.parametrize(("block", "words"), [("G4 X2 Y5", "Y"), ("G4 X2 G0", "G0"), ("G4 F2 G1 Z1", "Z"),
                                              ("G4 X2 F3", "X and F")])
@pytest.mark.parametrize("command", ["run", "check"])
def test_din_dwell_without_p_is_a_block_of_its_own(tmp_path, command, block, words):
    proc = _run(tmp_path, "p.ngc", f"G21 G90\nG0 X1\n{block}\nM2\n", command)
    assert proc.returncode == 1, proc.stdout + proc.stderr
    assert "p.ngc:3:" in proc.stderr and "error NC009" in proc.stderr and words in proc.stderr


@pytest.mark.parametrize(("dialect", "name", "text", "line"), [
    ("sin800", "p.mpf", "%MPF1\nN1 G1 X10 F100\nN2 G4 F2 Y5\nN3 M30\n", 3),
    ("sin800", "p.mpf", "%MPF1\nN1 G4 X2 Z1\nN3 M30\n", 2),
    ("cpl", "p.cpl", "N1 G1 X10 F100\nN2 G4 X2 Y5\nN3 M30\n", 2),
])
@pytest.mark.parametrize("command", ["run", "check"])
def test_controls_refuse_an_axis_word_in_a_dwell_block_L5465(tmp_path, command, dialect, name, text, line):
    proc = _run(tmp_path, name, text, command, "--dialect", dialect)
    assert proc.returncode == 1, proc.stdout + proc.stderr
    assert f"{name}:{line}" in proc.stderr and "NC009" in proc.stderr and "dwell" in proc.stderr
    assert "Traceback" not in proc.stderr


def test_sin800_dwell_alone_still_dwells(tmp_path):
    proc = _run(tmp_path, "p.mpf", "%MPF1\nN1 G4 F2\nN2 M30\n", "run", "--dialect", "sin800", "--json")
    assert proc.returncode == 0, proc.stderr
    assert json.loads(proc.stdout)["cycle_time_s"] == pytest.approx(2.0, abs=0.01)
