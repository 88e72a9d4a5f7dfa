"""The executed state at the program's time when that time lies inside a queued block (manual §4.1, §4.2, §4.12).

The machine of these tests has the default axis dynamics: max_feed 5000 mm/min, rapid 10000 mm/min,
acceleration 1000 mm/s^2. Moves start and end at rest with a trapezoidal speed profile (nc.dynamics): path
speed v and acceleration a capped per axis; the ramp takes v/a seconds and v^2/(2a) mm.
"""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from ncvm.machine.config import machine_from_dict

AXES = [{"name": "X"}, {"name": "Y"}, {"name": "Z"}]

# N10 G1 X100 F6000 on one axis: F6000 = 100 mm/s is capped at max_feed 5000 mm/min
V = 5000.0 / 60.0  # 83.333 mm/s
A = 1000.0  # mm/s^2 (one axis moves: share 1)
RAMP_T = V / A  # 0.08333 s
RAMP_S = V * V / (2.0 * A)  # 3.4722 mm
X100_TIME = 100.0 / V + V / A  # 1.2 + 0.08333 = 1.28333 s


def x100_at(t: float) -> float:
    """Where N10 G1 X100 F6000 is t seconds after its start (t within the constant-speed part)."""
    assert RAMP_T <= t <= X100_TIME - RAMP_T
    return RAMP_S + V * (t - RAMP_T)


def mill(tmp_path: Path, **extra):
    data = {"axis": AXES, "paths": {"program_path": ["."], "file_root": "files"}}
    data.update(extra)
    return machine_from_dict(data, "<test>", tmp_path)


def test_wait_500_ms_into_a_move_sees_the_axis_half_way(tmp_path, run_text):
    text = 'N10 G1 X100 F6000\n10 WAIT(,500)\n20 T% = CLOCK : X = MPOS("X")\n' \
           "30 S = SPOS(1) : W = WPOS(1) : C = CPOS(1)\nM30\n"
    r = run_text(text, name="p.cpl", machine=mill(tmp_path))
    v = r["variables"]
    assert v["T%"] == 500  # the program resumes after 500 ms, not after the whole 1283 ms block
    # 0.5 s = 0.0833 s ramp (3.472 mm) + 0.4167 s at 83.33 mm/s (34.722 mm) = 38.194 mm
    assert x100_at(0.5) == pytest.approx(38.19444, abs=1e-4)
    assert v["X"] == pytest.approx(x100_at(0.5), abs=1e-4)
    assert v["S"] == pytest.approx(x100_at(0.5), abs=1e-4) and v["W"] == pytest.approx(x100_at(0.5), abs=1e-4)
    assert v["C"] == 100.0  # CPOS is the prepared value: the block's end point
    # the toolpath, the final position and the cycle time are those of the whole block
    assert r["position"]["X"] == 100.0
    assert r["cycle_time_s"] == pytest.approx(X100_TIME)


def test_wait_does_not_change_toolpath_position_or_cycle_time(tmp_path, run_text):
    # rest to rest: a timed WAIT reads the clock, an exact stop after N10, where the look-ahead planner would
    # blend the corner of the plain run (tests/nc/test_planner.py, docs/planner.md)
    rest = "rest-to-rest"
    plain = run_text("N10 G1 X100 F6000\nN20 G1 Y50\nM30\n", name="a.cpl", machine=mill(tmp_path), time_model=rest)
    waited = run_text("N10 G1 X100 F6000\n10 WAIT(,500)\nN20 G1 Y50\nM30\n", name="b.cpl", machine=mill(tmp_path),
                      time_model=rest)
    assert waited["motion"] == plain["motion"]
    assert waited["position"] == plain["position"]
    # N20 is prepared at 0.5 s and starts when N10 ends: 1.28333 s + 50/83.333 + 0.08333 = 1.96667 s
    assert waited["cycle_time_s"] == plain["cycle_time_s"] == pytest.approx(X100_TIME + 50.0 / V + V / A)


def test_successive_waits_follow_the_move_then_idle(tmp_path, run_text):
    text = ('N10 G1 X100 F6000\n10 WAIT(,500)\n20 X1 = MPOS(1) : T1% = CLOCK\n30 WAIT(,500)\n'
            "40 X2 = MPOS(1) : T2% = CLOCK\n50 WAIT(,500)\n60 X3 = MPOS(1) : T3% = CLOCK\nM30\n")
    v = run_text(text, name="p.cpl", machine=mill(tmp_path))["variables"]
    assert (v["T1%"], v["T2%"], v["T3%"]) == (500, 1000, 1500)
    # 1.0 s: 3.472 mm + 83.333 mm/s * 0.9167 s = 79.861 mm; 1.5 s is past the block's end at 1.283 s
    assert v["X1"] == pytest.approx(x100_at(0.5), abs=1e-4)
    assert v["X2"] == pytest.approx(79.86111, abs=1e-4) == x100_at(1.0)
    assert v["X3"] == 100.0


