"""CPL manual examples, strings (CPL manual §5, L3595-3834: MID$, STR$, VAL, string variables and character areas).

Each test runs the manual's program, repaired only where an OCR slip or the
comment says why, and asserts the result the manual states.
"""

from __future__ import annotations

import pytest


def test_s2_mid_write_right_after_the_last_character_l3419(run):
    """§5.3 L3419-3421: writing components 4-6 of "ABC" is allowed (the gap case is bad/mid_gap.cpl)."""
    assert run('1 DIM A$ (10)\n2 A$= "ABC"\n3 MID$ (A$,4,3) ="DEF"\nM30\n')["variables"] == {"A$": "ABCDEF"}


def test_s6_str_with_template_and_default_l3530(run):
    """§5.6 L3530-3539: A$ = "number = 12.333", B$ = "   2.500" (default format, 8 characters)."""
    r = run('10 DIM A$(50)\n20 DIM B$(21)\n30 A$ = STR$("number = ##.###",(37/3))\n40 B$ = STR$(2.5)\nM30\n')
    assert r["variables"] == {"A$": "number = 12.333", "B$": "   2.500"}


def test_s7_val_with_a_decimal_point_into_an_integer_l3549(run):
    """§5.6 L3549 and L3557: line 1 of the VAL example is INVALID ASSIGNMENT (lines 2-7 are val.cpl)."""
    r = run('1 I% = VAL("1.23DE")\n2 K% = VAL("123DE")\nM30\n')
    assert r["error"]["code"] == "CPL021" and r["error"]["line"] == 1
    assert r["error"]["message"].startswith("INVALID ASSIGNMENT")


STRING_VARIABLE = '1 A$="ABCDEFGHIJKLMN"\n2 B$=MID$(A$,2,1)\n3 C$=MID$(A$,4,4)\n'


def test_s9_string_variable_without_dim_l3599(run):
    """§5.8 L3601-3608: a STRING variable takes a string, CHR$ and MID$ parts of another."""
    r = run('1 A$="ABCDE"\n2 B$=CHR$(10)\n3 N%=ASC(B$)\nM30\n')
    assert r["variables"] == {"A$": "ABCDE", "B$": "\n", "N%": 10}
    r = run(STRING_VARIABLE + "M30\n")
    assert r["variables"] == {"A$": "ABCDEFGHIJKLMN", "B$": "B", "C$": "DEFG"}


@pytest.mark.parametrize("line4", ['4 MID$(A$,1,4)="ABCD"', "4 A$=MID$(A$,1,3) + MID$(A$,4,1)", "4 A$=B$ + A$"])
def test_s9_forbidden_forms_on_a_string_variable_l3610(run, line4):
    """§5.8 L3610-3614: each of the three lines 4 is a fault (the variable is not DIMensioned)."""
    r = run(STRING_VARIABLE + line4 + "\nM30\n")
    assert r["error"]["code"] == "CPL025" and r["error"]["line"] == 4


@pytest.mark.parametrize(("text", "line"), [
    ('1 DIM XYZ$(15)\n2 B$="ABCDE"\n4 MID$(XYZ$,6,5)=B$\nM30\n', 3),  # L3646-3650: 1st-5th not assigned
    ('1 DIM XYZ$(100)\n3 MID$(XYZ$,1,6)="ABCDEF"\n5 MID$(XYZ$,9,5)="TESTE"\nM30\n', 3),  # L3688-3694: 7-8
])
def test_s10_character_area_not_used_l3646(run, text, line):
    """§5.8 "CHARACTER AREA NOT USED" (the manual's other wording of CHARACTER FIELD NOT ASSIGNED)."""
    r = run(text)
    assert r["error"]["code"] == "CPL024" and r["error"]["line"] == line
    assert r["error"]["message"].startswith("CHARACTER FIELD NOT ASSIGNED")


def test_s11_mid_write_into_a_16_character_field_l3728(run):
    """§5.8.1 L3728-3745: the figures with the field contents are lost; by the MID$ write rules line 5 gives
    "DAS ", line 6 writes 6 characters ("DAS IST EI"), line 7 twelve, filling all 16 ("the character field
    was cut off" refers to line 6). ``XYZS`` and ``EI''`` are OCR damage."""
    r = run('1 DIM XYZ$(16)\n2 A$="DAS "\n3 B$="IST EIN TEST"\n4 C$="EIN EI"\n5 MID$(XYZ$,1,4)=A$ : R5$=XYZ$\n'
            '6 MID$(XYZ$,5,6)=B$ : R6$=XYZ$\n7 MID$(XYZ$,5,12)=B$ : L%=LEN(XYZ$)\nM30\n')
    v = r["variables"]
    assert (v["R5$"], v["R6$"], v["XYZ$"], v["L%"]) == ("DAS ", "DAS IST EI", "DAS IST EIN TEST", 16)
