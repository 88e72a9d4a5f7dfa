"""When a simulated run of several tasks is over (issue 15, rw_SymPas 2 and 3; docs/decisions.md).

A task that must watch events for ever stays in an endless loop (manual L1548): the run is over when the
main task has ended and the card has been quiet (no motion, no scenario event ahead) for 10 s; the tasks
still looping are reported with their lines. Every task waiting for something nothing can bring is a
deadlock (RUN005), found at once rather than by the step limit.
"""

from __future__ import annotations

MONITOR = """{$TASK 0}
program Main;
begin
  STARTCNCT(1);
  TRVL := 100.0; TRAC := 1000.0;
  MLAW(A1 := 100.0);
  writeln('main done');
end.

{$TASK 1}
program Mon;
begin
  while TRUE do
  begin
    if A1.dp > 50.0 then CI3 := 1;
    WT(20);
  end;
end.
"""


def test_monitor_task_in_an_endless_loop_ends_with_the_run_L1548(sap):
    r = sap(MONITOR)
    assert r["error"] is None
    assert r["output"][0] == "main done"
    assert r["output"][1].startswith("task 1 still running at ") and ":13 when the run ended" in r["output"][1]
    assert abs(r["cycle_time_s"] - 1.1) < 0.01  # the MLAW's time: not the quiet window, not hours
    tasks = {t["task"]: t for t in r["sympas"]["tasks"]}
    assert tasks[0]["state"] == "ENDED" and tasks[0]["line"] is None
    assert tasks[1]["state"] == "RUNNING" and tasks[1]["line"] == 13 and tasks[1]["program"] == "Mon"
    assert r["steps"] < 1_000_000


def test_a_task_that_moves_after_a_long_wait_is_not_cut_off_L1548(sap):
    """Task 1 sleeps 12 s (longer than the quiet window) after task 0 ended, then moves: the move is part
    of the run."""
    r = sap(MONITOR.replace("""  while TRUE do
  begin
    if A1.dp > 50.0 then CI3 := 1;
    WT(20);
  end;""", """  WT(12 * 15625);
  TRVL := 100.0; TRAC := 1000.0;
  MLAW(A2 := 10.0);
  while TRUE do WT(20);"""))
    assert r["error"] is None
    assert r["position"]["A2"] == 10.0
    assert abs(r["cycle_time_s"] - (12.0 + 0.2)) < 0.01


DEADLOCK = """{$TASK 0}
program Main;
begin
  STARTCNCT(1);
  while CI1 = 0 do WT(20);
  writeln('never');
end.

{$TASK 1}
program Other;
begin
  while CI0 = 0 do
    WT(20);
end.
"""


def test_deadlock_is_found_at_once_with_each_task_line(sap):
    r = sap(DEADLOCK)
    e = r["error"]
    assert e["code"] == "RUN005" and e["line"] == 5 and e["file"].endswith("prog.sap")
    assert "task 0 at line 5" in e["message"] and "task 1 at line 13" in e["message"]
    assert r["steps"] < 1_000_000
    assert {t["task"]: t["line"] for t in r["sympas"]["tasks"]} == {0: 5, 1: 13}


def test_waiting_for_a_time_with_clock_is_no_deadlock_L1679(sap):
    """A loop that waits on CLOCK for 30 s (longer than the quiet windows) goes on when the time is up."""
    r = sap("""program Wait;
var t0: integer;
begin
  t0 := CLOCK;
  while CLOCK - t0 < 30 * 15625 do WT(20);
  writeln('done');
end.
""")
    assert r["error"] is None and r["output"] == ["done"]
    assert abs(r["cycle_time_s"] - 30.0) < 0.01


def test_a_task_counting_without_motion_is_no_deadlock(sap):
    """Work without motion changes the task's variables: the run goes on to its end."""
    r = sap("""program Count;
var k, s: integer;
begin
  s := 0;
  for k := 1 to 400000 do s := s + 1;
  writeln(s);
end.
""")
    assert r["error"] is None and r["output"] == ["400000"]


def test_rs_is_reported_as_a_system_reset_not_a_normal_end_L2043(sap):
    r = sap("""{$TASK 0}
program R;
begin
  STARTCNCT(1);
  TRVL := 100.0;
  MLA(A1 := 100.0);
  WT(1000);
  RS;
  writeln('not here');
end.

{$TASK 1}
program L;
begin
  while TRUE do WT(20);
end.
""")
    assert r["error"] is None
    assert r["ended"].startswith("ended by RS (system reset) at ") and r["ended"].endswith("prog.sap:8")
    assert r["output"][0].endswith("prog.sap:8: RS: system reset by task 0: the axes stop, the running tasks "
                                   "are stopped")
    assert [t["state"] for t in r["sympas"]["tasks"]] == ["STOPPED", "STOPPED"]
    assert 0.0 < r["position"]["A1"] < 100.0


def test_the_summary_line_says_how_the_run_ended(tmp_path):
    from ncvm.cli import _summary

    doc = {"status": "ok", "ended": "ended with task(s) 1 still looping", "steps": 5, "cycle_time_s": 1.0,
           "motion": {"rapid_moves": 0, "feed_moves": 0, "arc_moves": 0, "rapid_length": 0.0, "feed_length": 0.0,
                      "bounds": {}}}
    assert _summary(doc).startswith("ncvm: ended with task(s) 1 still looping: 5 steps")
