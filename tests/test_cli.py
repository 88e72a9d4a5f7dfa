"""The CLI contract: exit codes, the JSON document of ``run --json``, diagnostics with a caret."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest
from click.testing import CliRunner

from ncvm import __version__, cli

PROGRAM = "(MSG, roughing)\nG17 G90 G0 X10 Y0\nG1 X20 F600\nG3 X10 Y10 R10\nM2\n"


@pytest.fixture
def invoke(tmp_path):
    def _invoke(*args: str):
        runner = CliRunner()
        return runner.invoke(cli.cli, [*args], catch_exceptions=False)

    return _invoke


@pytest.fixture
def prog(tmp_path) -> Path:
    p = tmp_path / "part.din"
    p.write_text(PROGRAM)
    return p


def test_run_json_is_the_documented_document(invoke, prog, tmp_path):
    r = invoke("run", str(prog), "--json", "--state", str(tmp_path / "st"))
    assert r.exit_code == 0
    doc = json.loads(r.stdout)
    assert set(doc) >= {"status", "dialect", "error", "output", "variables", "position", "motion", "cycle_time_s",
                        "steps"}
    assert doc["status"] == "ok" and doc["dialect"] == "din" and doc["error"] is None
    assert doc["output"] == ["roughing"]
    assert doc["position"] == pytest.approx({"X": 10.0, "Y": 10.0, "Z": 0.0})
    m = doc["motion"]
    assert (m["rapid_moves"], m["feed_moves"], m["arc_moves"]) == (1, 1, 1)
    assert m["rapid_length"] == pytest.approx(10.0)
    # quarter circle of radius 10 around (10, 0) from (20, 0) to (10, 10)
    assert m["feed_length"] == pytest.approx(10.0 + 3.141592653589793 * 5)
    assert m["bounds"] == {"X": pytest.approx([0.0, 20.0]), "Y": pytest.approx([0.0, 10.0]),
                           "Z": pytest.approx([0.0, 0.0])}
    assert isinstance(doc["steps"], int) and doc["steps"] == 5
    assert doc["cycle_time_s"] > 2.0  # 10 mm + 15.7 mm at 10 mm/s, plus the rapid


def test_run_without_json_prints_output_and_summary(invoke, prog, tmp_path):
    r = invoke("run", str(prog), "--state", str(tmp_path / "st"))
    assert r.exit_code == 0
    assert r.stdout == "roughing\n"
    assert "ended normally: 5 steps, 3 moves, path " in r.stderr  # rapid/feed/arc counts in --json


def test_run_fault_reports_everything_up_to_it(invoke, tmp_path):
    p = tmp_path / "bad.din"
    p.write_text("G1 X10 F100\nG3 X0 Y11 I-10 J0\n")
    r = invoke("run", str(p), "--json", "--state", str(tmp_path / "st"))
    assert r.exit_code == 1
    doc = json.loads(r.stdout)
    assert doc["status"] == "error" and doc["motion"]["feed_moves"] == 1
    assert doc["error"]["code"] == "NC002" and doc["error"]["line"] == 2 and doc["error"]["file"] == str(p)
    r = invoke("run", str(p), "--state", str(tmp_path / "st"))
    assert r.exit_code == 1 and f"{p}:2: error NC002:" in r.stderr and "G3 X0 Y11 I-10 J0" in r.stderr


def test_check_renders_file_line_col_and_caret(invoke, tmp_path):
    p = tmp_path / "bad.din"
    p.write_text("G1 X10 F100\nG1 X1 Y2 ?? \n")
    r = invoke("check", str(p))
    assert r.exit_code == 1
    lines = r.stderr.splitlines()
    assert lines[0].startswith(f"{p}:2:10: error NC001:")
    assert lines[1] == "    G1 X1 Y2 ?? "
    assert lines[2] == "    " + " " * 9 + "^"
    r = invoke("check", str(p), "--json")
    doc = json.loads(r.stdout)
    assert doc["files"][0]["ok"] is False
    assert doc["files"][0]["diagnostics"][0] | {"notes": []} == {
        "severity": "error", "code": "NC001", "message": doc["files"][0]["diagnostics"][0]["message"],
        "file": str(p), "line": 2, "column": 10, "notes": []}


def test_check_clean_program_exits_0(invoke, prog):
    r = invoke("check", str(prog))
    assert r.exit_code == 0 and "1 program(s) checked, 0 diagnostic(s)" in r.stderr


def test_check_a_whole_archive_folder(invoke, tmp_path):
    """A folder stands for every program below it (by extension); other files are left alone. The archive's
    machine.toml (X only) is the nearest one upwards of every program: part.din's Y axis is an error."""
    archive = tmp_path / "archive"
    (archive / "mill" / "old").mkdir(parents=True)
    (archive / "mill" / "part.din").write_text(PROGRAM)
    (archive / "mill" / "old" / "bad.din").write_text("G1 X1 ?\n")
    (archive / "mill" / "old" / "cycle.cpl").write_text("10 A% = 1 +\nM30\n")
    (archive / "readme.txt").write_text("not a program")
    (archive / "machine.toml").write_text("[[axis]]\nname = 'X'\n")
    r = invoke("check", str(archive))
    assert r.exit_code == 1
    assert "3 program(s) checked, 3 with errors, 4 diagnostic(s)" in r.stderr
    assert "machine (its axes: X)" in r.stderr
    doc = json.loads(invoke("check", str(archive), "--json").stdout)
    assert [(Path(f["file"]).name, f["ok"]) for f in doc["files"]] == [  # in path order
        ("bad.din", False), ("cycle.cpl", False), ("part.din", False)]
    assert {f["machine"] for f in doc["files"]} == {str(archive / "machine.toml")}
    (archive / "machine.toml").unlink()
    assert "3 program(s) checked, 2 with errors, 2 diagnostic(s)" in invoke("check", str(archive)).stderr
    r = invoke("check", str(archive / "mill" / "part.din"), str(archive / "nothing"))
    assert r.exit_code == 2 and "no such program" in r.stderr


