"""Bad input found by mutating the test programs: each gives a diagnostic or a run-time fault, never a traceback.

Every case here once escaped as a Python exception; the expected code is the
front end's own for that kind of mistake.
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from ncvm.api import check, run
from ncvm.runtime.session import RunOptions

EXAMPLES = Path(__file__).parent.parent.parent / "examples"

CASES = [
    # CPL: a character that starts nothing inside an [expr] word of an NC block
    ("p.cpl", "10 C% = 81\nN20 G[C@%] X10\nM30\n", "check", "CPL001"),
    # CPL: MID$ with one argument into a string variable (a live view needs the start position)
    ("p.cpl", '10 DIM A$(10)\n20 A$="ABC"\n30 C$=MID$(A$)\nM30\n', "check", "CPL001"),
    # SINUMERIK: R parameters end at R999
    ("p.mpf", "%MPF1\nN10 R60=60 G90 @447 R99999999999960 X20\nM30\n", "run", "SIN001"),
    ("p.mpf", "%MPF1\nN10 R99999=1\nM30\n", "run", "SIN001"),
    # SINUMERIK: a block push of R51 to R50 (no range), and a pop that does not match its push
    ("p.mpf", "%MPF1\nN10 @041 R51 R50\nN20 @043 R50 R51\nM30\n", "run", "SIN003"),
    ("p.mpf", "%MPF1\nN10 @041 R50 R51\nN20 @043 R50 R52\nM30\n", "run", "SIN006"),
    # rw_SymPas: a real constant beyond the double range
    ("p.sap", "program p;\nbegin\n  JAW(A1 := 100.1e990);\nend.\n", "check", "SP010"),
]


@pytest.mark.parametrize("name, text, how, code", CASES)
def test_no_traceback(run_text, tmp_path, name, text, how, code):
    if how == "check":
        path = tmp_path / name
        path.write_text(text, encoding="latin-1")
        diags = check(path)
        assert diags and diags[0].severity == "error"
        if code:
            assert diags[0].code == code
    else:
        r = run_text(text, name=name)
        assert r["status"] == "error"
        assert r["error"]["code"] == code


CL8 = "PROGRAM 9;\nCHANNEL NC 0;\nLOCAL REAL: R60;\nBEGIN\n"
DIGITS_4400 = "1" * 4400
DIGITS_400 = "1" * 400

#: issue 12, each once an internal error: (file name, text, code, line, column) at both check and run
NO_CRASH = [
    # Latin-1 letters and superscript digits are no letters or digits of the controls
    ("latin.cl8", CL8 + "  R60 = é;\nEND.\n", "E053", 5, 9),
    ("latin2.cl8", CL8 + "  Rß60 = 1;\nEND.\n", "E053", 5, 4),
    ("name.cpl", "10 Aé=1\nM30\n", "CPL001", 1, 5),
    ("name.sap", "program p;\nvar aé: integer;\nbegin\nend.\n", "SP001", 2, 6),
    ("sup.cpl", "¹10 A=1\nM30\n", "CPL001", 1, 1),
    ("sup.cpl", "10 A=1.²\nM30\n", "CPL001", 1, 8),
    ("sup.sap", "program p;\nvar i: integer;\nbegin\n  i := ³;\nend.\n", "SP001", 4, 8),
    ("task.sap", "{$TASK ¹}\nprogram p;\nbegin\nend.\n", "SP010", 1, 1),
    # number constants beyond every range (Python converts at most 4300 digits)
    ("big.cl8", CL8 + f"  R60 = {DIGITS_4400};\nEND.\n", "E050", 5, 9),
    ("big.cpl", f"10 A={DIGITS_4400}\nM30\n", "CPL001", 1, 6),
    ("big.cpl", f"10 A!={DIGITS_400}.5\nM30\n", "CPL001", 1, 7),
    ("big.cpl", f"{DIGITS_4400} A=1\nM30\n", "CPL001", 1, 1),
    ("param.cpl", f"10 A=P{DIGITS_4400}\nM30\n", "CPL001", 1, 6),
    ("param.cpl", "10 A=P1000\nM30\n", "CPL001", 1, 6),
    ("r.mpf", f"%MPF1\nN10 R{DIGITS_4400}=1\nM30\n", "SIN001", 2, 5),
    ("n.mpf", f"%MPF1\nN{DIGITS_4400} X1\nM30\n", "SIN001", 2, 1),
    # a 400-digit coordinate or R value: an NC word has at most 8 decades
    ("coord.din", f"G0 X{DIGITS_400}\nM30\n", "NC001", 1, 4),
    ("coord.din", "G0 X123456789\nM30\n", "NC001", 1, 4),
    ("coord.cpl", f"10 A=1\nN20 G1 X{DIGITS_400} F100\nM30\n", "CPL001", 2, 8),
    ("r.mpf", f"%MPF1\nN10 R1={DIGITS_400}\nM30\n", "SIN001", 2, 8),
    ("r.mpf", f"%MPF1\nN10 G1 X{DIGITS_400} F100\nM30\n", "SIN001", 2, 9),
    ("k.mpf", f"%MPF1\nN10 @200 R1 K{DIGITS_400}\nM30\n", "SIN001", 2, 14),
    # nesting: the manual's block level, else ncvm's limit (NEST001), at the line where it is exceeded
    ("deepif.cl8", CL8 + "IF R60 = 0 THEN\n" * 1000 + "R60 = 1;\n" + "ENDIF;\n" * 1000 + "END.\n", "E058", 15, 1),
    ("deep.cl8", CL8 + "  R60 =\n" + "(\n" * 1000 + "1" + ")" * 1000 + ";\nEND.\n", "NEST001", 70, 1),
    ("begin.cl8", CL8 + "BEGIN\n" * 1000 + "R60 = 1;\n" + "END;\n" * 1000 + "END.\n", "NEST001", 69, 1),
    ("chain.cl8", CL8 + "  R60 = 1" + "\n + 1" * 3000 + ";\nEND.\n", "NEST001", 70, 2),
    ("deep.sap", "program p;\nvar i: integer;\nbegin\n  i :=\n" + "(\n" * 1000 + "1" + ")" * 1000 + ";\nend.\n",
     "NEST001", 69, 1),
    ("deepif.sap", "program p;\nvar i: integer;\nbegin\n" + "if i = 0 then\n" * 1000 + "i := 1;\nend.\n",
     "NEST001", 68, 1),
    ("loops.sap", "program p;\nvar i: integer;\nbegin\n" + "while i < 1 do\n" * 17 + "i := 1;\nend.\n",
     "NEST001", 20, 1),
    ("chain.sap", "program p;\nvar i: integer;\nbegin\n  i := 1" + "\n + 1" * 600 + ";\nend.\n", "NEST001", 69, 2),
    ("unary.cpl", "10 A=" + "-" * 1000 + "1\nM30\n", "2153", 1, None),
]


@pytest.mark.parametrize("name, text, code, line, col", NO_CRASH)
def test_no_internal_error_at_check_and_run(run_text, tmp_path, name, text, code, line, col):
    path = tmp_path / name
    path.write_text(text, encoding="latin-1")
    first = check(path)[0]
    assert (first.code, first.span.line) == (code, line), first.render()
    if col is not None:
        assert first.span.column == col, first.render()
    r = run_text(text, name=name)
    assert (r["error"]["code"], r["error"]["line"]) == (code, line), r["error"]


@pytest.mark.parametrize("name, text", [
    ("bom.cl8", CL8 + "  R60 = 1;\nEND.\n"), ("bom.cpl", "10 A=1\nM30\n"), ("bom.din", "G0 X1\nM30\n"),
    ("bom.mpf", "%MPF1\nN10 R1=1\nM30\n"), ("bom.sap", "program p;\nbegin\nend.\n"),
])
def test_a_byte_order_mark_is_read_as_nothing(run_text, tmp_path, name, text):
    path = tmp_path / name
    path.write_bytes(b"\xef\xbb\xbf" + text.encode("latin-1"))
    assert check(path) == []
    result, _ = run(path, options=RunOptions(state_dir=tmp_path / ".ncvm"))
    assert result["status"] == "ok", result["error"]


def test_a_byte_order_mark_keeps_the_columns_of_the_first_line(tmp_path):
    path = tmp_path / "p.cpl"
    path.write_bytes(b"\xef\xbb\xbf10 A=(1\nM30\n")
    d = check(path)[0]
    assert (d.code, d.span.line, d.span.column) == ("CPL001", 1, 7)
    assert "\n    10 A=(1\n" in d.render()


@pytest.mark.parametrize("command", ["MLAW(A1 := 1e308)", "MLA(A1 := 1e308)", "MLRW(A1 := 1e308)",
                                     "JAW(A1 := 1e308)"])
def test_a_target_beyond_the_card_range_is_an_invalid_parameter(run_text, command):
    r = run_text(f"program p;\nbegin\n  {command};\nend.\n", name="p.sap")
    assert (r["error"]["code"], r["error"]["line"]) == ("32768", 3), r["error"]


def test_a_sharp_s_in_a_cpl_string_keeps_the_columns_after_it(run_text):
    # str.upper() made ß two letters: the closing quote was looked for one place too far
    r = run_text('10 A$="ßßß":B=7\n20 PRN#(0,A$,B)\nM30\n', name="p.cpl")
    assert r["status"] == "ok", r["error"]
    assert r["variables"]["B"] == 7.0


def test_number_run_into_a_name_in_cl800(tmp_path):
    """A digit followed by '_' (a mangled name such as act.999_depth) is a bad name, not a crash."""
    text = (EXAMPLES / "cl800" / "deep_hole_drilling.cl8").read_text(encoding="latin-1")
    assert "act._depth" in text
    path = tmp_path / "p.cl8"
    path.write_text(text.replace("act._depth", "act.999999999999_depth"), encoding="latin-1")
    diags = check(path)
    assert diags and diags[0].severity == "error" and diags[0].span.line == text[:text.index("act._depth")].count("\n") + 1


def test_control_characters_in_graphic_text(run_text):
    """GPR with CHR$(13): a control character takes a blank place (it has no glyph)."""
    r = run_text('10 GPR(100,100,CHR$(13)+"A"+CHR$(10))\nM30\n', name="p.cpl")
    assert r["status"] == "ok", r["error"]


R_OVERFLOW = "N10 R1=99999999 R5=15000\nN20 R2=R1*R1*R1*R1\nN30 R3=R2*R2*R2*R2*R2*R2*R2*R2*R2\n"


# the first block beyond +/-99999999 (N20, line 3) stops the run since issue 15 (L7079); these programs
# reached infinity and NaN only because the values between the R range and the double range were stored
@pytest.mark.parametrize("name, text, line", [
    # a product beyond the double range was infinity: the move went to X inf with an inf cycle time
    ("inf.mpf", "%MPF1\n" + R_OVERFLOW + "N40 R4=R3*R3\nN50 G1 X=R4 F100\nM30\n", 3),
    # infinity less infinity was NaN, a position of NaN
    ("nan.mpf", "%MPF1\n" + R_OVERFLOW + "N40 R4=R3*R3-R3*R3\nN50 G1 X=R4 F100\nM30\n", 3),
    ("feed.mpf", "%MPF1\n" + R_OVERFLOW + "N40 R4=R3*R3\nN50 G1 X10 F=R4\nM30\n", 3),
    # SQRTS of two huge values
    ("sqrts.mpf", "%MPF1\n" + R_OVERFLOW + "N40 R4=R3*R1*R1*R5\nN50 @614 R6 R4 R4\nN60 G1 X=R6 F100\nM30\n", 3),
    ("inf.cl8", CL8 + "  R60 = 99999999;\n" + "  R60 = R60*R60*R60*R60;\n" * 4 + "  (:G01 X=R60 F100:); LF;\nEND.\n",
     None),
])
def test_an_r_value_beyond_the_double_range_is_the_cl800_error(run_text, name, text, line):
    r = run_text(text, name=name)
    assert r["status"] == "error" and r["error"]["code"] == "CL800", r["error"]
    assert "outside the R parameter range" in r["error"]["message"]
    if line is not None:
        assert r["error"]["line"] == line
    assert r["motion"]["feed_moves"] == 0


@pytest.mark.parametrize("fn", ["SIN", "COS", "sin", "cos"])
def test_sin_and_cos_of_infinity_give_no_valid_value_in_sympas(run_text, fn):
    """A math function's invalid argument gives NaN, no error (rw_SymPas manual §6.6, L1643-2172); SIN(inf) was an internal error."""
    r = run_text(f"program p;\nvar x: double;\nbegin\n  x := 1e300;\n  x := {fn}(x * x);\n  writeln(x);\nend.\n",
                 name="p.sap")
    assert r["status"] == "ok", r["error"]
    assert r["output"] == ["nan"]


