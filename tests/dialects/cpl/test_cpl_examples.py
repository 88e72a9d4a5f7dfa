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


def test_measlog_writes_and_reads_back_its_log(tmp_path):
    from ncvm.machine.config import load_machine

    machine = load_machine(MACHINE)
    machine.file_root = tmp_path / "files"
    machine.file_root.mkdir()
    for _ in range(2):  # a second run starts the log anew
        result, _ = run(EXAMPLES / "measlog.cpl", machine=machine, options=RunOptions(state_dir=tmp_path))
        assert result["status"] == "ok", result["error"]
    records = (machine.file_root / "PMEASLOG").read_text(encoding="latin-1").split("\n")
    assert records[0] == "BORE     X        Y       DIAMETER"
    assert records[1] == " 1   -50.000    8.660  12.0290"  # D = 12 + 0.03 sin 75
    assert records[7:] == ["\x03", ""]
    assert result["output"][-1] == "LOG: 6 bores, mean D=12.0058, max deviation 0.0300, 4 rejected"
    assert result["output"][:4] == ["BORE  1 OUT OF TOLERANCE: D=12.0290", "BORE  3 OUT OF TOLERANCE: D=11.9788",
                                    "BORE  4 OUT OF TOLERANCE: D=11.9740", "BORE  6 OUT OF TOLERANCE: D=12.0300"]
