"""Expression, condition and block lowering conventions of CL 800 manual L6427-6469; L6386-6413; L461-463; L1222-1226, one small program each."""

from __future__ import annotations

import pytest

from ncvm.dialects import get_dialect
from ncvm.machine.model import Machine

HEAD = "PROGRAM 9;\nCHANNEL NC 0;\nPAR REAL: R5, R6, R7, R8;\nPOINTER: R50;\nBEGIN\n"


def compile_body(body: str) -> list[str]:
    obj = get_dialect("cl800").build("t.cl8", HEAD + body + "\nEND.\n", Machine())
    return obj.text().splitlines()[1:]


@pytest.mark.parametrize("body,first", [
    # parentheses and precedence through temporaries, single-level chains only (ncvm's reading; the CL 800 manual is silent)
    ("R5 = R6 - (R7 - R8);", "@040 K2 R50 R99 R99=R7-R8 R5=R6-R99"),
    ("R5 = R6 + R7 * R8;", "@040 K2 R50 R99 R99=R7*R8 R5=R6+R99"),
    ("R5 = -(R6 + R7);", "@040 K2 R50 R99 R99=R6+R7 R5=-R99"),
    ("R5 = R6 * -R7;", "@040 K2 R50 R99 R99=-R7 R5=R6*R99"),
    ("R5 = -R6 + R7 - 4;", "@040 K1 R50 R5=-R6+R7-4"),
    # pointers never stand in an arithmetic word
    ("[R50] = R6 + 1;", "@040 K2 R50 R99 R99=R6+1 @201 P50 R99"),
    ("R5 = [R50] + 1;", "@040 K2 R50 R99 @201 R99 P50 R5=R99+1"),
    # a constant left of a comparison is loaded into a temporary; a pointer is a <Var>
    ("IF 3 < R5 THEN INC (R6); ENDIF;", "@040 K2 R50 R99 @201 R99 K3 @125 R99 R5 K2001 @620 R6"),
    ("IF [R50] > 3 THEN INC (R6); ENDIF;", "@040 K1 R50 @123 P50 K3 K2001 @620 R6"),
    # functions and system memory reads straight into the target, nested ones through temporaries
    ("R5 = SQRTS (R6 + 1, 2);", "@040 K2 R50 R99 R99=R6+1 @614 R5 R99 K2"),
    ("R5 = ABS (MDN (100));", "@040 K2 R50 R99 @300 R99 K100 @610 R5 R99"),
    ("R5 = R6 > R7;", "@040 K1 R50 @673 R5 R6 R7"),
])
def test_lowering(body: str, first: str):
    assert compile_body(body)[0].startswith(first)


def test_for_with_computed_final_value_reserves_its_temporary():
    blocks = compile_body("FOR R5 := 1 TO R6 * 2 DO R7 = R7 + R5 * 3;")
    # R99 holds the final value for the whole loop, so the body's temporary is R98
    assert blocks == ["@040 K3 R50 R98 R99 @201 R5 K1 R99=R6*2",
                      "N5001 @151 R5 R99 K5002 R98=R5*3 R7=R7+R98 @620 R5 @100 K-5001",
                      "N5002 @042 K3 R50 R98 R99 M17"]


def test_long_case_splits_at_120_characters():
    alts = "\n".join(f"= {i}: INC (R6);" for i in range(1, 21))
    blocks = compile_body(f"CASE R5\n{alts}\nENDCASE;")
    assert all(len(b) <= 120 for b in blocks)
    # each @111 item is atomic: the first (118 characters) does not fit behind the push
    assert blocks[0] == "@040 K1 R50"
    assert blocks[1].startswith("@111 R5 K1 K1001 K2 K1002") and blocks[1].endswith("K12 K1012")
    assert blocks[2] == "@111 R5 K13 K1013 K14 K1014 K15 K1015 K16 K1016 K17 K1017 K18 K1018 K19 K1019 K20 K1020 @100 K1021"
    assert blocks[3] == "N1001 @620 R6 @100 K1021"


def test_goto_backward_and_forward():
    text = ("PROGRAM 9;\nCHANNEL NC 0;\nPAR REAL: R5;\nLABEL: Again, Done;\nBEGIN\n"
            "Again: INC (R5);\nIF R5 < 10 THEN GOTO Again; ENDIF;\nGOTO Done;\nDone: LF;\nEND.\n")
    blocks = get_dialect("cl800").build("t.cl8", text, Machine()).text().splitlines()
    assert blocks == ["%SPF9", "N7001 @620 R5 @125 R5 K10 K2001 @100 K-7001", "N2001 @100 K7002", "N7002", "M17"]


def test_ess_comes_first():
    text = "PROGRAM 9;\nCHANNEL NC 0;\nESS;\nLOCAL REAL: R60;\nBEGIN\nR60 = 1;\nEND.\n"
    assert get_dialect("cl800").build("t.cl8", text, Machine()).text() == \
        "%SPF9\n@00f @040 K1 R60 @201 R60 K1\n@042 K1 R60 M17\n"


def test_bit_number_from_a_constant_and_constants_inline():
    text = ("PROGRAM 9;\nCHANNEL NC 0;\nCONST BITNO := 3, LIMIT := 2.50;\nPAR PATTERN: R10:=INPUT;\n"
            "PAR BOOLEAN: R21;\nBEGIN\n  R21 = INPUT.BITNO; SET BIT (INPUT.BITNO);\n"
            "  IF R21 = 1 THEN R21 = LIMIT; ENDIF;\nEND.\n")
    assert get_dialect("cl800").build("t.cl8", text, Machine()).text() == (
        "%SPF9\n@203 R21 R10 K3 @661 R10 K3 @121 R21 K1 K2001 @201 R21 K2.5\nN2001 M17\n")
