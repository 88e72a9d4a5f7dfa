"""WAIT (manual §4.1 L1232): parameter types checked when linking, every form of the manual, WAIT in an NC block."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("text", [
    "10 WAIT(IC(1,1,1)=1)\n",  # L1213: <state> is a BOOLEan expression
    "10 WAIT(,1000,E)\n",  # L1217: <result var> is an Integer variable
    "10 WAIT(,1000,E!)\n",
])
def test_wait_parameter_types_are_checked_when_linking(run, text):
    r = run(text + "M30\n")
    assert r["error"]["code"] == "CPL032" and r["steps"] == 0


def test_wait_with_every_form_of_the_manual_l1232(run):
    """L1232-1239 in one program, no input ever set: E% = 1 after 1000 ms; WAIT(,TIME%) returns nothing;
    NOT IC(3,2,1) holds at once (C% = 0); IC(4,4,1)=E7? with E7? TRUE times out after 250 ms (ERG% = 1);
    IC(2,0,2)=(E1? OR E2?) with both FALSE holds at once."""
    r = run("10 WAIT(,1000,E%)\n15 TIME% = 500\n20 WAIT(,TIME%)\n30 WAIT(NOT IC(3,2,1),,C%)\n"
            "35 E7? = TRUE\n40 WAIT(IC(4,4,1)=E7?,250,ERG%)\n45 E1? = FALSE : E2? = FALSE\n"
            "50 WAIT(IC(2,0,2)=(E1? OR E2?))\n60 T% = CLOCK\nN70 WAIT\nM30\n")
    assert r["status"] == "ok", r["error"]
    v = r["variables"]
    assert (v["E%"], v["C%"], v["ERG%"], v["T%"]) == (1, 0, 1, 1750)


def test_wait_in_an_nc_block_without_parameters_still_drains(run):
    """L1197-1203: "N20 WAIT" is WAIT as an NC block; a comment after a blank is not a parameter list."""
    r = run("N10 G1 X50 F3000\nN20 WAIT (MSG, waited)\n30 X = MPOS(1)\nM30\n")
    assert r["status"] == "ok", r["error"]
    assert r["variables"]["X"] == 50.0 and "waited" in r["output"]
