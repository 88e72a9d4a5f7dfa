"""A deadlock is found at once even when another task is a monitor loop that reads CLOCK.

Issue 15 (rw_SymPas 3): "A real deadlock (every task waits for an event nothing in the scenario can
trigger) is found only by the step limit after 6-9 minutes ... detect it at once and report each task's
line." With a plain monitor loop (`v := A1.dp; WT(100)`) ncvm reports RUN005 after ~70,000 steps. Let the
monitor read the clock instead (`t := CLOCK`, the usual time stamp of the manual's monitoring pattern,
L1548) and the run goes on for minutes (over 2 minutes measured, no end): docs/sympas.md counts CLOCK
reads as a change of the card's state, so task 0's wait for CI1, which no task ever writes, is never called
a deadlock. With a step budget 30 times what the other case needs, the run must end with RUN005 naming
both tasks' lines, not RUN001.
"""

from __future__ import annotations

PROGRAM = """{$TASK 0}
program T0;
begin
  CI0 := 0; CI1 := 0;
  STARTCNCT(1);
  while CI1 = 0 do WT(10);
  writeln('t0 done');
end.
{$TASK 1}
program T1;
var t: integer;
begin
  while TRUE do
  begin
    t := CLOCK;
    WT(100);
  end;
end.
"""

MACHINE = '[[axis]]\nname = "X"\n[[axis]]\nname = "Y"\n[[axis]]\nname = "Z"\n'


def test_deadlock_beside_a_clock_reading_monitor_is_run005(sap_on):
    result = sap_on(PROGRAM, MACHINE, max_steps=2_000_000)
    assert result["error"] is not None
    assert result["error"]["code"] == "RUN005", result["error"]
    # task 1 sleeps in its WT(100) (line 16) whenever the others look: that is the line it stands at
    assert "task 0 at line 6" in result["error"]["message"] and "task 1 at line 16" in result["error"]["message"]
