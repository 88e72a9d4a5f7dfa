"""The rw_SymPas step limit is never passed (docs/decisions.md "The rw_SymPas step limit is never passed").

Every group of statements counted at once is tested at its head, before any of it runs: a group that would
pass ``--max-steps`` is not begun, ``steps`` is the statements that ran, the variables, moves and output are
theirs, and RUN001 names the first statement that did not run. The figures are worked out by hand from the
counting: each statement counts one (a run of plain assignments counts as one group), a WHILE or FOR test
and a GOTO count one each time they run, a REPEAT's UNTIL test one at its line.
"""

from __future__ import annotations

import subprocess
import sys

import pytest


def _stop(r: dict) -> tuple:
    """(code, line, steps) of a run stopped by the step limit."""
    assert r["status"] == "error", (r["status"], r["steps"])
    return r["error"]["code"], r["error"]["line"], r["steps"]


STRAIGHT = """\
program Straight;
var a, b, c: integer;
begin
  a := 1;
  MLAW(A1 := 1.0);
  b := 2;
  MLAW(A1 := 2.0);
  c := 3;
end.
"""


def test_straight_code_stops_at_the_first_statement_past_the_limit(sap):
    """Five single statements under a limit of 3: ``a := 1``, the first move and ``b := 2`` run; the
    second MLAW (line 7) is named and not made."""
    r = sap(STRAIGHT, max_steps=3)
    assert _stop(r) == ("RUN001", 7, 3)
    assert r["variables"] == {"a": 1, "b": 2, "c": 0}
    assert r["motion"]["feed_moves"] == 1


def test_straight_code_within_the_limit_ends_normally(sap):
    r = sap(STRAIGHT, max_steps=5)
    assert r["status"] == "ok" and r["steps"] == 5
    assert r["variables"] == {"a": 1, "b": 2, "c": 3}


GROUP = """\
program Group;
var a, b, c: integer;
begin
  a := 1;
  b := 2;
  c := 3;
  MLAW(A1 := 1.0);
end.
"""


def test_a_run_of_assignments_that_does_not_fit_is_not_begun(sap):
    """The three assignments are one group: under a limit of 2 none of them runs (0 steps, line 4)."""
    r = sap(GROUP, max_steps=2)
    assert _stop(r) == ("RUN001", 4, 0)
    assert r["variables"] == {"a": 0, "b": 0, "c": 0}


def test_a_limit_at_the_end_of_a_group_runs_the_group_and_names_the_next_statement(sap):
    r = sap(GROUP, max_steps=3)
    assert _stop(r) == ("RUN001", 7, 3)
    assert r["variables"] == {"a": 1, "b": 2, "c": 3}
    assert r["motion"]["feed_moves"] == 0


WHILE = """\
program Loop;
var a, b: integer;
begin
  a := 0;
  b := 0;
  while a < 100 do
  begin
    a := a + 1;
    b := b + 1;
    MLAW(A1 := a * 1.0);
  end;
end.
"""


@pytest.mark.parametrize(("limit", "line", "steps", "passes", "moves"), [
    (1, 4, 0, 0, 0),       # a := 0; b := 0 is one group of two
    (2, 6, 2, 0, 0),       # the WHILE test
    (3, 8, 3, 0, 0),       # a := a + 1; b := b + 1 is one group of two
    (5, 10, 5, 1, 0),      # the MLAW
    (6, 6, 6, 1, 1),       # the WHILE test after the first pass
    (100, 8, 99, 24, 24),  # 3 + 24 passes of 4; the 25th pass's two assignments do not fit
    (101, 10, 101, 25, 24),  # they fit exactly: the limit falls at the group's end
    (402, 6, 402, 100, 100),  # 3 + 100 passes less the last WHILE test
])
def test_while_loop_stops_before_the_statement_that_does_not_fit(sap, limit, line, steps, passes, moves):
    r = sap(WHILE, max_steps=limit)
    assert _stop(r) == ("RUN001", line, steps)
    assert r["variables"] == {"a": passes, "b": passes}
    assert r["motion"]["feed_moves"] == moves


def test_while_loop_that_ends_at_the_limit_ends_normally(sap):
    r = sap(WHILE, max_steps=403)
    assert r["status"] == "ok" and r["steps"] == 403 and r["variables"] == {"a": 100, "b": 100}


SKIPPED = """\
program Skipped;
var a, b, c: integer;
begin
  a := 0;
  while a > 0 do
  begin
    a := a + 1;
    b := 1;
  end;
  c := 5;
end.
"""


def test_a_loop_body_that_does_not_run_is_not_stopped(sap):
    """The WHILE test is false at once: the body that would not fit is never due, the run ends with its
    three statements (``a := 0``, the test, ``c := 5``)."""
    r = sap(SKIPPED, max_steps=3)
    assert r["status"] == "ok" and r["steps"] == 3 and r["variables"] == {"a": 0, "b": 0, "c": 5}


FOR = """\
program ForLoop;
var i, s: integer;
begin
  s := 0;
  for i := 1 to 10 do
    s := s + i;
end.
"""


