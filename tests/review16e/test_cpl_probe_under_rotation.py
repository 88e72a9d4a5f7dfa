"""Issue 16 "Done means": the JSONL trace carries, for every motion, the end point in program coordinates
("work"), and translations are compared against it; "Probing is probing". docs/cpl.md: with a `probe`
event left, a G75 block "ends at those positions, the latch holds them and SD(9) = 0". Under a CPL G38
rotation (manual §4.8, L2022-2050) the probe switches (SD(9) = 0, PPOS(2) = 15) but the block runs on to
its programmed end point: the trace's "work" (and every later position of the run) says Y20, where the
machine never went. Without the rotation the same probe ends the block at Y15."""

from __future__ import annotations

import json

import pytest

from tests.review16e.helpers import mill, ncvm, write

EVENT = '[[scenario]]\ntime = 0.0\nkind = "probe"\nY = 35.0\n'  # machine Y: work Y15 under G54 Y20

STRAIGHT = """N10 G90 G17 G54 G0 X0 Y0 Z5
N20 G75 Y20 F100
30 PRN#(0,"SD9=",SD(9)," PPOS=",PPOS(2))
N40 M30
"""

ROTATED = """N10 G90 G17 G54 G0 X0 Y0 Z5
N15 G38 X0 Y0 R90
N20 G75 X20 F100
30 PRN#(0,"SD9=",SD(9)," PPOS=",PPOS(2))
N35 G39
N40 M30
"""


@pytest.mark.parametrize("program", [STRAIGHT, ROTATED], ids=["straight", "rotated"])
def test_probe_block_ends_where_the_probe_switched(tmp_path, program):
    write(tmp_path, {"machine.toml": mill(), "probe.cpl": program, "probe.toml": EVENT})
    r = ncvm(tmp_path, "run", "probe.cpl", "-m", "machine.toml", "--scenario", "probe.toml",
             "--trace", "run.jsonl")
    assert r.returncode == 0, r.stderr
    assert "SD9=        0 PPOS=  15.000" in r.stdout
    probe_moves = [rec for rec in map(json.loads, (tmp_path / "run.jsonl").read_text().splitlines())
                   if rec.get("call") == "feed"]
    assert probe_moves[0]["work"]["Y"] == pytest.approx(15.0), probe_moves[0]
