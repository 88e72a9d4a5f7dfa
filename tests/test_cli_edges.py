"""Command-line edges a script meets: outputs into the state directory or onto stdout, outputs that
fail while they are written, ``--json`` before the command, Ctrl-C outside the run, and the machine
file of the program's folder. Real processes where a real stdout or signal matters."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest
from click.testing import CliRunner

from ncvm import cli
from tests.runtime.ctrl_c import ctrl_c

PROGRAM = "(MSG, roughing)\nG17 G90 G0 X10 Y0\nG1 X20 F600\nM2\n"
NCVM = [sys.executable, "-c", "from ncvm.cli import main; main()"]


def invoke(*args):
    return CliRunner().invoke(cli.cli, [str(a) for a in args], catch_exceptions=False)


@pytest.fixture
def work(tmp_path, monkeypatch) -> Path:
    monkeypatch.chdir(tmp_path)
    (tmp_path / "part.din").write_text(PROGRAM)
    return tmp_path


def ncvm(*args, **kw) -> subprocess.CompletedProcess:
    return subprocess.run([*NCVM, *map(str, args)], capture_output=True, text=True, timeout=120, **kw)


def usage_document(stdout: str) -> dict:
    doc = json.loads(stdout)
    assert doc["status"] == "usage_error", doc
    return doc


# -- the state directory is the controller's memory: no output goes into it --------------------------

@pytest.mark.parametrize("option, name", [("--gcode", "store.sqlite"), ("--trace", "lock"),
                                          ("--plot", "store.png"), ("--screen", "s.png")])
def test_an_output_into_the_state_directory_is_refused_and_the_store_kept(work, option, name):
    state = work / "st"
    state.mkdir()
    store = state / "store.sqlite"
    store.write_bytes(b"SQLite format 3\x00 the permanent values")
    r = invoke("run", "part.din", "--state", "st", "--json", option, f"st/{name}")
    assert r.exit_code == 2, r.output
    assert f"{option} st/{name}: is inside the state directory st" in r.stderr
    assert "roughing" not in r.stdout
    usage_document(r.stdout)
    assert store.read_bytes() == b"SQLite format 3\x00 the permanent values"


def test_the_state_directory_is_found_through_a_symlink_and_the_default_name(work):
    (work / ".ncvm").mkdir()
    os.symlink(".ncvm", "alias")
    r = invoke("run", "part.din", "--gcode", "alias/store.sqlite")
    assert r.exit_code == 2 and "is inside the state directory .ncvm" in r.stderr, r.output
    r = invoke("run", "part.din", "--screen-dir", ".ncvm/shots")
    assert r.exit_code == 2 and "--screen-dir .ncvm/shots: is inside the state directory .ncvm" in r.stderr
    r = invoke("run", "part.din", "--screen-dir", ".ncvm")
    assert r.exit_code == 2 and "is inside the state directory" in r.stderr


# -- stdout as an output ------------------------------------------------------------------------------

def test_dev_stdout_into_a_pipe_takes_the_gcode(work):
    r = ncvm("run", "part.din", "--gcode", "/dev/stdout")
    assert r.returncode == 0, r.stderr
    assert "G1 X20" in r.stdout and "roughing" in r.stdout


def test_with_json_no_output_may_go_to_stdout(work):
    r = ncvm("run", "part.din", "--json", "--gcode", "/dev/stdout")
    assert r.returncode == 2, r.stderr
    assert "--gcode /dev/stdout: is stdout, which carries the JSON document" in r.stderr
    usage_document(r.stdout)
    with open(work / "out.json", "w") as f:  # stdout redirected into the file the trace would write
        p = subprocess.run([*NCVM, "run", "part.din", "--json", "--trace", "out.json"], stdout=f,
                           stderr=subprocess.PIPE, text=True, timeout=120)
    assert p.returncode == 2, p.stderr
    usage_document((work / "out.json").read_text())


# -- an output that fails while it is written ---------------------------------------------------------

@pytest.mark.parametrize("option, name", [("--trace", "t.jsonl"), ("--gcode", "g.ngc"), ("--plot", "p.png")])
def test_a_full_disk_under_an_output_is_a_usage_error_not_a_bug(work, option, name):
    os.symlink("/dev/full", name)  # every write fails with ENOSPC
    r = ncvm("run", "part.din", "--json", option, name)
    assert r.returncode == 2, r.stderr
    assert "internal error" not in r.stderr and "Traceback" not in r.stderr
    assert f"{name}: cannot write: No space left on device" in r.stderr
    usage_document(r.stdout)


# -- --json before the command ------------------------------------------------------------------------

@pytest.mark.parametrize("args", [["--json", "run", "part.din"], ["--json"], ["--version", "--json"],
                                  ["--json", "check", "part.din"]])
def test_json_before_the_command_is_a_json_usage_error(work, args):
    r = invoke(*args)
    assert r.exit_code == 2, r.output
    doc = usage_document(r.stdout)
    assert "--json goes after the command" in doc["error"]["message"]


# -- Ctrl-C outside the run itself --------------------------------------------------------------------

@pytest.mark.parametrize("command", ["run", "check"])
def test_ctrl_c_outside_the_run_gives_a_json_document_naming_the_command(work, monkeypatch, command):
    def interrupted(*a, **k):
        raise KeyboardInterrupt

    monkeypatch.setattr(f"ncvm.api.{command}", interrupted)
    r = invoke(command, "part.din", "--json")
    assert r.exit_code == 1, r.output
    doc = json.loads(r.stdout)
    assert doc["status"] == "error" and doc["error"]["code"] == "RUN004"
    assert doc["error"]["message"] == f"{command} interrupted by the user"
    assert "interrupted" in r.stderr and "Aborted" not in r.stderr


def test_ctrl_c_during_a_long_run_gives_the_result_document(work):
    (work / "spin.cpl").write_text("10 A = 0\n20 WHILE A < 2000000000 DO\n30 A = A + 1\n40 END\n")
    p = subprocess.Popen([*NCVM, "run", "spin.cpl", "--json"], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                         text=True)
    out, err = ctrl_c(p, settle=3, timeout=60)
    assert p.returncode == 1, err
    assert json.loads(out)["error"]["code"] == "RUN004"


# -- the machine file of the program's folder: run and check agree ------------------------------------

LATHE = """[machine]
name = "lathe"
[[axis]]
name = "X"
min = -100.0
max = 100.0
rapid = 5000.0
max_feed = 2000.0
accel = 500.0
[[axis]]
name = "Z"
min = -100.0
max = 100.0
rapid = 5000.0
max_feed = 2000.0
accel = 500.0
"""


def test_run_uses_the_machine_file_of_the_programs_folder_like_check(work):
    (work / "cell").mkdir()
    (work / "cell" / "machine.toml").write_text(LATHE)
    (work / "cell" / "turn.din").write_text("N10 G0 X10 Z5\nN20 G1 Y3 F100\nN30 M30\n")
    checked = invoke("check", "cell/turn.din")
    ran = invoke("run", "cell/turn.din", "--state", "st")
    assert checked.exit_code == ran.exit_code == 1, (checked.output, ran.output)
    assert "NC011" in checked.stderr and "NC011" in ran.stderr
    assert "ncvm: machine file cell/machine.toml (the program's folder)" in ran.stderr
    given = invoke("run", "cell/turn.din", "--state", "st", "--machine", "cell/machine.toml")
    assert "the program's folder" not in given.stderr


# -- a dwell's X is a time, not an axis ---------------------------------------------------------------

@pytest.mark.parametrize("name, text", [
    ("dwell.din", "N10 G0 Z5\nN20 G4 X2\nN30 M30\n"),
    ("dwell.cpl", "N10 G0 Z5\nN20 G4 X2\nN30 M30\n"),
    ("dwell.mpf", "%MPF5\nN10 G0 Z5\nN20 G4 X2\nN30 M30\n"),
])
def test_the_dwell_time_x_on_a_machine_without_x_is_no_axis_word(work, name, text):
    (work / "machine.toml").write_text(LATHE.replace('"X"', '"Y"'))
    (work / name).write_text(text)
    assert invoke("check", name).exit_code == 0
    r = invoke("run", name, "--state", "st", "--json")
    assert r.exit_code == 0, r.stdout
    assert json.loads(r.stdout)["cycle_time_s"] >= 2.0


# -- a key script on a pipe is read once ---------------------------------------------------------------

def test_a_key_script_from_a_pipe_reaches_the_dialog(work):
    examples = Path(__file__).parents[1] / "examples" / "cpl"
    keys = (examples / "flangedlg.keys").read_text()
    r = ncvm("run", examples / "flangedlg.cpl", "--keys", "/dev/stdin", "--state", "st", input=keys)
    assert r.returncode == 0, r.stderr
    assert "FLANGE: 8 holes" in r.stdout


# -- compile's outputs ---------------------------------------------------------------------------------

CL800 = Path(__file__).parents[1] / "examples" / "cl800" / "hole_pattern.cl8"


@pytest.mark.parametrize("args", [["-o", "full.spf"], ["-o", "l.spf", "--xref", "full.spf"]])
def test_compile_onto_a_full_disk_is_a_usage_error(work, args):
    os.symlink("/dev/full", "full.spf")
    r = ncvm("compile", CL800, *args)
    assert r.returncode == 2, r.stderr
    assert "full.spf: cannot write: No space left on device" in r.stderr and "internal error" not in r.stderr


def test_compile_writes_nothing_into_the_default_state_directory(work):
    (work / ".ncvm").mkdir()
    (work / ".ncvm" / "store.sqlite").write_bytes(b"kept")
    r = invoke("compile", CL800, "-o", ".ncvm/store.sqlite")
    assert r.exit_code == 2 and "is inside the state directory .ncvm" in r.stderr, r.output
    assert (work / ".ncvm" / "store.sqlite").read_bytes() == b"kept"


# -- what the messages name ----------------------------------------------------------------------------

def test_messages_name_what_the_user_gave(work):
    os.symlink("nowhere/x.ngc", "dangling.ngc")
    r = invoke("run", "part.din", "--gcode", "dangling.ngc")
    assert r.exit_code == 2 and "--gcode dangling.ngc: folder" in r.stderr and "nowhere does not exist" in r.stderr
    os.mkfifo("pipe.din")
    r = invoke("run", "pipe.din")  # refused before the pipe is opened: no writer, and nothing hangs
    assert r.exit_code == 2 and "pipe.din: a program from a pipe needs its dialect named (-d din)" in r.stderr
    r = invoke("run", "pipe.din", "-d", "cpl")
    assert r.exit_code == 2 and "pipe.din: a program from a pipe is read by dialect din only; a cpl" in r.stderr
    r = invoke("compile", "pipe.din")  # compile reads files only
    assert r.exit_code == 2 and "pipe.din: not a file" in r.stderr, r.stderr
    (work / "machine.toml").write_text(LATHE)
    r = invoke("run", "part.din", "--gcode", "machine.toml")
    assert r.exit_code == 2 and "--gcode machine.toml: it would overwrite the machine file machine.toml" in r.stderr
    assert LATHE == (work / "machine.toml").read_text()


# -- check and run point at the same word ------------------------------------------------------------

@pytest.mark.parametrize("name, text, column", [
    ("col.cpl", "N10 G0 X1\n   N20 G1 Y2 B5 F100\n", 14),
    ("col.mpf", "%MPF6\nN10 G0 X1\nN20 G1 Y2 C5 F100\n", 11),
])
def test_run_reports_a_missing_axis_at_the_column_check_shows(work, name, text, column):
    (work / name).write_text(text)
    checked = invoke("check", name, "--json")
    ran = invoke("run", name, "--json", "--state", "st")
    where = json.loads(checked.stdout)["files"][0]["diagnostics"][0]
    error = json.loads(ran.stdout)["error"]
    assert (error["line"], error["column"]) == (where["line"], where["column"]) == (where["line"], column)


# -- a sub-program is an input too --------------------------------------------------------------------

def test_an_output_onto_a_sub_program_is_refused_before_the_run(work):
    examples = Path(__file__).parents[1] / "examples" / "cpl"
    for name in ("flange.cpl", "BOLTCIRC", "machine.toml"):
        (work / name).write_bytes((examples / name).read_bytes())
    source = (work / "BOLTCIRC").read_bytes()
    r = invoke("run", "flange.cpl", "--gcode", "BOLTCIRC", "--state", "st")
    assert r.exit_code == 2, r.output
    assert "--gcode BOLTCIRC: would overwrite a program the run may call as a sub-program" in r.stderr
    assert (work / "BOLTCIRC").read_bytes() == source
    for _ in range(2):  # the flat G-code of the last run is written again
        r = invoke("run", "flange.cpl", "--gcode", "flange.ngc", "--state", "st")
        assert r.exit_code == 0 and "FLANGE: 14 holes drilled" in r.stdout, r.output


def test_an_output_into_the_controllers_file_root_is_refused(work):
    (work / "machine.toml").write_text(LATHE + '[paths]\nfile_root = "ctl"\n')
    (work / "ctl").mkdir()
    r = invoke("run", "part.din", "--trace", "ctl/LOG.TXT", "--state", "st")
    assert r.exit_code == 2, r.output
    assert "--trace ctl/LOG.TXT: is inside the controller's file root" in r.stderr
