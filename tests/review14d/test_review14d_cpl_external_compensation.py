"""Bosch Typ3 osa external and general tool compensation (G145...G845, G147...G847) selected in a program.

The CPL manual counts them among the tool compensations that change the tool's position, with the H word:
"PPOS considers the following compensations: ... tool compensations (Hx, G145...G845, G147...G847)"
(L1572-1574); TC writes their values ("TC(1,745,0)=A: the value of variable A in mm is assigned to the
external length compensation G745", L1888) and MCODS(51) reports "the external tool compensation values
active in <channel>. Order: radius, length compensation" (L3000). ncvm reports the 5 mm active and moves the
tool as if nothing were selected: a silent wrong position. Issue 14 §1: "implement it, or refuse it with a
clear 'not supported by ncvm' (never silently ignore a word)"."""

from __future__ import annotations

from review14d_run import run

EXTERNAL = """5 DIM BUF(2)
10 TC(1,745,0)=5
N20 G0 X0 Y0 Z0
N30 G745
N40 G0 Z-10
N45 WAIT
50 V=0 : A=MCODS(51,1,V,BUF,2)
60 PRN#(0,"EXT ",BUF(2))
N70 M30
"""

GENERAL = """10 TC(3,347,0)=7
N20 G0 X0 Y0 Z0
N30 G71 G347
N40 G0 Z-10
N50 M30
"""


def _compensated_or_refused(result, rows, length):
    """The run either ends with the tool shifted by the active length compensation along Z, as H shifts it,
    or stops saying the function is not supported."""
    if result["status"] == "ok":
        last = [r for r in rows if r["call"] in ("rapid", "feed", "arc")][-1]
        assert abs(last["end"]["Z"] - (-10.0 + length)) < 1e-6, (
            f"Z-10 under a {length} mm length compensation ends at machine Z {last['end']['Z']}: "
            "the compensation the program selected is silently ignored")
    else:
        assert "not supported by ncvm" in result["error"]["message"], result["error"]


def test_l1574_g745_external_length_compensation_moves_the_tool_or_is_refused(tmp_path):
    result, rows, _stderr = run(tmp_path, "ext.cpl", EXTERNAL)
    if result["status"] == "ok":
        # ncvm itself reports the 5 mm external length compensation active (MCODS(51), L3000) ...
        assert "5.000" in "".join(result["output"]), result["output"]
    # ... so the move must follow it, or the run must refuse G745.
    _compensated_or_refused(result, rows, 5.0)


def test_l1574_g347_general_length_compensation_moves_the_tool_or_is_refused(tmp_path):
    """The manual's "TC(3,347,0)=A: the general geometry compensation G347 is assigned the variable value A
    for length compensation L(2)1" (L1891). Which axis L(2)1 acts on is the general compensation's geometry;
    on whichever axis, an end point unchanged on every axis ignores it, so any shift passes."""
    result, rows, _stderr = run(tmp_path, "gen.cpl", GENERAL)
    if result["status"] == "ok":
        last = [r for r in rows if r["call"] in ("rapid", "feed", "arc")][-1]
        assert (last["end"]["X"], last["end"]["Y"], last["end"]["Z"]) != (0.0, 0.0, -10.0), (
            "G347 with a 7 mm length compensation ends at the uncompensated point: silently ignored")
    else:
        assert "not supported by ncvm" in result["error"]["message"], result["error"]
