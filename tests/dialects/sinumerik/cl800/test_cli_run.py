"""The command line (compile, --xref, check --all) and the run() hand-over to the sin800 NC."""

from __future__ import annotations

from pathlib import Path

from click.testing import CliRunner

from ncvm import dialects
from ncvm.api import run
from ncvm.cli import cli
from ncvm.dialects.sinumerik.cl800.codegen import marked
from ncvm.runtime.session import RunOptions

GOLDEN = Path(__file__).parent / "golden"


def test_compile_command_writes_object_and_listing(tmp_path: Path):
    src = tmp_path / "if.cl8"
    src.write_text((GOLDEN / "b_if_then_else.cl8").read_text())
    res = CliRunner().invoke(cli, ["compile", str(src), "-o", str(tmp_path / "L505.spf"),
                                   "--xref", str(tmp_path / "x.lst")])
    assert res.exit_code == 0, res.output
    assert (tmp_path / "L505.spf").read_text() == marked((GOLDEN / "b_if_then_else.spf").read_text())
    assert (tmp_path / "x.lst").read_text() == marked((GOLDEN / "b_if_then_else.lst").read_text())


def test_l361_the_cross_reference_run_writes_the_listing_under_the_source_name_and_no_object(tmp_path: Path):
    """L361: a dedicated compilation creates no object code that can be loaded in the NC, but a listing file
    with the same file name as the source code; L363-365: each statement has its source line."""
    src = tmp_path / "if.cl8"
    src.write_text((GOLDEN / "b_if_then_else.cl8").read_text())
    res = CliRunner().invoke(cli, ["compile", str(src), "--xref"])
    assert res.exit_code == 0, res.output
    assert sorted(p.name for p in tmp_path.iterdir()) == ["if.cl8", "if.lst"]
    listing = (tmp_path / "if.lst").read_text().splitlines()
    # ACD (line 4) and the IF (line 5) share the first NC block with the push (line 3): each has its line
    assert listing[1:4] == ["    3 @041 R70 R71", "    4   @36a R70 K1",
                            "    5   @124 R70 K20 K2001 @201 R71 K1500 @100 K2002"]


def test_compile_command_reports_the_first_error(tmp_path: Path):
    src = tmp_path / "bad.cl8"
    src.write_text("PROGRAM 9;\nCHANNEL NC 0;\nBEGIN\n  R60 = 1;\n  R61 = 2;\nEND.\n")
    res = CliRunner().invoke(cli, ["compile", str(src)])
    assert res.exit_code == 1
    assert "bad.cl8:4:3: error E041: Parameter not declared (R60)" in res.output
    assert "R61" not in res.output
    assert not (tmp_path / "L9.spf").exists()
    res = CliRunner().invoke(cli, ["check", "--all", str(src)])
    assert "E041" in res.output and "(R61)" in res.output


class _RecordingNc:
    """Stands in for the sin800 dialect: records what the CL 800 front end hands over."""

    def __init__(self):
        self.calls = []

    def run(self, path, text, session):
        self.calls.append((path, text, session))
        session.variables["handed_over"] = 1


def test_run_hands_the_object_program_to_sin800(tmp_path: Path, monkeypatch):
    nc = _RecordingNc()
    monkeypatch.setitem(dialects._LOADED, "sin800", nc)
    src = tmp_path / "for.cl8"
    src.write_text((GOLDEN / "c_for_to.cl8").read_text())
    result, session = run(src, options=RunOptions(state_dir=tmp_path / ".ncvm"))
    assert result["status"] == "ok" and result["dialect"] == "cl800"
    [(path, text, sess)] = nc.calls
    assert path == str(tmp_path / "L502.spf")
    assert text == (GOLDEN / "c_for_to.spf").read_text()
    assert sess is session and result["variables"] == {"handed_over": 1}


def test_run_stops_before_the_nc_on_a_compile_error(tmp_path: Path, monkeypatch):
    nc = _RecordingNc()
    monkeypatch.setitem(dialects._LOADED, "sin800", nc)
    src = tmp_path / "bad.cl8"
    src.write_text("PROGRAM 9;\nCHANNEL NC 0;\nBEGIN\n  R60 = 1;\nEND.\n")
    result, _ = run(src, options=RunOptions(state_dir=tmp_path / ".ncvm"))
    assert result["error"]["code"] == "E041" and result["error"]["line"] == 4
    assert nc.calls == []


def test_compile_refuses_a_file_without_end_dot(tmp_path: Path):
    src = tmp_path / "open.cl8"
    src.write_text("PROGRAM 9;\nCHANNEL NC 0;\nBEGIN\n  LF;\n(* unfinished *)\n")
    res = CliRunner().invoke(cli, ["compile", str(src)])
    assert res.exit_code == 1 and "open.cl8:4: error E300: File cannot be compiled" in res.output
    res = CliRunner().invoke(cli, ["check", str(src)])
    assert "error E060" in res.output  # the editor's analysis reports the missing END.


def test_a_run_time_error_names_the_cl800_statement(tmp_path: Path):
    """Issue 15: a CL 800 error of the run is reported at the .cl8 statement that caused it (here the second
    of two statements the compiler packed into one NC block), not at the object program the run never
    writes; the object block is in a note."""
    src = tmp_path / "rt.cl8"
    src.write_text("PROGRAM 7;\nCHANNEL NC 0;\nPAR REAL: R10, R11;\nBEGIN\n  R10 = 5;\n  R11 = INV LN (100);\nEND.\n")
    result, _ = run(src, options=RunOptions(state_dir=tmp_path / ".ncvm"))
    err = result["error"]
    assert (err["code"], err["file"], err["line"]) == ("CL800", str(src), 6)
    assert err["stack"] == ["object program L7.spf line 2: @201 R10 K5 @641 R11 K100 M17"]
    assert not (tmp_path / "L7.spf").exists()
    res = CliRunner().invoke(cli, ["run", str(src)])
    assert res.exit_code == 1 and "rt.cl8:6: error CL800" in res.output and "R11 = INV LN (100);" in res.output
