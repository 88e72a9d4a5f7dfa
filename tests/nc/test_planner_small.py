"""The planner's plain-Python plan of a few moves (nc/planner.py ``_plan_rows``) gives the numpy plan's
answers to the last bit: every move's time, entry and exit speed, and the clock (issue 18: a short run
imports no numpy for its moves). Random sequences of straight moves (as the kernel's hot path adds them and
as :meth:`Planner.add` does), arcs and helices (tangents turning within the move), rapid moves, exact-stop
flags, both time models, windows 1..N and corner tolerances are planned both ways."""

from __future__ import annotations

import math
import random
import subprocess
import sys

import pytest

from ncvm.machine.config import machine_from_dict
from ncvm.nc.dynamics import AxisDynamics, trapezoid_time
from ncvm.nc.planner import (
    LOOKAHEAD,
    POSITIONING,
    REST,
    SMALL,
    STOP_END,
    STOP_START,
    Planner,
    rest_times_for,
    straight_row_limits,
)

AXES = [{"name": "X", "accel": 1000.0, "max_feed": 5000.0, "rapid": 20000.0},
        {"name": "Y", "accel": 600.0, "max_feed": 4000.0, "rapid": 15000.0},
        {"name": "Z", "accel": 300.0, "max_feed": 2000.0, "rapid": 8000.0}]
DYN = AxisDynamics(machine_from_dict({"axis": AXES}).axes)


class Clock:
    def __init__(self, settled: float = 0.0):
        self.settled = settled
        self.pending = None

    def settle(self, t: float) -> None:
        self.settled = t


class Timings:
    """Collects canon ``timing`` as floats (and what kind of sequence came)."""

    def __init__(self):
        self.times, self.entry, self.exit, self.kinds = [], [], [], []

    def timing(self, times, entry, exit):
        self.kinds.append(type(times))
        for out, col in ((self.times, times), (self.entry, entry), (self.exit, exit)):
            out += [float(x) for x in col]


def unit(rng: random.Random, n: int = 3) -> tuple:
    while True:
        u = [rng.choice((0.0, 0.0, rng.uniform(-1, 1))) for _ in range(n)]
        norm = math.sqrt(sum(x * x for x in u))
        if norm > 1e-3:
            return tuple(x / norm for x in u)


def add_random(planner: Planner, rng: random.Random, count: int) -> None:
    """``count`` random moves: hot-path rows (deltas and a feed or rapid), straight and arc moves via add."""
    prev = unit(rng)
    for _ in range(count):
        kind = rng.random()
        flags = rng.choice((0, 0, 0, STOP_END, STOP_START))
        if kind < 0.4:  # the kernel's straight-move hot path (fastmove): deltas, feed in mm/min
            turn = rng.random()
            d = tuple(x * rng.uniform(0.01, 30.0) for x in (prev if turn < 0.3 else unit(rng)))
            if turn > 0.9:
                d = tuple(-x for x in d)  # a reversal
            rapid = rng.random() < 0.15
            planner.rows += (-1.0, math.inf if rapid else rng.uniform(10.0, 9000.0), 0.0,
                             POSITIONING if rapid else flags, *d)
            length = math.sqrt(sum(x * x for x in d))
            prev = tuple(x / length for x in d)
        elif kind < 0.7:  # a straight move added whole (the kernel's straight_out), sometimes straight on
            u = prev if rng.random() < 0.3 else unit(rng)
            planner.add(rng.uniform(0.001, 40.0), rng.uniform(1.0, 120.0), rng.uniform(50.0, 1200.0), flags, u, u)
            prev = u
        else:  # an arc or helix: its tangent turns within the move; sometimes tangent to the move before
            u_in = prev if rng.random() < 0.4 else unit(rng)
            u_out = unit(rng)
            length = rng.uniform(0.0, 25.0) if rng.random() > 0.05 else 0.0
            planner.add(length, rng.uniform(1.0, 80.0), rng.uniform(50.0, 900.0),
                        flags if length > 0.0 else POSITIONING, u_in, u_out)
            prev = u_out


