"""Independent review of issue 15, rw_SymPas items 6/7: soft limits in the program's terms.

docs/sympas.md "Software limits": "A move that would carry an axis from inside its software limits
`sll`/`slr` across one is stopped where it gets there"; EVLSS (L1584-1586) fires when the axis position
passes a limit configured with TOM or SMA. rw_SymPas manual L1668-1672, L2144-2158, L1413: dp, rp, tp, lp and
sll/slr are read in the user coordinate (u = m - zerooffset - ZO), sll/slr stored in machine coordinates.
"""

from .helpers import run_json


def test_a_move_still_running_when_the_program_ends_is_stopped_at_slr(tmp_path):
    """MLAW(A1 := 450) with slr = 400 stops at 400 (TOM). The same move started with MLA by a program
    that then ends (or waits less than the move takes) is not watched any more once the tasks have
    ended: A1 ends at 450 in the JSON `position`, past the limit the card would have stopped it at,
    with only a warning. The axis must stop at slr whether or not a task still runs."""
    doc = run_json(
        tmp_path,
        """\
        {$TASK 0}
        program Main;
        begin
          TRVL := 200.0; TRAC := 2000.0;
          MLA(A1 := 450.0);
        end.
        """,
    )
    assert doc["status"] == "ok"
    assert doc["position"]["A1"] == 400.0
    assert any("software limit slr = 400 of A1" in line for line in doc["output"])


def test_a_move_started_by_a_task_that_ends_is_stopped_at_slr(tmp_path):
    """Task 1 starts MLA(A2 := 350) (slr of A2 = 300) and ends; task 0 waits 1 s and ends: A2 runs to
    350 unchecked (position A2 350.0), although a MLAW of the same move stops at 300."""
    doc = run_json(
        tmp_path,
        """\
        {$TASK 0}
        program Main;
        begin
          STARTCNCT(1);
          WT(15625);
          writeln('main end ', CI1);
        end.

        {$TASK 1}
        program Mover;
        begin
          TRVL := 200.0; TRAC := 2000.0;
          MLA(A2 := 350.0);
          CI1 := 1;
        end.
        """,
    )
    assert doc["status"] == "ok"
    assert doc["position"]["A2"] == 300.0


def test_slr_reads_in_the_users_coordinates_after_szpa(tmp_path):
    """§10.6: sll/slr are exposed in u = m - zerooffset. After SZPA(A1 := 100) the right limit at
    machine 400 reads 300, the position where TOM stops A1 reads dp = 300. ncvm reads slr = 400 (the
    machine figure) and its message "software limit slr = 400 of A1 reached" names a limit the
    program's A1 (dp 300) never shows."""
    doc = run_json(
        tmp_path,
        """\
        {$TASK 0}
        program Main;
        begin
          TRVL := 100.0; TRAC := 1000.0;
          SZPA(A1 := 100.0);
          MLAW(A1 := 350.0);
          writeln('dp ', A1.dp, ' slr ', A1.slr);
        end.
        """,
    )
    assert doc["status"] == "ok"
    assert doc["position"]["A1"] == 300.0
    assert "dp 300 slr 300" in doc["output"]