@pytest.mark.parametrize(("statement", "output"), [
    ("writeln(SIN(x * x))", ["nan", "1e+300"]), ("writeln(COS(x * x) + 1)", ["nan", "1e+300"]),
    ("if COS(x * x) <> COS(x * x) then writeln('nan')", ["nan", "1e+300"]),
    ("x := SIN(x * x) + twice(x)", ["twice", "nan"])])
def test_sin_and_cos_of_infinity_give_nan_in_every_context(run_text, statement, output):
    """Outside a plain assignment (and in one with a routine call, which must run once) SIN and COS check
    their argument inline; a plain assignment catches the unchecked function's error instead."""
    text = ("program p;\nvar x: double;\nfunction twice(v: double): double;\nbegin\n  writeln('twice');\n"
            f"  twice := v + v;\nend;\nbegin\n  x := 1e300;\n  {statement};\n  writeln(x);\nend.\n")
    r = run_text(text, name="p.sap")
    assert r["status"] == "ok", r["error"]
    assert r["output"] == output


@pytest.mark.parametrize("command", ["MCRW(A1 := 1.0, A2 := 0.0, PHI := 1e300)",
                                     "MHRW(A1 := 1.0, A2 := 0.0, PHI := 1e20, A3 := 1.0)",
                                     "MCR3DW(A1 := 1.0, A2 := 0.0, A3 := 0.0, PHI := 1e300, PN3 := 1.0)"])