@pytest.mark.parametrize("args, message", [
    (["run", "absent.din"], "no such program"),
    (["run", "{prog}", "--machine", "absent.toml"], "cannot read machine file"),
    (["compile", "{prog}"], "has no compiler"),
])
def test_usage_errors_exit_2(invoke, prog, tmp_path, args, message):
    r = invoke(*[a.format(prog=prog) for a in args])
    assert r.exit_code == 2 and message in r.stderr and "Traceback" not in r.stderr


def test_unknown_content_asks_for_dialect(invoke, tmp_path):
    p = tmp_path / "mystery.txt"
    p.write_text("this is no program at all\nreally not\n")
    r = invoke("run", str(p))
    assert r.exit_code == 2 and "pass --dialect" in r.stderr


def test_content_sniffing_finds_din_without_extension(invoke, tmp_path):
    p = tmp_path / "PART1"
    p.write_text(PROGRAM)
    r = invoke("run", str(p), "--json", "--state", str(tmp_path / "st"))
    assert r.exit_code == 0 and json.loads(r.stdout)["dialect"] == "din"


def test_max_steps_stops_with_file_and_line(invoke, tmp_path):
    p = tmp_path / "long.din"
    p.write_text("G1 F100\n" + "".join(f"X{i}\n" for i in range(1, 50)))
    r = invoke("run", str(p), "--json", "--max-steps", "10", "--state", str(tmp_path / "st"))
    doc = json.loads(r.stdout)
    assert r.exit_code == 1 and doc["error"]["code"] == "RUN001" and doc["error"]["line"] == 11
    assert doc["steps"] == 10 and doc["position"]["X"] == pytest.approx(9.0)


def test_internal_error_exits_70_without_traceback(invoke, prog, monkeypatch):
    import ncvm.api

    def broken(*args, **kwargs):
        raise ZeroDivisionError("a bug")

    monkeypatch.setattr(ncvm.api, "run", broken)
    monkeypatch.delenv("NCVM_DEBUG", raising=False)
    r = invoke("run", str(prog))
    assert r.exit_code == 70
    assert "internal error: ZeroDivisionError: a bug" in r.stderr and "please report" in r.stderr.lower()
    assert "Traceback" not in r.stderr


def test_version_and_console_script():
    r = subprocess.run([sys.executable, "-c", "from ncvm.cli import main; main()", "--version"],
                       capture_output=True, text=True)
    assert r.returncode == 0 and r.stdout.strip() == f"ncvm, version {__version__}"


def test_scenario_merges_into_the_machine_and_screen_needs_a_dialect_with_one(invoke, prog, tmp_path):
    scenario = tmp_path / "s.toml"
    scenario.write_text('[[scenario]]\ntime = 1\nkind = "input"\naddress = "E1.0"\nvalue = true\n')
    r = invoke("run", str(prog), "--scenario", str(scenario), "--screen", str(tmp_path / "s.png"),
               "--state", str(tmp_path / "st"))
    assert r.exit_code == 0
    assert "dialect 'din' has no operator screen" in r.stderr and not (tmp_path / "s.png").exists()
    bad = tmp_path / "bad.toml"
    bad.write_text("[[scenario]]\ntime = 'soon'\nkind = 'input'\n")
    r = invoke("run", str(prog), "--scenario", str(bad))
    assert r.exit_code == 2 and 'scenario file error: scenario[0].time = "soon": must be a number' in r.stderr


@pytest.mark.parametrize("state", ["", " "])
def test_an_empty_state_is_refused_not_taken_as_the_current_directory(invoke, prog, tmp_path, monkeypatch, state):
    monkeypatch.chdir(tmp_path)
    r = invoke("run", str(prog), "--state", state)
    assert r.exit_code == 2 and "--state is empty" in r.output
    assert not (tmp_path / "lock").exists() and not (tmp_path / "store.sqlite").exists()
