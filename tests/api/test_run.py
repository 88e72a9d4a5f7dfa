"""ncvm.run and ncvm.check (docs/api.md): a file or program text, typed results, the moves on request."""

from __future__ import annotations

import json
import math
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

import ncvm
from ncvm.diagnostics import Diagnostic, UsageError

ROOT = Path(__file__).resolve().parents[2]
DIN = "G0 X10 Y5\nG1 X20 F100\nG2 X30 Y15 I10 J0\nT2 M6\nG1 X0 Y0 F200\nG1 X0 Y0\nM30\n"


@pytest.fixture
def examples(tmp_path, monkeypatch):
    """A copy of examples/, the current directory: the runs' state stays in the test's folder."""
    shutil.copytree(ROOT / "examples", tmp_path / "examples")
    monkeypatch.chdir(tmp_path)
    return tmp_path / "examples"


def cli_json(*args: str, cwd: Path) -> dict:
    out = subprocess.run([sys.executable, "-m", "ncvm", "run", *args, "--json"], capture_output=True, text=True,
                         cwd=cwd, timeout=300)
    return json.loads(out.stdout)


@pytest.mark.parametrize("program", ["cpl/flange.cpl", "sin800/flange.mpf", "cl800/deep_hole.cl8",
                                     "sympas/two_tasks.sap", "din/face_and_circle.din"])
def test_a_file_runs_as_ncvm_run_runs_it(examples, program):
    """Same document as ``ncvm run --json`` in its own process, the folder's machine file included."""
    result = ncvm.run(f"examples/{program}", state_dir=".api")
    assert isinstance(result, ncvm.RunResult)
    assert result.to_json() == cli_json(f"examples/{program}", "--state", ".cli", cwd=examples.parent)
    own = examples / program.split("/")[0] / "machine.toml"
    assert result.machine == (f"examples/{own.parent.name}/machine.toml" if own.is_file() else "built-in")
    assert result.path == f"examples/{program}" and result.status == "ok" and not result.failed


def test_program_text_runs_as_the_same_file(examples):
    text = (examples / "cpl/flange.cpl").read_text(encoding="latin-1")
    as_text = ncvm.run(text, dialect="cpl", machine="examples/cpl/machine.toml", state_dir=".t")
    as_file = ncvm.run("examples/cpl/flange.cpl", state_dir=".f")
    assert as_text.path is None and as_file.path == "examples/cpl/flange.cpl"
    for name in ("status", "output", "variables", "position", "motion", "cycle_time_s", "steps"):
        assert getattr(as_text, name) == getattr(as_file, name), name


def test_program_text_calls_the_programs_of_the_current_directory(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "SUB.cpl").write_text("N10 G1 X7 F100\nM17\n")
    result = ncvm.run("10 CALL SUB\nM30\n", dialect="cpl", state_dir=".s")
    assert result.status == "ok", result.error
    assert result.position["X"] == 7


