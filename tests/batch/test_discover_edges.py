"""Archive edges of a batch: linked folders that loop, an empty folder, the shared state directory's token,
the external lists of CL 800 named with an extension (docs/batch.md "Which files run")."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

GOOD_DIN = "N10 G90 G0 X0 Y0 Z10\nN20 G1 X20 F300\nM30\n"


def ncvm(*args: str, cwd: Path) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "ncvm", *args], cwd=cwd, capture_output=True, text=True,
                          timeout=300, stdin=subprocess.DEVNULL)


def test_a_link_back_to_an_enclosing_folder_is_entered_once(tmp_path):
    """A link to the archive's own folder (a loop) does not make the batch run forever nor twice."""
    (tmp_path / "archive" / "cell").mkdir(parents=True)
    (tmp_path / "archive" / "cell" / "part.din").write_text(GOOD_DIN)
    (tmp_path / "archive" / "cell" / "up").symlink_to(tmp_path / "archive", target_is_directory=True)
    r = ncvm("run", "archive", "--jobs", "1", "--state", "st", "--json", cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    assert [p["path"] for p in json.loads(r.stdout)["programs"]] == ["archive/cell/part.din"]


def test_an_empty_folder_says_no_programs_found(tmp_path):
    (tmp_path / "empty").mkdir()
    (tmp_path / "empty" / "notes.txt").write_text("nothing to run\n")
    for command in ("run", "check"):
        r = ncvm(command, "empty", cwd=tmp_path)
        assert r.returncode == 0, r.stderr
        assert "no programs found in empty" in r.stderr, (command, r.stderr)


def test_the_shared_state_token_is_removed_after_the_batch(tmp_path):
    """--shared-state writes a token file the runs look for; the state directory keeps only the runs' data."""
    (tmp_path / "parts").mkdir()
    (tmp_path / "parts" / "count.cpl").write_text("10 IF @1 = NUL THEN @1 = 0 ENDIF\n20 @1 = @1 + 1\nM30\n")
    r = ncvm("run", "parts", "--jobs", "1", "--shared-state", "--state", "st", "--json", cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    assert json.loads(r.stdout)["programs"][0]["error"] is None
    assert not [p.name for p in (tmp_path / "st").iterdir() if p.name.startswith("batch-token-")]


def test_a_missing_main_program_of_main_txt_is_listed_with_the_reason(tmp_path):
    (tmp_path / "cell").mkdir()
    (tmp_path / "cell" / "main.txt").write_text("flange.din\npocket.din\n")
    (tmp_path / "cell" / "flange.din").write_text(GOOD_DIN)
    r = ncvm("run", "cell", "--jobs", "1", "--state", "st", "--json", cwd=tmp_path)
    skipped = {s["path"]: s["reason"] for s in json.loads(r.stdout)["skipped"]}
    assert "there is no such file" in skipped["cell/pocket.din"]


def test_a_task_carries_relative_paths_inside_its_folders_only(tmp_path):
    """A relative path a program names travels with its task (an include of a sub-folder), never a file
    outside the program's search folders (`../`): a cluster task carries the archive's files alone."""
    from ncvm.archive.discover import discover
    from ncvm.archive.tasks import Settings, TaskBuilder

    (tmp_path / "secret.txt").write_text("not for the workers\n")
    robot = tmp_path / "robot"
    (robot / "lib").mkdir(parents=True)
    (robot / "lib" / "speeds.inc").write_text("const feed = 80.0;\n")
    (robot / "move.sap").write_text("program Move;\n{! lib/speeds.inc}\n{ see ../secret.txt }\nbegin\nend.\n")
    program = discover([str(robot / "move.sap")]).programs[0]
    task = TaskBuilder(Settings(max_steps=1000), base=tmp_path).task(0, program)
    assert str(robot / "lib" / "speeds.inc") in task.files
    assert not [name for name, data in task.files.items() if b"not for the workers" in data]


def test_a_cl800_external_list_with_an_extension_is_checked_not_run(tmp_path):
    """An external list named `.cl8` (after a comment) is data: `check` checks it, `run` lists it as skipped."""
    (tmp_path / "cl800").mkdir()
    (tmp_path / "cl800" / "cenlst.cl8").write_text(
        "(* central data *)\nEXTERNAL 40;\nCHANNEL NC 0;\nID (0-CENLST-23.11.26-NCV);\n"
        "CENTRAL REAL: R900:=load_1;\nENDEXTERN\n")
    (tmp_path / "cl800" / "ok.din").write_text(GOOD_DIN)
    r = ncvm("run", "cl800", "--jobs", "1", "--state", "st", "--json", cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    assert "external list" in {s["path"]: s["reason"] for s in json.loads(r.stdout)["skipped"]}["cl800/cenlst.cl8"]
    checked = ncvm("check", "cl800", "--json", cwd=tmp_path)
    assert "cl800/cenlst.cl8" in {f["file"] for f in json.loads(checked.stdout)["files"]}, checked.stderr
