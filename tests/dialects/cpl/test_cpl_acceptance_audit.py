"""Acceptance audit of the CPL dialect against manual chapters 2-3: what a user of a Typ3 control tries and the
manual states, where the suite did not yet assert it."""

from __future__ import annotations

import pytest


@pytest.fixture
def run(run_text, reference):
    return lambda text, **kw: run_text(text, name="p.cpl", machine=reference(**kw))


# -- §3.1 sub-programs by G address --------------------------------------------------------------------------


CYCLE = '10 #HOLES% = #HOLES% + 1 : #DEPTH = P1\nN1 G1 Z[P1] F100\nN2 G0 Z10\n'


def test_g81_calls_program_99999081_without_a_table_entry_l1073(run, reference):
    """§3.1 L1071-1074: "the programs for the drilling cycles (99999081 through 99999086) are permanently
    assigned to the functions G81 through G86". The machine file maps nothing; G81 calls 99999081 and, being a
    drilling cycle, again after every traversing block until G80: at X0, X10 and X20, not at X30."""
    m = reference()
    (m.program_path[0] / "99999081").write_text(CYCLE)
    r = run("1 #HOLES% = 0\nN1 G0 X0 Y0 Z10\nN2 G81 [-5]\nN3 X10\nN4 X20\nN5 G80\nN6 X30\nM30\n")
    assert r["status"] == "ok", r["error"]
    assert r["variables"]["#HOLES%"] == 3 and r["variables"]["#DEPTH"] == -5.0
    assert r["position"]["X"] == 30.0 and r["motion"]["feed_moves"] == 3


@pytest.mark.parametrize("code", [82, 83, 84, 85, 86])
def test_g82_to_g86_call_their_programs_l1073(run, reference, code):
    m = reference()
    (m.program_path[0] / f"999990{code}").write_text(CYCLE)
    r = run(f"1 #HOLES% = 0\nN1 G0 X0 Y0 Z10\nN2 G{code} [-2]\nN5 G80\nM30\n")
    assert r["status"] == "ok", r["error"]
    assert r["variables"]["#HOLES%"] == 1 and r["variables"]["#DEPTH"] == -2.0


def test_missing_drilling_cycle_program_is_a_link_error(run):
    """Linking checks sub-program calls (§2.3 L413): G81 without program 99999081 stops before anything runs."""
    r = run('10 PRN#(0,"started")\nN2 G81 [-5]\nM30\n')
    assert r["error"]["code"] == "CPL005" and "99999081" in r["error"]["message"]
    assert r["output"] == [] and r["error"]["line"] == 2


def test_machine_file_entry_replaces_a_drilling_cycle(run, reference):
    m = reference(cpl={"calls": {"G81": {"program": "MYDRILL", "modal": True}}})
    (m.program_path[0] / "MYDRILL").write_text(CYCLE)
    r = run("1 #HOLES% = 0\nN2 G81 [-1]\nN3 X5\nN4 G80\nM30\n", cpl={"calls": {"G81": {"program": "MYDRILL",
                                                                                   "modal": True}}})
    assert r["status"] == "ok", r["error"]
    assert r["variables"]["#HOLES%"] == 2
