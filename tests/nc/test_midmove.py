"""Positions part-way through an executed block (nc/midmove.py) against the kernel's own move times.

A move's trapezoid is symmetric (accelerate and decelerate alike), so half-way through the kernel's time a
straight move is at its midpoint and an arc at half its sweep: that holds only if midmove times the move
exactly as the kernel did.
"""

from __future__ import annotations

import math

import pytest

from ncvm.machine.config import machine_from_dict
from ncvm.nc.block import Block
from ncvm.nc.canon import Canon, Src
from ncvm.nc.kernel import NcKernel
from ncvm.nc.midmove import MotionRecorder, position_at

SRC = Src("t", 1)


def kernel():
    axes = [{"name": "X", "max_feed": 3000, "accel": 500}, {"name": "Y"}, {"name": "Z", "accel": 200}]
    return NcKernel(machine_from_dict({"axis": axes}), Canon([]))


def run(k, g, **words):
    """Execute one block with the recorder on: (clock before, clock after, position before, moves)."""
    clock = k.machine.clock
    t0, before = clock.now, k.machine_pos
    with MotionRecorder(k.canon, clock) as rec:
        k.execute(Block(g, (), {a: float(v) for a, v in words.items()}, None, None, SRC))
    return t0, clock.now, before, list(rec.moves)


@pytest.mark.parametrize("g, words, mid", [
    ((0,), {"X": 40, "Y": 30, "Z": -10}, (20.0, 15.0, -5.0)),  # rapid, Z's acceleration limits the path
    ((1,), {"X": 100, "F": 9000}, (50.0, 0.0, 0.0)),  # F9000 capped at X's 3000 mm/min
    ((1,), {"X": 0.2, "Y": 0.1, "F": 600}, (0.1, 0.05, 0.0)),  # too short to reach the feed: a triangle
])
def test_straight_move_is_at_its_midpoint_half_way(g, words, mid):
    k = kernel()
    t0, t1, before, moves = run(k, g, **words)
    assert t1 > t0
    assert position_at(moves, k.dyn, (t0 + t1) / 2, before) == pytest.approx(mid, abs=1e-9)
    assert position_at(moves, k.dyn, t0, before) == pytest.approx(before, abs=1e-12)
    assert position_at(moves, k.dyn, t1, before) == k.machine_pos


def test_helical_arc_is_at_half_its_sweep_half_way():
    k = kernel()
    k.execute(Block((1,), (), {"X": 10.0, "F": 1200.0}, None, None, SRC))
    # counter-clockwise quarter circle about (0,0) from (10,0) to (0,10), rising 4 mm in Z
    t0, t1, before, moves = run(k, (3,), X=0, Y=10, Z=4, I=-10, J=0)
    x, y, z = position_at(moves, k.dyn, (t0 + t1) / 2, before)
    assert (x, y, z) == pytest.approx((10 * math.cos(math.pi / 4), 10 * math.sin(math.pi / 4), 2.0), abs=1e-9)
    # before the middle the point lies on the circle too, nearer the start
    x, y, _ = position_at(moves, k.dyn, t0 + (t1 - t0) / 4, before)
    assert math.hypot(x, y) == pytest.approx(10.0) and 0 < math.atan2(y, x) < math.pi / 4


def test_dwell_holds_and_nothing_moves_before_the_block():
    k = kernel()
    t0, t1, before, moves = run(k, (4,), F=2)
    assert t1 - t0 == 2.0 and moves == []
    assert position_at(moves, k.dyn, t0 + 1.0, before) == before
