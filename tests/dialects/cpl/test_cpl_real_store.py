"""REAL (binary32) stores rounded inline by the generated code (CPL manual §2.4.3, L650-737): the same values and the same
INVALID FLOAT VALUE (CPL042) at the same boundaries as the ``values.f32`` call they replace."""

from __future__ import annotations

import math
import random
import struct
from decimal import Decimal

import pytest
from hypothesis import given
from hypothesis import strategies as st

from ncvm.dialects.cpl import ast as A
from ncvm.dialects.cpl import codegen
from ncvm.dialects.cpl import values as V
from ncvm.dialects.cpl.linker import link

FLT_MAX = 3.4028234663852886e38
HALFWAY = 3.4028235677973366e38  # between FLT_MAX and 2**128: rounds (to even) up, beyond the range


@pytest.fixture
def run(run_text):
    return lambda text: run_text(text, name="p.cpl")


def literal(x: float) -> str:
    """The exact decimal digits of a double, as a CPL constant (CPL writes no exponent)."""
    text = format(Decimal(x), "f")
    return text if "." in text else text + ".0"


def store(run, value: float, expr: str = "D! * 1"):
    """Run ``R = <expr>`` with D! = value: (result of the run, R)."""
    r = run(f"10 R = 5.0 : D! = {literal(value)}\n20 R = {expr}\nM30\n")
    return r, r["variables"].get("R")


@pytest.mark.parametrize(("value", "stored"), [
    (0.1, 0.10000000149011612),
    (16777217.0, 16777216.0),  # a tie: to even
    (16777219.0, 16777220.0),
    (1.0e-45, 1.401298464324817e-45),  # the smallest subnormal
    (1.0e-46, 0.0),
    (FLT_MAX, FLT_MAX),
    (math.nextafter(HALFWAY, 0.0), FLT_MAX),  # just below the halfway point: FLT_MAX
    (-math.nextafter(HALFWAY, 0.0), -FLT_MAX),
])
def test_real_store_rounds_to_binary32(run, value, stored):
    r, got = store(run, value)
    assert r["status"] == "ok", r["error"]
    assert got == stored


@pytest.mark.parametrize("expr", [
    "D! * 1",  # a DOUBLE operand: unbounded, the store tests for infinity first
    "D! * D!",  # 1e76 finite as a DOUBLE, beyond the REAL range
    "D! * D! * D! * D! * D! * D! * D! * D! * D! * D!",  # infinity as a DOUBLE
])
@pytest.mark.parametrize("value", [HALFWAY, -HALFWAY, 1.0e38, -1.0e300])
def test_real_store_beyond_the_range_is_cpl042(run, value, expr):
    r, got = store(run, value, expr)
    if value == 1.0e38 and expr == "D! * 1":
        assert r["status"] == "ok" and got == 9.999999680285692e37  # the nearest binary32
        return
    assert r["error"]["code"] == "CPL042", r["error"]
    assert "outside the REAL range" in r["error"]["message"]
    assert r["error"]["line"] == 2


@pytest.mark.parametrize(("text", "stored"), [
    (f"10 A = {literal(3.0e38)}\n20 A = A * 1.2\n", None),  # REAL operands only: finite, no infinity test
    (f"10 A = {literal(3.0e38)}\n20 A = A * 1.134\n", 3.4019999521888145e38),
    (f"10 A = {literal(-3.0e38)}\n20 A = A + A\n", None),
    (f"10 A = {literal(-3.0e38)}\n20 A = A / 0.5\n", None),
    ("10 A% = 2147483647\n20 A = A% * 1.0 * A% * A% * A% * A% * 10000000000.0\n", None),
])
def test_bounded_real_store_beyond_the_range_is_cpl042(run, text, stored):
    r = run(text + "M30\n")
    if stored is not None:
        assert r["status"] == "ok" and r["variables"]["A"] == pytest.approx(stored, rel=1e-7)
        return
    assert r["error"]["code"] in ("CPL042", "CPL027"), r["error"]
    if r["error"]["code"] == "CPL042":
        assert "outside the REAL range" in r["error"]["message"]


def test_a_failed_store_leaves_the_variable_as_it_was(run):
    r = run(f"10 A = {literal(2.0e38)}\n20 A = A * 4\nM30\n")
    assert r["error"]["code"] == "CPL042"
    assert r["variables"]["A"] == pytest.approx(2.0e38, rel=1e-7)


def test_nul_in_a_real_store_is_cpl020(run):
    r = run("10 A = B + 1\nM30\n")
    assert r["error"]["code"] == "CPL020"


