"""Independent review of issue 15, rw_SymPas item 3 (a deadlock beside a monitor task).

Issue 15 rw_SymPas 3: "A real deadlock ... is found only by the step limit after 6-9 minutes, with
file/line null: detect it at once and report each task's line." Permanent event monitoring in its own
task is the manual's pattern (L1548); a monitor that writes a heartbeat (CLOCK) into a CI variable for a
host or the other task to see is a common form of it.
"""

from .helpers import SLIDE, run_json


def test_a_wait_nothing_can_end_beside_a_heartbeat_monitor_names_the_waiting_line(tmp_path):
    """Task 0 polls CI0, which no task and no scenario event ever writes; task 1 writes CLOCK into CI3
    every 10 ticks. After 370 s of simulated time (3,000,000 steps) the run ends with RUN001 "step
    limit ... runaway program?" and file/line null: no word of the line the program waits at. (With the
    default step limit it runs for minutes.) Expected: RUN005 at task 0's wait, or at the least an error
    that names where the program stands (p.sap line 6)."""
    doc = run_json(
        tmp_path,
        """\
        {$TASK 0}
        program Main;
        begin
          STARTCNCT(1);
          writeln('waiting');
          while CI0 = 0 do WT(5);
          writeln('never');
        end.

        {$TASK 1}
        program Mon;
        begin
          while TRUE do
          begin
            CI3 := CLOCK;
            WT(10);
          end;
        end.
        """,
        "--max-steps", "3000000",
        machine=SLIDE, timeout=300,
    )
    assert doc["status"] == "error"
    error = doc["error"]
    assert error["code"] == "RUN005" or (error["file"] == str(tmp_path / "p.sap") or error["line"] == 6), error
