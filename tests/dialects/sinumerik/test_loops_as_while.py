"""A stretch between two labels that jumps back to its own head runs as a Python ``while`` loop (issue 18,
the loop's speed): its jump back is a ``continue``, a jump forward leaves it, falling off its end goes on
with the next block. Every figure here (R values, blocks counted) is worked out by hand."""

from __future__ import annotations

from pathlib import Path

from sin800_helpers import R, run_mpf

from ncvm.dialects.sinumerik import compile_unit


def _generated(tmp_path: Path, text: str) -> str:
    return compile_unit(str(tmp_path / "p.mpf"), text, ("X", "Y", "Z"), "main").source.text()


def test_exit_past_the_next_label(tmp_path):
    # N20-N25 loop while R1 < 5 (@125 leaves for N40 once R1 >= 5); N30 is a label (N15's target) in between.
    # Blocks: N10 + 4 passes of N20, N25 + N20 of the fifth + N40 + M30 = 12
    text = ("%MPF1\nN10 R1=0 R2=0 @100 K20\nN15 R9=1 @100 K30\nN20 @620 R1 @125 R1 K5 K40\n"
            "N25 R2=R2+R1 @100 K-20\nN30 R3=99\nN40 R4=R2\nM30\n")
    assert "while True:" in _generated(tmp_path, text)
    r = run_mpf(tmp_path, text, ok=True)
    assert (R(r, 1), R(r, 2), R(r, 3), R(r, 4)) == (5.0, 10.0, 0.0, 10.0)
    assert r["steps"] == 12


def test_falling_off_the_end_of_a_loop_goes_on_with_the_next_label(tmp_path):
    # N20 jumps back while R1 < 3 (@124); then N30 and, as the next label, N40: 1 + 3 + 1 + 1 + M30 = 7 blocks
    text = "%MPF1\nN10 R1=0 R6=0 @121 R6 K0 K40\nN20 @620 R1 @124 R1 K3 K-20\nN30 R2=R1*10\nN40 R3=R2+1\nM30\n"
    assert "while True:" in _generated(tmp_path, text)
    r = run_mpf(tmp_path, text, ok=True)
    assert (R(r, 1), R(r, 2), R(r, 3)) == (3.0, 30.0, 31.0)
    assert r["steps"] == 7


def test_nested_loops_the_outer_jump_goes_through_the_dispatch(tmp_path):
    # inner N30 three times per outer pass, outer N20-N40 four times: R3 = 12;
    # blocks 1 + 4 x (N20 + 3 x N30 + N40) + M30 = 22. The stretch from N30 jumps back to N20 (an earlier
    # label): it stays in the dispatch chain
    text = ("%MPF1\nN10 R1=0 R3=0\nN20 R2=0\nN30 @620 R2 R3=R3+1 @124 R2 K3 K-30\n"
            "N40 @620 R1 @124 R1 K4 K-20\nM30\n")
    assert "while True:\n" not in _generated(tmp_path, text).split("while True:", 1)[1]  # the dispatch loop only
    r = run_mpf(tmp_path, text, ok=True)
    assert (R(r, 1), R(r, 2), R(r, 3)) == (4.0, 3.0, 12.0)
    assert r["steps"] == 22


def test_a_loop_with_moves_and_a_sub_program_call(tmp_path):
    # each pass: a G1 move and L5 (which adds 1 to R10); four passes
    sub = "%SPF5\nR10=R10+1 M17\n"
    text = "%MPF1\nN10 R1=0 R10=0 G1 F1000\nN20 @620 R1 X=R1 L5 @124 R1 K4 K-20\nM30\n"
    assert "while True:" in _generated(tmp_path, text)
    r = run_mpf(tmp_path, text, files={"L5.spf": sub}, ok=True)
    assert R(r, 1) == 4.0 and R(r, 10) == 4.0
    assert r["motion"]["feed_moves"] == 4 and r["motion"]["bounds"]["X"] == [0.0, 4.0]
