"""A word for an axis the machine lacks is an error in every dialect, at run time and in ``ncvm check``.

CPL gives its manual's run-time error 1938 (axis index programmed is not configured); DIN and the
SINUMERIK 800 (no number in their manuals) give NC011. The blocks before the refused one run.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from click.testing import CliRunner

from ncvm import cli

XYZ = "[[axis]]\nname = 'X'\n[[axis]]\nname = 'Y'\n[[axis]]\nname = 'Z'\n"
LATHE = "[[axis]]\nname = 'X'\n[[axis]]\nname = 'Z'\n"
WITH_A = XYZ + "[[axis]]\nname = 'A'\nkind = 'rotary'\n"


@pytest.fixture
def ncvm(tmp_path):
    """ncvm(command, name, text, machine=XYZ, *more) -> (exit code, JSON document) through the real CLI."""

    def _ncvm(command: str, name: str, text: str, machine: str = XYZ, *more: str):
        (tmp_path / name).write_text(text, encoding="latin-1")
        (tmp_path / "m.toml").write_text(machine)
        args = [command, str(tmp_path / name), "--machine", str(tmp_path / "m.toml"), "--json", *more]
        if command == "run":
            args += ["--state", str(tmp_path / "st")]
        r = CliRunner().invoke(cli.cli, args, catch_exceptions=False)
        return r.exit_code, json.loads(r.stdout)

    return _ncvm


def error(doc: dict) -> tuple:
    e = doc["error"]
    return e["code"], e["line"], e["message"]


def check_errors(doc: dict) -> list[tuple]:
    return [(d["code"], d["line"], d["column"]) for d in doc["files"][0]["diagnostics"] if d["severity"] == "error"]


# -- DIN -----------------------------------------------------------------------------------------

def test_din_refuses_a_rotary_axis_word_after_running_the_blocks_before_it(ncvm):
    text = "G1 X10 F100\nG1 X20 Y5\nG1 A10 (MSG, turn)\nG1 X0\nM2\n"
    code, doc = ncvm("run", "p.din", text)
    assert code == 1 and error(doc)[:2] == ("NC011", 3)
    assert "axis A is not configured on this machine (its axes: X Y Z)" in doc["error"]["message"]
    assert doc["error"]["column"] == 4
    assert doc["motion"]["feed_moves"] == 2 and doc["position"]["X"] == pytest.approx(20.0)
    assert doc["output"] == [] and doc["steps"] == 3
    code, doc = ncvm("check", "p.din", text)
    assert code == 1 and check_errors(doc) == [("NC011", 3, 4)]


def test_din_plain_blocks_on_a_lathe_refuse_y_in_the_middle_of_a_run(ncvm):
    """Plain X/Y/Z blocks run as columns; the run stops before the row with Y, as block by block."""
    text = "G1 X10 F100\nG1 Z5\nG1 X20 Y5\nG1 X0\nM2\n"
    code, doc = ncvm("run", "p.din", text, LATHE)
    assert code == 1 and error(doc)[:2] == ("NC011", 3) and doc["error"]["column"] == 8
    assert doc["motion"]["feed_moves"] == 2 and doc["position"] == pytest.approx({"X": 10.0, "Z": 5.0})
    code, doc = ncvm("check", "p.din", text, LATHE)
    assert check_errors(doc) == [("NC011", 3, 8)]


def test_din_skipped_block_runs_nothing_but_check_flags_it(ncvm):
    text = "G1 X10 F100\n/G1 B5\nM2\n"
    code, doc = ncvm("run", "p.din", text)
    assert code == 0 and doc["status"] == "ok"
    code, doc = ncvm("check", "p.din", text)
    assert check_errors(doc) == [("NC011", 2, 5)]


def test_din_axes_the_machine_has_run(ncvm):
    code, doc = ncvm("run", "p.din", "G1 X10 A90 F100\nM2\n", WITH_A)
    assert code == 0 and doc["position"]["A"] == pytest.approx(90.0)
    code, doc = ncvm("check", "p.din", "G1 X10 A90 F100\nG1 Q5 E3\nM2\n", WITH_A)  # Q, E: no axis letters
    assert code == 0 and check_errors(doc) == []


def test_check_of_an_archive_uses_the_machine_file_of_each_program_folder(tmp_path):
    """A 4-axis cell keeps its machine file beside its programs: its A words are no error there."""
    (tmp_path / "cell4").mkdir()
    (tmp_path / "cell4" / "machine.toml").write_text(WITH_A)
    (tmp_path / "cell4" / "index.din").write_text("G1 X10 A90 F100\nM2\n")
    (tmp_path / "mill").mkdir()
    (tmp_path / "mill" / "index.din").write_text("G1 X10 A90 F100\nM2\n")
    r = CliRunner().invoke(cli.cli, ["check", str(tmp_path), "--json"], catch_exceptions=False)
    files = {Path(f["file"]).parent.name: [d["code"] for d in f["diagnostics"]] for f in json.loads(r.stdout)["files"]}
    assert r.exit_code == 1 and files == {"cell4": [], "mill": ["NC011"]}
    r = CliRunner().invoke(cli.cli, ["check", str(tmp_path), "--json", "--machine", str(tmp_path / "cell4" / "machine.toml")])
    assert r.exit_code == 0


# -- CPL -----------------------------------------------------------------------------------------

CPL = ("N10 G1 X10 F100\n"
       "20 IF 1 = 2 THEN\n"
       "N30 G1 C5\n"  # never reached: refused only when it runs
       "40 ENDIF\n"
       "50 B = 5\n"
       "N60 G1 Y[B]\n"
       "N70 G1 B[B] X1\n"
       "N80 G1 U7\n"
       "M30\n")


def test_cpl_refuses_with_error_1938_where_the_block_runs(ncvm):
    code, doc = ncvm("run", "p.cpl", CPL)
    assert code == 1 and error(doc)[:2] == ("1938", 7)
    assert doc["error"]["message"].startswith("axis index programmed is not configured: address B")
    assert doc["motion"]["feed_moves"] == 2 and doc["position"]["Y"] == pytest.approx(5.0)


def test_cpl_check_lists_every_literal_axis_address(ncvm):
    code, doc = ncvm("check", "p.cpl", CPL)
    assert code == 1 and check_errors(doc) == [("1938", 3, 8), ("1938", 7, 8), ("1938", 8, 8)]


@pytest.mark.parametrize("block, address", [
    ("N20 G0 Z5", "Z"),  # a constant plain row
    ("N20 G0 X2=5", "X2"),  # an extended address (manual L2110)
])
def test_cpl_constant_blocks_and_extended_addresses(ncvm, block, address):
    """On a machine with the axes X and Y only."""
    code, doc = ncvm("run", "p.cpl", f"N10 G1 X10 F100\n{block}\nM30\n", "[[axis]]\nname = 'X'\n[[axis]]\nname = 'Y'\n")
    assert code == 1 and error(doc)[:2] == ("1938", 2) and f"address {address} " in doc["error"]["message"]
    assert doc["motion"]["feed_moves"] == 1


def test_cpl_words_made_at_run_time_are_refused_as_they_come(ncvm):
    text = '10 A$ = "A5"\nN20 G1 X10 F100\nN30 G1 [A$]\nM30\n'
    code, doc = ncvm("run", "p.cpl", text)
    assert code == 1 and error(doc)[:2] == ("1938", 3) and doc["motion"]["feed_moves"] == 1
    code, doc = ncvm("check", "p.cpl", text)  # not literal: check cannot see it
    assert code == 0


def test_cpl_program_excluded_from_linking(ncvm):
    code, doc = ncvm("run", "p.cpl", "(DIN)\nN10 G1 X10 F100\nN20 G1 W3\nM30\n")
    assert code == 1 and error(doc)[:2] == ("1938", 3) and doc["motion"]["feed_moves"] == 1


def test_cpl_axes_the_machine_has_run(ncvm):
    code, doc = ncvm("run", "p.cpl", "N10 G1 X10 A[45] F100\nM30\n", WITH_A)
    assert code == 0 and doc["position"]["A"] == pytest.approx(45.0)


# -- SINUMERIK 800 and CL 800 ------------------------------------------------------------------------

SIN = "%MPF1\nN10 G1 X10 F100\nN20 G2 X20 B5\nN30 G1 A30 X25\nN40 G1 U5\nN50 G1 C=R1\nN60 M30\n"


def test_sin800_refuses_an_axis_word_but_not_the_radius_b_and_the_angle_a(ncvm):
    code, doc = ncvm("run", "p.mpf", SIN)
    assert code == 1 and error(doc)[:2] == ("NC011", 5) and "axis U is not configured" in doc["error"]["message"]
    assert doc["motion"]["feed_moves"] + doc["motion"]["arc_moves"] == 3
    code, doc = ncvm("check", "p.mpf", SIN)
    assert code == 1 and check_errors(doc) == [("NC011", 5, 8), ("NC011", 6, 8)]


def test_sin800_with_decode_ahead_runs_the_decoded_blocks_first(ncvm):
    code, doc = ncvm("run", "p.mpf", "%MPF1\nN10 G1 X10 F100\nN20 G1 X20\nN30 G1 W5\nN40 M30\n",
                     XYZ + "[sin800]\ndecode_ahead = 3\n")
    assert code == 1 and error(doc)[:2] == ("NC011", 4) and doc["motion"]["feed_moves"] == 2


def test_cl800_check_reads_the_din_words_of_its_blocks(ncvm):
    source = (Path(__file__).parents[2] / "examples" / "cl800" / "hole_pattern.cl8").read_text(encoding="latin-1")
    assert "(:G01 F200 L=R20 P1:)" in source
    code, doc = ncvm("check", "holes.cl8", source)
    assert code == 0
    changed = source.replace("(:G01 F200 L=R20 P1:)", "(:G01 F200 V3 L=R20 P1:)", 1)
    code, doc = ncvm("check", "holes.cl8", changed)
    line = changed[:changed.index("V3")].count("\n") + 1
    assert code == 1 and check_errors(doc) == [("NC011", line, changed.splitlines()[line - 1].index("V3") + 1)]


# -- rw_SymPas ----------------------------------------------------------------------------------------

def test_sympas_names_axes_by_declared_specifiers(ncvm):
    """rw_SymPas was never silent: A5 on a 3-axis card is undeclared (compiler error 3), an AXIS variable
    set to a number the card lacks stops the task with run-time error 256."""
    code, doc = ncvm("check", "p.sap", "program P;\nbegin\n  MLAW(A1 := 10.0, A5 := 10.0);\nend.\n")
    assert code == 1 and check_errors(doc) == [("3", 3, 20)]
    text = "program P;\nvar v: axis;\nbegin\n  TRVL := 50.0; TRAC := 500.0;\n  v.an := 7;\n  MLAW(v := 10.0);\nend.\n"
    code, doc = ncvm("run", "p.sap", text)
    assert code == 1 and error(doc)[:2] == ("256", 6)
