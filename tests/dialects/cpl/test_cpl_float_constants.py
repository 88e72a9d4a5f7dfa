"""Integer constants beside a REAL operand (CPL manual §2.4.3, L650-737: the constant takes the precision of its
context) are written as floats where that gives the same result: the operand is a float or NUL at run time."""

from __future__ import annotations

import math
import struct
from decimal import Decimal

import pytest


@pytest.fixture
def run(run_text):
    return lambda text: run_text(text, name="p.cpl")


def test_integer_constants_beside_real_operands_are_written_as_floats(generated):
    text = generated("10 S = 1.5 : X = 0.25 : D! = 2.0 : I% = 3\n20 A = SQRT(ABS(S) + 1)\n30 B = INT(X * 10) / 3\n"
                     "40 C = 2 - SIN(X) + COS(X) * 4 + 1 / X\n50 E! = D! * 2\n60 F = I% * 2 + X\n"
                     "70 G = X * 9007199254740993\nM30\n")
    assert "_msqrt((abs(v_S_r) + 1.0))" in text
    assert "(v_X_r * 10.0)" in text
    assert "(2.0 - _msin(" in text and "* 4.0)" in text and "(1.0 / v_X_r)" in text
    assert "(v_D_d * 2)" in text  # a DOUBLE local may hold what a computed DOUBLE store left: kept as written
    assert "(v_I_i * 2)" in text  # INTEGER arithmetic
    assert "(v_X_r * 9007199254740993)" in text  # beyond 2**53 the constant would round: kept


@pytest.mark.parametrize("x", [0.1, -2.5, 1.0e30, 1.0e-30, 123456.789, -0.0])
def test_the_results_are_those_of_the_integer_constants(run, x):
    """The same stored values as with the constant an integer (Python converts it exactly either way)."""
    lit = format(Decimal(x), "f")
    lit = ("-" if math.copysign(1.0, x) < 0 and not lit.startswith("-") else "") + lit + ("" if "." in lit else ".0")
    r = run(f"10 X = {lit}\n20 A = X * 3 + 1 : B = 7 - X : C = ABS(X) * 2 : D = 1 / (ABS(X) + 1)\nM30\n")
    assert r["status"] == "ok", r["error"]
    v = r["variables"]
    X = v["X"]

    def f32(y):
        return struct.unpack("<f", struct.pack("<f", y))[0]

    assert v["A"] == f32(X * 3 + 1) and v["B"] == f32(7 - X) and v["C"] == f32(abs(X) * 2)
    assert v["D"] == f32(1 / (abs(X) + 1))
    assert math.copysign(1.0, v["C"]) == 1.0


def test_nul_beside_an_integer_constant_is_still_cpl020(run):
    r = run("10 A = B * 2 + 1\nM30\n")
    assert r["error"]["code"] == "CPL020"
