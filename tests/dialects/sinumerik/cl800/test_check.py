"""The WS 800 A stops at the first error and reports its line; ``check --all`` lists every error."""

from __future__ import annotations

from pathlib import Path

import pytest

from ncvm.api import check
from ncvm.diagnostics import UsageError
from ncvm.dialects import get_dialect
from ncvm.machine.model import Machine

PROG = """\
PROGRAM 9;
CHANNEL NC 0;
LOCAL REAL: R60:=depth;
BEGIN
  depht = 1;
  R61 = 2;
  depth = (1 + 2;
  IF depth > 1 THEN INC (depth) ENDCASE;
END.
"""


def _check(tmp_path: Path, text: str, all_errors: bool):
    p = tmp_path / "p.cl8"
    p.write_text(text)
    return check(p, all_errors=all_errors)


def test_first_error_only(tmp_path: Path):
    diags = _check(tmp_path, PROG, all_errors=False)
    assert [(d.code, d.span.line, d.span.column) for d in diags] == [("E037", 5, 3)]
    assert diags[0].message.startswith("Variable name not declared")


def test_all_errors(tmp_path: Path):
    diags = _check(tmp_path, PROG, all_errors=True)
    assert [(d.code, d.span.line) for d in diags] == [("E037", 5), ("E041", 6), ("E006", 7), ("E019", 8)]


def test_clean_program_has_no_diagnostics(tmp_path: Path):
    assert _check(tmp_path, PROG.replace("  depht = 1;\n  R61 = 2;\n  depth = (1 + 2;\n", "")
                  .replace("ENDCASE", "ENDIF"), all_errors=True) == []


def test_lists_found_next_to_the_program(tmp_path: Path):
    (tmp_path / "KAPLIST").write_text("EXTERNAL 60;\nCHANNEL NC 0;\nID (0-KAPLIST-03.04.85-KUB);\n"
                                      "GLOBAL REAL: R150:=refpl;\nENDEXTERN\n")
    (tmp_path / "CENLIST.cl8").write_text("EXTERNAL 10;\nID (0-CENLIST-28.03.85-KUB);\n"
                                          "CENTRAL REAL: R900:=Load_1,R950:=Read_3;\nENDEXTERN\n")
    text = ('PROGRAM 81;\nCHANNEL NC 1;\nGLOBAL: "KAPLIST";\nCENTRAL: "CENLIST";\n'
            'LOCAL REAL: R60:=start_Z;\nBEGIN\n  start_Z = refpl + Load_1; read_3 = start_Z;\nEND.\n')
    assert _check(tmp_path, text, all_errors=True) == []
    out = get_dialect("cl800").build(str(tmp_path / "p.cl8"), text, Machine())
    # one local: @040 K1 (a "range" needs two registers); push and pop never share the first block
    assert out.text() == "%SPF81\n@040 K1 R60 R60=R150+R900 @201 R950 R60\n@042 K1 R60 M17\n"


def test_lists_on_the_program_path(tmp_path: Path):
    lists = tmp_path / "lists"
    lists.mkdir()
    (lists / "CENLIST").write_text("EXTERNAL 10;\nID (0-CENLIST-28.03.85-KUB);\nCENTRAL REAL: R900:=Load_1;\n"
                                   "ENDEXTERN\n")
    m = Machine()
    m.program_path = [lists]
    text = 'PROGRAM 81;\nCHANNEL NC 1;\nCENTRAL: "CENLIST";\nBEGIN\n  Load_1 = 5;\nEND.\n'
    p = tmp_path / "p.cl8"
    assert get_dialect("cl800").check(str(p), text, m) == []
    assert get_dialect("cl800").build(str(p), text, m).text() == "%SPF81\n@201 R900 K5 M17\n"


