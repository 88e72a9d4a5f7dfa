"""DIN/ISO and rw_SymPas: a run that stops reports the moves made before the stop, as the same moves ending
normally would (docs/decisions.md, "A run that stops"; the CPL and SINUMERIK cases are in their dialects' tests).

A DIN program runs block by block (plain stretches column-wise): a block refused at run time or the step
limit stops it after the blocks before it. The rw_SymPas card runs spooled segments on its own once a task
started them (SSMS): a task's run-time error does not stop them, and segments never started never move.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from ncvm.api import run
from ncvm.runtime.session import RunOptions

AXIS = "min = -1000.0\nmax = 1000.0\nrapid = 60000.0\nmax_feed = 60000.0\naccel = 1000.0\n"
MACHINE = "".join(f'[[axis]]\nname = "{a}"\n{AXIS}' for a in "XYZ")
SAME = ("motion", "position", "cycle_time_s", "limit_violations")


def go(folder: Path, name: str, text: str, machine: str = MACHINE, **options) -> dict:
    (folder / "machine.toml").write_text(machine)
    (folder / name).write_text(text)
    return run(folder / name, machine=folder / "machine.toml",
               options=RunOptions(state_dir=folder / ".ncvm", **options))[0]


def din(n: int) -> list[str]:
    return [f"N{i} G1 X{i} F600" for i in range(1, n + 1)]


def test_din_a_block_refused_mid_file_keeps_the_moves_before_it(tmp_path):
    """Line 700 of 1,000 1 mm blocks has G7 (NC004): 699 moves, X699, 69.9 s plus one ramp (0.01 s)."""
    lines = din(1000)
    lines[699] = "N700 G7 X1"
    r = go(tmp_path, "bad.nc", "\n".join(lines) + "\nM30\n")
    assert (r["error"]["code"], r["error"]["line"]) == ("NC004", 700)
    assert r["motion"]["feed_moves"] == 699 and r["position"]["X"] == 699.0
    assert r["cycle_time_s"] == pytest.approx(69.91)
    ended = go(tmp_path, "ok.nc", "\n".join(din(699)) + "\nM30\n")
    assert {k: r[k] for k in SAME} == {k: ended[k] for k in SAME}


def test_din_the_step_limit_keeps_the_blocks_that_ran(tmp_path):
    r = go(tmp_path, "long.nc", "\n".join(din(1000)) + "\nM30\n", max_steps=700)
    assert (r["error"]["code"], r["error"]["line"]) == ("RUN001", 701)
    ended = go(tmp_path, "ok.nc", "\n".join(din(700)) + "\nM30\n")
    assert r["motion"]["feed_moves"] == 700
    assert {k: r[k] for k in SAME} == {k: ended[k] for k in SAME}


SAP = """program T;
var i, z: integer;
begin
CL(A1, A2);
TRVL := 10.0; TRAC := 100.0;
SMLR(A1 := 10.0); SMLR(A1 := 10.0); SMLR(A1 := 10.0);
{}
z := 0;
{}
end.
"""


@pytest.mark.parametrize("start", ["SSMS(A1);", ""], ids=["started", "never started"])
def test_sympas_spooled_segments_a_task_started_run_on_after_its_error(tmp_path, start):
    """Three 10 mm segments spooled and started with SSMS run to their end after ``5 mod 0`` (error 32768),
    as they do when the program ends there; without SSMS they never move, either way."""
    stop = go(tmp_path, "stop.sap", SAP.format(start, "i := 5 mod z;"))
    end = go(tmp_path, "end.sap", SAP.format(start, ""))
    assert (stop["error"]["code"], stop["error"]["line"]) == ("32768", 9)
    assert end["status"] == "ok"
    assert stop["motion"]["feed_moves"] == (3 if start else 0)
    # the cycle time of a program that never moves is its statements' time (a tick each, docs/decisions.md)
    same = SAME if start else ("motion", "position", "limit_violations")
    assert {k: stop[k] for k in same} == {k: end[k] for k in same}
