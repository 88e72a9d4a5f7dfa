"""Properties that must hold for every value: what PRN# writes, VAL and INP# read back."""

from __future__ import annotations

from decimal import ROUND_HALF_UP, Decimal

from hypothesis import given, settings
from hypothesis import strategies as st

from ncvm.dialects.cpl.io.files import CplFiles
from ncvm.dialects.cpl.io.format import format_items, format_number
from ncvm.dialects.cpl.io.strings import val
from ncvm.dialects.cpl.io.values import Double


@given(st.integers(min_value=-99_999_999, max_value=999_999_999))
def test_integers_in_standard_format_read_back(v):
    text = format_items([v]).text
    assert len(text) == 9 and val(text) == v


@given(st.floats(min_value=-99_999.0, max_value=999_999.0, allow_nan=False), st.integers(0, 4))
def test_templates_round_half_away_from_zero_and_read_back(v, decimals):
    template = "#" * 7 + ("." + "#" * decimals if decimals else "")
    text = format_items([template, Double(v)]).text
    expected = Decimal(repr(v)).quantize(Decimal(1).scaleb(-decimals), rounding=ROUND_HALF_UP)
    assert len(text) == len(template)
    assert Decimal(text.strip()) == expected
    assert val(text) == float(expected) or (expected == 0 and val(text) == 0)


@given(st.integers(min_value=-(2**31), max_value=2**31 - 1), st.integers(1, 12), st.integers(0, 4),
       st.booleans(), st.booleans())
def test_an_integer_prints_as_the_same_number_as_a_double(v, before, decimals, ljust, trim):
    """INTEGERs take a path of their own (no Decimal rounding: they are exact); in a template and in the
    standard format they print as a DOUBLE of the same value does, overflow and LJUST alike."""
    template = "#" * before + ("." + "#" * decimals if decimals else "")
    as_int = format_items(["<", template, ">", v], ljust=ljust, trim=trim)
    as_double = format_items(["<", template, ">", Double(float(v))], ljust=ljust, trim=trim)
    assert as_int == as_double
    assert format_items([v], ljust=ljust).text == format_number(float(v), "D", 9, 0, pad=not ljust) or (
        len(str(v)) > 9 and format_items([v]).text == str(v))


@settings(max_examples=30, deadline=None)
@given(st.lists(st.text(alphabet=st.characters(min_codepoint=32, max_codepoint=255), max_size=40), max_size=8))
def test_prn_records_come_back_with_inp(tmp_path_factory, records):
    root = tmp_path_factory.mktemp("prop")
    fs = CplFiles(root=root, durable=False)
    fs.OPENW(1, "P")
    for r in records:
        fs.PRN(1, r)
    fs.CLOSE(1)
    fs.OPENR(1, "P")
    back = []
    while not fs.EOF(1):
        back.append(fs.INP(1, "S")[0])
    assert back == records
