"""Chapter 5 string functions, each manual example with its stated (or OCR-repaired) result."""

from __future__ import annotations

import pytest

from ncvm.dialects.cpl.io import strings as S
from ncvm.dialects.cpl.io.errors import CplRuntimeError


def field(size, text=None):
    f = S.CharacterField(size)
    if text is not None:
        f.assign(text)
    return f


def error_of(fn, *args, **kw):
    with pytest.raises(CplRuntimeError) as err:
        fn(*args, **kw)
    return err.value


def test_dim_limits():
    assert field(1024).size == 1024
    assert error_of(S.CharacterField, 0).message == "INVALID FIELD LIMIT: DIM size 0 (1..1024)"
    assert error_of(S.CharacterField, 1025).code == "CPL022"


def test_s1_mid_into_dimensioned_copies_into_variable_is_a_view():
    # L3381-3401: DIM A$(10): DIM B$(5): A$="ABCDEFGHIJ": B$=MID$(A$,2,5): C$=MID$(A$,2,5): A$="QRSTUVWXYZ"
    a, b = field(10, "ABCDEFGHIJ"), field(5)
    b.assign(S.mid(a, 2, 5))
    c = S.string_variable_value(S.mid_for_variable(a, 2, 5))
    assert b.text == "BCDEF" and c.text == "BCDEF"
    a.assign("QRSTUVWXYZ")
    assert b.text == "BCDEF" and c.text == "RSTUV"


def test_s2_mid_write_at_length_plus_one_and_plus_two():
    # L3417-3429
    a = field(10, "ABC")
    S.mid_write(a, 4, 3, "DEF")
    assert a.text == "ABCDEF"
    a = field(10, "ABC")
    err = error_of(S.mid_write, a, 5, 3, "DEF")
    assert err.message.startswith("CHARACTER FIELD NOT ASSIGNED")


def test_s3_len():
    # L3439-3449
    xyz = field(10, "ABC")
    assert S.length(xyz) == 3
    xyz.assign("")
    assert S.length(xyz) == 0
    xyz.assign(None)
    assert S.length(xyz) == -1


def test_s4_instr():
    # L3463-3476
    a = field(8, "A")
    S.mid_write(a, 2, None, "UVWXYZ")
    b = field(16, "ABCDEF UVWXYZ GH")
    assert S.instr(S.mid(a, 2), b, 4) == 8
    assert S.instr(S.mid(a, 2, 4), b, 10) == 0
    assert S.instr(S.mid(a, 2), b) == 8
    assert S.instr("UVWXYZ", "ABCDEF UVWXYZ GH", 4) == 8
    assert error_of(S.instr, "A", "B", 0).message.startswith("INVALID PARAMETER")


def test_s5_asc_chr():
    # L3490-3512: DIM A$(1): A$="ABC" keeps "A"
    a = field(1, "ABC")
    assert S.asc(a) == 65 and S.asc("BCD") == 66
    a.assign("")
    assert S.asc(a) == -1
    a.assign(None)
    assert S.asc(a) == -1
    a.assign(S.chr_(65))
    assert a.text == "A"
    assert S.chr_(35) == "#"
    assert error_of(S.chr_, 256).code == "CPL023"


def test_s6_str():
    # L3530-3539, L3797-3801
    assert S.str_("number = ##.###", 37 / 3) == "number = 12.333"
    assert S.str_("A$ = ##.###", 37 / 3) == "A$ = 12.333"
    assert S.str_(2.5) == "   2.500"
    assert S.str_(42) == "       42"
    err = error_of(S.string_variable_value, S.str_(2.5), computed=True)
    assert err.code == "CPL025"


def test_s7_val():
    # L3547-3569
    assert error_of(S.val_integer, "1.23DE").message.startswith("INVALID ASSIGNMENT")
    assert S.val_integer("123DE") == 123
    assert S.val_integer("ABC") is None
    assert S.val("-1.23DE") == pytest.approx(-1.23)
    assert S.val("+ 000001234TEST4365") == 1234
    assert S.val("ABC1.23DE") is None
    assert S.val("1234567.234567") == 1234567.234567
    assert S.val(None) is None


