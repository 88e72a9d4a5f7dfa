"""NUL (manual §2.5 L758-769): ``<variable> = NUL`` is a condition, NUL anywhere else in a
comparison is RUNTIME ERROR VARIABLE NOT ASSIGNED (CPL020)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("cond", ["X% = 3", "X% <> 3", "3 = X%", "X = 1.5", "A$ = \"ABC\"", "A$ <> \"\"",
                                  "B? = TRUE", "X% = Y%", "MID$(\"ABCD\",5,1) = \"\"", "VAL(\"A1\") = 0"])
def test_equality_with_a_nul_operand_is_variable_not_assigned(run, cond):
    r = run(f"10 IF {cond} THEN\n20 R%=1\n30 ENDIF\nM30\n")
    assert r["error"]["code"] == "CPL020" and "VARIABLE NOT ASSIGNED" in r["error"]["message"]


def test_comparison_with_the_nul_keyword_is_a_condition(run):
    text = ("1 XSET = 5\n2 A? = XSET = NUL\n3 B? = XSET <> NUL\n4 XSET = NUL\n5 C? = XSET = NUL\n"
            "6 D? = NUL = XSET\n7 J% = VAL(\"ABC\")\n8 E? = J% = NUL\n9 F? = MID$(\"ABCD\",5,1) = NUL\nM30\n")
    v = run(text)["variables"]
    assert (v["A?"], v["B?"], v["C?"], v["D?"], v["E?"], v["F?"]) == (False, True, True, True, True, True)


def test_assigned_values_compare_as_before(run):
    v = run("1 X% = 3\n2 A? = X% = 3\n3 S$ = \"AB\"\n4 B? = S$ <> \"AB\"\n5 T? = TRUE\n6 C? = T? = TRUE\nM30\n")
    assert (v["variables"]["A?"], v["variables"]["B?"], v["variables"]["C?"]) == (True, False, True)


def test_unassigned_character_field_is_nul_in_a_comparison(run):
    """A DIMensioned field not yet assigned reads NUL (L3392): a condition with NUL, an error with text."""
    v = run('10 DIM A$(5) : DIM T$(2,5)\n20 B? = A$ = NUL\n30 C? = T$(1) <> NUL\nM30\n')["variables"]
    assert (v["B?"], v["C?"]) == (True, False)
    assert run('10 DIM A$(5)\n20 B? = A$ = "X"\nM30\n')["error"]["code"] == "CPL020"