def plan_both(seed: int, count: int, model: str, window: int, tolerance: float, entry2: float = 0.0,
              settled: float = 0.0):
    out = []
    for python in (True, False):
        rng = random.Random(seed)
        timings, clock = Timings(), Clock(settled)
        planner = Planner(clock, timings, DYN, model=model, window=window, tolerance=tolerance)
        add_random(planner, rng, count)
        planner.entry2 = entry2
        if python:
            planner._plan_rows()
        else:
            planner._plan(None)
        out.append((timings, clock.settled))
    return out


@pytest.mark.parametrize("model", [LOOKAHEAD, REST])
@pytest.mark.parametrize("seed", range(40))
def test_plain_python_plan_equals_the_numpy_plan_to_the_last_bit(seed, model):
    rng = random.Random(1000 + seed)
    count = rng.choice((1, 2, 3, 5, 10, SMALL - 1, SMALL, SMALL + 7, 150))
    window = rng.choice((1, 2, 3, 7, count, count + 5, 100))
    tolerance = rng.choice((0.0, 0.005, 0.02, 0.1, 5.0))
    entry2 = rng.choice((0.0, 0.0, rng.uniform(0.0, 900.0)))  # the entry a commit left (a chunk's window)
    (py, py_clock), (nd, nd_clock) = plan_both(seed, count, model, window, tolerance, entry2, rng.uniform(0, 99))
    assert py.kinds == [list] and nd.kinds != [list]
    assert len(py.times) == len(nd.times) > 0
    assert py.times == nd.times
    assert py.entry == nd.entry
    assert py.exit == nd.exit
    assert py_clock == nd_clock
    assert all(math.copysign(1.0, a) == math.copysign(1.0, b) for a, b in zip(py.exit, nd.exit))


@pytest.mark.parametrize("moves", [1, SMALL - 1, SMALL, 3 * SMALL])
def test_a_flush_of_fewer_than_small_moves_is_planned_without_numpy_and_more_with(moves):
    timings = Timings()
    planner = Planner(Clock(), timings, DYN)
    add_random(planner, random.Random(moves), moves)
    arcs_doubled = len(planner.rows) // planner.width
    planner.stop()
    assert timings.kinds == [list] if arcs_doubled < SMALL else timings.kinds != [list]
    assert planner.rows == [] and planner.blocks == [] and planner.entry2 == 0.0


def test_chunks_committed_then_a_few_moves_flushed_keep_numpy_and_agree():
    """A commit leaves the window's moves as an array: the flush after it plans them with numpy."""
    timings, clock = Timings(), Clock()
    planner = Planner(clock, timings, DYN, window=3)
    planner.limit = 40 * planner.width  # commit early (as CHUNK would in a long program)
    add_random(planner, random.Random(5), 60)
    assert planner.blocks
    planner.stop()
    assert list not in timings.kinds[-1:]
    assert all(t >= 0.0 for t in timings.times) and clock.settled == pytest.approx(sum(timings.times), rel=1e-12)


def test_a_few_moves_planned_in_a_fresh_interpreter_import_no_numpy():
    code = ("import sys, random\n"
            "sys.path.insert(0, %r)\n"
            "from test_planner_small import Clock, Timings, DYN, add_random\n"
            "from ncvm.nc.planner import Planner\n"
            "t = Timings(); p = Planner(Clock(), t, DYN)\n"
            "add_random(p, random.Random(3), 20); p.stop()\n"
            "assert len(t.times) == 20, t.times\n"
            "print('numpy' in sys.modules)\n") % str(__import__("pathlib").Path(__file__).parent)
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip() == "False"


