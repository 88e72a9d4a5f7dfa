"""Independent review of issue 15, rw_SymPas item 3 (a deadlock beside a monitor task).

Issue 15 rw_SymPas 3: "A real deadlock ... is found only by the step limit after 6-9 minutes, with
file/line null: detect it at once and report each task's line." Permanent event monitoring in its own
task is the manual's pattern (L1548); a monitor that writes a heartbeat (CLOCK) into a CI variable for a
host or the other task to see is a common form of it.
"""

import json
import subprocess
import sys
import textwrap

MACHINE = textwrap.dedent(
    """\
    [machine]
    name = "APCI-8001 slide"

    [[axis]]
    name = "X"
    min = -10.0
    max = 400.0
    rapid = 12000.0
    max_feed = 6000.0
    accel = 1500.0
    """
)


def test_a_wait_nothing_can_end_beside_a_heartbeat_monitor_names_the_waiting_line(tmp_path):
    """Task 0 polls CI0, which no task and no scenario event ever writes; task 1 writes CLOCK into CI3
    every 10 ticks. After 370 s of simulated time (3,000,000 steps) the run ends with RUN001 "step
    limit ... runaway program?" and file/line null: no word of the line the program waits at. (With the
    default step limit it runs for minutes.) Expected: RUN005 at task 0's wait, or at the least an error
    that names where the program stands (p.sap line 6)."""
    (tmp_path / "machine.toml").write_text(MACHINE)
    program = tmp_path / "p.sap"
    program.write_text(
        textwrap.dedent(
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
            """
        )
    )
    done = subprocess.run(
        [sys.executable, "-m", "ncvm", "run", "--json", "--max-steps", "3000000", str(program)],
        capture_output=True, text=True, cwd=tmp_path, timeout=300,
    )
    doc = json.loads(done.stdout)
    assert doc["status"] == "error"
    error = doc["error"]
    assert error["code"] == "RUN005" or (error["file"] == str(program) or error["line"] == 6), error
