"""DIN cases: din_flat_50k, the 50,000-block plain program of the peer set, through ncvm and rs274; and
din_collinear_1000, 1,000 collinear 1 mm blocks at F3000, which prints its cycle time under the look-ahead
planner and the rest-to-rest model (issue 18: 20.05 s ± 2 % in continuous-path mode)."""

from __future__ import annotations

import subprocess
import sys

from benchlib import PEERS, WORK, Case, rs274_case

from ncvm.api import run
from ncvm.runtime.session import RunOptions

FLAT = WORK / "flat_50k.ngc"
LINES = 50_000


def make_flat() -> None:
    WORK.mkdir(exist_ok=True)
    if not FLAT.exists():
        subprocess.run([sys.executable, str(PEERS / "gen_flat.py"), "-n", str(LINES), "-o", str(FLAT)], check=True)


def run_flat() -> None:
    result, _ = run(FLAT, dialect="din", options=RunOptions(state_dir=WORK / ".ncvm"))
    assert result["status"] == "ok", result["error"]


COLLINEAR = WORK / "collinear_1000.ngc"
COLLINEAR_GOAL = 20.05  # s: 1,000 mm at 50 mm/s and one ramp up and down at 1,000 mm/s² (the default mill)


def make_collinear() -> None:
    WORK.mkdir(exist_ok=True)
    # from X0 to X1000 (past the default mill's soft limit, which only warns): no positioning move first
    COLLINEAR.write_text("\n".join(["G21 G90 G94 G64 F3000"] + [f"G1 X{i}" for i in range(1, 1001)] + ["M2"]) + "\n")


def collinear_figures() -> dict:
    """The cycle time under the look-ahead planner and the rest-to-rest model (figures of the JSON too)."""
    figures = {"cycle_time_goal_s": COLLINEAR_GOAL}
    for model, key in (("lookahead", "cycle_time_s"), ("rest-to-rest", "cycle_time_rest_to_rest_s")):
        result = collinear(model)
        figures[key] = result["cycle_time_s"]
        print(f"  din_collinear_1000: cycle time {result['cycle_time_s']:.3f} s ({result['cycle_time_model']}; "
              f"goal {COLLINEAR_GOAL} s ± 2 % in continuous-path mode)", flush=True)
    return figures


def collinear(model: str) -> dict:
    result, _ = run(COLLINEAR, dialect="din", options=RunOptions(state_dir=WORK / ".ncvm", time_model=model))
    assert result["status"] == "ok", result["error"]
    return result


def run_collinear() -> None:
    """The measured run; it returns nothing, since run.measure takes returned figures for a whole-process case's."""
    collinear("lookahead")


def cases() -> dict[str, Case]:
    return {
        "din_flat_50k": Case(run_flat, LINES, "lines/s", setup=make_flat),
        "din_collinear_1000": Case(run_collinear, 1000, "lines/s", setup=make_collinear,
                                   figures=collinear_figures),
        "rs274_din_flat_50k": rs274_case(FLAT, LINES, "lines/s", setup=make_flat),
    }