@given(st.one_of(st.floats(allow_nan=True, allow_infinity=True), st.integers(-2**140, 2**140)))
def test_inline_rounding_agrees_with_f32(x):
    """The generated store's primitive, the C float of a memoryview set and read back: the value f32 gives, or a
    refusal or a value that is not finite (which the store tests for) where f32 raises."""
    try:
        expected = V.f32(x)
    except V.CplError:
        expected = None
    cell = memoryview(bytearray(4)).cast("f")
    try:
        cell[0] = x
        got = cell[0]
    except (ValueError, TypeError):
        got = None
    if expected is not None and got is not None and math.isfinite(got):
        assert struct.pack("<d", got) == struct.pack("<d", expected)
    else:  # a refusal, or the infinity or NaN the store tests for
        assert expected is None and (got is None or not math.isfinite(got))


def test_a_real_store_rounds_inline_and_tests_for_infinity_only_when_unbounded(generated):
    text = generated("10 I% = 3 : D! = 2.0 : S = 1.5\n20 X = I% * 0.001\n"
                     "30 S = S * 0.999 + SIN(X) * COS(X) + SQRT(ABS(S) + 1)\n40 Y = D! * 2\nM30\n")
    stores = [line.strip() for line in text.splitlines() if "_r32" in line]
    assert stores == [
        "_r32 = (v_I_i * 0.001)", "try: _m32[0] = _r32", "except Exception: _m32[0] = _f32(_r32)",
        "_r32 = (((v_S_r * 0.999) + (_msin(v_X_r * 0.017453292519943295) * _mcos(v_X_r * 0.017453292519943295)))"
        " + _msqrt((abs(v_S_r) + 1.0)))",
        "try: _m32[0] = _r32", "except Exception: _m32[0] = _f32(_r32)",
        "_r32 = (v_D_d * 2)", "try: _m32[0] = _r32", "except Exception: _m32[0] = _f32(_r32)",
        "if _t32 - _t32: _t32 = _f32(_r32)",
    ]
    assert "v_X_r = _m32[0]" in text and "v_S_r = _m32[0]" in text  # bounded: no test
    assert "_t32 = _m32[0]" in text and "v_Y_r = _t32" in text


@pytest.mark.parametrize(("expr", "bound"), [
    ("I% * 0.001", 2147483.648), ("-A + 2", FLT_MAX + 2), ("A / 4", FLT_MAX / 4), ("A / B", math.inf),
    ("D! * 1", math.inf), ("SQRT(ABS(A))", math.sqrt(FLT_MAX)), ("INT(D!)", 2147483648.0), ("TAN(A)", math.inf),
])
def test_magnitude_bounds_what_a_real_store_can_hold(tmp_path, reference, expr, bound):
    path = tmp_path / "p.cpl"
    text = f"10 I% = 1 : A = 1 : B = 1 : D! = 1\n20 X = {expr}\nM30\n"
    path.write_text(text)
    ln = link(str(path), text, reference()).units[str(path)]
    e = [s.expr for s in ln.prog.stmts if isinstance(s, A.Assign)][-1]
    assert codegen.magnitude(e) == pytest.approx(bound)


def test_inline_rounding_agrees_with_struct_on_a_million_values():
    """The memoryview's C float against struct's binary32 (an independent packing, to nearest even): a million
    doubles of random bit patterns (every exponent, subnormals, infinities, NaNs) and of random magnitudes
    around the REAL range's edges. Where struct refuses (beyond FLT_MAX after rounding) the store reads back
    an infinity of the value's sign, which the store's test turns into CPL042."""
    rng = random.Random(18)
    bits = [struct.unpack("<d", rng.getrandbits(64).to_bytes(8, "little"))[0] for _ in range(500_000)]
    edges = [rng.choice((-1.0, 1.0)) * rng.uniform(0.99, 1.01) * rng.choice((FLT_MAX, 1.1754943508222875e-38, 1.4e-45))
             for _ in range(500_000)]
    cell = memoryview(bytearray(4)).cast("f")
    pack, unpack = struct.Struct("<f").pack, struct.Struct("<f").unpack
    for x in bits + edges:
        cell[0] = x
        got = cell[0]
        try:
            want = unpack(pack(x))[0]
        except OverflowError:
            assert math.isinf(got) and math.copysign(1.0, got) == math.copysign(1.0, x), x
            continue
        if math.isnan(want):
            assert math.isnan(got), x
        else:
            assert struct.pack("<d", got) == struct.pack("<d", want), x


@pytest.mark.parametrize(("expr", "stored"), [
    ("D! * -0.0", "-0.0"), ("-(D! * 0.0)", "-0.0"), ("D! * 0.0", "0.0"),
])
def test_a_real_store_keeps_the_sign_of_zero(run, expr, stored):
    r, got = store(run, 1.5, expr)
    assert r["status"] == "ok", r["error"]
    assert got == 0.0 and math.copysign(1.0, got) == math.copysign(1.0, float(stored))
