"""The look-ahead path planner (nc/planner.py): cycle times computed by hand, exact stops, the trace.

Every machine here has the schema's axis defaults (acceleration 1000 mm/s², maximum feed 5000 mm/min)
unless a test says otherwise; docs/planner.md writes the formulas out.
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

from ncvm.machine.config import machine_from_dict
from ncvm.nc.dynamics import AxisDynamics
from ncvm.nc.planner import Planner, junction_speeds2, move_times

AXES = [{"name": n, "min": -2000.0, "max": 2000.0} for n in "XYZ"]
A = 1000.0  # mm/s²


def machine(**motion):
    return machine_from_dict({"axis": AXES, "tool": [{"number": 1}], **({"motion": motion} if motion else {})})


def collinear(n: int = 1000, head: str = "G64") -> str:
    return "\n".join([f"G90 G94 {head} F3000"] + [f"G1 X{i}" for i in range(1, n + 1)] + ["M2"]) + "\n"


def test_collinear_1000_blocks_take_the_blended_time(run_text):
    # 1,000 mm at 50 mm/s plus one ramp up and one down (v/a = 0.05 s): 20.05 s; rest to rest 1,000 trapezoids
    r = run_text(collinear(), machine=machine())
    assert r["cycle_time_s"] == pytest.approx(20.05, rel=1e-9)
    assert r["cycle_time_model"] == "look-ahead"
    old = run_text(collinear(), machine=machine(), time_model="rest-to-rest")
    assert old["cycle_time_s"] == pytest.approx(1000 * 2 * math.sqrt(1.0 / A), rel=1e-9)  # 63.246 s, never 50 mm/s
    assert old["cycle_time_model"] == "rest-to-rest"


def test_machine_file_selects_the_rest_to_rest_model(run_text):
    r = run_text(collinear(10), machine=machine(model="rest-to-rest"))
    assert r["cycle_time_s"] == pytest.approx(10 * 2 * math.sqrt(1.0 / A))


def test_window_of_one_block_makes_every_junction_brakeable_within_its_own_move(run_text):
    # lookahead 1: a junction is passed at most at sqrt(2 a L) = 44.72 mm/s (a stop within the next 1 mm);
    # between junctions the move reaches 50 mm/s. First and last move: 0 <-> 44.72 mm/s in one ramp.
    r = run_text(collinear(), machine=machine(lookahead=1))
    vj = math.sqrt(2 * A * 1.0)
    middle = 2 * (50.0 - vj) / A + (1.0 - 2 * (50.0 ** 2 - vj ** 2) / (2 * A)) / 50.0
    assert r["cycle_time_s"] == pytest.approx(2 * vj / A + 998 * middle, rel=1e-9)


def corner_time(tolerance: float, v: float = 50.0, length: float = 10.0) -> float:
    """Two moves of ``length`` at right angles, from rest to rest, through the junction-deviation corner."""
    sin_half = math.sin(math.radians(45.0))
    radius = tolerance * sin_half / (1.0 - sin_half)
    corner_accel = A / math.sqrt(0.5)  # the junction's direction (-1, 1)/sqrt(2) shares both axes
    vj = min(v, math.sqrt(corner_accel * radius))
    one = v / A + (v - vj) / A + (length - v * v / (2 * A) - (v * v - vj * vj) / (2 * A)) / v
    return 2 * one


@pytest.mark.parametrize("tolerance", [0.0, 0.02, 0.1, 10.0])
def test_right_angle_corner_at_known_tolerances(run_text, tolerance):
    r = run_text("G90 G64 F3000\nG1 X10\nG1 Y10\nM2\n", machine=machine(corner_tolerance=tolerance))
    assert r["cycle_time_s"] == pytest.approx(corner_time(tolerance), rel=1e-9)


def test_right_angle_corner_figures():
    assert corner_time(0.0) == pytest.approx(0.5)  # a sharp corner without tolerance: an exact stop
    assert corner_time(0.02) == pytest.approx(0.4848, abs=1e-4)  # 8.26 mm/s through the corner
    assert corner_time(10.0) == pytest.approx(0.45)  # a tolerance so wide the corner is passed at full feed


def test_g64_p_sets_the_tolerance_in_a_din_program(run_text):
    r = run_text("G90 G64 P0.1 F3000\nG1 X10\nG1 Y10\nM2\n", machine=machine())
    assert r["cycle_time_s"] == pytest.approx(corner_time(0.1), rel=1e-9)


def test_circle_above_its_centripetal_limit(run_text, tmp_path):
    # R5 full circle at F6000 (100 mm/s): centripetal v = sqrt(a R) = 70.71 mm/s; the tangential acceleration
    # of an arc is the plane axes' smallest, a (nc.dynamics.arc_limits: at the quadrant points one axis takes
    # the whole ramp): 2 pi 5 / 70.71 + 70.71 / 1000 = 0.4443 + 0.0707 = 0.5150 s from rest to rest. Rest to
    # rest without the centripetal cap the arc runs at the axes' maximum feed, 5000 mm/min = 83.33 mm/s (at the
    # quadrant points one axis alone carries the path speed): 0.3770 + 0.0833 = 0.4603 s
    text = "G90 G0 X5 Y0\nG64 G2 X5 Y0 I-5 J0 F6000\nM2\n"
    trace = tmp_path / "t.jsonl"
    run_text(text, machine=machine(), trace=trace)
    arc = [json.loads(x) for x in trace.read_text().splitlines() if '"arc"' in x][0]
    v = math.sqrt(A * 5.0)
    assert arc["time"] == pytest.approx(2 * math.pi * 5 / v + v / A, rel=1e-9)
    run_text(text, machine=machine(), trace=trace, time_model="rest-to-rest")
    arc = [json.loads(x) for x in trace.read_text().splitlines() if '"arc"' in x][0]
    vmax = 5000.0 / 60.0
    assert arc["time"] == pytest.approx(2 * math.pi * 5 / vmax + vmax / A, rel=1e-9)


def slow_axis_machine(**limits):
    """The schema's axes with some limits changed, e.g. ``X={"max_feed": 3000.0}``."""
    axes = [{**axis, **limits.get(axis["name"], {})} for axis in AXES]
    return machine_from_dict({"axis": axes, "tool": [{"number": 1}]})


