"""REL @730 and INTA @736 (manual L4400-4436, ch.10 L6798-6799): waits and remaining travel delete by
an external input, with the decode buffer drained first.

Times are computed by hand from the axis defaults (max_feed 5000 mm/min = 83.333 mm/s, accel
1000 mm/s^2): a straight G1 of L mm at F6000 accelerates for 0.08333 s over 3.4722 mm, cruises at
83.333 mm/s and brakes the same way, so it takes L / 83.333 + 0.08333 s (100 mm: 1.28333 s).
"""

from __future__ import annotations

from pathlib import Path

import pytest
from sin800_helpers import R, input_event, machine, run_mpf

MACHINE = machine("XZ")


def _run(tmp_path: Path, text: str, sin800: str = "", events: str = ""):
    return run_mpf(tmp_path, text, sin800 + events, machine_text=MACHINE)


def _ok(tmp_path: Path, text: str, sin800: str = "", events: str = ""):
    return run_mpf(tmp_path, text, sin800 + events, machine_text=MACHINE, ok=True)


MOVE_T = 100 / (5000 / 60) + (5000 / 60) / 1000  # 1.28333 s for 100 mm


# -- REL ------------------------------------------------------------------------------------------
def test_rel_manual_example_no_wait_when_the_input_came_during_the_move(tmp_path):
    # LF; REL (1, 2); (: G00 G90 X5 Z20:); LF; -- here as G1 X100: the input is 1 at 0.5 s, before the
    # position is reached (1.28333 s), so the program goes on at once
    r = _ok(tmp_path, "%MPF1\n@730 K1 K2 G1 G90 X100 F6000\nM30\n", events=input_event(0.5, 2, 1))
    assert r["cycle_time_s"] == pytest.approx(MOVE_T)


def test_rel_waits_after_the_position_is_reached(tmp_path):
    # the move ends at 1.28333 s with the input at 0; it changes to 1 at 3 s: the next move starts then
    r = _ok(tmp_path, "%MPF1\n@730 K1 K2 G1 G90 X100 F6000\nX0\nM30\n", events=input_event(3.0, 2, 1))
    assert r["cycle_time_s"] == pytest.approx(3.0 + MOVE_T)


def test_rel_drains_the_decode_buffer(tmp_path):
    # 3 blocks decoded ahead: REL still waits only after the X100 move has executed (1.28 s -> 3 s),
    # then X0 runs: 3 + 1.28333 s (waiting at decode time would give 3 + 2 * 1.28333 s)
    r = _ok(tmp_path, "%MPF1\nG1 G90 X100 F6000\n@730 K1 K2\nX0\nM30\n", sin800="decode_ahead = 3\n",
            events=input_event(3.0, 2, 1))
    assert r["cycle_time_s"] == pytest.approx(3.0 + MOVE_T)


def test_rel_input_that_never_comes_is_sin007(tmp_path):
    r = _run(tmp_path, "%MPF1\n@730 K2 K7\nM30\n")
    assert r["error"]["code"] == "SIN007"
    r = _run(tmp_path, "%MPF1\n@730 K3 K0\nM30\n")
    assert r["error"]["code"] == "CL800"


# -- INTA -----------------------------------------------------------------------------------------
# the input fires at 0.6 s: 3.4722 mm of ramp + 83.333 mm/s * (0.6 - 0.08333) s = 46.5278 mm
CUT = 0.5 * 1000 * (5000 / 60 / 1000) ** 2 + (5000 / 60) * (0.6 - (5000 / 60) / 1000)


def test_inta_deletes_the_remaining_travel_when_the_input_fires(tmp_path):
    r = _ok(tmp_path, "%MPF1\nG1 G90 F6000\n@736 K1 K1 K3 X100\n@714 @361 R1 K1\nM30\n", events=input_event(0.6, 3, 1))
    assert R(r, 1) == pytest.approx(CUT) and CUT == pytest.approx(46.527778)
    assert r["cycle_time_s"] >= 0.6


def test_inta_axis_0_means_all_axes_of_the_block(tmp_path):
    # X100 Z100: same profile along the diagonal (X, Z each capped by the path share), cut at 0.6 s
    r = _ok(tmp_path, "%MPF1\nG1 G90 F3000\n@736 K0 K1 K3 X30 Z40\n@714 @361 R1 K1 @361 R2 K2\nM30\n",
            events=input_event(0.6, 3, 1))
    # path 50 mm at 50 mm/s, accel 1000 * 50/40 capped by Z: a = 1000 / 0.8 = 1250 mm/s^2
    v, a = 50.0, 1250.0
    s = 0.5 * a * (v / a) ** 2 + v * (0.6 - v / a)
    assert (R(r, 1), R(r, 2)) == (pytest.approx(30 * s / 50), pytest.approx(40 * s / 50))


def test_inta_position_reached_when_the_input_does_not_fire(tmp_path):
    r = _ok(tmp_path, "%MPF1\nG1 G90 F6000\n@736 K1 K1 K3 X100\n@714 @361 R1 K1\nM30\n")
    assert R(r, 1) == 100.0 and r["cycle_time_s"] == pytest.approx(MOVE_T)


def test_inta_input_already_at_the_level_moves_nothing(tmp_path):
    r = _ok(tmp_path, "%MPF1\nG1 G90 F6000\n@736 K1 K1 K3 X100\n@714 @361 R1 K1\nM30\n",
            sin800='inputs = { "1" = "00001000" }\n')
    assert R(r, 1) == 0.0


def test_inta_negative_bit_waits_for_a_zero_signal(tmp_path):
    r = _ok(tmp_path, "%MPF1\nG1 G91 F6000\n@736 K1 K1 K-3 X100\n@714 @361 R1 K1\nM30\n",
            sin800='inputs = { "1" = "00001000" }\n', events=input_event(0.6, 3, 0))
    assert R(r, 1) == pytest.approx(CUT)


def test_inta_for_an_axis_not_in_the_block_does_nothing(tmp_path):
    r = _ok(tmp_path, "%MPF1\nG1 G90 F6000\n@736 K2 K1 K3 X100\n@714 @361 R1 K1\nM30\n", events=input_event(0.6, 3, 1))
    assert R(r, 1) == 100.0


def test_inta_starts_where_the_buffered_blocks_end(tmp_path):
    # 2 blocks decoded ahead: X50 (50/83.333 + 0.08333 = 0.68333 s) runs first, then the INTA block;
    # the input fires at 1.0 s, 0.31667 s into it: 50 + 3.4722 + 83.333 * (0.31667 - 0.08333) = 72.9167
    r = _ok(tmp_path, "%MPF1\nG1 G90 X50 F6000\n@736 K1 K1 K3 X100\n@714 @361 R1 K1\nM30\n",
            sin800="decode_ahead = 2\n", events=input_event(1.0, 3, 1))
    assert R(r, 1) == pytest.approx(72.916667)


def test_inta_input_byte_out_of_range_is_a_cl800_error(tmp_path):
    # arcs: tests/dialects/sinumerik/test_inta_arcs.py
    r = _run(tmp_path, "%MPF1\n@736 K1 K3 K0 G1 X10 F100\nM30\n")
    assert r["error"]["code"] == "CL800"