def test_lists_are_looked_for_inside_the_program_folders_only(tmp_path: Path):
    """A list name is a name in a program folder, as a program name is (machine.files): "a/../../" with
    an extension would read ../.ext above the folder, and a link in the folder may lead anywhere; both
    printed the host file's first line in the diagnostic. They are lists that do not exist (E200)."""
    progs = tmp_path / "progs"
    (progs / "a").mkdir(parents=True)
    (tmp_path / ".ext").write_text("HOST-SECRET\n")
    (tmp_path / "host.cl8").write_text("HOST-SECRET\n")
    (progs / "LINKED.cl8").symlink_to(tmp_path / "host.cl8")
    m = Machine()
    m.program_path = [progs]
    for name in ("a/../../", "LINKED"):
        (progs / "p.cl8").write_text(f'PROGRAM 81;\nCHANNEL NC 1;\nGLOBAL: "{name}";\nBEGIN\nEND.\n')
        diags = check(progs / "p.cl8", machine=m)
        assert [(d.code, d.span.line) for d in diags] == [("E200", 3)], name
        assert not any("HOST-SECRET" in str(d) for d in diags)


def test_strict_mode_drops_the_leniencies(tmp_path: Path):
    m = Machine()
    m.sections["cl800"] = {"strict": True}
    d = get_dialect("cl800")
    p = str(tmp_path / "p.cl8")
    head = "PROGRAM 9;\nCHANNEL NC 0;\nLOCAL REAL: R60:=a_b;\nBEGIN\n"
    assert d.check(p, head + "  R60 = 1\nEND.\n", Machine()) == []
    assert [x.code for x in d.check(p, head + "  R60 = 1\nEND.\n", m)] == ["E001"]
    assert [x.code for x in d.check(p, head + "  R60 := 1;\nEND.\n", m)] == ["E004"]
    assert [x.code for x in d.check(p, head + "  a_b. = 1;\nEND.\n", m)] == ["E047"]  # read as a bit access
    assert d.check(p, head + "  a_b. = 1;\nEND.\n", Machine()) == []
    m.sections["cl800"] = {"stict": True}
    with pytest.raises(UsageError, match="cl800.stict"):
        d.check(p, head + "END.\n", m)


def test_program_number_range_per_control(tmp_path: Path):
    m = Machine()
    d = get_dialect("cl800")
    text = "PROGRAM 1000;\nCHANNEL NC 0;\nBEGIN\nEND.\n"
    assert d.check(str(tmp_path / "p.cl8"), text, m) == []  # 850/880: 1..9999 (L1069)
    m.sections["cl800"] = {"control": "810"}
    [diag] = d.check(str(tmp_path / "p.cl8"), text, m)
    assert diag.code == "E027" and "1..999" in diag.message


@pytest.mark.parametrize("name", ["hole_pattern.cl8", "deep_hole_drilling.cl8"])
def test_e208_is_an_editor_message_the_manual_listings_7_3_and_7_4_compile(tmp_path: Path, name: str):
    """L6218-6230: E208 (line longer than one screen line) is caused by incorrect editor operation; the
    compiler takes the listings of 7.3 and 7.4 with their lines of 85-89 characters (L5378, L5530)."""
    from ncvm.api import compile_program

    src = Path(__file__).parents[4] / "examples" / "cl800" / name
    assert max(len(line) for line in src.read_text().splitlines()) > 84
    assert check(src) == []
    compile_program(src, out=tmp_path / "out.spf")
    assert (tmp_path / "out.spf").read_text().startswith("%SPF")


def _warnings(tmp_path: Path, body: str) -> list[tuple[str, int]]:
    src = tmp_path / "sd.cl8"
    src.write_text("PROGRAM 7;\nCHANNEL NC 0;\nPAR REAL: R10, R11, R12;\nBEGIN\n" + body + "END.\n")
    return [(d.code, d.span.line) for d in check(src)]


