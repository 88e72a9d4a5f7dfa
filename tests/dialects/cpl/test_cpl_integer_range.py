"""INTEGER is 32 bits (manual §2.4.3, L655), also inside expressions and for a FOR counter's exit value."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("goto", ["", "5 GOTO 10\n"])
def test_for_exit_value_beyond_the_integer_range(run, goto):
    """§2.5.5 L934: after the loop the counter is past the end value; past +2147483647 (L655) an INTEGER cannot
    hold it: INVALID INTEGER VALUE at NEXT, in the structured and in the GOTO form of a program alike (the
    structured form used to leave 2147483648 in I%)."""
    r = run(goto + "10 FOR I%=2147483646 TO 2147483647 : NEXT\n20 J% = I%\nM30\n")
    assert r["error"]["code"] == "CPL027" and (r["error"]["line"], r["error"]["column"]) == (1 + bool(goto), 38)


@pytest.mark.parametrize("text, col", [
    ("10 A% = 65536 : B! = A% * A%\n", 17),  # stored into a DOUBLE
    ("10 A% = 2147483647 : B = A% + 1\n", 22),  # stored into a REAL
    ("10 A% = 65536 : IF A% * A% > 0 THEN B = 1 ENDIF\n", 17),  # compared
    ("10 A% = 65536 : X = A% * A% / 2\n", 17),  # divided (the quotient is REAL)
    ("10 A% = -2147483648 : IF -A% > 0 THEN B = 1 ENDIF\n", 23),
])
def test_integer_results_outside_32_bits_are_invalid_integer_value(run, text, col):
    """L655: "An INTEGER variable occupies 32 bits ... -2.147.483.648 through +2.147.483.647"; + - * of two
    INTEGERs is INTEGER (CPL manual §2.4.3, L650-737), so a result past that range is INVALID INTEGER VALUE wherever it is used,
    not only when stored into an INTEGER variable (it used to reach REAL variables and comparisons as 2^32)."""
    r = run(text + "M30\n")
    assert r["error"]["code"] == "CPL027" and r["error"]["column"] == col


def test_integer_expressions_in_range_and_big_constants_are_unchanged(run):
    """L484-490: a constant takes the precision of its context (D2! = -123456789012345 is the manual's)."""
    r = run("10 A% = 6 : B = A% * 2 : D2! = -123456789012345 : E! = 2147483647 * 2\n"
            "20 IF A% * A% = 36 THEN C? = TRUE ENDIF\nM30\n")
    assert r["status"] == "ok", r["error"]
    v = r["variables"]
    assert (v["B"], v["D2!"], v["E!"], v["C?"]) == (12.0, -123456789012345.0, 4294967294.0, True)
