"""Blocks that only compute and branch are counted once per stretch (issue 18, the loop's speed), yet
``steps`` still counts every block run up to and including the one that ends the run: a fault takes back
the blocks of the stretch not reached, a jump out of a stretch those it skips, and the step limit stops a
runaway loop at exactly the limit. Each figure here is the block count by hand."""

from __future__ import annotations

from pathlib import Path

from sin800_helpers import R, run_mpf

from ncvm.api import run
from ncvm.dialects.sinumerik import compile_unit
from ncvm.runtime.session import RunOptions


def test_fault_in_the_middle_of_a_stretch_counts_the_blocks_up_to_it(tmp_path):
    # N10-N60 compute only: one stretch; N40 leaves the R range (L7079): N10, N20, N30, N40 ran
    text = "%MPF1\nN10 R1=99999999 R2=5\nN20 R3=R2*2\nN30 R4=R3+1\nN40 R5=R1+R1\nN50 R6=1\nN60 R7=2\nM30\n"
    r = run_mpf(tmp_path, text)
    assert r["error"]["code"] == "CL800" and r["error"]["line"] == 5
    assert r["steps"] == 4
    assert R(r, 4) == 11.0 and R(r, 6) == 0.0


def test_a_negative_square_root_in_a_stretch_is_the_cl800_error_at_its_block(tmp_path):
    # @613 SQRT of -1 (L6725) in the third block: N10, N20, N30 ran; INC (@620) counted R1 up to 5 first
    r = run_mpf(tmp_path, "%MPF1\nN10 R1=4 R2=-1\nN20 @620 R1\nN30 R3=R1*2 @613 R4 R2\nN40 R5=1\nM30\n")
    assert r["error"]["code"] == "CL800" and r["error"]["line"] == 4
    assert "SQRT(-1): no square root of a negative number" in r["error"]["message"]
    assert r["steps"] == 3 and R(r, 1) == 5.0 and R(r, 3) == 10.0


def test_square_root_and_increment_in_a_loop(tmp_path):
    r = run_mpf(tmp_path, "%MPF1\nN10 R1=0 R2=0\nN20 @620 R1 @613 R3 R1 R2=R2+R3 @124 R1 K9 K-20\nM30\n", ok=True)
    assert R(r, 1) == 9.0 and abs(R(r, 2) - sum(k ** 0.5 for k in range(1, 10))) < 1e-12


def test_while_exit_from_the_middle_of_a_stretch(tmp_path):
    # N20-N50 one stretch; N30's WHILE leaves it for N60 when R1 reaches 4:
    # N10 + 3 passes of N20-N50 (12) + N20, N30 of the last pass + N60 + M30 = 17
    text = ("%MPF1\nN10 R1=0 R2=0\nN20 @620 R1\nN30 R2=R2+R1 @135 R1 K4 K60\nN40 R3=R2*2\n"
            "N50 R4=R3+1 @100 K-20\nN60 R5=R2\nM30\n")
    r = run_mpf(tmp_path, text, ok=True)
    assert r["steps"] == 17 and R(r, 5) == 10.0 and R(r, 4) == 13.0


def test_computed_goto_out_of_a_stretch(tmp_path):
    # @100 R7 jumps to N50 (R7 = 50): N40 leaves its stretch; the same 17 blocks as above
    text = ("%MPF1\nN10 R1=0 R2=0 R7=50\nN20 @620 R1\nN30 R2=R2+R1 @135 R1 K4 K60\nN40 R3=R2*2 @100 R7\n"
            "N50 R4=R3+1 @100 K-20\nN60 R5=R2\nM30\n")
    r = run_mpf(tmp_path, text, ok=True)
    assert r["steps"] == 17 and R(r, 3) == 12.0


def test_runaway_loop_stops_at_exactly_the_limit(tmp_path):
    # N20-N40 one stretch of 3 blocks, looping: 1 + 333 passes = 1000 blocks; the 334th pass would pass the
    # limit, so the run stops at its head (N20) with the variables of the 1000 blocks it reports
    (tmp_path / "p.mpf").write_text("%MPF1\nN10 R1=0\nN20 R1=R1+1\nN30 R2=R1*2\nN40 R3=R2-1 @100 K-20\n")
    result, _ = run(tmp_path / "p.mpf", options=RunOptions(state_dir=tmp_path / ".n", max_steps=1000))
    assert result["error"]["code"] == "RUN001" and result["error"]["line"] == 3
    assert result["steps"] == 1000 and result["variables"]["R1"] == 333.0 and result["variables"]["R3"] == 665.0


def test_a_pass_of_a_computing_loop_counts_its_blocks_at_once(tmp_path):
    """The generated loop body: one count for the stretch, not one per block; a debug build (step hook before
    every block) counts block by block."""
    text = "%MPF1\nN10 R1=0\nN20 R1=R1+1\nN30 R2=R1*2\nN40 R3=R2-1 @124 R1 K9 K-20\nM30\n"
    path = str(Path(tmp_path) / "p.mpf")
    fast = compile_unit(path, text, ("X", "Y", "Z"), "main").source.text()
    debug = compile_unit(path, text, ("X", "Y", "Z"), "main", debug=True).source.text()
    assert fast.count("_st += 3") == 1 and fast.count("_st += 1") == 2  # N20-N40; N10 and M30 alone
    assert "_st += 3" not in debug and debug.count("_st += 1") == 5


def test_fault_in_the_first_item_of_a_block_in_a_stretch(tmp_path):
    # N10-N30 one stretch; N20's first item leaves the R range (L7079), its second is never reached:
    # N10 and N20 ran, N30 (counted ahead) is taken back
    text = "%MPF1\nN10 R1=99999999 R2=5\nN20 R5=R1+R1 R3=1\nN30 R4=1\nM30\n"
    r = run_mpf(tmp_path, text)
    assert r["error"]["code"] == "CL800" and r["error"]["line"] == 3
    assert r["steps"] == 2 and R(r, 3) == 0.0


def test_fault_after_a_central_r_read_in_a_stretch(tmp_path):
    # the central R read's mark is put before its item's lines: the steps taken back move with them
    text = "%MPF1\nN10 R1=99999999 R2=1\nN20 R6=R900 @135 R2 K4 K40 R5=R1+R1\nN30 R4=1\nN40 R7=1\nM30\n"
    r = run_mpf(tmp_path, text)
    assert r["error"]["code"] == "CL800" and r["error"]["line"] == 3
    assert r["steps"] == 2
