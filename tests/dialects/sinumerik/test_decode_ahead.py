"""Decode-ahead (CL 800 manual L4287-4334): a buffer of N decoded blocks, STOP DEC, and its lint."""

from __future__ import annotations

from pathlib import Path

from sin800_helpers import R, run_mpf

from ncvm.api import check


def _run(tmp_path: Path, text: str, ahead: int, extra: str = ""):
    return run_mpf(tmp_path, text, f"decode_ahead = {ahead}\n" + extra, ok=True)


ACTUAL = "%MPF1\nN10 G90 G01 X10 Y5 F1000\nN20 X20\nN30 @361 R1 K1\nN40 @714\nN50 @361 R2 K1 @361 R3 K2\n"


def test_lockstep_reads_the_programmed_position(tmp_path):
    r = _run(tmp_path, ACTUAL, 0)
    assert (R(r, 1), R(r, 2), R(r, 3)) == (20.0, 20.0, 5.0)


def test_buffer_of_two_blocks_hides_both_moves_until_stop_dec(tmp_path):
    # N10 and N20 wait in the buffer (2 blocks): ACPM(1) still sees the start point X0
    r = _run(tmp_path, ACTUAL, 2)
    assert (R(r, 1), R(r, 2), R(r, 3)) == (0.0, 20.0, 5.0)
    assert r["position"]["X"] == 20.0


def test_buffer_of_one_block_has_executed_the_first_move(tmp_path):
    # decoding N20 pushes N10 out of the 1-block buffer: ACPM(1) sees X10
    r = _run(tmp_path, ACTUAL, 1)
    assert (R(r, 1), R(r, 2)) == (10.0, 20.0)


def test_program_end_executes_the_buffer(tmp_path):
    r = _run(tmp_path, "%MPF1\nG90 G01 X10 F1000\nX30 Y7\n", 4)
    assert r["position"]["X"] == 30.0 and r["position"]["Y"] == 7.0


M94 = 'm_functions = { 94 = { R60 = "DB20.DW1" } }\n[sin800.plc.1]\nDB = { "20" = [0, 150] }\n'


def test_m94_part_number_needs_stop_dec(tmp_path):
    """Manual L4305-4326: the PLC's R60 is seen only after STOP DEC when decoding runs ahead."""
    r = _run(tmp_path, "%MPF1\nM94\n@201 R1 R60\n@714\n@201 R2 R60\nM30\n", 3, M94)
    assert (R(r, 1), R(r, 2)) == (0.0, 150.0)
    r = _run(tmp_path, "%MPF1\nM94\n@201 R1 R60\n@714\n@201 R2 R60\nM30\n", 0, M94)
    assert (R(r, 1), R(r, 2)) == (150.0, 150.0)


def test_meas_m_values_arrive_with_stop_dec(tmp_path):
    probe = '[[scenario]]\ntime = 0.0\nkind = "probe"\ninput = 1\nposition = { X = 42.5, Y = 10.0 }\n'
    r = _run(tmp_path, "%MPF1\nG1 F1000 Y10\n@720 R93 K1 X100 Y10\nR2=R93\n@714 R1=R93\nM30\n", 2, probe)
    assert (R(r, 2), R(r, 1), R(r, 93)) == (0.0, 42.5, 42.5)
    assert r["position"]["X"] == 42.5


def test_zero_offset_write_waits_for_the_blocks_before_it(tmp_path):
    # R1: the move still waits in the buffer. ZOA(1, 1, 0) = 100 (G54 X coarse): the G54 block decoded
    # before it still runs with X offset 0 (R2 = 5); the next block X6 with it (R3 = 100 + 6)
    r = _run(tmp_path, "%MPF1\nG54 G90 G0 X5\n@361 R1 K1\n@430 K1 K1 K0 K100\n@714\n@361 R2 K1\nX6\n"
                       "@714 @361 R3 K1\n", 3)
    assert (R(r, 1), R(r, 2), R(r, 3)) == (0.0, 5.0, 106.0)


def _lint(tmp_path: Path, text: str):
    path = tmp_path / "lint.mpf"
    path.write_text(text)
    return check(path, dialect="sin800")


def test_lint_warns_for_actual_value_read_after_motion(tmp_path):
    diags = _lint(tmp_path, "%MPF1\nG1 X10 F100\nR5=1\n@361 R1 K1\n@714\n@361 R2 K1\n")
    assert [(d.code, d.severity, d.span.line, d.span.column) for d in diags] == [("SIN010", "warning", 4, 1)]
    assert "ACPM" in diags[0].message and "line 2" in diags[0].message


def test_lint_input_read_and_sub_program_call(tmp_path):
    (tmp_path / "L5.spf").write_text("%SPF5\nN10 G0 X0\nN20 M17\n")  # a missing one is RUN002 at its call
    diags = _lint(tmp_path, "%MPF1\nL5\nN10 @187 K1 K2 K10\n")
    assert [(d.code, d.span.line) for d in diags] == [("SIN010", 3)]
    assert "IF INT" in diags[0].message


def test_lint_meas_m_without_stop_dec(tmp_path):
    diags = _lint(tmp_path, "%MPF1\n@720 R93 K1 X100\nR1=R93\n")
    assert [(d.code, d.span.line) for d in diags] == [("SIN010", 2)]
    assert _lint(tmp_path, "%MPF1\n@720 R93 K1 X100\n@714 R1=R93\n") == []


def test_lint_quiet_without_motion_or_with_stop_dec(tmp_path):
    assert _lint(tmp_path, "%MPF1\n@361 R1 K1\nG1 X1 F100\n@714\n@362 R2 K1\n") == []


def test_lint_read_in_the_block_of_the_motion_l2668(tmp_path):
    """L2668: STOP DEC in the block before the read. A move in the read's own block executes after the
    read, whether or not @714 stands between them."""
    for text in ("%MPF1\nG1 X10 F100 @361 R1 K1\n", "%MPF1\nG1 X10 F100 @714 @361 R1 K1\n"):
        diags = _lint(tmp_path, text)
        assert [(d.code, d.span.line) for d in diags] == [("SIN010", 2)]
        assert "same NC block" in diags[0].message
    assert _lint(tmp_path, "%MPF1\n@361 R1 K1 G1 X10 F100\n") == []  # the read before the move is meant
