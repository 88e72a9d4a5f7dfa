"""One rule for a program's own <name>.scenario.toml and <name>.keys: ``ncvm run p`` takes them as a batch
and the API do, names them on stderr, and --scenario given on the command line wins."""

from __future__ import annotations

import json
import shutil
import subprocess
import sys
from pathlib import Path

import ncvm

NCVM = str(Path(sys.executable).parent / "ncvm")
EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def _folder(tmp_path: Path) -> Path:
    folder = tmp_path / "cpl"
    folder.mkdir()
    for name in ("measlog.cpl", "measlog.scenario.toml", "machine.toml"):
        shutil.copy(EXAMPLES / "cpl" / name, folder / name)
    return folder


def _run(tmp_path, *args):
    out = subprocess.run([NCVM, "run", *args, "--json"], cwd=tmp_path, capture_output=True, text=True, timeout=300)
    return json.loads(out.stdout), out.stderr


def test_ncvm_run_of_one_program_takes_its_scenario_as_the_api_does(tmp_path):
    _folder(tmp_path)
    doc, err = _run(tmp_path, "cpl/measlog.cpl", "--state", "s1")
    assert "scenario cpl/measlog.scenario.toml (beside the program)" in err
    api = ncvm.run(tmp_path / "cpl" / "measlog.cpl", state_dir=tmp_path / "s2")
    assert round(doc["cycle_time_s"], 6) == round(api.cycle_time_s, 6)
    assert doc["output"][-1:] == api.output[-1:]


def test_a_scenario_named_on_the_command_line_wins(tmp_path):
    folder = _folder(tmp_path)
    (folder / "none.toml").write_text("")
    own, _ = _run(tmp_path, "cpl/measlog.cpl", "--state", "s1")
    named, err = _run(tmp_path, "cpl/measlog.cpl", "--state", "s2", "--scenario", "cpl/none.toml")
    assert "beside the program" not in err
    assert named["cycle_time_s"] != own["cycle_time_s"]
