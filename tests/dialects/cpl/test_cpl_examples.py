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


def test_flangedlg_dialog_previews_and_drills(tmp_path):
    keys = EXAMPLES / "flangedlg.keys"
    result, session = run(EXAMPLES / "flangedlg.cpl", machine=MACHINE,
                          options=RunOptions(state_dir=tmp_path, keys=keys))
    assert result["status"] == "ok", result["error"]
    v = result["variables"]
    assert (v["DA"], v["DL"], v["N%"], v["DH"], v["DEPTH"]) == (140.0, 100.0, 8, 10.0, 15.0)
    assert result["output"][-1] == "FLANGE: 8 holes on D100.000 drilled"
    assert "PREVIEW" in result["output"]
    assert result["motion"]["feed_moves"] == 8
    assert result["motion"]["bounds"]["Z"][0] == -15.0
    assert max(result["motion"]["bounds"]["X"]) == 50.0  # the hole circle has radius 50
    assert session.screen is not None


def test_measlog_probes_logs_and_reads_back(tmp_path):
    """G75 with trigger points from the example's scenario, PPOS, SD(9); PRN# log; INP# and EOF report."""
    from ncvm.machine.config import load_machine

    machine = load_machine(MACHINE)
    machine.file_root = tmp_path / "files"
    machine.file_root.mkdir()
    options = RunOptions(state_dir=tmp_path, scenario=EXAMPLES / "measlog.scenario.toml")
    for _ in range(2):  # a second run starts the log anew (and the scenario is not added to the machine twice)
        result, _ = run(EXAMPLES / "measlog.cpl", machine=machine, options=options)
        assert result["status"] == "ok", result["error"]
    records = (machine.file_root / "PMEASLOG").read_text(encoding="latin-1").split("\n")
    assert records[0] == "BORE     X        Y       DIAMETER"
    # bore 1 at X-50 has D = 12 + 0.03 sin 75 = 12.02898: the 2 mm ball touches at -50 +- (D/2 - 1),
    # scenario X -44.9855 and -55.0145, so D = 10.0290 + 2
    assert records[1] == " 1   -50.000    8.660  12.0290"
    assert records[5] == " 5    30.000   -8.660  12.0078"  # 12 + 0.03 sin 375 = 12.00776
    assert records[6:] == ["\x03", ""]  # bore 6: its second touch is missing from the scenario
    assert result["output"] == ["BORE  6: PROBE NOT DEFLECTED", "BORE  1 OUT OF TOLERANCE: D=12.0290",
                                "BORE  3 OUT OF TOLERANCE: D=11.9788", "BORE  4 OUT OF TOLERANCE: D=11.9740",
                                "LOG: 5 bores, mean D=12.0009, max deviation 0.0290, 3 rejected"]


def test_measlog_without_trigger_points_measures_nothing(tmp_path):
    r = run_example("measlog.cpl", tmp_path)
    assert r["output"][-1] == "LOG: no bore measured" and len(r["output"]) == 7
