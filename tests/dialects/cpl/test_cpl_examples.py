"""The example programs in examples/cpl run and do what they say."""

from __future__ import annotations

from pathlib import Path

from ncvm.api import run
from ncvm.runtime.session import RunOptions

EXAMPLES = Path(__file__).parents[3] / "examples" / "cpl"
MACHINE = EXAMPLES / "machine.toml"


def run_example(name: str, state: Path) -> dict:
    result, _ = run(EXAMPLES / name, machine=MACHINE, options=RunOptions(state_dir=state))
    assert result["status"] == "ok", result["error"]
    return result


def test_flange_drills_two_bolt_circles(tmp_path):
    r = run_example("flange.cpl", tmp_path)
    assert r["output"] == ["FLANGE: 14 holes drilled"]
    assert r["motion"]["feed_moves"] == 14
    assert r["motion"]["bounds"]["Z"][0] == -12.0
    # the first hole of the outer circle sits at 22.5 degrees on radius 70
    assert max(r["motion"]["bounds"]["X"]) < 70.0 and min(r["motion"]["bounds"]["X"]) > -70.0


def test_pocket_steps_down_to_depth(tmp_path):
    r = run_example("pocket.cpl", tmp_path)
    assert r["output"] == ["POCKET: 5 depth passes"]
    assert r["motion"]["bounds"]["Z"][0] == -12.0
    assert r["motion"]["bounds"]["X"] == [-35.0, 35.0]
    assert r["motion"]["bounds"]["Y"] == [-20.0, 20.0]


def test_partcount_counts_across_runs(tmp_path):
    outputs = [run_example("partcount.cpl", tmp_path)["output"] for _ in range(6)]
    assert outputs[0] == ["PART 1 OF 5; slot length cut so far 30.0 mm"]
    assert outputs[4][-1] == "BATCH COMPLETE: change the pallet"
    assert outputs[5] == ["PART 1 OF 5; slot length cut so far 180.0 mm"]