def test_s8_trim():
    # L3587-3594
    a = " ABCDEF "
    assert S.trim(a, "L") == "ABCDEF "
    assert S.trim(a, "R") == " ABCDEF"
    assert S.trim(a) == "ABCDEF"
    assert error_of(S.trim, a, "X").code == "CPL023"


def test_s9_forbidden_forms_on_string_variables():
    # L3599-3614: MID$(A$,1,4)="ABCD", A$=MID$(..)+MID$(..), A$=B$+A$ on non-dimensioned A$
    a = "ABCDEFGHIJKLMN"
    assert S.mid(a, 2, 1) == "B" and S.mid(a, 4, 4) == "DEFG"
    assert error_of(S.mid_write, a, 1, 4, "ABCD").code == "CPL025"
    assert error_of(S.string_variable_value, S.concat(S.mid(a, 1, 3), S.mid(a, 4, 1)), computed=True).code == "CPL025"


def test_s10_reading_and_writing_character_fields():
    # L3623-3696
    vwx = field(13, "TEST TEST TES")
    assert S.mid(vwx, 12, 1) == "E"
    xyz = field(15)
    S.mid_write(xyz, 1, 5, "ABCDE")
    S.mid_write(xyz, 6, 5, "ABCDE")
    assert xyz.text == "ABCDEABCDE"
    xyz = field(15)
    assert error_of(S.mid_write, xyz, 6, 5, "ABCDE").code == "CPL024"
    xyz = field(100)
    S.mid_write(xyz, 1, 10, "ABCDE")
    assert xyz.text == "ABCDE" and S.length(xyz) == 5
    S.mid_write(xyz, 6, 3, "T")
    assert xyz.text == "ABCDET" and S.length(xyz) == 6
    xyz = field(100)
    S.mid_write(xyz, 1, 10, "1234567890")
    S.mid_write(xyz, 3, 3, "T")
    assert xyz.text == "12T4567890" and S.length(xyz) == 10
    xyz = field(100)
    S.mid_write(xyz, 1, 6, "ABCDEF")
    assert error_of(S.mid_write, xyz, 9, 5, "TESTE").code == "CPL024"


def test_s11_assignment_length_and_truncation():
    # L3702-3747; the figures for lines 5-7 are lost, the results follow the MID$ write rules
    xyz = field(16, " ")
    assert xyz.text == " " and S.length(xyz) == 1
    xyz = field(3, "ABCDEF")
    assert xyz.text == "ABC" and S.length(xyz) == 3
    xyz = field(16)
    S.mid_write(xyz, 1, 4, "DAS ")
    assert xyz.text == "DAS "
    S.mid_write(xyz, 5, 6, "IST EIN TEST")
    assert xyz.text == "DAS IST EI"
    S.mid_write(xyz, 5, 12, "IST EIN TEST")
    assert xyz.text == "DAS IST EIN TEST"


def test_s12_comparisons_by_ascii():
    # L3753-3769
    a, b, c, d = field(10, "ANTON"), field(15, "WILLY"), "ABCDE", "VWXYZ"
    assert S.compare(a, b) < 0
    assert S.compare(S.mid(a, 2, 3), S.mid(b, 1, 3)) != 0
    assert S.compare(a, "TEST") != 0
    assert S.compare("A", "C") < 0
    assert not S.compare(c, d) > 0
    assert S.compare(a, c) != 0
    assert S.compare("TE", S.mid(d, 2, 2)) < 0  # "TE" < "WX"


