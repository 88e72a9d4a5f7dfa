"""Formatted output (CPL manual §6, L4015-4040; §7, L4539-4612; §5, L3514-3539): templates, the template queue, standard formats, LJUST, overflow."""

from __future__ import annotations

import math

import pytest

from ncvm.dialects.cpl.io.errors import CplRuntimeError
from ncvm.dialects.cpl.io.format import format_items, standard_text
from ncvm.dialects.cpl.io.values import Double


def out(*items, **kw):
    return format_items(items, **kw).text


def test_sqrt_table_template_in_loop():
    # L4565-4577: DSP(LIN%+I%,COL%,"###.### IS ROOT OF ##",SQRT(I%),I%)
    lines = [out("###.### IS ROOT OF ##", math.sqrt(i), i) for i in range(1, 11)]
    assert lines[0] == "  1.000 IS ROOT OF  1"
    assert lines[1] == "  1.414 IS ROOT OF  2"
    assert lines[2] == "  1.732 IS ROOT OF  3"
    assert lines[9] == "  3.162 IS ROOT OF 10"


def test_standard_formats_real():
    # L4579-4585: A=25 : B=SQRT(A): DSP(Z,S,"A=",A," B=",B," C= ",A+B); REAL is ####.### (CPL manual L3524-3528; L4554-4556)
    assert out("A=", 25.0, " B=", 5.0, " C= ", 30.0) == "A=  25.000 B=   5.000 C=   30.000"


def test_template_queue_over_several_strings():
    # L4587-4601: FA$=" A= ###.#" : FB$=" B= #.#" : FC$=" C= ##" : DSP(Z%,S%,FA$,FB$,FC$,A,B,B+A)
    assert out(" A= ###.#", " B= #.#", " C= ##", 25.0, 5.0, 30.0) == " A=  25.0 B= 5.0 C= 30"


def test_boolean_and_strings_print_in_place_templates_take_later_numbers():
    # L4603-4612 repaired (CPL manual L4603-4612): DSP(5,1,"XPOS ###.### YPOS ###.###",T1$,B?,X,Y,T2$,I%)
    text = out("XPOS ###.### YPOS ###.###", " MEAS.PROBE=", True, 1.5, 2.5, " NO.=", 200)
    assert text == "XPOS   1.500 YPOS   2.500 MEAS.PROBE=TRUE NO.=      200"


def test_prn_templates_over_several_arguments():
    # L4080-4097 (A$ = 5000 read as a numeric variable): one record
    text = out("######", "###.####", "#.######", 5000, 1.231, Double(4 / 3), "ABCDE", "CDEFGHI")
    assert text == "  5000  1.23101.333333ABCDECDEFGHI"


def test_standard_integer_double_boolean_nul():
    assert standard_text(200, "I") == "      200"
    assert standard_text(-123456789, "I") == "-123456789"  # widened, never cut
    assert standard_text(Double(1.5), "D") == "        1.500000"
    assert out(Double(4 / 3)) == "        1.333333"
    assert out(2.5) == "   2.500"
    assert out(False, None, True) == "FALSETRUE"


def test_surplus_templates_print_as_hashes():
    assert out("A=### B=###", 7) == "A=  7 B=###"
    assert out("NO #") == "NO #"


def test_rounding_half_away_from_zero_and_minus_sign_takes_a_position():
    assert out("#", 2.5) == "3"
    assert out("##.#", -1.25) == "-1.3"
    assert out("#.##", -0.001) == "0.00"  # no negative zero
    assert out("##", -5) == "-5"


def test_overflow_star_for_prn_error_for_dsp():
    result = format_items(["X=#.#", -1.5])
    assert result.text == "X=***" and result.overflows == 1
    result = format_items(["##", 123])
    assert result.text == "**" and result.overflows == 1
    with pytest.raises(CplRuntimeError) as err:
        format_items(["##", 123], on_overflow="error")
    assert err.value.message.startswith("format not permitted")


def test_ljust_drops_leading_blanks():
    assert out("X", 1.5, " Y", 20, ljust=True) == "X1.500 Y20"
    assert out("X###.###", 1.5, ljust=True) == "X1.500"
    assert out(3, ". Record", ljust=True) == "3. Record"  # L4301 example


def test_real_reads_as_seven_digit_decimal():
    import struct
    r = struct.unpack("<f", struct.pack("<f", 1.231))[0]  # a REAL variable holds binary32
    assert out("#.####", r) == "1.2310"
    assert out("#.###", struct.unpack("<f", struct.pack("<f", 0.0005))[0]) == "0.001"


def test_integer_in_template_with_decimals():
    assert out("###.##", 7) == "  7.00"
