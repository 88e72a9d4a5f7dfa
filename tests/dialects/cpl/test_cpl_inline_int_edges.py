"""INT written inline with one range test (issue 18): a value strictly between -2147483649 and 2147483648
truncates toward zero into the INTEGER range (CPL manual §2.5.1 L804); at those bounds and beyond, and for
infinity, the run stops with the built-in's error, as the checked INT does."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize(("value", "expected"), [
    ("2147483647.75", 2147483647),
    ("-2147483648.75", -2147483648),
    ("-0.5", 0),
    ("-7.9", -7),
    ("2147483648.0", None),
    ("-2147483649.0", None),
    ("1" + "0" * 200 + ".0", None),  # squared below: infinity
])
def test_int_of_a_double_at_the_edges_of_the_integer_range(run, generated, value, expected):
    square = len(value) > 100
    text = f"10 D! = {value}\n20 M% = INT(D! * {'D!' if square else '1'})\nM30\n"
    assert "_F_INT(_a)" in generated(text).split("v_M_i = ")[-1].splitlines()[0]  # the inline form
    r = run(text)
    if expected is None:
        assert r["error"]["code"] == "CPL027" and r["error"]["line"] == 2, r["error"]
        assert "INT result" in r["error"]["message"]
        return
    assert r["status"] == "ok", r["error"]
    assert r["variables"]["M%"] == expected
