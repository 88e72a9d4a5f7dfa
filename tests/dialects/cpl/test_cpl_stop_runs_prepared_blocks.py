"""A CPL run that stops keeps the moves it prepared before the stop (docs/decisions.md, "A run that stops").

Block preparation runs ahead of execution (CPL manual §4.1, L1190): the NC blocks before a faulting CPL
statement were transferred to the block buffer and the control executes them; the RUNTIME ERROR is reported
after them. Before, a run that stopped dropped them: the manual's kind of program reported 0 moves at X0.

Hand counts on a machine whose axes accelerate at 1000 mm/s^2: at F600 (10 mm/s) a ramp takes 0.01 s and
0.05 mm, so n collinear 10 mm blocks in continuous path (G62, the power-on state) take n + 0.01 s, and
from rest to rest n * 1.01 s.
"""

from __future__ import annotations

import json
import random
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from ncvm.dialects.cpl.runtime import BLOCK_BUFFER
from ncvm.machine.config import machine_from_dict

MOVES3 = "N1 G1 X10 F600\nN2 G1 X20\nN3 G1 X30\n"
SAME = ("motion", "position", "cycle_time_s", "limit_violations")


def machine(tmp_path: Path, **cpl):
    axis = {"min": -1000.0, "max": 1000.0, "rapid": 60000.0, "max_feed": 60000.0, "accel": 1000.0}
    data = {"axis": [{"name": n, **axis} for n in "XYZ"], "paths": {"program_path": ["."], "file_root": "files"}}
    if cpl:
        data["cpl"] = cpl
    return machine_from_dict(data, "<test>", tmp_path)


@pytest.fixture
def cpl(tmp_path, run_text):
    """cpl(text, **options) -> the result of the CPL program ``text`` on the 1000 mm/s^2 machine."""
    def go(text: str, cpl_section: dict | None = None, **options):
        return run_text(text, name="p.cpl", machine=machine(tmp_path, **(cpl_section or {})), **options)

    return go


def stopped(r: dict, code: str, line: int) -> None:
    assert r["status"] == "error" and (r["error"]["code"], r["error"]["line"]) == (code, line), r["error"]


def test_the_three_moves_before_a_runtime_error_are_executed_manual_L1190(cpl):
    """The program of the finding: CPL021 at line 4 (right), after N1-N3 moved X to 30 (was: 0 moves, X0)."""
    r = cpl(MOVES3 + "40 A%=2.5\nN4 M30\n")
    stopped(r, "CPL021", 4)
    assert r["motion"]["feed_moves"] == 3 and r["motion"]["feed_length"] == pytest.approx(30.0)
    assert r["motion"]["bounds_program"]["X"] == [10.0, 30.0]
    assert r["position"]["X"] == 30.0
    assert r["cycle_time_s"] == pytest.approx(3.01)  # 30 mm at 10 mm/s, one ramp up and one down


def test_rest_to_rest_times_each_prepared_block(cpl):
    r = cpl(MOVES3 + "40 A%=2.5\nN4 M30\n", time_model="rest-to-rest")
    stopped(r, "CPL021", 4)
    assert r["cycle_time_s"] == pytest.approx(3 * 1.01)


def test_a_file_error_keeps_the_moves_before_it(cpl):
    """OPENR of a file that is not there: FILE DOES NOT EXIST after the three moves."""
    r = cpl(MOVES3 + '40 OPENR(1,"NOSUCH")\nN4 M30\n')
    stopped(r, "CPL612", 4)
    assert r["motion"]["feed_moves"] == 3 and r["position"]["X"] == 30.0
    assert r["cycle_time_s"] == pytest.approx(3.01)


def test_the_step_limit_keeps_the_moves_of_the_statements_that_ran(cpl):
    """A loop of 1 mm G1 blocks: FOR counts 1 step, each pass N20 and NEXT 2, so 101 steps prepare 50
    blocks; the 51st N20 is refused with RUN001 (was: 0 moves)."""
    r = cpl("10 FOR I%=1 TO 10000\nN20 G1 X[I%] F600\n30 NEXT I%\nM30\n", max_steps=101)
    stopped(r, "RUN001", 2)
    assert r["steps"] == 101
    assert r["motion"]["feed_moves"] == 50 and r["motion"]["feed_length"] == pytest.approx(50.0)
    assert r["position"]["X"] == 50.0
    assert r["cycle_time_s"] == pytest.approx(5.01)