def test_program_text_dialect_by_content(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    sympas = (ROOT / "examples/sympas/contour.sap").read_text(encoding="latin-1")
    assert ncvm.run(sympas, state_dir=".s").dialect == "sympas"
    with pytest.raises(UsageError, match=r"<text>: cannot tell the dialect.*pass dialect="):
        ncvm.run("hello\nworld\n")


def test_a_str_without_a_line_end_is_a_file_never_text(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    with pytest.raises(UsageError, match=r"no such program file: G0 X10 \(program text is a str with a line end\)"):
        ncvm.run("G0 X10", dialect="din")
    with pytest.raises(UsageError, match="no such program file"):
        ncvm.check("part.din")


def test_an_error_is_typed_and_names_the_text(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    result = ncvm.run("G0 X10\nG1 X20 F100 Q\n", dialect="din", state_dir=".s")
    assert result.status == "error" and result.failed
    e = result.error
    assert isinstance(e, Diagnostic) and (e.code, e.span.file, e.span.line, e.span.column) == ("NC001", "<text>", 2, 13)
    assert result.to_json()["error"] == {"code": "NC001", "message": "cannot read 'Q'", "file": "<text>", "line": 2,
                                         "column": 13}


def test_the_call_stack_of_an_error_in_a_sub_program(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "SUB.cpl").write_text("10 A=1\n20 B=A/0\nM17\n")
    (tmp_path / "main.cpl").write_text("10 CALL SUB\nM30\n")
    result = ncvm.run("main.cpl", state_dir=".s")
    e = result.error
    assert (e.code, e.span.file, e.span.line) == ("CPL028", "SUB.cpl", 2)
    assert e.notes == ["called from main.cpl at main.cpl:1:4"] == result.to_json()["error"]["stack"]


def test_check_a_file_and_text(examples):
    assert ncvm.check("examples/cpl/flange.cpl") == []
    found = ncvm.check("G1 X1 Q\nG1 X2 Q\n", dialect="din", all_errors=True)
    assert [(d.code, d.span.file, d.span.line) for d in found] == [("NC001", "<text>", 1), ("NC001", "<text>", 2)]


def test_moves_are_a_table_of_every_move(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    result = ncvm.run(DIN, dialect="din", moves=True, state_dir=".s")
    moves = result.moves
    assert moves.dtype.names == ("kind", "start_X", "start_Y", "start_Z", "end_X", "end_Y", "end_Z", "feed", "time",
                                 "file", "line", "tool")
    assert moves["kind"].tolist() == ["rapid", "feed", "arc", "feed", "feed"]
    assert moves["line"].tolist() == [1, 2, 3, 5, 6] and set(moves["file"]) == {"<text>"}
    assert moves["tool"].tolist() == [0, 0, 0, 2, 2]
    assert math.isnan(moves["feed"][0]) and moves["feed"][1:].tolist() == [100, 100, 200, 200]
    assert (moves["start_X"][1:] == moves["end_X"][:-1]).all()
    assert (moves["end_X"][2], moves["end_Y"][2]) == (30, 15)
    assert moves["time"][-1] == 0.0  # a move of length 0 takes no time
    assert moves["time"][1] == pytest.approx(10 / 100 * 60, rel=0.01)  # 10 mm at 100 mm/min, ramps aside
    assert moves["time"].sum() == pytest.approx(result.cycle_time_s)
    assert len(moves) == result.motion.rapid_moves + result.motion.feed_moves + result.motion.arc_moves


def test_moves_of_a_sub_program_name_its_file(examples):
    moves = ncvm.run("examples/cpl/flange.cpl", moves=True, state_dir=".s").moves
    assert {"examples/cpl/flange.cpl", "examples/cpl/BOLTCIRC"} <= set(moves["file"])


def test_moves_of_a_cl800_program_name_its_own_lines(examples):
    moves = ncvm.run("examples/cl800/deep_hole.cl8", moves=True, state_dir=".s").moves
    assert moves["file"][0] == "examples/cl800/deep_hole.cl8"


def test_moves_the_card_times_have_no_time_of_their_own(examples):
    result = ncvm.run("examples/sympas/contour.sap", moves=True, state_dir=".s")
    assert result.cycle_time_model == "card" and len(result.moves)
    assert all(math.isnan(t) for t in result.moves["time"])


def test_moves_are_recorded_only_when_asked(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    result = ncvm.run(DIN, dialect="din", state_dir=".s")
    assert result.move_table is None
    with pytest.raises(ValueError, match=r"moves=True"):
        _ = result.moves
    with pytest.raises(ValueError, match=r"moves=True"):
        result.moves_frame()


def test_moves_frame(tmp_path, monkeypatch):
    pd = pytest.importorskip("pandas")
    monkeypatch.chdir(tmp_path)
    frame = ncvm.run(DIN, dialect="din", moves=True, state_dir=".s").moves_frame()
    assert isinstance(frame, pd.DataFrame) and len(frame) == 5
    assert frame.groupby("kind").size().to_dict() == {"arc": 1, "feed": 3, "rapid": 1}


def test_moves_frame_without_pandas_names_the_extra(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    result = ncvm.run(DIN, dialect="din", moves=True, state_dir=".s")
    monkeypatch.setitem(sys.modules, "pandas", None)  # import pandas fails as where it is not installed
    with pytest.raises(ImportError, match=r"pip install 'ncvm\[frames\]'"):
        result.moves_frame()


def test_run_options_by_keyword_or_whole(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    loop = "N10 G0 X1\nN20 G0 X2\nN30 G0 X3\nM30\n"
    assert ncvm.run(loop, dialect="din", max_steps=2, state_dir=".s").error.code == "RUN001"
    whole = ncvm.run(loop, dialect="din", options=ncvm.RunOptions(max_steps=2, state_dir=Path(".s")))
    assert whole.error.code == "RUN001"
    with pytest.raises(TypeError, match=r"unknown run option\(s\) max_step; the options are .*max_steps"):
        ncvm.run(loop, dialect="din", max_step=2)
    ncvm.run(loop, dialect="din", state_dir="given")
    assert (tmp_path / "given").is_dir()


def test_a_machine_object(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    mill = (ROOT / "examples/machines/mill3.toml").read_text()
    (tmp_path / "m.toml").write_text(mill.replace('name = "small vertical mill"', 'name = "small"').replace(
        "max = 600.0", "max = 5.0"))
    machine = ncvm.load_machine(tmp_path / "m.toml")
    assert isinstance(machine, ncvm.Machine)
    result = ncvm.run("G0 X10\nM30\n", dialect="din", machine=machine, state_dir=".s")
    assert result.machine == "small"
    assert result.status == "ok" and result.failed and "<text>" in result.limit_violations[0]


def test_everything_is_importable_from_ncvm():
    from ncvm import Machine, RunOptions, RunResult, batch, check, load_machine, run  # noqa: F401

    assert {"run", "check", "batch", "RunResult", "RunOptions", "Machine", "load_machine"} <= set(ncvm.__all__)
    assert all(getattr(ncvm, name) is not None for name in ncvm.__all__)
    with pytest.raises(AttributeError):
        _ = ncvm.no_such_name


def test_import_ncvm_loads_none_of_it():
    out = subprocess.run([sys.executable, "-c", "import ncvm, sys; print(sorted(sys.modules))"],
                         capture_output=True, text=True, timeout=60, check=True)
    modules = set(eval(out.stdout))
    assert not {"numpy", "pandas", "ncvm.api", "ncvm.public"} & modules
