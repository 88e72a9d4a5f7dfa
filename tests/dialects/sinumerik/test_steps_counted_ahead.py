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


def _limited(tmp_path: Path, text: str, limit: int, files: dict | None = None) -> dict:
    for name, body in (files or {}).items():
        (tmp_path / name).write_text(body)
    (tmp_path / "p.mpf").write_text(text)
    result, _ = run(tmp_path / "p.mpf", dialect="sin800",
                    options=RunOptions(state_dir=tmp_path / ".n", max_steps=limit))
    return result


CONSTANT = "%MPF1\nN1 G90 G94 F1000\n" + "".join(f"N{i + 2} G1 X{i + 1}\n" for i in range(30)) + "N40 M30\n"


def test_a_run_of_constant_blocks_stops_at_the_block_past_the_limit(tmp_path):
    """30 constant G1 blocks (one generated run) under a limit of 10: N1 and nine moves run, the run stops
    with RUN001 at N11 (line 12), the tenth move never made."""
    result = _limited(tmp_path, CONSTANT, 10)
    assert result["error"]["code"] == "RUN001" and result["error"]["line"] == 12
    assert result["steps"] == 10 and result["motion"]["feed_moves"] == 9 and result["position"]["X"] == 9.0


def test_a_run_of_constant_blocks_at_the_limits_edges(tmp_path):
    """Limit 1: only N1 runs (stop at N2, line 3); 31: every move, stop at the M30 (line 33); 32: ends."""
    first = _limited(tmp_path, CONSTANT, 1)
    assert first["error"]["line"] == 3 and first["steps"] == 1 and first["motion"]["feed_moves"] == 0
    last = _limited(tmp_path, CONSTANT, 31)
    assert last["error"]["line"] == 33 and last["steps"] == 31 and last["motion"]["feed_moves"] == 30
    whole = _limited(tmp_path, CONSTANT, 32)
    assert whole["status"] == "ok" and whole["steps"] == 32


def test_blocks_that_only_count_inside_a_run_count_toward_the_limit(tmp_path):
    """N3 and N5 hold only a block number: they count as blocks but do nothing. Limit 4: N1, N2 (X1), N3,
    N4 (X2); the stop is at N5 (line 6), X at 2."""
    text = "%MPF1\nN1 G90 G94 F1000\nN2 G1 X1\nN3\nN4 X2\nN5\nN6 X3\nN7 M30\n"
    result = _limited(tmp_path, text, 4)
    assert result["error"]["line"] == 6 and result["steps"] == 4 and result["position"]["X"] == 2.0
    assert result["motion"]["feed_moves"] == 2


CYCLE = "%SPF81\nN1 G1 Z-1\nN2 G0 Z2\nN3 M17\n"  # L81: three blocks at each position
DRILL = "%MPF1\nN10 G17 G90 G94 F100\nN20 G81 X10\nN30 X20\nN31\nN40 X30\nN50 X40\nN60 G80\nN70 M30\n"


def test_a_run_under_a_drilling_cycle_counts_each_block_before_its_cycle(tmp_path):
    """Blocks in order: N10, N20, L81 (3), N30, L81 (3), N31, N40, L81 (N1 = the 12th) ... 20 in all.
    Each limit stops at the block after the last one it allows, in the main program or the cycle."""
    assert _limited(tmp_path, DRILL, 100, {"L81.spf": CYCLE})["steps"] == 20
    for limit, file, line, x, z in ((5, "p.mpf", 4, 10.0, 2.0), (6, "L81.spf", 2, 20.0, 2.0),
                                    (9, "p.mpf", 5, 20.0, 2.0), (12, "L81.spf", 3, 30.0, -1.0)):
        result = _limited(tmp_path, DRILL, limit, {"L81.spf": CYCLE})
        assert result["error"]["code"] == "RUN001" and result["steps"] == limit
        assert (Path(result["error"]["file"]).name, result["error"]["line"]) == (file, line), limit
        assert (result["position"]["X"], result["position"]["Z"]) == (x, z), limit


def test_a_computing_stretch_that_does_not_fit_reports_the_blocks_that_ran(tmp_path):
    """The runaway loop of three blocks a pass under a limit of 1,001: the 334th pass does not fit and is not
    begun, so 1,000 blocks ran and 1,000 are reported (not the limit)."""
    (tmp_path / "p.mpf").write_text("%MPF1\nN10 R1=0\nN20 R1=R1+1\nN30 R2=R1*2\nN40 R3=R2-1 @100 K-20\n")
    result, _ = run(tmp_path / "p.mpf", options=RunOptions(state_dir=tmp_path / ".n", max_steps=1001))
    assert result["error"]["code"] == "RUN001" and result["error"]["line"] == 3
    assert result["steps"] == 1000 and result["variables"]["R1"] == 333.0
