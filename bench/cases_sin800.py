"""SINUMERIK 800 cases: the peer loops (loop_arith.ngc, loop_motion.ngc) written as @ code programs, and a loop
writing a central R parameter (no peer), the cost of the permanent store."""

from __future__ import annotations

from pathlib import Path

from benchlib import PEERS, WORK, Case, rs274_case

from ncvm.api import run
from ncvm.runtime.session import RunOptions

HERE = Path(__file__).parent / "sin800"


def _runner(name: str):
    def run_once() -> None:
        result, _ = run(HERE / name, dialect="sin800", options=RunOptions(state_dir=WORK / ".ncvm"))
        assert result["status"] == "ok", result["error"]

    return run_once


def cases() -> dict[str, Case]:
    return {
        "sin800_loop_arith": Case(_runner("loop_arith.mpf"), 100_000, "iterations/s"),
        "sin800_loop_motion": Case(_runner("loop_motion.mpf"), 100_000, "G1/s"),
        # R900 is permanent: each store into it is written through to the store before the next statement
        "sin800_perm_write": Case(_runner("perm_write.mpf"), 10_000, "writes/s"),
        "rs274_sin800_loop_arith": rs274_case(PEERS / "loop_arith.ngc", 100_000, "iterations/s"),
        "rs274_sin800_loop_motion": rs274_case(PEERS / "loop_motion.ngc", 100_000, "G1/s"),
    }
