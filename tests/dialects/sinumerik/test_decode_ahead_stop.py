"""A SINUMERIK / CL 800 run that stops keeps the blocks decoded ahead (docs/decisions.md, "A run that stops").

With ``[sin800] decode_ahead = N`` up to N decoded blocks wait for execution (CL 800 manual L4287-4334). An
alarm in decoding (a CL 800 error, a sub-program not found, the step limit) stops decoding; the blocks decoded
before it were handed to execution and run, and the alarm is reported after them. Before, they were dropped:
three moves decoded ahead of a division by zero reported 0 moves at X0.

Hand counts: the axes accelerate at 1000 mm/s^2; at F600 (10 mm/s) a ramp takes 0.01 s and 0.05 mm. The
power-on G60 (exact stop) brings every block to rest: a 10 mm block takes 1.01 s.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from sin800_helpers import run_mpf

from ncvm.api import run
from ncvm.runtime.session import RunOptions

AXIS = "accel = 1000.0\nmax_feed = 60000.0\nrapid = 60000.0\nmin = -1000.0\nmax = 1000.0\n"
MACHINE = "".join(f'[[axis]]\nname = "{a}"\n{AXIS}' for a in "XYZ") + '[sin800]\ncontrol = "880"\n'
MOVES3 = "%MPF1\nN10 G90 G01 X10 F600\nN20 X20\nN30 X30\n"
SAME = ("motion", "position", "cycle_time_s", "limit_violations")


def mpf(tmp_path: Path, text: str, ahead: int, **options):
    (tmp_path / "machine.toml").write_text(MACHINE + f"decode_ahead = {ahead}\n")
    path = tmp_path / "prog.mpf"
    path.write_text(text)
    return run(path, dialect="sin800", machine=tmp_path / "machine.toml",
               options=RunOptions(state_dir=tmp_path / ".ncvm", **options))[0]


def stopped(r: dict, code: str, line: int) -> None:
    assert r["status"] == "error" and (r["error"]["code"], r["error"]["line"]) == (code, line), r["error"]


@pytest.mark.parametrize("ahead", [0, 1, 4])
def test_a_cl800_error_after_three_decoded_moves_executes_them(tmp_path, ahead):
    r = mpf(tmp_path, MOVES3 + "N40 R1=0 R2=5/R1\nM30\n", ahead)
    stopped(r, "CL800", 5)
    assert r["motion"]["feed_moves"] == 3 and r["motion"]["feed_length"] == pytest.approx(30.0)
    assert r["position"]["X"] == 30.0
    assert r["cycle_time_s"] == pytest.approx(3 * 1.01)


def test_a_sub_program_not_found_keeps_the_decoded_moves(tmp_path):
    r = mpf(tmp_path, MOVES3 + "N40 L77\nM30\n", 4)
    stopped(r, "RUN002", 5)
    assert r["motion"]["feed_moves"] == 3 and r["position"]["X"] == 30.0


def test_the_step_limit_keeps_the_decoded_moves(tmp_path):
    r = mpf(tmp_path, MOVES3 + "N40 X40\nM30\n", 4, max_steps=3)
    stopped(r, "RUN001", 5)
    assert r["motion"]["feed_moves"] == 3 and r["position"]["X"] == 30.0
    assert r["cycle_time_s"] == pytest.approx(3 * 1.01)


def test_a_decoded_block_that_faults_stops_execution_there(tmp_path):
    """N30 cannot run (G02 without centre): its NC003 comes before the missing L77 in the program, and N35,
    decoded behind it, never runs."""
    r = mpf(tmp_path, "%MPF1\nN10 G90 G01 X10 F600\nN20 X20\nN30 G02 X30\nN35 G01 X40\nN40 L77\nM30\n", 4)
    stopped(r, "NC003", 4)
    assert r["motion"]["feed_moves"] == 2 and r["position"]["X"] == 20.0


def test_a_cl800_program_keeps_the_moves_decoded_before_its_error(tmp_path):
    """The CL 800 source compiles to an object program the SINUMERIK runs: the same rule, the .cl8 line."""
    (tmp_path / "machine.toml").write_text(MACHINE + "decode_ahead = 4\n")
    src = tmp_path / "p.cl8"
    src.write_text("PROGRAM 9;\nCHANNEL NC 0;\nLOCAL REAL: R60:=a, R61:=b;\nBEGIN\n(:G90 G01 X10 F600:); LF;\n"
                   "(:X20:); LF;\n(:X30:); LF;\na = 0;\nb = 5 / a;\nEND.\n")
    r = run(src, machine=tmp_path / "machine.toml", options=RunOptions(state_dir=tmp_path / ".ncvm"))[0]
    stopped(r, "CL800", 9)
    assert r["motion"]["feed_moves"] == 3 and r["position"]["X"] == 30.0


def test_a_rounding_waiting_for_its_next_block_is_not_made_at_a_stop(tmp_path):
    """N20 rounds its corner with the next block (B5), which never comes: N20 stays undone, N10 ran."""
    r = run_mpf(tmp_path, "%MPF1\nN10 G90 G01 X10 F600\nN20 X20 B5\nN30 R1=0 R2=5/R1\nM30\n",
                machine_text=MACHINE)
    stopped(r, "CL800", 4)
    assert r["motion"]["feed_moves"] == 1 and r["position"]["X"] == 10.0


MOVE = st.tuples(st.sampled_from(["G00", "G01"]), st.integers(-400, 400), st.integers(-400, 400))


@settings(max_examples=12, deadline=None)
@given(moves=st.lists(MOVE, max_size=10), ahead=st.sampled_from([0, 1, 3, 8]))
def test_a_fault_after_n_moves_reports_the_motion_of_the_n_moves_ending_normally(tmp_path_factory, moves, ahead):
    folder = tmp_path_factory.mktemp("stop")
    text = "%MPF1\n" + "".join(f"N{10 * (i + 1)} {g} X{x} Y{y} F{600 + 10 * i}\n" for i, (g, x, y) in enumerate(moves))
    r_end = mpf(folder, text + "M30\n", ahead)
    r_stop = mpf(folder, text + "N999 R1=0 R2=5/R1\nM30\n", ahead)
    assert r_end["status"] == "ok"
    stopped(r_stop, "CL800", len(moves) + 2)
    assert {k: r_stop[k] for k in SAME} == {k: r_end[k] for k in SAME}