def test_a_loop_of_ten_thousand_moves_under_the_step_limit_of_the_finding(cpl):
    """The finding's loop: 10,000 G1 blocks under --max-steps 30001 reported 0 moves. Three steps a pass
    (N20, J%, NEXT) and FOR: 30,001 steps prepare all 10,000 blocks, M30 is the step past the limit."""
    r = cpl("10 FOR I%=1 TO 10000\nN20 G1 X[I% * 0.01] F600\n25 J% = I%\n30 NEXT I%\nM30\n", max_steps=30001)
    stopped(r, "RUN001", 5)
    assert r["motion"]["feed_moves"] == 10_000 and r["position"]["X"] == pytest.approx(100.0)
    assert r["cycle_time_s"] == pytest.approx(10.01)


def test_a_fault_of_a_prepared_block_comes_first_in_the_program(cpl):
    """N3 cannot be executed (G2 without centre, NC003): the fault of line 4 comes later in the program.
    The run stops at N3 after N1 and N2."""
    r = cpl("N1 G1 X10 F600\nN2 G1 X20\nN3 G2 X30\n40 A%=2.5\nN4 M30\n")
    stopped(r, "NC003", 3)
    assert r["motion"]["feed_moves"] == 2 and r["motion"]["arc_moves"] == 0
    assert r["position"]["X"] == 20.0 and r["cycle_time_s"] == pytest.approx(2.01)


def test_blocks_after_a_faulting_block_never_execute(cpl):
    """N4 waits in the buffer behind N3, which faults: execution stops at N3, N4 is not executed."""
    r = cpl("N1 G1 X10 F600\nN2 G1 X20\nN3 G2 X30\nN4 G1 X40\n50 A%=2.5\nM30\n")
    stopped(r, "NC003", 3)
    assert r["motion"]["feed_moves"] == 2 and r["position"]["X"] == 20.0


def test_a_fault_in_the_half_of_a_full_buffer_that_executes_drops_the_blocks_behind_it(cpl):
    """BLOCK_BUFFER blocks fill the buffer and its older half executes; block 100 of them faults (G2 without
    a centre): the 99 blocks before it ran, none after it, also when the program's stop drains the buffer."""
    n = BLOCK_BUFFER + 5
    r = cpl(f"10 FOR I%=1 TO {n}\n20 IF I% = 100 THEN\nN21 G2 X[I%] F600\n22 ELSE\nN23 G1 X[I%] F600\n"
            "24 ENDIF\n30 NEXT I%\n40 A%=2.5\nM30\n")
    stopped(r, "NC003", 3)
    assert r["motion"]["feed_moves"] == 99 and r["position"]["X"] == 99.0


def test_more_blocks_than_the_buffer_holds_all_run_before_the_error(cpl):
    """The buffer ran over (its older half executed while preparing); the newer half runs at the stop."""
    n = BLOCK_BUFFER + 5
    r = cpl(f"10 FOR I%=1 TO {n}\nN20 G1 X[I% * 0.001] F600\n30 NEXT I%\n40 A%=2.5\nM30\n")
    stopped(r, "CPL021", 4)
    assert r["motion"]["feed_moves"] == n and r["position"]["X"] == pytest.approx(n * 0.001)


def test_a_configured_lookahead_keeps_the_waiting_blocks(cpl):
    """[cpl] lookahead = 2: N1 executed when N3 was prepared, N2 and N3 wait at the error and run."""
    r = cpl(MOVES3 + "40 A%=2.5\nN4 M30\n", {"lookahead": 2})
    stopped(r, "CPL021", 4)
    assert r["motion"]["feed_moves"] == 3 and r["position"]["X"] == 30.0


def test_an_error_in_a_sub_program_keeps_the_moves_of_caller_and_callee(cpl, tmp_path):
    (tmp_path / "SUB").write_text("N1 G1 X20 F600\n20 A% = 1.5\nN2 M30\n")
    r = cpl("N1 G1 X10 F600\n10 CALL SUB\nN2 G1 X30\nM30\n")
    stopped(r, "CPL021", 2)
    assert r["error"]["file"].endswith("SUB")
    assert r["motion"]["feed_moves"] == 2 and r["position"]["X"] == 20.0
    assert r["cycle_time_s"] == pytest.approx(2.01)


def test_a_prepared_block_beyond_the_soft_limit_is_reported(cpl):
    r = cpl("N1 G1 X10 F600\nN2 G1 X1200\nN3 G1 X30\n40 A%=2.5\nM30\n")
    stopped(r, "CPL021", 4)
    assert len(r["limit_violations"]) == 1 and "X reaches 1200" in r["limit_violations"][0]


def test_the_trace_has_the_moves_the_summary_counts(cpl, tmp_path):
    trace = tmp_path / "t.jsonl"
    r = cpl(MOVES3 + "40 A%=2.5\nN4 M30\n", trace=trace)
    stopped(r, "CPL021", 4)
    feeds = [rec for rec in map(json.loads, trace.read_text().splitlines()) if rec["call"] == "feed"]
    assert [(f["line"], f["end"]["X"]) for f in feeds] == [(1, 10.0), (2, 20.0), (3, 30.0)]
    assert sum(f["time"] for f in feeds) == pytest.approx(r["cycle_time_s"])