def test_an_arc_beyond_the_card_range_is_an_invalid_parameter(run_text, command):
    """PHI := 1e300 was an internal error (OverflowError), PHI := 1e20 a helix of 1.7e16 s."""
    r = run_text(f"program p;\nbegin\n  {command};\nend.\n", name="p.sap")
    assert (r["error"]["code"], r["error"]["line"]) == ("32768", 3), r["error"]
    assert "beyond the card's position range" in r["error"]["message"]


def check_in_a_child(path: Path) -> str:
    """``ncvm check`` of ``path`` in a child process, its diagnostics; the generous timeout only guards
    against a hang (the behaviour is the diagnostic, not the time it took)."""
    done = subprocess.run([sys.executable, "-m", "ncvm", "check", str(path)], capture_output=True, text=True,
                          timeout=600)
    assert done.returncode == 1, done.stderr
    return done.stdout + done.stderr


def test_a_long_line_of_letters_is_read_in_linear_time(tmp_path):
    """Each letter scanned the rest of its run for an extended address (Q1=25): 80,000 letters took 300 s."""
    path = tmp_path / "p.mpf"
    path.write_text("%MPF1\nN10 " + "A" * 100_000 + "\nM30\n", encoding="latin-1")
    assert f"{path}:2:5: error SIN001" in check_in_a_child(path)


