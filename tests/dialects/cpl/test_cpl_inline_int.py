"""INT written inline (issue 18): an argument proven within the INTEGER range is a plain ``int()``; any other
keeps the inline range test, and a value beyond the range still stops the run with the built-in's error."""

from __future__ import annotations

import pytest


def test_int_of_a_bounded_argument_is_a_plain_int_and_of_a_real_one_is_tested(generated):
    text = generated("10 I% = 9 : X = 2.5\n20 M% = INT(I% / 7)\n30 N% = INT(X * 10)\nM30\n")
    assert "int((v_I_i / 7))" in text.split("v_M_i = ")[-1].splitlines()[0]
    assert "_F_INT(_a)" in text.split("v_N_i = ")[-1].splitlines()[0]


@pytest.mark.parametrize(("text", "expected"), [
    ("10 I% = -23\n20 M% = INT(I% / 7)\n", {"M%": -3}),  # toward zero
    ("10 I% = 2147483647\n20 M% = INT(I% / 0.5)\n", None),  # a quotient by a constant below 1: not bounded
    ("10 X = 2.75\n20 M% = INT(X * 10)\n", {"M%": 27}),
])
def test_int_values_and_range(run_text, text, expected):
    r = run_text(text + "M30\n", name="p.cpl")
    if expected is None:
        assert r["error"]["code"] == "CPL027" and "INT result 4294967294" in r["error"]["message"], r["error"]
        return
    assert r["status"] == "ok", r["error"]
    for k, v in expected.items():
        assert r["variables"][k] == v