def test_l4301_actual_value_read_needs_stop_dec_in_a_block_before_it(tmp_path: Path):
    """L4301, L2668: STOP DEC before each read of actual values, in the block before the read. The
    compiler packs statements into one NC block until LF: a move, STOP DEC and the read in one block
    read the position before the move (SIN010 at the read's source line)."""
    assert _warnings(tmp_path, "  (: G0 X10 :);\n  R10 = ACPM (1);\n") == [("SIN010", 6)]
    assert _warnings(tmp_path, "  (: G0 X10 :);\n  STOP DEC;\n  R10 = ACPM (1);\n") == [("SIN010", 7)]
    assert _warnings(tmp_path, "  (: G0 X10 :); LF;\n  STOP DEC;\n  R10 = ACPM (1);\n") == []
    assert _warnings(tmp_path, "  (: G0 X10 :); LF;\n  R11 = 1; LF;\n  R10 = ACPM (1);\n") == [("SIN010", 7)]


def test_l4301_stop_dec_after_each_measurement(tmp_path: Path):
    """L4301: STOP DEC after each "measure" (MEAS M); the warning names the MEAS M statement's line."""
    meas = "  R10 = MEAS M (1); PRAP (1) = 20; LF;\n"
    assert _warnings(tmp_path, meas + "  R11 = R10 + 1;\n") == [("SIN010", 5)]
    assert _warnings(tmp_path, meas + "  STOP DEC;\n  R11 = R10 + 1;\n") == []


def _first(tmp_path: Path, decl: str, body: str) -> tuple[str, int]:
    src = tmp_path / "p.cl8"
    src.write_text(f"PROGRAM 7;\nCHANNEL NC 0;\n{decl}BEGIN\n{body}END.\n")
    d = check(src)[0]
    return d.code, d.span.line


def test_l7074_a_bit_pattern_with_other_digits_is_e051(tmp_path: Path):
    """L7074-7075: a bit pattern has 8 digits 0/1; B00000002 is E051 (bit pattern outside limits)."""
    assert _first(tmp_path, "LOCAL PATTERN: R60;\n", "  R60 = B00000002;\n") == ("E051", 5)


def test_l1297_a_label_has_at_most_8_characters(tmp_path: Path):
    """L1297: the name of a label can have up to 8 characters."""
    assert _first(tmp_path, "LABEL: Destinat9;\n", "  GOTO Destinat9;\n  Destinat9: R0 = 1;\n") == ("E061", 3)
    src = tmp_path / "p.cl8"
    src.write_text("PROGRAM 7;\nCHANNEL NC 0;\nPAR INTEGER: R0;\nLABEL: Destinat;\nBEGIN\n  GOTO Destinat;\n"
                   "  Destinat: R0 = 1;\nEND.\n")
    assert check(src) == []


@pytest.mark.parametrize("kind", ["REAL", "INTEGER", "PATTERN"])
def test_l4730_a_condition_is_boolean_not_a_variable_of_another_type(tmp_path: Path, kind: str):
    """L4730-4748: IF takes a BOOLEAN condition; a REAL (INTEGER, PATTERN) variable alone is E030."""
    body = "  IF R60 THEN R61 = 1; ENDIF;\n"
    assert _first(tmp_path, f"LOCAL {kind}: R60;\nLOCAL BOOLEAN: R61;\n", body) == ("E030", 6)
    src = tmp_path / "p.cl8"
    src.write_text(f"PROGRAM 7;\nCHANNEL NC 0;\nLOCAL BOOLEAN: R60, R61;\nBEGIN\n{body}END.\n")
    assert check(src) == []


@pytest.mark.parametrize(("decl", "where"), [
    ("LABEL: Dest;\nLOCAL REAL: R60:=Dest;\n", (4, 13)),   # the variable is the second declaration
    ("LOCAL REAL: R60:=Dest;\nLABEL: Dest;\n", (4, 8)),    # the label is
    ("CONST: Dest:=5;\nLABEL: Dest;\n", (4, 8)),
])
def test_e036_names_the_second_declaration(tmp_path: Path, decl: str, where: tuple[int, int]):
    """E036 (variable name double, L6194) stands where the name is declared the second time."""
    src = tmp_path / "p.cl8"
    src.write_text(f"PROGRAM 7;\nCHANNEL NC 0;\n{decl}BEGIN\n  R60 = 1;\nEND.\n")
    d = [d for d in check(src, all_errors=True) if d.code == "E036"][0]
    assert (d.span.line, d.span.column) == where