def test_wait_inside_an_arc_reads_the_point_on_the_arc(tmp_path, run_text):
    text = "N10 G2 X20 Y0 I10 J0 F3000\n10 WAIT(,400)\n20 T% = CLOCK : PX = MPOS(1) : PY = MPOS(2)\nM30\n"
    r = run_text(text, name="p.cpl", machine=mill(tmp_path))
    v = r["variables"]
    # a clockwise half circle from (0,0) about (10,0), radius 10, through (10,10): length 10*pi = 31.416 mm.
    # Timed by its length: F3000 = 50 mm/s stays under the plane axes' 83.33 mm/s; the acceleration is the
    # axes' own 1000 mm/s^2 (nc.dynamics.arc_limits).
    v_path, a_path = 50.0, 1000.0
    ramp_t, ramp_s = v_path / a_path, v_path ** 2 / (2.0 * a_path)  # 0.05 s, 1.25 mm
    s = ramp_s + v_path * (0.4 - ramp_t)  # 18.75 mm along the arc after 0.4 s
    angle = math.pi - s / 10.0  # clockwise from the start angle pi
    assert v["T%"] == 400
    assert v["PX"] == pytest.approx(10.0 + 10.0 * math.cos(angle), abs=1e-4)
    assert v["PY"] == pytest.approx(10.0 * math.sin(angle), abs=1e-4)
    assert r["position"]["X"] == 20.0 and r["position"]["Y"] == pytest.approx(0.0, abs=1e-12)
    assert r["cycle_time_s"] == pytest.approx(10.0 * math.pi / v_path + v_path / a_path)  # 0.66367 s


def test_wait_ending_between_two_blocks(tmp_path, run_text):
    # N10 and N20 take 10 mm / 10 mm/s + 10/1000 s = 1.01 s each; the dwell N15 0.5 s
    text = ("N10 G1 X10 F600\nN15 G4 F0.5\nN20 G1 X20\n10 WAIT(,1010)\n20 T1% = CLOCK : Q1 = MPOS(1)\n"
            "30 D1%=0:V=0:E%=MCODS(39,1,V,D1%,1)\n40 WAIT(,250)\n50 T2% = CLOCK : Q2 = MPOS(1)\n"
            "60 D2%=0:V=0:E%=MCODS(39,1,V,D2%,1)\n70 WAIT(,250)\n80 T3% = CLOCK : Q3 = MPOS(1)\n"
            "90 D3%=0:V=0:E%=MCODS(39,1,V,D3%,1)\nM30\n")
    r = run_text(text, name="p.cpl", machine=mill(tmp_path))
    v = r["variables"]
    # 1.01 s: N10 has just ended; the dwell is the block the channel takes up now (not yet executed)
    assert (v["T1%"], v["Q1"], v["D1%"]) == (1010, 10.0, 1)
    # 1.26 s: inside the dwell, which holds the axis at X10
    assert (v["T2%"], v["Q2"], v["D2%"]) == (1260, 10.0, 1)
    # 1.51 s: the dwell has ended exactly; N20 starts now, the axis is still at X10 and no dwell is executing
    assert (v["T3%"], v["Q3"], v["D3%"]) == (1510, 10.0, 0)
    assert r["position"]["X"] == 20.0
    assert r["cycle_time_s"] == pytest.approx(1.01 + 0.5 + 1.01)


def test_wait_for_an_input_that_comes_mid_move(tmp_path, run_text):
    m = mill(tmp_path, scenario=[{"time": 0.3, "kind": "input", "address": "IC(4,4,1)", "value": True}])
    text = "N10 G1 X100 F6000\n10 WAIT(IC(4,4,1)=TRUE,1000,R%)\n20 T% = CLOCK : P = MPOS(1)\nM30\n"
    r = run_text(text, name="p.cpl", machine=m)
    v = r["variables"]
    # the input comes 0.3 s into the move: 3.472 mm + 83.333 mm/s * 0.2167 s = 21.528 mm
    assert (v["R%"], v["T%"]) == (2, 300)
    assert v["P"] == pytest.approx(21.52778, abs=1e-4) == x100_at(0.3)
    assert r["cycle_time_s"] == pytest.approx(X100_TIME)


def test_an_input_after_the_programs_time_is_not_seen_yet(tmp_path, run_text):
    m = mill(tmp_path, scenario=[{"time": 1.0, "kind": "input", "address": "IC(4,4,1)", "value": True}])
    text = "N10 G1 X100 F6000\n10 WAIT(,500)\n20 EARLY? = IC(4,4,1)\n30 WAIT(,600)\n40 LATE? = IC(4,4,1)\nM30\n"
    v = run_text(text, name="p.cpl", machine=m)["variables"]
    # at 0.5 s the block still moves (until 1.283 s), but the input comes only at 1.0 s
    assert (v["EARLY?"], v["LATE?"]) == (False, True)