@pytest.mark.parametrize("model", [LOOKAHEAD, REST])
@pytest.mark.parametrize("seed", range(60))
def test_a_single_move_flushed_from_rest_equals_the_numpy_plan(seed, model):
    """A flush of one move (a drilling cycle's plunge before its dwell, issue 18) is timed by ``_plan_rest``:
    the numpy plan's time, speeds and clock to the last bit."""
    out = []
    for stop in (True, False):
        rng = random.Random(seed)
        timings, clock = Timings(), Clock(rng.uniform(0, 99))
        planner = Planner(clock, timings, DYN, model=model)
        add_random(planner, rng, 1)
        if len(planner.rows) != planner.width:  # an arc (two rows): the general plan
            continue
        if stop:
            planner.stop()  # _plan_rest
        else:
            planner._plan(None)
        out.append((timings.times, timings.entry, timings.exit, clock.settled))
    assert len(out) in (0, 2) and (not out or out[0] == out[1])


def test_a_single_move_flush_takes_the_short_path(monkeypatch):
    timings = Timings()
    planner = Planner(Clock(), timings, DYN)
    planner.rows += (-1.0, 600.0, 0.0, 0, 0.0, 0.0, -14.0)
    calls = []
    monkeypatch.setattr(Planner, "_plan_rows", lambda self: calls.append("rows"))  # not reached
    planner.stop()
    assert calls == [] and timings.kinds == [list] and len(timings.times) == 1 and planner.rows == []


def add_stopping(planner: Planner, rng: random.Random, count: int) -> None:
    """``count`` random moves most of whose junctions are exact stops (rapid positionings, G61/G09 flags),
    as drilling programs flush them at each dwell; now and then one that blends with the move before."""
    for _ in range(count):
        kind = rng.random()
        flags = rng.choice((POSITIONING, POSITIONING, STOP_END, STOP_START, STOP_END | STOP_START, 0))
        if kind < 0.6:  # the hot path's row: a rapid move or a move at feed
            d = tuple(x * rng.uniform(0.01, 60.0) for x in unit(rng))
            rapid = flags == POSITIONING
            planner.rows += (-1.0, math.inf if rapid else rng.uniform(10.0, 9000.0), 0.0, flags, *d)
        elif kind < 0.85:
            u = unit(rng)
            planner.add(rng.uniform(0.0, 40.0), rng.uniform(1.0, 120.0), rng.uniform(50.0, 1200.0), flags, u, u)
        else:  # an arc (two rows: its end tangent)
            length = rng.uniform(0.0, 25.0)
            planner.add(length, rng.uniform(1.0, 80.0), rng.uniform(50.0, 900.0), flags if length > 0.0 else POSITIONING,
                        unit(rng), unit(rng))


def signed(column) -> list[tuple[float, float]]:
    """Speeds with the sign of each zero (a JSON trace writes -0.0 as such)."""
    return [(x, math.copysign(1.0, x)) for x in column]


@pytest.mark.parametrize("model", [LOOKAHEAD, REST])
@pytest.mark.parametrize("seed", range(80))
def test_a_flush_of_moves_from_rest_to_rest_equals_both_other_plans(seed, model):
    """A flush whose moves all start and end at rest (every junction an exact stop: the moves of a drilling
    program between two dwells) is timed by ``_plan_rest``: the times, speeds and clock of the plain-Python
    plan and of the numpy plan, to the last bit and the sign of a zero. The flushes that blend are planned
    as before (``_plan_rows``)."""
    rng = random.Random(7000 + seed)
    count = rng.choice((1, 2, 3, 4, 5, 9, SMALL - 1))
    entry2 = rng.choice((0.0, 0.0, 0.0, -0.0, rng.uniform(0.0, 400.0)))
    settled, window = rng.uniform(0, 99), rng.choice((1, 3, 100))
    out, rows = [], 0
    for how in ("stop", "rows", "numpy"):
        timings, clock = Timings(), Clock(settled)
        planner = Planner(clock, timings, DYN, model=model, window=window)
        add_stopping(planner, random.Random(seed), count)
        rows = len(planner.rows) // planner.width
        planner.entry2 = entry2
        if how == "numpy":
            planner._plan(None)
        else:
            (planner.stop if how == "stop" else planner._plan_rows)()
        assert planner.rows == [] and len(timings.times) == count
        out.append((timings.times, signed(timings.entry), signed(timings.exit), clock.settled))
    stop, plain, numpy = out
    assert plain == numpy
    if rows == 1 and entry2 == 0.0:  # one move from rest: entry and exit 0.0 (as before, whatever entry2's sign)
        assert stop == (plain[0], [(0.0, 1.0)], [(0.0, 1.0)], plain[3])
    else:
        assert stop == plain


