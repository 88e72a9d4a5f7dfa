"""One error, one code: the manual names its errors by text, and each text gets one code
whichever statement raises it (INVALID INTEGER VALUE, L4130, was CPL027 in arithmetic and CPL027 in INP#;
INVALID PARAMETER, L3390, was CPL023 in the string and file functions and CPL023 in graphics)."""

from __future__ import annotations

from collections import defaultdict

import pytest

from ncvm.dialects.cpl.errors import CODES
from ncvm.dialects.cpl.io.errors import ERRORS


def test_each_manual_error_text_has_one_code():
    codes = defaultdict(set)
    for code, (text, _where) in CODES.items():
        codes[text.upper()].add(code)
    for code, text, _where in ERRORS.values():
        codes[text.upper()].add(code)
    # "runtime error" is the manual's word for errors it gives no text (§4.2-4.9); ncvm's codes tell them apart
    shared = {text: sorted(c) for text, c in codes.items() if len(c) > 1 and text != "RUNTIME ERROR"}
    assert shared == {}


@pytest.fixture
def run(run_text, tmp_path):
    root = tmp_path / ".ncvm" / "files"
    root.mkdir(parents=True)
    return lambda text: run_text(text, name="p.cpl")


@pytest.mark.parametrize("text", [
    "10 A%=2147483647\n20 A%=A%+1\nM30\n",  # arithmetic (CPL manual §2.4.3, L650-737)
    '10 OPENW(1,"P1") : PRN#(1,"3000000000") : CLOSE(1)\n20 OPENR(1,"P1") : INP#(1,A%)\nM30\n',  # INP#, L4130
])
def test_invalid_integer_value_is_cpl027_everywhere_l4130(run, text):
    r = run(text)
    assert r["error"]["code"] == "CPL027" and r["error"]["message"].startswith("INVALID INTEGER VALUE")


@pytest.mark.parametrize("text", [
    '10 DIM A$(5) : A$="ABC" : B%=INSTR("B",A$,0)\nM30\n',  # string function, L3461
    "10 COL(9)\nM30\n",  # graphics colour code 0..7 (L4938)
])
def test_invalid_parameter_is_cpl023_everywhere_l3390(run, text):
    r = run(text)
    assert r["error"]["code"] == "CPL023" and r["error"]["message"].startswith("INVALID PARAMETER")


@pytest.mark.parametrize("text", [
    "10 D! = 1000000000000000000000000000000.0\n20 R = D! * D!\nM30\n",  # a REAL beyond +/-1e38
    '10 OPENW(1,"P1") : PRN#(1,"1' + "0" * 400 + '") : CLOSE(1)\n20 OPENR(1,"P1") : INP#(1,D!)\nM30\n',  # L4130
])
def test_invalid_float_value_is_cpl042_everywhere_l4130(run, text):
    r = run(text)
    assert r["error"]["code"] == "CPL042" and r["error"]["message"].startswith("INVALID FLOAT VALUE")