@pytest.mark.parametrize("model", ["lookahead", "rest-to-rest"])
@pytest.mark.parametrize("hook", [None, lambda *a: None])  # plain run (column-wise) and block by block (kernel)
def test_circle_above_one_axis_max_feed_runs_at_that_axis_feed(run_text, model, hook):
    """A full circle R10 at F4000 (66.67 mm/s) with X's maximum feed 3000 mm/min (50 mm/s): at the quadrant
    points (here the start point) X alone carries the path speed, so the circle runs at 50 mm/s all along:
    2 pi 10 / 50 + 50 / 1000 = 1.2566 + 0.05 = 1.3066 s (the centripetal cap sqrt(1000 * 10) = 100 mm/s does
    not bind). The 45 degree chord's share gave min(66.67, 50 sqrt 2) = 66.67 mm/s: X at 66.67 mm/s at the
    quadrant points, 0.9425 + 0.0667 = 1.0091 s a circle."""
    m = slow_axis_machine(X={"max_feed": 3000.0})
    r = run_text("G90 G64 F4000\nG2 X0 Y0 I0 J10\nG2 X0 Y0 I0 J10\nM2\n", machine=m, time_model=model, hook=hook)
    v = 50.0
    one = 2 * math.pi * 10 / v + v / A
    if model == "rest-to-rest":
        assert r["cycle_time_s"] == pytest.approx(2 * one, rel=1e-9)
    else:  # the two circles join tangentially at the full speed: one ramp up, one down
        assert r["cycle_time_s"] == pytest.approx(2 * one - v / A, rel=1e-9)


@pytest.mark.parametrize("hook", [None, lambda *a: None])
def test_helix_linear_axis_caps_the_path_speed_by_its_own_share(run_text, tmp_path, hook):
    """A helix: full circle R10 in XY (62.832 mm) rising 20 mm in Z, length L = hypot(62.832, 20) = 65.938 mm,
    at F6000 (100 mm/s) with Z's maximum feed 600 mm/min (10 mm/s). Z's share of the path is 20 / L, so the
    path runs at 10 L / 20 = 32.97 mm/s and the helix takes 20 / 10 = 2 s at speed. The ramp: X and Y share
    p = 62.832 / L of the path (1000 / p = 1049.4 mm/s^2), Z 20 / L (1000 L / 20 = 3297 mm/s^2): v / (1000 / p)
    = 10 * 62.832 / 20 / 1000 = 0.0314 s. Without Z's share the helix ran at 100 mm/s, Z at 30.3 mm/s."""
    m = slow_axis_machine(Z={"max_feed": 600.0})
    trace = tmp_path / "t.jsonl"
    r = run_text("G90 G64 F6000\nG2 X0 Y0 Z20 I0 J10\nM2\n", machine=m, trace=trace, hook=hook)
    planar = 2 * math.pi * 10
    assert r["cycle_time_s"] == pytest.approx(20.0 / 10.0 + 10.0 * planar / 20.0 / A, rel=1e-9)
    arc = [json.loads(x) for x in trace.read_text().splitlines() if '"arc"' in x][0]
    assert arc["v_exit"] == 0.0 and arc["time"] == pytest.approx(r["cycle_time_s"], rel=1e-9)


