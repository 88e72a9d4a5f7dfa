"""rw_SymPas cases: the arithmetic loop and 100,000 linear moves on the simulated card, plus rs274 peers."""

from __future__ import annotations

from benchlib import HERE, PEERS, WORK, Case, rs274_case

from ncvm.api import run
from ncvm.runtime.session import RunOptions

ARITH = HERE / "sympas" / "loop_arith.sap"
MOTION = HERE / "sympas" / "motion.sap"


def _runner(path):
    def go() -> None:
        result, _ = run(path, dialect="sympas", options=RunOptions(state_dir=WORK / ".ncvm"))
        assert result["status"] == "ok", result["error"]

    return go


def cases() -> dict[str, Case]:
    return {
        "sympas_loop_arith": Case(_runner(ARITH), 100_000, "iterations/s"),
        "sympas_motion": Case(_runner(MOTION), 100_000, "moves/s"),
        "rs274_sympas_loop_arith": rs274_case(PEERS / "loop_arith.ngc", 100_000, "iterations/s"),
        "rs274_sympas_loop_motion": rs274_case(PEERS / "loop_motion.ngc", 100_000, "moves/s"),
    }
