"""What the deadlock watch counts (issue 15, rw_SymPas 3; docs/decisions.md "Deadlocks beside monitor tasks").

A task that must watch for ever loops (manual L1548): its own variables and CLOCK reads do not free the
main task, so a main task waiting for a CI nothing writes is RUN005 at once beside it. A task that sleeps
through the whole window wakes at a known time and may act then: that is no deadlock.
"""

from __future__ import annotations

MAIN_WAITS_FOR_CI1 = """{$TASK 0}
program T0;
begin
  CI1 := 0;
  STARTCNCT(1);
  while CI1 = 0 do WT(10);
  writeln('t0 done');
end.
{$TASK 1}
program T1;
var n: integer;
begin
BODY
end.
"""


def test_a_counting_monitor_does_not_hide_the_deadlock_L1548(sap):
    r = sap(MAIN_WAITS_FOR_CI1.replace("BODY", "  n := 0;\n  while TRUE do begin n := n + 1; WT(100); end;"))
    e = r["error"]
    assert e["code"] == "RUN005" and e["line"] == 6
    assert "task 0 at line 6" in e["message"] and "task 1 at line 14" in e["message"]
    assert r["steps"] < 100_000


def test_a_task_sleeping_longer_than_the_window_then_writing_ci_is_no_deadlock(sap):
    """Task 1 sleeps 38.4 s (WT counts 64 us ticks: 15625 a second, L2228-2233) and then sets CI1: task 0 goes on."""
    r = sap(MAIN_WAITS_FOR_CI1.replace("BODY", "  WT(600000);\n  CI1 := 1;"))
    assert r["error"] is None, r["error"]
    assert r["output"] == ["t0 done"]
    assert abs(r["cycle_time_s"] - 38.4) < 0.01


def test_a_monitor_that_frees_the_main_task_within_the_window_is_no_deadlock(sap):
    """The monitor reads the clock and writes CI1 after 5 s: the main task ends."""
    r = sap(MAIN_WAITS_FOR_CI1.replace("BODY", "  n := CLOCK;\n  while CLOCK - n < 5 * 15625 do WT(100);\n"
                                                 "  CI1 := 1;\n  while TRUE do WT(100);"))
    assert r["error"] is None, r["error"]
    assert r["output"][0] == "t0 done"