def test_helix_plane_axis_caps_the_path_speed_by_the_plane_share(run_text):
    """The same helix with X's maximum feed 3000 mm/min (50 mm/s) and Z free: X carries p = 62.832 / L of the
    path speed at the quadrant points, so the path runs at 50 / p = 52.47 mm/s (above X's own 50, as the
    path is longer than its plane part) and ramps at 1000 / p: L / (50 / p) + (50 / p) / (1000 / p)
    = 62.832 / 50 + 0.05 = 1.3066 s, the flat circle's time."""
    m = slow_axis_machine(X={"max_feed": 3000.0})
    r = run_text("G90 G64 F6000\nG2 X0 Y0 Z20 I0 J10\nM2\n", machine=m, time_model="rest-to-rest")
    assert r["cycle_time_s"] == pytest.approx(2 * math.pi * 10 / 50.0 + 50.0 / A, rel=1e-9)


def test_a_small_circle_ramps_no_faster_than_an_axis_can(run_text):
    """A full circle R1 at F3000 on the default mill (X and Y 1,000 mm/s^2): the centripetal cap holds
    sqrt(1000 * 1) = 31.62 mm/s, the ramps run at 1,000 mm/s^2 (at the start point the path runs along Y
    alone): 2 pi / 31.62 + 31.62 / 1000 = 0.1987 + 0.0316 = 0.2303 s (the 45 degree chord's 1,414 mm/s^2
    gave 0.2211 s)."""
    r = run_text("G21 G90 G94 G64 F3000\nG2 X0 Y0 I1 J0\nM2\n")
    assert r["cycle_time_s"] == pytest.approx(0.2303, abs=5e-5)


def test_tangent_line_into_arc_runs_at_the_arc_speed(run_text):
    # X0 -> X10 then a CCW half circle R10 tangent to it: the junction is straight on, at the arc's speed
    # sqrt(1000 * 10) = 100 mm/s, which the F3000 line is slower than: no slowdown at the junction at all
    r = run_text("G90 G64 F3000\nG1 X10\nG3 X10 Y20 I0 J10\nM2\n", machine=machine())
    length = 10 + math.pi * 10
    # ramps: up on the line at A, down on the arc at A as well (the arc's tangential acceleration)
    assert r["cycle_time_s"] == pytest.approx(length / 50.0 + 50.0 / A / 2 + 50.0 / A / 2, rel=1e-9)


def test_trace_has_time_and_entry_exit_speeds(run_text, tmp_path):
    trace = tmp_path / "t.jsonl"
    run_text("G90 G64 F3000\nG1 X5\nG1 X10\nG1 X15\nM2\n", machine=machine(), trace=trace)
    moves = [json.loads(x) for x in trace.read_text().splitlines() if '"feed"' in x]
    assert [(m["v_entry"], m["v_exit"]) for m in moves] == [(0.0, 3000.0), (3000.0, 3000.0), (3000.0, 0.0)]
    assert [m["time"] for m in moves] == pytest.approx([0.125, 0.1, 0.125])  # a ramp costs v / 2a = 0.025 s
    assert moves[0]["end"] == {"X": 5.0, "Y": 0.0, "Z": 0.0}  # the old fields are as they were


@pytest.mark.parametrize("stop", ["G61", "G60", "G61.1"])
def test_iso_modal_exact_stop(run_text, stop):
    r = run_text(collinear(10, stop), machine=machine())
    assert r["cycle_time_s"] == pytest.approx(10 * 2 * math.sqrt(1.0 / A))


