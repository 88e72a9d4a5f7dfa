"""The measuring G functions of manual §4.2 beside G75: G275 "on-the-fly measurement" (only the programmed
axis is measured, L1589-1591; CPROBE refused, L1449) and G375 "measuring fixed stop" (PPOS/PROBE read the
stop, L1593/L1628; SD(9) 0 = reached, 1 = not yet, L2230). Values computed by hand in each test."""

from __future__ import annotations

import pytest

#: G54 shifts X by 10 mm: MCS = WCS + 10 on X
G54_X10 = {"G54": [10.0, 0.0, 0.0]}
START = "N1 G54\nN2 G0 X0 Y0 Z0\n"


@pytest.fixture
def run(run_text, reference):
    def _run(text, *events):
        m = reference(1, offsets=G54_X10, scenario=[{"time": 0.0, **e} for e in events])
        return run_text(START + text, name="p.cpl", machine=m)
    return _run


def probe(**axes):
    return {"kind": "probe", **axes}


def fixed_stop(**axes):
    return {"kind": "fixed_stop", **axes}


# -- G275 on-the-fly measurement -------------------------------------------------------------------
def test_g275_latches_the_axis_and_goes_on_to_the_end_point(run):
    r = run("N3 G275 X50 F500\n4 S%=SD(9)\n5 PR=PROBE(1)\n6 PP=PPOS(1)\n7 XM=PPOS(\"X\")\nM30\n", probe(X=40.0))
    v = r["variables"]
    assert r["status"] == "ok", r["error"]
    # the probe switched at MCS 40: PROBE 40, PPOS = 40 - G54 10 = 30 (WCS); SD(9) read in the next block
    assert (v["S%"], v["PR"], v["PP"], v["XM"]) == (0, 40.0, 30.0, 30.0)
    # on the fly: the move is not cut, X ends at WCS 50 = MCS 60; feed 60 - 10 = 50 mm
    assert r["position"]["X"] == 50.0
    assert r["motion"]["bounds"]["X"] == [0.0, 60.0] and r["motion"]["feed_length"] == 50.0


def test_g275_measures_only_the_programmed_axis(run):
    """The event gives Y as well; with G275 only X is measured (L1591), so PPOS/PROBE of Y are refused."""
    r = run("N3 G275 X50 F500\n4 A=PPOS(1)\n5 B=PROBE(2)\nM30\n", probe(X=40.0, Y=3.0))
    assert r["variables"]["A"] == 30.0
    assert r["error"]["code"] == "CPL040" and r["error"]["line"] == 5 and "Y" in r["error"]["message"]
    r = run("N3 G275 X50 F500\n4 B=PPOS(2)\nM30\n", probe(X=40.0, Y=3.0))
    assert r["error"]["code"] == "CPL040" and "not measured" in r["error"]["message"]


def test_g75_still_measures_every_axis_of_the_channel(run):
    """Against the G275 case above: G75 latches every axis the probe event gives (L1589-1591)."""
    r = run("N3 G75 X50 Y50 F500\n4 A=PPOS(1)\n5 B=PROBE(2)\nM30\n", probe(X=40.0, Y=3.0))
    assert r["status"] == "ok", r["error"]
    assert (r["variables"]["A"], r["variables"]["B"]) == (30.0, 3.0)


def test_cprobe_after_g275_is_a_runtime_error_l1449(run):
    r = run("N3 G275 X50 F500\n4 S%=SD(9)\n5 C=CPROBE(1)\nM30\n", probe(X=40.0))
    assert r["variables"]["S%"] == 0
    assert r["error"]["code"] == "CPL040" and r["error"]["line"] == 5 and "G275" in r["error"]["message"]


def test_g275_not_switched_gives_sd9_1(run):
    r = run("N3 G275 X50 F500\n4 S%=SD(9)\n5 A=PPOS(1)\nM30\n")
    assert r["variables"]["S%"] == 1 and r["position"]["X"] == 50.0
    assert r["error"]["code"] == "CPL040" and r["error"]["line"] == 5


def test_g275_with_an_event_for_another_axis_does_not_switch(run):
    r = run("N3 G275 X50 F500\n4 S%=SD(9)\nM30\n", probe(Y=3.0))
    assert r["status"] == "ok" and r["variables"]["S%"] == 1


def test_g275_programs_exactly_one_axis(run):
    r = run("N3 G275 X50 Y20 F500\nM30\n", probe(X=40.0))
    assert r["error"]["code"] == "CPL040" and r["error"]["line"] == 3
    assert run("N3 G275 F500\nM30\n")["error"]["code"] == "CPL040"


def test_g75_and_g275_cannot_stand_in_one_block(run):
    assert run("N3 G75 G275 X50 F500\nM30\n", probe(X=40.0))["error"]["code"] == "CPL040"