def test_mcods_positions_and_motion_state_at_the_programs_time(tmp_path, run_text):
    text = ("N10 G1 X100 F6000\n10 WAIT(,500)\n20 DIM P(3) : V=0 : E%=MCODS(1,-1,V,P,3)\n"
            "30 DIM G(3) : V=0 : E%=MCODS(83,1,V,G,3)\n40 DIM S%(2) : V=0 : E%=MCODS(32,1,V,S%,2)\n"
            "50 WAIT(,1000)\n60 DIM S2%(2) : V=0 : E%=MCODS(32,1,V,S2%,2)\nM30\n")
    v = run_text(text, name="p.cpl", machine=mill(tmp_path))["variables"]
    assert v["P"][1] == pytest.approx(x100_at(0.5), abs=1e-4)  # MCODS 1: MCS positions
    assert v["G"][1] == pytest.approx(100.0 - x100_at(0.5), abs=1e-4)  # MCODS 83: distance to go
    assert v["S%"][1:] == [3, 1]  # IPO active: the block still moves at 0.5 s
    assert v["S2%"][1:] == [3, 3]  # at 1.5 s it has ended


def test_mcods_version_wait_lets_the_moving_block_finish(tmp_path, run_text):
    text = ("N10 G1 X100 F6000\n10 WAIT(,500)\n20 DIM P(3) : V=0 : E%=MCODS(1,-1,V,P,3)\n"
            "30 X1 = P(1) : E%=MCODS(1,-1,V,P,3) : T% = CLOCK\nM30\n")
    v = run_text(text, name="p.cpl", machine=mill(tmp_path))["variables"]
    # the same version again waits until the position changes: execution goes on to the block's end
    assert v["X1"] == pytest.approx(x100_at(0.5), abs=1e-4)
    assert v["P"][1] == 100.0 and v["T%"] == round(X100_TIME * 1000)


def test_with_a_lookahead_depth_the_wait_also_ends_mid_move(tmp_path, run_text):
    text = "N10 G1 X100 F6000\n10 WAIT(,500)\n20 T% = CLOCK : X = MPOS(1)\nN30 G1 X0\nM30\n"
    r = run_text(text, name="p.cpl", machine=mill(tmp_path, cpl={"lookahead": 2}))
    v = r["variables"]
    assert v["T%"] == 500 and v["X"] == pytest.approx(x100_at(0.5), abs=1e-4)
    assert r["cycle_time_s"] == pytest.approx(2 * X100_TIME)  # N30 starts when N10 has ended


def test_clock_example_of_the_manual_times_one_block(tmp_path, run_text):
    """Manual §4.12 L2472-2490: CLOCK before and after N4, each behind a WAIT; the difference is N4's time."""
    text = ("N1 G1 F3000\n20 WAIT\n30 STARTTIME% = CLOCK\nN4 G1X50Y70\n40 WAIT\n"
            "50 ENDTIME% = CLOCK: DIFF% = ENDTIME%-STARTTIME%\nM30\n")
    v = run_text(text, name="p.cpl", machine=mill(tmp_path))["variables"]
    # length sqrt(50^2 + 70^2) = 86.023 mm at F3000 = 50 mm/s (no axis over 83.33 mm/s); the acceleration is
    # limited by Y: 1000 / (70 / 86.023) = 1228.9 mm/s^2. Time 86.023 / 50 + 50 / 1228.9 = 1.7612 s
    length = math.hypot(50.0, 70.0)
    expected = length / 50.0 + 50.0 / (1000.0 / (70.0 / length))
    # (a name keeps 8 significant characters: STARTTIME% is STARTTIM%)
    assert v["STARTTIM%"] == 0 and v["DIFF%"] == round(expected * 1000) == 1761


def test_wait_without_parameters_while_a_block_moves_waits_for_its_end(tmp_path, run_text):
    text = "N10 G1 X100 F6000\n10 WAIT(,500)\n20 X1 = MPOS(1)\n30 WAIT\n40 T% = CLOCK : X2 = MPOS(1)\nM30\n"
    v = run_text(text, name="p.cpl", machine=mill(tmp_path))["variables"]
    assert v["X1"] == pytest.approx(x100_at(0.5), abs=1e-4)
    assert (v["T%"], v["X2"]) == (round(X100_TIME * 1000), 100.0)  # 1283 ms: every block before it executed


def test_a_file_written_mid_move_is_dated_at_the_programs_time(tmp_path, run_text):
    # N10 takes 2000 / 83.333 + 0.0833 = 24.08 s; the program writes the file 10 s into it
    text = ('N10 G1 X2000 F6000\n10 WAIT(,10000)\n20 DIM T$(8) : T$ = TIME\n'
            '30 OPENW(1,"STAMP") : PRN#(1,"X") : CLOSE(1)\n40 DIM F$(8) : F$ = FILEDATE("STAMP",2)\n'
            "50 WAIT\n60 DIM E$(8) : E$ = TIME\nM30\n")
    v = run_text(text, name="p.cpl", machine=mill(tmp_path))["variables"]
    assert v["F$"] == v["T$"]
    assert _seconds(v["E$"]) - _seconds(v["T$"]) == 14  # the block ends at 24.08 s: 24 - 10 whole seconds


def _seconds(hms: str) -> int:
    """TIME's "HH.MM.SS" as seconds of the day."""
    h, m, s = (int(p) for p in hms.split("."))
    return 3600 * h + 60 * m + s