def test_g09_stops_at_the_end_of_its_block_only(run_text):
    text = "G90 G64 F3000\nG1 X1\nG09 G1 X2\nG1 X3\nG1 X4\nM2\n"
    r = run_text(text, machine=machine())
    # G09 ends the second block at rest: each pair of blended 1 mm moves runs as one 2 mm triangle
    assert r["cycle_time_s"] == pytest.approx(2 * 2 * math.sqrt(2.0 / A))


def test_m_functions_and_dwells_are_exact_stops(run_text):
    one, pair = 2 * math.sqrt(1.0 / A), 2 * math.sqrt(2.0 / A)  # 1 mm, 2 mm from rest to rest (below 50 mm/s)
    # the axes stand while the M function is output before the block's move, and after it
    r = run_text("G90 G64 F3000\nG1 X1\nG1 X2 M8\nG1 X3\nG1 X4\nM2\n", machine=machine())
    assert r["cycle_time_s"] == pytest.approx(2 * one + pair)
    r = run_text("G90 G64 F3000\nG1 X1\nG1 X2\nG4 P0\nG1 X3\nG1 X4\nM2\n", machine=machine())
    assert r["cycle_time_s"] == pytest.approx(2 * pair)


def test_tool_change_time_from_the_machine_file(run_text):
    base = run_text("T1 M6\nG1 X10 F3000\nM2\n", machine=machine())
    slow = run_text("T1 M6\nG1 X10 F3000\nM2\n", machine=machine(tool_change_time=7.5))
    assert slow["cycle_time_s"] - base["cycle_time_s"] == pytest.approx(7.5)


def test_rapid_moves_position_with_an_exact_stop(run_text):
    r = run_text("G90 G0 X10\nG0 X20\nM2\n", machine=machine())
    assert r["cycle_time_s"] == pytest.approx(2 * 2 * math.sqrt(10.0 / A))  # 166.7 mm/s is never reached in 10 mm


def test_reading_the_clock_during_a_timed_wait_is_an_exact_stop(run_text):
    # CPL WAIT(,100) lets execution run to 0.1 s and reads the clock after each block: N1 and N2 run from rest
    # to rest (0.0632 s each), the program reads the clock and the position inside N2 at 0.1 s, where N2's
    # own profile has it; N3..N8 (6 mm) are blended afterwards
    one = 2 * math.sqrt(1.0 / A)
    text = "N1 G1 X1 F3000\nN2 X2\nN3 X3\nN4 X4\n10 WAIT(,100)\n20 T% = CLOCK : P = MPOS(1)\n" \
           "N5 X5\nN6 X6\nN7 X7\nN8 X8\nM30\n"
    r = run_text(text, name="c.cpl", machine=machine())
    assert r["variables"]["T%"] == 100
    left = 2 * one - 0.1  # N2 still decelerating: it ends at 2 * one
    assert r["variables"]["P"] == pytest.approx(2.0 - 0.5 * A * left * left, abs=1e-6)
    assert r["cycle_time_s"] == pytest.approx(2 * one + 6.0 / 50.0 + 50.0 / A)


def test_cpl_continuous_path_by_default_and_g61_exact_stop(run_text):
    blended = run_text("N1 G1 X10 F3000\nN2 X20\nM30\n", name="a.cpl", machine=machine())
    assert blended["cycle_time_s"] == pytest.approx(20.0 / 50.0 + 50.0 / A)
    exact = run_text("N1 G61 G1 X10 F3000\nN2 X20\nN3 G62 X30\nN4 X40\nM30\n", name="b.cpl", machine=machine())
    assert exact["cycle_time_s"] == pytest.approx(2 * (10.0 / 50.0 + 50.0 / A) + 20.0 / 50.0 + 50.0 / A)


def test_cpl_wait_is_an_exact_stop(run_text):
    r = run_text("N1 G1 X10 F3000\n10 WAIT\nN2 X20\nM30\n", name="w.cpl", machine=machine())
    assert r["cycle_time_s"] == pytest.approx(2 * (10.0 / 50.0 + 50.0 / A))


# -- the vectorised passes against a plain per-junction loop --------------------------------------------
def _reference(length, v, a, j, window):
    """Backward and forward passes written as loops over the junctions (squared speeds)."""
    p = len(length)
    w = list(j) + [0.0]
    for i in range(p - 1, -1, -1):
        w[i] = min(w[i], w[i + 1] + 2 * a[i] * length[i])
        if i + window <= p:
            w[i] = min(w[i], sum(2 * a[k] * length[k] for k in range(i, i + window)))
    w[0] = j[0]
    for i in range(p):
        w[i + 1] = min(w[i + 1], w[i] + 2 * a[i] * length[i])
    return w


