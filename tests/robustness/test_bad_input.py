"""Bad input found by mutating the test programs: each gives a diagnostic or a run-time fault, never a traceback.

Every case here once escaped as a Python exception; the expected code is the
front end's own for that kind of mistake.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from ncvm.api import check

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
