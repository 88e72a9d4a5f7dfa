"""A DIN program from a pipe: ``cat part.ngc | ncvm run -d din -`` and a named pipe (FIFO), run and checked
as from a file, named ``<stdin>`` (or the FIFO's path) in diagnostics, traces and the G-code; refused clearly
without ``-d din``, for the dialects that read files, in a batch, and where another input is stdin too."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from tests.conftest import fifo_with as fifo_at

PART = "G0 X0 Y0 Z5\nG1 Z-1 F200\nG1 X40 F600\nG2 X60 Y20 R20\nG1 Y50\nG0 Z5\nM2\n"
#: a syntax error on line 2 (check and run refuse the program before it moves)
BAD_SYNTAX = "G1 X10 F100\nG1 Y5 Q7 &\nM2\n"
#: a word for an axis the built-in mill lacks on line 3: refused when the run gets there (after two moves)
NO_B_AXIS = "G1 X10 F100\nG1 Y5\nG1 B5\nM2\n"


def ncvm(cwd: Path, *args: str, stdin: str | None = None) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "ncvm", *args], cwd=cwd, input=stdin, capture_output=True,
                          text=True, timeout=120)


def fifo_with(tmp_path: Path, text: str, name: str = "part.ngc") -> Path:
    """A FIFO in ``tmp_path`` a thread writes ``text`` to once a reader opens it."""
    return fifo_at(tmp_path / name, text)


def test_a_program_from_stdin_runs_as_from_a_file_with_every_output(tmp_path):
    (tmp_path / "part.ngc").write_text(PART)
    from_file = ncvm(tmp_path, "run", "part.ngc", "--json", "--state", "s1", "--trace", "f.jsonl", "--gcode", "f.ngc")
    piped = ncvm(tmp_path, "run", "-d", "din", "-", "--json", "--state", "s2", "--trace", "p.jsonl", "--gcode",
                 "p.ngc", "--plot", "p.svg", stdin=PART)
    assert piped.returncode == 0 and from_file.returncode == 0, piped.stderr
    result = json.loads(piped.stdout)
    assert result == json.loads(from_file.stdout)
    assert result["motion"]["feed_moves"] == 3 and result["motion"]["arc_moves"] == 1
    trace = [json.loads(line) for line in (tmp_path / "p.jsonl").read_text().splitlines()]
    assert {r["file"] for r in trace if "file" in r} == {"<stdin>"}
    assert [r["line"] for r in trace if r["call"] in ("feed", "arc")] == [2, 3, 4, 5]
    gcode, original = (tmp_path / "p.ngc").read_text(), (tmp_path / "f.ngc").read_text()
    assert gcode.startswith("(written by ncvm from <stdin> for LinuxCNC")
    assert gcode.splitlines()[1:] == original.splitlines()[1:]  # the same motion, only the name differs
    assert (tmp_path / "p.svg").read_text().lstrip().startswith("<?xml")


def test_the_summary_line_of_a_piped_run(tmp_path):
    done = ncvm(tmp_path, "run", "-d", "din", "-", "--state", "s", stdin=PART)
    assert done.returncode == 0, done.stderr
    assert "ncvm: ended normally: 7 steps, 6 moves" in done.stderr


@pytest.mark.parametrize("command", ["run", "check"])
def test_a_syntax_error_from_stdin_names_stdin_with_its_line_and_source(tmp_path, command):
    done = ncvm(tmp_path, command, "-d", "din", "-", *(["--state", "s"] if command == "run" else []),
                stdin=BAD_SYNTAX)
    assert done.returncode == 1
    assert "<stdin>:2:10: error NC001: cannot read '&'\n    G1 Y5 Q7 &\n             ^\n" in done.stderr


def test_check_of_stdin_as_json(tmp_path):
    done = ncvm(tmp_path, "check", "-d", "din", "-", "--json", stdin=BAD_SYNTAX)
    assert done.returncode == 1, done.stderr
    [entry] = json.loads(done.stdout)["files"]
    assert entry["file"] == "<stdin>" and not entry["ok"]
    assert [(d["code"], d["file"], d["line"], d["column"]) for d in entry["diagnostics"]] == \
        [("NC001", "<stdin>", 2, 10)]
    clean = ncvm(tmp_path, "check", "-d", "din", "-", stdin=PART)
    assert clean.returncode == 0 and "ncvm: 1 program(s) checked, 0 diagnostic(s)" in clean.stderr


def test_a_fault_in_a_program_from_a_named_pipe_shows_its_source_line(tmp_path):
    fifo = fifo_with(tmp_path, NO_B_AXIS)
    done = ncvm(tmp_path, "run", "-d", "din", str(fifo), "--state", "s")
    assert done.returncode == 1
    assert (f"{fifo}:3:4: error NC011: axis B is not configured on this machine (its axes: X Y Z)\n    G1 B5\n"
            "       ^\n") in done.stderr
    assert "stopped with error NC011: 3 steps, 2 moves" in done.stderr


def test_a_named_pipe_runs_and_checks_as_its_text_does(tmp_path):
    (tmp_path / "part.ngc").write_text(PART)
    from_file = json.loads(ncvm(tmp_path, "run", "part.ngc", "--json", "--state", "s1").stdout)
    fifo = fifo_with(tmp_path, PART, "pipe.ngc")
    piped = ncvm(tmp_path, "run", "-d", "din", fifo.name, "--json", "--state", "s2")
    assert piped.returncode == 0 and json.loads(piped.stdout) == from_file, piped.stderr
    fifo.unlink()
    fifo = fifo_with(tmp_path, BAD_SYNTAX, "pipe.ngc")
    checked = ncvm(tmp_path, "check", "-d", "din", fifo.name, "--json")
    assert checked.returncode == 1
    [entry] = json.loads(checked.stdout)["files"]
    assert entry["file"] == "pipe.ngc" and entry["diagnostics"][0]["line"] == 2


def test_a_program_from_stdin_uses_the_current_folders_machine_file_and_says_so(tmp_path):
    axis = "[[axis]]\nname = \"{}\"\nmin = -100.0\nmax = 100.0\nrapid = 5000.0\nmax_feed = 2000.0\naccel = 500.0\n"
    (tmp_path / "machine.toml").write_text('[machine]\nname = "lathe"\n' + axis.format("X") + axis.format("Z"))
    done = ncvm(tmp_path, "run", "-d", "din", "-", "--state", "s", stdin="G1 X10 Z-5 F100\nM2\n")
    assert done.returncode == 0, done.stderr
    assert "ncvm: machine file machine.toml (the current folder: the program is read from stdin)" in done.stderr
    refused = ncvm(tmp_path, "run", "-d", "din", "-", "--state", "s", stdin="G1 Y5 F100\nM2\n")
    assert refused.returncode == 1 and "<stdin>:1:4: error NC011: axis Y is not configured" in refused.stderr


@pytest.mark.parametrize("command", ["run", "check"])
def test_a_pipe_without_its_dialect_is_refused_before_it_is_read(tmp_path, command):
    fifo = tmp_path / "part.ngc"
    os.mkfifo(fifo)  # no writer: opening it would wait for ever
    for program in ("-", fifo.name):
        done = ncvm(tmp_path, command, program, "--json", stdin=PART)
        name = "<stdin>" if program == "-" else fifo.name
        message = (f"{name}: a program from a pipe needs its dialect named (-d din): nothing tells it before the "
                   "pipe is read")
        assert done.returncode == 2 and f"ncvm: error: {message}" in done.stderr
        assert json.loads(done.stdout)["error"]["message"] == message


@pytest.mark.parametrize("dialect", ["cpl", "cl800", "sympas"])
def test_a_dialect_that_reads_files_says_which_takes_a_pipe(tmp_path, dialect):
    done = ncvm(tmp_path, "run", "-d", dialect, "-", "--state", "s", stdin=PART)
    assert done.returncode == 2
    assert (f"ncvm: error: <stdin>: a program from a pipe is read by dialect din only; a {dialect} program is "
            "read from its file (give the file)") in done.stderr
    assert not (tmp_path / "s").exists()


def test_a_pipe_is_one_program_alone(tmp_path):
    (tmp_path / "part.ngc").write_text(PART)
    for args in (("run", "-d", "din", "-", "part.ngc", "--state", "s"), ("run", "-d", "din", "-", "-j", "2"),
                 ("check", "-d", "din", "part.ngc", "-")):
        done = ncvm(tmp_path, *args, stdin=PART)
        assert done.returncode == 2, args
        verb = "is checked" if args[0] == "check" else "runs"
        assert f"<stdin>: a program from a pipe {verb} alone, not in a batch" in done.stderr


def test_no_other_input_of_a_run_from_stdin_is_stdin(tmp_path):
    done = ncvm(tmp_path, "run", "-d", "din", "-", "--keys", "/dev/stdin", "--state", "s", stdin=PART)
    assert done.returncode == 2
    assert "ncvm: error: --keys /dev/stdin: is stdin, which carries the program; give a file" in done.stderr


def test_an_empty_stdin_is_an_empty_program(tmp_path):
    done = ncvm(tmp_path, "run", "-d", "din", "-", "--json", "--state", "s", stdin="")
    assert done.returncode == 0, done.stderr
    assert json.loads(done.stdout)["steps"] == 0


# -- the API -------------------------------------------------------------------------------------------

def test_the_engine_reads_stdin_for_dash(tmp_path):
    code = ("import json, sys\nfrom pathlib import Path\nfrom ncvm.api import run\n"
            "from ncvm.runtime.session import RunOptions\n"
            "r, _ = run('-', 'din', options=RunOptions(state_dir=Path('s')))\n"
            "print(json.dumps([r['status'], r['error'], r['motion']['feed_moves']]))\n")
    done = subprocess.run([sys.executable, "-c", code], cwd=tmp_path, input=NO_B_AXIS, capture_output=True,
                          text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    status, error, moves = json.loads(done.stdout)
    assert (status, moves) == ("error", 2)
    assert (error["code"], error["file"], error["line"], error["column"]) == ("NC011", "<stdin>", 3, 4)


def test_the_python_api_runs_and_checks_a_named_pipe(tmp_path):
    import ncvm

    fifo = fifo_with(tmp_path, NO_B_AXIS)
    result = ncvm.run(fifo, dialect="din", state_dir=tmp_path / "s")
    assert result.error.code == "NC011" and result.error.span.line == 3 and result.motion.feed_moves == 2
    assert result.error.render() == (f"{fifo}:3:4: error NC011: axis B is not configured on this machine (its "
                                     "axes: X Y Z)\n    G1 B5\n       ^")
    fifo.unlink()
    fifo = fifo_with(tmp_path, BAD_SYNTAX)
    [diag] = ncvm.check(fifo)  # told from its name
    assert (diag.code, diag.span.file, diag.span.line) == ("NC001", str(fifo), 2)
    assert diag.render().endswith("\n    G1 Y5 Q7 &\n             ^")


def test_the_api_refuses_a_pipe_of_a_dialect_that_reads_files(tmp_path):
    import ncvm
    from ncvm.diagnostics import UsageError

    fifo = tmp_path / "p.cpl"
    os.mkfifo(fifo)  # no writer: refused before it is opened
    with pytest.raises(UsageError, match="a program from a pipe is read by dialect din only; a cpl program"):
        ncvm.run(fifo, state_dir=tmp_path / "s")


def test_a_file_named_dash_is_a_file_for_the_python_api(tmp_path, monkeypatch):
    import ncvm

    monkeypatch.chdir(tmp_path)
    (tmp_path / "-").write_text("G1 X7 F100\nM2\n")
    result = ncvm.run("-", dialect="din", state_dir=tmp_path / "s")
    assert result.error is None and result.position["X"] == 7.0
