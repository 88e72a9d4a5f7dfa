"""The CPL step limit is never passed, and the run reports what ran (docs/decisions.md "The CPL step limit
is never passed"; ``ncvm run --max-steps N``: "Stop a runaway program after this many statements and blocks").

Generated code counts a group of statements at its head and tests the limit there: a group that does not fit
is not begun. A loop, a structure holding a loop or a call, is a group of its own, and a call ends its group;
a loop's pass (its body and its END, NEXT or UNTIL) is a group. RUN001 names the first statement that did not
run; ``steps`` is the statements that ran and the variables are theirs. Figures below are counted by hand.
"""

from __future__ import annotations

import subprocess
import sys

import pytest

WHILE = "10 N% = 0\n20 WHILE N% < 100 DO\n30 N% = N% + 1\n40 M% = N%\n50 END\n"
FOR = "10 FOR I% = 1 TO 100\n20 A% = I%\n30 NEXT I%\n"
REPEAT = "10 K% = 0\n20 REPEAT\n30 K% = K% + 1\n40 UNTIL K% > 100\n"
GOTO = "10 N% = 0\n20 .TOP N% = N% + 1\n30 M% = N%\n40 GOTO .TOP\n"
STRAIGHT = "".join(f"{10 * k} A% = {k}\n" for k in range(1, 6))


@pytest.fixture
def limited(run_text, reference):
    """limited(text, limit, **programs) -> the result of ``text`` under --max-steps ``limit`` (programs: files
    beside it on the program path)."""
    def _run(text: str, limit: int, **programs: str) -> dict:
        machine = reference()
        for name, body in programs.items():
            (machine.program_path[0] / name).write_text(body)
        return run_text(text, name="p.cpl", machine=machine, max_steps=limit)
    return _run


def _stop(r: dict) -> tuple:
    """(steps, the file and line RUN001 names, the variables)."""
    assert r["status"] == "error" and r["error"]["code"] == "RUN001", r["error"]
    return r["steps"], r["error"]["file"].rsplit("/", 1)[-1], r["error"]["line"], r["variables"]


def test_straight_code_ends_when_the_limit_falls_at_its_end(limited):
    """Five statements under a limit of 5: they all run, the run ends normally."""
    r = limited(STRAIGHT, 5)
    assert r["status"] == "ok" and r["steps"] == 5 and r["variables"]["A%"] == 5


def test_straight_code_that_does_not_fit_is_not_begun(limited):
    """Five statements under a limit of 4: the one group does not fit; nothing runs, RUN001 at line 1."""
    assert _stop(limited(STRAIGHT, 4)) == (0, "p.cpl", 1, {})


@pytest.mark.parametrize("limit, expected", [
    (1, (1, "p.cpl", 2, {"N%": 0})),  # N% = 0 ran; the WHILE is a group of its own
    (2, (2, "p.cpl", 3, {"N%": 0})),  # N% = 0 and the WHILE: the first pass (3) does not fit
    (8, (8, "p.cpl", 3, {"N%": 2, "M%": 2})),  # 2 + two passes of 3: the limit at a pass's end
    (10, (8, "p.cpl", 3, {"N%": 2, "M%": 2})),  # the third pass would make 11: not begun
    (11, (11, "p.cpl", 3, {"N%": 3, "M%": 3})),
])
def test_while_loop_stops_at_the_head_of_a_pass(limited, limit, expected):
    assert _stop(limited(WHILE, limit)) == expected


@pytest.mark.parametrize("limit, expected", [
    (1, (1, "p.cpl", 2, {"I%": 1})),  # the FOR set I% = 1
    (7, (7, "p.cpl", 2, {"I%": 4, "A%": 3})),  # FOR + three passes of A% = I% and NEXT
    (8, (7, "p.cpl", 2, {"I%": 4, "A%": 3})),
])
def test_for_loop_stops_at_the_head_of_a_pass(limited, limit, expected):
    assert _stop(limited(FOR, limit)) == expected


@pytest.mark.parametrize("limit, expected", [
    (6, (6, "p.cpl", 3, {"K%": 2})),  # K% = 0, REPEAT, two passes of K% = K% + 1 and UNTIL
    (7, (6, "p.cpl", 3, {"K%": 2})),
])
def test_repeat_loop_stops_at_the_head_of_a_pass(limited, limit, expected):
    assert _stop(limited(REPEAT, limit)) == expected