def test_e010_a_missing_dot_after_end_is_reported_at_end(tmp_path: Path):
    """E010 ("." expected): at the END of a 7-line file, not at a line 8 the file does not have."""
    src = tmp_path / "p.cl8"
    src.write_text("PROGRAM 7;\nCHANNEL NC 0;\nLOCAL REAL: R60;\nBEGIN\n  R60 = 1;\n  R60 = 2;\nEND\n")
    d = check(src)[0]
    assert (d.code, d.span.line, d.span.column) == ("E010", 7, 4)


def test_l1145_the_id_designation_has_its_fixed_terms(tmp_path: Path):
    """L1116-1145: terms 1-4 of ID are fixed and separated by hyphens; ``ID (X);`` is E032."""
    assert _first(tmp_path, "ID (X);\n", "") == ("E032", 3)
    src = tmp_path / "p.cl8"
    src.write_text("PROGRAM 7;\nCHANNEL NC 0;\nID (0-EXAMPLE-22.07.85-KUB-SIEM:MA:850:02);\nBEGIN\nEND.\n")
    assert check(src) == []


def _lists(tmp_path: Path, refs: str) -> tuple[str, str, int]:
    (tmp_path / "A.cl8").write_text('EXTERNAL 50;\nCHANNEL NC 0;\nGLOBAL REAL: R150:=x;\nENDEXTERN\n')
    (tmp_path / "B.cl8").write_text('EXTERNAL 51;\nCHANNEL NC 0;\nCENTRAL REAL: R950:=y;\nENDEXTERN\n')
    (tmp_path / "C.cl8").write_text('CHANNEL NC 0;\nGLOBAL REAL: R152:=z;\nENDEXTERN\n')
    src = tmp_path / "p.cl8"
    src.write_text(f"PROGRAM 7;\nCHANNEL NC 0;\n{refs}BEGIN\nEND.\n")
    d = check(src)[0]
    return d.code, Path(d.span.file).name, d.span.line


def test_l1307_a_list_that_does_not_start_with_external_is_e014(tmp_path: Path):
    """L1307-1318: a declaration list starts with EXTERNAL <list number>; E014 "EXTERNAL" expected."""
    assert _lists(tmp_path, 'GLOBAL: "C";\n') == ("E014", "C.cl8", 1)


@pytest.mark.parametrize("refs", ['GLOBAL: "A"; "B";\n', 'GLOBAL: "A"; CENTRAL: "B";\n'])
def test_e035_one_list_reference_per_line(tmp_path: Path, refs: str):
    """E035 (only one file name possible per line, L6190): two list names on one line."""
    assert _lists(tmp_path, refs) == ("E035", "p.cl8", 3)
    src = tmp_path / "ok.cl8"
    src.write_text('PROGRAM 8;\nCHANNEL NC 0;\nGLOBAL: "A";\nCENTRAL: "B";\nBEGIN\nEND.\n')
    assert check(src) == []


def test_l4338_ess_stands_at_the_start_of_the_statement_part(tmp_path: Path):
    """L4338: ESS "must be located at the start of the statement part"; elsewhere it is refused rather
    than moved to the start of the object program."""
    assert _first(tmp_path, "PAR INTEGER: R1;\n", "  R1 = 1;\n  ESS;\n") == ("E061", 6)
    assert _first(tmp_path, "PAR INTEGER: R1;\n", "  IF R1 > 0 THEN ESS; ENDIF;\n") == ("E061", 5)
    src = tmp_path / "p.cl8"
    src.write_text("PROGRAM 7;\nCHANNEL NC 0;\nPAR INTEGER: R1;\nBEGIN\n  ESS;\n  R1 = 1;\nEND.\n")
    assert check(src) == []