def test_s14_chaining_into_fields():
    # L3781-3795 (A$ has length 5, CPL manual L3783)
    a, b = field(100, "THIS "), field(100, "IS A TEST")
    c, d, e = field(10), field(20), field(30)
    S.mid_write(c, 1, 6, S.concat(a, b))
    S.mid_write(d, 1, 10, S.concat(S.mid(a, 1, 1), S.mid(b, 1, 2)))
    e.assign(S.concat(a, S.mid(b, 1)))
    x, y = "ABC", "DE"
    f, g, h, i = field(30), field(30), field(30), field(30)
    f.assign(S.concat(x, y))
    g.assign(S.concat(x, a))
    h.assign(S.concat(x, a, "TEST"))
    i.assign(S.concat("TES", "T1"))
    assert (a.text, S.length(a)) == ("THIS ", 5)
    assert (c.text, S.length(c)) == ("THIS I", 6)
    assert (d.text, S.length(d)) == ("TIS", 3)
    assert (e.text, S.length(e)) == ("THIS IS A TEST", 14)
    assert (f.text, S.length(f)) == ("ABCDE", 5)
    assert (g.text, S.length(g)) == ("ABCTHIS ", 8)
    assert (h.text, S.length(h)) == ("ABCTHIS TEST", 12)
    assert (i.text, S.length(i)) == ("TEST1", 5)
    err = error_of(S.concat, "A", "B", "C", "D")
    assert (err.code, err.message) == ("2153", "NESTING TOO DEEP: 4 strings chained, at most 3")


def test_s15_val_on_mid_slices():
    # L3803-3807 with the OCR damage repaired
    folge = field(20, "XVALUE -0001.234 MM")
    assert S.val(S.mid(folge, 7)) == pytest.approx(-1.234)
    assert S.val_integer(S.mid(folge, 7, 6)) == -1
    assert S.val_integer(S.mid(folge, 15, 5)) == 34
    assert S.val_integer(S.mid(folge, 18)) is None


def test_s16_len_of_literal_field_variable_and_chain():
    # L3809-3819 (line 7 repaired to LEN(S$+Z$+S$), CPL manual L3817)
    z = field(10, "TEST")
    s = "TEST"
    assert (S.length("TEST"), S.length(z), S.length(s)) == (4, 4, 4)
    assert S.length(S.concat(s, z, s)) == 12


def test_s17_mid_read_reference_values():
    # L3821-3823
    a = field(4, "ABCD")
    assert S.mid(a, 2, 2) == "BC"
    assert S.mid(a, 2, 5) == "BCD"
    assert S.mid(a, 5, 1) is None
    f = field(10, S.mid(a, 2))
    assert f.text == "BCD"
    f.assign(S.mid(f, 1, 1))
    assert f.text == "B"
    assert error_of(S.mid, a, 0).code == "CPL023"
    assert error_of(S.mid, a, 1, 1025).code == "CPL023"


def test_s17_mid_write_reference_values():
    # L3825-3827
    a, b, c = field(4, "ABCD"), field(10, "1234567890"), field(10, "EFGHIJKLMN")
    d = field(10, a)
    assert d.text == "ABCD"
    S.mid_write(d, 2, 3, b)
    assert d.text == "A123"
    S.mid_write(d, 5, 1, c)
    assert d.text == "A123E"
    S.mid_write(d, 4, None, b)
    assert d.text == "A121234567"


def test_s17_trim_reference_values():
    # L3829-3833; the OCR put blanks around "=": only "XVALUE=0.123 " gives all four stated results
    xyz = field(16, "XVALUE=0.123 ")
    a = S.string_variable_value(S.mid_for_variable(xyz, 8))
    assert a.text == "0.123 "
    assert S.trim(S.mid(xyz, 8)) == "0.123"
    assert S.trim(S.mid(xyz, 8), "L") == "0.123 "
    assert S.trim(S.mid(xyz, 8), "R") == "0.123"


def test_character_table_rows():
    cd = S.CharacterTable(9, 2)
    cd.row(3).assign("DEF")
    assert cd.row(3).text == "DE" and cd.row(2).text is None
    assert error_of(cd.row, 10).code == "CPL023"
