"""The deadlock watch sees waits that no running task can release, beside a task that keeps writing the
card's registers (issue 15 rw_SymPas 3; a monitor in its own task, L1548): only a task with a statement
that assigns what the waiting main task reads can release it.
"""

from __future__ import annotations

MACHINE = '[[axis]]\nname = "X"\n[[axis]]\nname = "Y"\n'


MONITOR = """{$TASK 0}
program Main;
begin
  STARTCNCT(1);
  while CI0 = 0 do WT(5);
  writeln('released');
end.
{$TASK 1}
program Mon;
begin
  while TRUE do
  begin
    %s
    WT(10);
  end;
end.
"""


def test_a_heartbeat_in_cd_does_not_hide_the_deadlock(sap_on):
    result = sap_on(MONITOR % "CD7 := CLOCK * 0.5;", MACHINE, max_steps=3_000_000)
    assert result["error"]["code"] == "RUN005", result["error"]
    assert result["error"]["line"] == 5
    assert "task 0 at line 5" in result["error"]["message"]


def test_a_counter_that_releases_the_wait_later_is_no_deadlock(sap_on):
    # task 1 counts in CI3 and sets CI0 after 4000 rounds (~26 s of card time, past two quiet windows):
    # it assigns CI0, which task 0 reads, so task 0 may still be released, and it is
    result = sap_on(MONITOR % "CI3 := CI3 + 1; if CI3 = 4000 then CI0 := 1;", MACHINE, max_steps=3_000_000)
    assert result["error"] is None, result["error"]
    assert "released" in result["output"]