#: characters str.splitlines() takes for line ends that no control does: FF (a printed listing's page
#: break), VT, FS/GS/RS and NEL (byte 85 of Latin-1)
NOT_LINE_ENDS = ["\f", "\v", "\x1c", "\x1d", "\x1e", "\x85"]


@pytest.mark.parametrize("char", NOT_LINE_ENDS)
@pytest.mark.parametrize("name, text, line, source", [
    ("p.din", "G0 X0 (page{c}break)\nG1 X@ F100\nM30\n", 2, "G1 X@ F100"),
    ("p.cpl", "(page{c}break)\n10 A=(\nM30\n", 2, "10 A=("),
    ("p.mpf", "%MPF1\nN10 (page{c}break) G0 X0\nN20 X@\nM30\n", 3, "N20 X@"),
    ("p.sap", "program p;\n{{ page{c}break }}\nbegin\n  x := 1;\nend.\n", 4, "  x := 1;"),
    ("p.cl8", "PROGRAM 9;\nCHANNEL NC 0;\n(* page{c}break *)\nBEGIN\n  R60 = @;\nEND.\n", 5, "  R60 = @;"),
])
def test_only_lf_cr_end_a_line(tmp_path, char, name, text, line, source):
    """A form feed in a comment broke the comment in two and shifted the lines after it (and the source
    line shown with a diagnostic was another one)."""
    path = tmp_path / name
    path.write_text(text.format(c=char), encoding="latin-1")
    d = check(path)[0]
    assert d.span.line == line, d.render()
    assert d.render().split("\n")[1] == "    " + source


def test_a_file_is_read_once_for_all_its_diagnostics(tmp_path, monkeypatch):
    """ncvm check read the file again for each diagnostic: 100,000 bad lines took minutes."""
    from ncvm import diagnostics

    path = tmp_path / "p.din"
    path.write_text("G1 X@\n" * 50, encoding="latin-1")
    diags = check(path)
    reads = []
    real = diagnostics.read_lines_at
    monkeypatch.setattr(diagnostics, "read_lines_at", lambda p, numbers: reads.append(p) or real(p, numbers))
    rendered = diagnostics.render_all(diags)
    assert len(diags) == 50 and len(reads) == 1
    assert rendered[49].split("\n")[1] == "    G1 X@"


def test_long_numbers_before_a_bad_character_are_read_at_once(tmp_path):
    """The clean-line regex tried every split of every digit run: three 300-digit words and an '@' never ended
    (found by the fuzz test)."""
    path = tmp_path / "p.din"
    path.write_text("G1 " + " ".join("X" + "1" * 300 for _ in range(3)) + " @\nM30\n", encoding="latin-1")
    out = check_in_a_child(path)
    assert f"{path}:1:" in out and "error NC001" in out, out


@pytest.mark.parametrize("name", ["L5.spf", "other.mpf"])
def test_a_byte_order_mark_is_read_as_nothing_in_a_sin800_sub_program(tmp_path, name):
    """Issue 15 (SINUMERIK 9): a sub-program found by its name or by its %SPF header, saved with a BOM."""
    (tmp_path / name).write_bytes(b"\xef\xbb\xbf%SPF5\nN001 R20=200\nM17\n")
    (tmp_path / "main.mpf").write_text("%MPF1\nL5\nM30\n")
    result, _ = run(tmp_path / "main.mpf", options=RunOptions(state_dir=tmp_path / ".ncvm"))
    assert result["status"] == "ok", result["error"]
    assert result["variables"]["R20"] == 200.0