def test_the_prepared_moves_are_those_of_the_same_program_ending_normally(cpl):
    r_end = cpl(MOVES3 + "N4 M30\n")
    r_stop = cpl(MOVES3 + "40 A%=2.5\nN4 M30\n")
    assert {k: r_stop[k] for k in SAME} == {k: r_end[k] for k in SAME}


# -- the differential property: a fault after N moves reports what the same N moves ending normally do ----------
STOPS = {"runtime error": "40 A%=2.5\n", "file error": '40 OPENR(1,"NOSUCH")\n', "NUL used": "40 B = UNSET + 1\n"}


def _program(moves: list[tuple[int, float, float]]) -> str:
    words = {0: "G0", 1: "G1"}
    return "".join(f"N{i + 1} {words[g]} X{x:.3f} Y{y:.3f} F{1000 + 100 * i}\n" for i, (g, x, y) in enumerate(moves))


MOVE = st.tuples(st.sampled_from([0, 1]), st.floats(-500, 500, allow_nan=False), st.floats(-500, 500, allow_nan=False))


@settings(max_examples=15, deadline=None)
@given(moves=st.lists(MOVE, max_size=12), stop=st.sampled_from(sorted(STOPS)), lookahead=st.sampled_from([0, 1, 4]))
def test_a_fault_after_n_moves_reports_the_motion_of_the_n_moves_ending_normally(tmp_path_factory, moves, stop,
                                                                                 lookahead):
    from ncvm.api import run
    from ncvm.runtime.session import RunOptions

    folder = tmp_path_factory.mktemp("stop")
    text = _program(moves)
    results = []
    for name, tail in (("end.cpl", "M30\n"), ("stop.cpl", STOPS[stop] + "M30\n")):
        (folder / name).write_text(text + tail)
        m = machine(folder, **({"lookahead": lookahead} if lookahead else {}))  # a machine keeps its clock
        results.append(run(folder / name, machine=m, options=RunOptions(state_dir=folder / ".ncvm"))[0])
    r_end, r_stop = results
    assert r_end["status"] == "ok" and r_stop["status"] == "error"
    assert r_stop["error"]["line"] == len(moves) + 1
    assert {k: r_stop[k] for k in SAME} == {k: r_end[k] for k in SAME}


def test_a_long_random_loop_stopped_by_the_step_limit_matches_its_prefix(cpl):
    """Stopped by RUN001 in a loop over a table of moves: the moves of the passes that ran, ending normally.
    A pass is 3 steps (N20, K%, NEXT; FOR 1 more), so 3 * k + 1 steps run k passes and refuse the next N20."""
    rnd = random.Random(18)
    moves = [(rnd.uniform(-400, 400), rnd.uniform(-400, 400)) for _ in range(300)]
    table = "".join(f"{i + 1} XS({i + 1}) = {x:.3f} : YS({i + 1}) = {y:.3f}\n" for i, (x, y) in enumerate(moves))
    loop = "0 DIM XS(300), YS(300)\n{}500 FOR I%=1 TO {}\nN20 G1 X[XS(I%)] Y[YS(I%)] F900\n25 K% = I%\n30 NEXT I%\nM30\n"
    setup = 1 + 2 * len(moves)  # DIM and the table's assignments
    k = 217
    r_stop = cpl(loop.format(table, len(moves)), max_steps=setup + 3 * k + 1)
    r_end = cpl(loop.format(table, k))
    stopped(r_stop, "RUN001", len(moves) + 3)
    assert r_stop["steps"] == setup + 3 * k + 1 and r_stop["motion"]["feed_moves"] == k
    assert {key: r_stop[key] for key in SAME} == {key: r_end[key] for key in SAME}


def test_a_sub_program_that_does_not_compile_when_first_called_keeps_the_moves_before(tmp_path, cpl):
    """EXCL is excluded from linking (CALL ... DIN, §3.3) and calls SUBX by M66: SUBX is linked when first
    called and does not compile (CPL004). N1 and EXCL's N10 ran before it."""
    (tmp_path / "EXCL").write_text("N10 G1 X20\nN20 M66\nM30\n")
    (tmp_path / "SUBX").write_text("10 IF X > 1 THEN\n")
    r = cpl("N1 G1 X10 F600\n10 CALL EXCL DIN\nM30\n", {"calls": {"M66": "SUBX"}})
    assert r["error"]["code"] == "CPL004" and r["error"]["file"].endswith("SUBX")
    assert r["motion"]["feed_moves"] == 2 and r["position"]["X"] == 20.0
    assert r["cycle_time_s"] == pytest.approx(2.01)