def test_for_loop_stops_at_its_test(sap):
    """``s := 0``, the FOR, then passes of the body and the FOR's test: under 7 the third pass's body
    runs (s = 1 + 2 + 3) and its test (line 5) does not."""
    r = sap(FOR, max_steps=7)
    assert _stop(r) == ("RUN001", 5, 7)
    assert r["variables"] == {"i": 3, "s": 6}


def test_for_loop_whose_last_test_does_not_fit(sap):
    """22 statements in all: under 21 the last body runs (s = 55), the last FOR test is named."""
    r = sap(FOR, max_steps=21)
    assert _stop(r) == ("RUN001", 5, 21)
    assert r["variables"] == {"i": 10, "s": 55}
    assert sap(FOR, max_steps=22)["status"] == "ok"


REPEAT = """\
program Rep;
var k: integer;
begin
  k := 0;
  repeat
    k := k + 1;
  until k >= 5;
end.
"""


@pytest.mark.parametrize(("limit", "line", "k"), [
    (3, 6, 1),   # k := 0, k := 1, the UNTIL test: the second pass's body is named
    (4, 7, 2),   # ... k := 2: its UNTIL test (line 7) is named
    (10, 7, 5),  # the last body runs, the last UNTIL test does not
])
def test_repeat_loop_stops_before_the_statement_that_does_not_fit(sap, limit, line, k):
    """``k := 0``, then passes of ``k := k + 1`` and the UNTIL test (11 statements in all)."""
    r = sap(REPEAT, max_steps=limit)
    assert _stop(r) == ("RUN001", line, limit)
    assert r["variables"] == {"k": k}


def test_repeat_loop_that_ends_at_the_limit_ends_normally(sap):
    ok = sap(REPEAT, max_steps=11)
    assert ok["status"] == "ok" and ok["steps"] == 11 and ok["variables"] == {"k": 5}


GOTO = """\
program G;
label again;
var i: integer;
begin
  i := 0;
  again: i := i + 1;
  if i < 100 then goto again;
end.
"""


@pytest.mark.parametrize(("limit", "line", "steps", "i"), [
    (9, 7, 9, 3),    # i := 0, then passes of i := i + 1, IF, GOTO: the third GOTO does not fit
    (10, 6, 10, 3),  # it fits exactly; the statement it jumps back to is named
])
def test_goto_back_stops_at_the_statement_that_does_not_fit(sap, limit, line, steps, i):
    r = sap(GOTO, max_steps=limit)
    assert _stop(r) == ("RUN001", line, steps)
    assert r["variables"] == {"i": i}


CALLS = """\
program Calls;
var a: integer;
procedure Bump;
begin
  a := a + 1;
  MLAW(A1 := a * 1.0);
end;
begin
  a := 0;
  Bump;
  Bump;
end.
"""


@pytest.mark.parametrize(("limit", "line", "a", "moves"), [
    (3, 6, 1, 0),  # a := 0, the call, a := a + 1: the MLAW in the procedure is named
    (5, 5, 1, 1),  # ... the MLAW, the second call: the procedure's first statement is named
])
def test_a_procedure_stops_at_its_statement_that_does_not_fit(sap, limit, line, a, moves):
    r = sap(CALLS, max_steps=limit)
    assert _stop(r) == ("RUN001", line, limit)
    assert r["variables"] == {"a": a}
    assert r["motion"]["feed_moves"] == moves


TWO_TASKS = """\
{$TASK 0}
program Main;
begin
  STARTCNCT(1);
  while TRUE do CI5 := CI5 + 1;
end.
{$TASK 1}
program Other;
begin
  while TRUE do CI6 := CI6 + 1;
end.
"""


@pytest.mark.parametrize("limit", [20_000, 20_001, 20_002])
def test_the_limit_is_one_for_all_tasks_of_the_card(sap, limit):
    """Every group here is one statement, so the run stops at exactly the limit, and the statements that
    ran are the increments' worth: STARTCNCT and each task's first WHILE test (3), two for each pass (the
    increment and the next test), less the test each task may have stopped before."""
    r = sap(TWO_TASKS, max_steps=limit)
    code, _, steps = _stop(r)
    assert code == "RUN001" and steps == limit
    ci = r["sympas"]["ci"]
    assert 0 <= 3 + 2 * (ci["5"] + ci["6"]) - limit <= 2, ci
    assert r["error"]["line"] in (5, 10)


def test_the_runaway_error_names_file_line_and_shows_the_source_line(tmp_path):
    """RUN001 is reported like every run-time error: ``file:line: error RUN001`` and the source line."""
    program = tmp_path / "loop.sap"
    program.write_text(WHILE)
    done = subprocess.run([sys.executable, "-m", "ncvm", "run", "--state", str(tmp_path / "st"), "--max-steps",
                           "5", str(program)], capture_output=True, text=True, timeout=300)
    assert done.returncode == 1
    assert f"{program}:10: error RUN001: step limit of 5 statements reached" in done.stderr
    assert "    MLAW(A1 := a * 1.0);" in done.stderr
    assert "5 steps, 0 moves" in done.stderr
