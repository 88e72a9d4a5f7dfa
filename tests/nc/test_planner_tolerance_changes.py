"""A change of the corner tolerance (``G64 P``) applies to the junctions programmed after it: each junction
keeps the tolerance in force when the move that starts at it was added, however long it waits in the
look-ahead window (docs/decisions.md, "Corner tolerance per junction"). Both planner paths (numpy and plain
Python) agree to the last bit with changes too."""

from __future__ import annotations

import json
import math
import random
import subprocess
import sys

import pytest
from test_planner_small import DYN, Clock, Timings, add_random

from ncvm.nc.planner import LOOKAHEAD, REST, SMALL, Planner, junction_speed2

X, Y = (1.0, 0.0, 0.0), (0.0, 1.0, 0.0)
V, A = 50.0, 1000.0  # mm/s, mm/s^2: 100 mm moves reach every corner's speed


def zigzag(planner: Planner, count: int, changes: dict[int, float]) -> None:
    """``count`` 100 mm moves turning 90 degrees at each junction; ``changes``: moves added -> new tolerance."""
    for i in range(count):
        if i in changes:
            planner.set_tolerance(changes[i])
        u = X if i % 2 == 0 else Y
        planner.add(100.0, V, A, 0, u, u)


def corner(tolerance: float) -> float:
    """The speed (mm/min) of one of the zigzag's corners under ``tolerance``."""
    return math.sqrt(junction_speed2(X, Y, V, V, DYN.accel, tolerance)) * 60.0


@pytest.mark.parametrize("count, window, limit", [(12, 100, None), (300, 3, 20), (300, 40, 50)])
def test_each_corner_keeps_the_tolerance_in_force_when_its_second_move_was_added(count, window, limit):
    """Commits (a short window, a low limit) plan the older moves while the later ones wait: the junctions
    still waiting keep their tolerance, counted from the first move left."""
    timings = Timings()
    planner = Planner(Clock(), timings, DYN, window=window, tolerance=0.01)
    if limit:
        planner.limit = limit * planner.width
    first, second = count // 3, 2 * count // 3
    zigzag(planner, count, {first: 0.5, first + 1: 1.0, second: 0.01})
    planner.stop()
    assert corner(0.01) < corner(0.5) < corner(1.0) < V * 60.0  # distinct limits: the checks can fail
    expected = [corner(0.01 if i < first or i >= second else 0.5 if i == first else 1.0)
                for i in range(1, count)]
    assert timings.exit[:-1] == pytest.approx(expected, rel=1e-9)
    assert timings.exit[-1] == 0.0
    assert planner.changes == []


def test_a_change_with_one_move_waiting_is_the_tolerance_of_its_next_junction():
    timings = Timings()
    planner = Planner(Clock(), timings, DYN, tolerance=0.01)
    zigzag(planner, 4, {1: 0.5})
    assert planner.changes == []
    planner.stop()
    assert timings.exit[:-1] == pytest.approx([corner(0.5)] * 3, rel=1e-9)


@pytest.mark.parametrize("model", [LOOKAHEAD, REST])
@pytest.mark.parametrize("seed", range(30))
def test_plain_python_plan_equals_the_numpy_plan_with_tolerance_changes(seed, model):
    out = []
    for python in (True, False):
        rng = random.Random(seed)
        timings, clock = Timings(), Clock()
        planner = Planner(clock, timings, DYN, model=model, window=rng.choice((1, 2, 5, 100)), tolerance=0.02)
        for _ in range(rng.randint(1, 5)):
            add_random(planner, rng, rng.randint(0, SMALL // 6))
            planner.set_tolerance(rng.choice((0.0, 0.005, 0.02, 0.1, 5.0)))
        add_random(planner, rng, rng.randint(1, 5))
        if python:
            planner._plan_rows()
        else:
            planner._plan(None)
        out.append((timings.times, timings.entry, timings.exit, clock.settled))
    assert out[0] == out[1]


def _exit_speeds(tmp_path, name: str, text: str) -> list[float]:
    program, trace = tmp_path / f"{name}.ngc", tmp_path / f"{name}.jsonl"
    program.write_text(text)
    done = subprocess.run([sys.executable, "-m", "ncvm", "run", "-d", "din", "--state", str(tmp_path / name),
                           "--trace", str(trace), str(program)], capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    return [r["v_exit"] for r in map(json.loads, trace.read_text().splitlines()) if r["call"] == "feed"]


def test_a_G64_P_in_a_moving_block_sets_the_corner_that_block_starts_at(tmp_path):
    """``G64 P0.5 G1 X20 Y10`` after corners under ``G64 P0.01``: the corner at X10 Y10 (where that block
    starts) is passed as under ``G64 P0.5`` throughout, the one before it as under ``G64 P0.01``."""
    moves = "G1 X10 Y0\nG1 X10 Y10\n{g64}G1 X20 Y10\nG1 X20 Y20\nM30\n"
    fine = _exit_speeds(tmp_path, "fine", "G21 G90 G17 F3000 G64 P0.01\n" + moves.format(g64=""))
    coarse = _exit_speeds(tmp_path, "coarse", "G21 G90 G17 F3000 G64 P0.5\n" + moves.format(g64=""))
    mixed = _exit_speeds(tmp_path, "mixed", "G21 G90 G17 F3000 G64 P0.01\n" + moves.format(g64="G64 P0.5 "))
    assert fine[0] < coarse[0] < 3000.0
    assert mixed[0] == pytest.approx(fine[0], rel=1e-9)
    assert mixed[1:3] == pytest.approx(coarse[1:3], rel=1e-9)
