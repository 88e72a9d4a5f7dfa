"""FOR counts with any numerical variable (manual §2.5.5 L924), not with a parameter or a non-number."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("goto", ["", "5 GOTO 10\n"])
def test_for_counts_with_any_numerical_variable_l924(run, goto):
    """§2.5.5 L924: "FOR <numerical variable>=<start value> ...": a permanent @n, a field element (its index
    taken at every pass), a global and @_R count like a local; each ends past its end value (L934)."""
    r = run(goto + "10 FOR @1=1 TO 3 : NEXT\n20 DIM F%(3) : FOR F%(1)=1 TO 3 : S%=F%(1) : NEXT\n"
            "30 FOR #G=0 STEP 0.5 TO 1 : NEXT\n40 FOR @_R(3)=1 TO 2 : NEXT\n"
            "50 DIM K%(2,2) : J%=1 : FOR K%(J%,2)=5 STEP -1 TO 4 : NEXT\n"
            "60 A% = @1 : B% = F%(1) : C = #G : D! = @_R(3) : E% = K%(1,2)\nM30\n")
    assert r["status"] == "ok", r["error"]
    v = r["variables"]
    assert (v["A%"], v["B%"], v["S%"], v["C"], v["D!"], v["E%"]) == (4, 4, 3, 1.5, 3.0, 3)


def test_for_with_a_parameter_or_a_non_number_is_an_error(run):
    assert run('10 FOR A$="A" TO "C" : NEXT\nM30\n')["error"]["code"] == "CPL001"