def test_an_empty_repeat_loop_is_stopped(tmp_path):
    """REPEAT ... UNTIL FALSE with nothing between: the UNTIL is counted on every pass (it was not: the loop
    ran for ever). The REPEAT and 49 UNTILs fill the limit of 50; RUN001 names the UNTIL."""
    program = tmp_path / "empty.cpl"
    program.write_text("10 REPEAT\n20 UNTIL FALSE\n")
    done = subprocess.run([sys.executable, "-m", "ncvm", "run", "--state", str(tmp_path / "st"), "--max-steps", "50",
                           str(program)], capture_output=True, text=True, timeout=120)
    assert done.returncode == 1, done.stderr
    assert f"{program}:2:" in done.stderr and "error RUN001" in done.stderr
    assert "20 UNTIL FALSE" in done.stderr  # the source line, as every run-time error shows it


@pytest.mark.parametrize("limit, expected", [
    (1, (1, "p.cpl", 2, {"N%": 0})),
    (7, (7, "p.cpl", 2, {"N%": 2, "M%": 2})),  # N% = 0, two passes of N%, M% and the GOTO
    (8, (8, "p.cpl", 3, {"N%": 3, "M%": 2})),  # the GOTO form counts and tests each statement
    (9, (9, "p.cpl", 4, {"N%": 3, "M%": 3})),  # the GOTO itself did not run
])
def test_goto_loop_stops_at_the_statement(limited, limit, expected):
    assert _stop(limited(GOTO, limit)) == expected


@pytest.mark.parametrize("limit, expected", [
    (3, (2, "SUB", 1, {"X%": 1})),  # X% = 1 and the CALL; SUB's three do not fit in the one left
    (4, (2, "SUB", 1, {"X%": 1})),
    (5, (5, "p.cpl", 3, {"X%": 1})),  # SUB ran; Y% = 2 does not fit
])
def test_call_ends_its_group(limited, limit, expected):
    """The CALL ends its group, so the called program is tested against the limit with nothing of the caller
    counted ahead of it."""
    r = limited("10 X% = 1\n20 CALL SUB\n30 Y% = 2\n", limit, SUB="10 A% = 1\n20 B% = 2\n30 C% = 3\n")
    assert _stop(r) == expected


@pytest.mark.parametrize("limit, expected", [
    (18, (18, "SUB", 1, {"I%": 3})),  # 2 + three passes of 5, the fourth CALL (18); SUB's two would make 20
    (20, (20, "p.cpl", 4, {"I%": 3})),  # the fourth CALL and SUB ran; I% = I% + 1 and END would make 22
])
def test_calls_in_a_loop_stop_exactly(limited, limit, expected):
    """I% = 0 and the WHILE (2), then each pass: the CALL (1), SUB's two statements, I% = I% + 1 and END (2)."""
    r = limited("5 I% = 0\n10 WHILE I% < 100 DO\n20 CALL SUB\n30 I% = I% + 1\n40 END\n", limit,
                SUB="10 A% = 1\n20 B% = 2\n")
    steps, file, line, variables = _stop(r)
    assert (steps, file, line, {"I%": variables["I%"]}) == expected


def test_selected_cycle_stops_in_time(limited):
    """A drilling cycle selected with G81 runs after N3 and N4. The cycle program (4 statements) is called
    with the caller's statements after it counted ahead, so the run stops early but never past the limit:
    N2's group (3) and the cycle (4) ran; under 12 the group of N3 to M30 (5) is counted, the cycle after N3
    does not fit beside it (12 + 4), and the run stops at the cycle's first statement with 8 steps."""
    cycle = "10 #HOLES% = #HOLES% + 1 : #DEPTH = P1\nN1 G1 Z[P1] F100\nN2 G0 Z10\n"
    main = "1 #HOLES% = 0\nN1 G0 X0 Y0 Z10\nN2 G81 [-5]\nN3 X10\nN4 X20\nN5 G80\nN6 X30\nM30\n"
    steps, file, line, variables = _stop(limited(main, 12, **{"99999081": cycle}))
    assert (steps, file, line, variables["#HOLES%"]) == (8, "99999081", 1, 1)
    assert limited(main, 20, **{"99999081": cycle})["steps"] == 20  # 3 + 4 + 5 + 4 + 4: the whole run fits