@pytest.mark.parametrize("window", [1, 3, 50])
def test_passes_match_the_loops(window):
    rng = np.random.default_rng(7)
    p = 40
    length = rng.uniform(0.01, 3.0, p)
    v = rng.uniform(5.0, 80.0, p)
    a = rng.uniform(200.0, 2000.0, p)
    u = rng.normal(size=(p, 3))
    u /= np.linalg.norm(u, axis=1)[:, None]
    flags = np.zeros(p, dtype=np.int64)

    class Clock:
        settled = 0.0
        pending = None

        def settle(self, t):
            self.settled = t

    class Canon:
        def timing(self, *args):
            self.args = args

    planner = Planner(Clock(), Canon(), AxisDynamics(machine().axes), window=window, tolerance=0.05)
    w = planner._speeds(np.vstack((length, v, a, flags, u.T, u.T)))
    j = np.zeros(p)
    j[1:] = junction_speeds2(u[:-1].T, u[1:].T, v[:-1], v[1:], np.zeros(p - 1, bool), np.full(3, A), 0.05)
    assert w == pytest.approx(_reference(length, v, a, j, window), rel=1e-9, abs=1e-9)
    times = move_times(length, v, a, w[:-1], w[1:])
    assert (times > 0).all() and (np.sqrt(w[1:]) <= np.maximum(v, 0) + 1e-9).all()


# -- SINUMERIK: G60 exact stop is the power-on state, G64 blends, STOP DEC stops -------------------------
def run_mpf(run_text, text: str) -> dict:
    r = run_text(text, name="p.mpf", machine=machine())
    assert r["status"] == "ok", r["error"]
    return r


def test_sinumerik_exact_stop_by_default_and_g64_continuous_path(run_text):
    one = 10.0 / 50.0 + 50.0 / A  # 10 mm at 50 mm/s from rest to rest
    r = run_mpf(run_text, "%MPF1\nN10 G1 G90 X10 F3000\nN20 X20\nM30\n")
    assert r["cycle_time_s"] == pytest.approx(2 * one)
    r = run_mpf(run_text, "%MPF1\nN10 G64 G1 G90 X10 F3000\nN20 X20\nM30\n")
    assert r["cycle_time_s"] == pytest.approx(20.0 / 50.0 + 50.0 / A)
    r = run_mpf(run_text, "%MPF1\nN10 G64 G1 G90 X10 F3000\nN15 G09 X20\nN20 X30\nN25 X40\nM30\n")
    assert r["cycle_time_s"] == pytest.approx(2 * (20.0 / 50.0 + 50.0 / A))
    r = run_mpf(run_text, "%MPF1\nN10 G64 G1 G90 X10 F3000\n@714\nN20 X20\nM30\n")
    assert r["cycle_time_s"] == pytest.approx(2 * one)


def test_column_path_and_block_path_plan_alike(run_text):
    # the same contour as a DIN program (plain rows, column-wise), as CPL blocks (its block buffer runs them
    # column-wise too) and as SINUMERIK blocks (one by one: the hot path and arc_out)
    moves = ["G1 X10 Y0", "G1 X10 Y10", "G3 X0 Y20 I-10 J0", "G1 X-5 Y20", "G2 X-15 Y20 I-5 J0", "G1 X-15 Y0"]
    din = run_text("G90 G64 F2400\n" + "\n".join(moves) + "\nM2\n", machine=machine())
    cpl = run_text("N1 G90 F2400\n" + "\n".join(f"N{i + 2} {m}" for i, m in enumerate(moves)) + "\nM30\n",
                   name="c.cpl", machine=machine())
    sin = run_mpf(run_text, "%MPF1\nN1 G64 G90 F2400\n" + "\n".join(f"N{i + 2} {m}" for i, m in enumerate(moves))
                  + "\nM30\n")
    assert din["cycle_time_s"] == pytest.approx(cpl["cycle_time_s"], rel=1e-12)
    assert din["cycle_time_s"] == pytest.approx(sin["cycle_time_s"], rel=1e-12)
    rest = run_text("G90 G64 F2400\n" + "\n".join(moves) + "\nM2\n", machine=machine(), time_model="rest-to-rest")
    assert din["cycle_time_s"] < rest["cycle_time_s"]