def test_a_drilling_flush_takes_the_rest_to_rest_path(monkeypatch):
    """Per hole, a retract, a positioning, a rapid approach and the plunge at feed, flushed at the dwell: every
    junction has a rapid move on one side, so no junction speed is worked out."""
    timings = Timings()
    planner = Planner(Clock(), timings, DYN)
    for row in ((-1.0, math.inf, 0.0, POSITIONING, 0.0, 0.0, 14.0), (-1.0, math.inf, 0.0, POSITIONING, 12.0, 5.0, 0.0),
                (-1.0, math.inf, 0.0, POSITIONING, 0.0, 0.0, -48.0), (-1.0, 150.0, 0.0, 0, 0.0, 0.0, -14.0)):
        planner.rows += row
    calls = []
    monkeypatch.setattr(Planner, "_plan_rows", lambda self: calls.append("rows"))  # not reached
    planner.stop()
    assert calls == [] and len(timings.times) == 4 and timings.entry == timings.exit == [0.0] * 4
    planner.rows += (-1.0, 150.0, 0.0, 0, 0.0, 0.0, -14.0, -1.0, 150.0, 0.0, 0, 0.0, 1.0, -14.0)  # these blend
    planner.stop()
    assert calls == ["rows"]


@pytest.mark.parametrize("axes", [1, 2, 4, 6])
def test_generated_rest_times_are_the_formulas_for_any_axes(axes):
    """The rest-to-rest times generated per machine (one unrolled line per axis) are trapezoid_time of
    straight_row_limits for hot-path rows and of the given limits for others, to the last bit, whatever the
    machine's axes and limits (an axis that never moves, one of tiny acceleration)."""
    rng = random.Random(axes)
    dyn = AxisDynamics(machine_from_dict({"axis": [
        {"name": "XYZABC"[i], "accel": rng.choice((0.5, 300.0, 1000.0, 25000.0)),
         "max_feed": rng.uniform(100.0, 9000.0), "rapid": rng.uniform(5000.0, 40000.0)} for i in range(axes)]}).axes)
    rows, want = [], []
    for _ in range(400):
        d = [rng.choice((0.0, rng.uniform(-80, 80), rng.uniform(-1e-6, 1e-6))) for _ in range(axes)]
        if not any(d):
            d[0] = 1e-9
        flags = rng.choice((POSITIONING, 0, STOP_END, STOP_START))
        if rng.random() < 0.7:
            feed = math.inf if flags == POSITIONING else rng.uniform(1.0, 20000.0)
            rows += (-1.0, feed, 0.0, flags, *d)
            want.append(trapezoid_time(*straight_row_limits(d, feed, flags == POSITIONING, dyn)))
        else:
            length, v, a = rng.choice((0.0, rng.uniform(0.0, 50.0))), rng.uniform(0.0, 200.0), rng.uniform(0.0, 900.0)
            rows += (length, v, a, flags, *d)
            want.append(trapezoid_time(length, v, a))
            if rng.random() < 0.3:  # an arc's end tangent row
                rows += (0.0, 0.0, 0.0, -1.0, *d)
    assert rest_times_for(dyn)(rows) == want
