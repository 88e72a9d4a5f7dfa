"""Typ3 osa external and general tool compensation (G145..G845, G147..G847) and the H word's table.

CPL manual: "PPOS considers the following compensations: ... tool compensations (Hx, G145...G845,
G147...G847)" (L1572-1574); TC writes them ("TC(1,745,0)=A ... external length compensation G745", L1888);
the external compensation's length is L(1)3, the general's L(2)3, L(2)1, L(2)2 (TC selections, L1857).
docs/decisions.md, "Issue 14: Typ3 external and general tool compensation"."""

from __future__ import annotations

from tests.review14.review14_helpers import MACHINE, make_runner, moves

TOOL = MACHINE + "[[tool]]\nnumber = 1\nlength = 40.0\nradius = 5.0\n"


def _z(rows):
    return [m[3] for m in moves(rows)]


def test_l1888_external_length_adds_to_h_and_g146_removes_it(tmp_path):
    text = ("10 TC(1,745,0)=5\nN20 G0 X0 Y0 Z0\nN30 H1 Z0\nN40 G745 Z0\nN50 H0 Z0\nN60 G146 Z0\nN70 M30\n")
    result, rows, _ = make_runner(tmp_path)("p.cpl", text, machine=TOOL)
    assert result["status"] == "ok", result
    # H1 (40 mm), then G745 adds 5; H0 leaves the external 5; G146 ends it
    assert _z(rows)[-4:] == [40.0, 45.0, 5.0, 0.0]


def test_l1888_external_length_in_inch_under_g70(tmp_path):
    text = "N5 G70\n10 TC(1,745,0)=1\nN20 G0 X0 Y0 Z0\nN30 G745 Z0\nN40 M30\n"
    result, rows, _ = make_runner(tmp_path)("p.cpl", text)
    assert result["status"] == "ok", result
    assert _z(rows)[-1] == 25.4


def test_l1891_general_length_l3_on_the_tool_axis(tmp_path):
    text = "10 TC(1,347,0)=7\nN20 G0 X0 Y0 Z0\nN30 G347 Z-10\nN40 M30\n"
    result, rows, _ = make_runner(tmp_path)("p.cpl", text)
    assert result["status"] == "ok", result
    assert moves(rows)[-1][1:4] == (0.0, 0.0, -3.0)


def test_l1891_general_compensation_across_the_tool_axis_is_refused(tmp_path):
    text = "10 TC(4,347,0)=2\nN20 G0 X0 Y0 Z0\nN30 G347 Z-10\nN40 M30\n"
    result, _rows, _ = make_runner(tmp_path)("p.cpl", text)
    assert result["error"]["code"] == "NC005", result["error"]
    assert "L(2)2" in result["error"]["message"] and "not supported by ncvm" in result["error"]["message"]


def test_l1146_h0_after_g22_k0_runs_and_h1_stops_with_nc009(tmp_path):
    ok = "N10 G22 K0\nN20 H0 G0 X0 Y0 Z0\nN30 M30\n"
    result, _rows, _ = make_runner(tmp_path)("ok.cpl", ok, machine=TOOL)
    assert result["status"] == "ok", result
    bad = "N10 G22 K0\nN20 H1 G0 X0 Y0 Z0\nN30 M30\n"
    result, _rows, _ = make_runner(tmp_path)("bad.cpl", bad, machine=TOOL)
    assert result["error"]["code"] == "NC009" and "G22 K0" in result["error"]["message"], result["error"]