def test_g275_shares_the_probe_events_with_g75_in_order(run):
    r = run("N3 G275 X50 F500\n4 A=PPOS(1)\nN5 G75 X0\n6 B=PPOS(1)\n7 C=CPROBE(1)\nM30\n", probe(X=40.0), probe(X=25.0))
    v = r["variables"]
    assert r["status"] == "ok", r["error"]
    # first event 40 - 10 = 30; second one: G75 from WCS 50 back, switching at MCS 25 = WCS 15; after G75
    # CPROBE is allowed again (no G92: PCS = WCS)
    assert (v["A"], v["B"], v["C"]) == (30.0, 15.0, 15.0) and r["position"]["X"] == 15.0


# -- G375 measuring fixed stop ---------------------------------------------------------------------
def test_g375_stops_at_the_fixed_stop(run):
    r = run("N3 G375 X50 F500\n4 S%=SD(9)\n5 PR=PROBE(1)\n6 PP=PPOS(1)\nM30\n", fixed_stop(X=35.0))
    v = r["variables"]
    assert r["status"] == "ok", r["error"]
    # the stop at MCS 35: PROBE 35, PPOS = 35 - 10 = 25 (WCS), SD(9) = 0 "fixed stop executed"
    assert (v["S%"], v["PR"], v["PP"]) == (0, 35.0, 25.0)
    # the move ends there: WCS 25, the toolpath reaches MCS 35, feed 35 - 10 = 25 mm
    assert r["position"]["X"] == 25.0
    assert r["motion"]["bounds"]["X"] == [0.0, 35.0] and r["motion"]["feed_length"] == 25.0


def test_g375_without_a_fixed_stop_reaches_the_end_point_sd9_1(run):
    r = run("N3 G375 X50 F500\n4 S%=SD(9)\n5 A=PROBE(1)\nM30\n", probe(X=40.0))  # a probe event is no stop
    assert r["variables"]["S%"] == 1 and r["position"]["X"] == 50.0
    assert r["motion"]["feed_length"] == 50.0
    assert r["error"]["code"] == "CPL040" and r["error"]["line"] == 5


def test_g375_incremental_and_the_next_block_go_on_from_the_stop(run):
    r = run("N3 G91 G375 X50 F500\nN4 X5\n5 WAIT\n6 W=WPOS(1)\n7 M=MPOS(1)\nM30\n", fixed_stop(X=35.0))
    v = r["variables"]
    assert r["status"] == "ok", r["error"]
    # stopped at WCS 25; G91 X5 goes on to WCS 30 = MCS 40 (not to 50 + 5)
    assert (v["W"], v["M"]) == (30.0, 40.0) and r["position"]["X"] == 30.0


def test_g375_measures_only_its_axis_and_cprobe_is_refused(run):
    r = run("N3 G375 Z-20 F500\n4 A=PPOS(3)\n5 B=PPOS(1)\nM30\n", fixed_stop(Z=-12.5))
    assert r["variables"]["A"] == -12.5  # no zero shift on Z
    assert r["error"]["code"] == "CPL040" and r["error"]["line"] == 5
    r = run("N3 G375 Z-20 F500\n4 C=CPROBE(3)\nM30\n", fixed_stop(Z=-12.5))
    assert r["error"]["code"] == "CPL040" and "G375" in r["error"]["message"]


def test_fixed_stop_and_probe_events_are_used_by_their_own_functions(run):
    text = "N3 G375 X50 F500\n4 A=PPOS(1)\nN5 G75 X0\n6 B=PPOS(1)\n7 S%=SD(9)\nM30\n"
    r = run(text, probe(X=20.0), fixed_stop(X=30.0))
    v = r["variables"]
    assert r["status"] == "ok", r["error"]
    # G375 takes the fixed stop (30 - 10 = 20), G75 the probe event (20 - 10 = 10)
    assert (v["A"], v["B"], v["S%"]) == (20.0, 10.0, 0)


def test_measuring_is_executed_before_preparation_goes_on(run):
    """Like G75, a G275/G375 block has run when the next CPL block reads MPOS (no WAIT)."""
    r = run("N3 G375 X50 F500\n4 M=MPOS(1)\nN5 G275 X0\n6 N=MPOS(1)\nM30\n", fixed_stop(X=35.0), probe(X=20.0))
    assert (r["variables"]["M"], r["variables"]["N"]) == (35.0, 10.0)


def test_measuring_block_with_a_typ3_g_function(run):
    """A measuring block may carry a Typ3 G function (here G145, an external tool compensation, stored);
    G75 with one stopped with an internal error before."""
    r = run("N3 G145 G375 X50 F500\n4 PP=PPOS(1)\n5 S%=SD(9)\nM30\n", fixed_stop(X=35.0))
    assert r["status"] == "ok", r["error"]
    assert (r["variables"]["PP"], r["variables"]["S%"], r["position"]["X"]) == (25.0, 0, 25.0)
    r = run("N3 G145 G75 X50 F500\n4 PP=PPOS(1)\nM30\n", probe(X=40.0))
    assert r["status"] == "ok" and r["variables"]["PP"] == 30.0 and r["position"]["X"] == 30.0
