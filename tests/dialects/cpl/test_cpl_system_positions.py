"""Manual §4.2 positions on the reference configuration (CPL manual §4.2, L1240-1714; §4.2, L1256-1337); examples with their results."""

from __future__ import annotations

import pytest


def test_axo_example_l1398(run):
    r = run('N10 G1 G90 X100 Y200 F1000\nN20 G92 X75 Y125\n30 XD = AXO("X")\n'
                                '40 YD = AXO(2,0)\nM30\n')
    assert r["status"] == "ok", r["error"]
    assert r["variables"]["XD"] == 25.0 and r["variables"]["YD"] == 75.0


def test_axo_of_another_channel_is_a_runtime_error_l1402(run):
    r = run("N10 G1 G90 X100 Y200 F1000\n50 X2D = AXO(4,0)\nM30\n")
    assert r["status"] == "error" and r["error"]["code"] == "1970" and r["error"]["line"] == 2


def test_cpos_example_l1420_on_channel_2(run):
    text = ("N1 G0 G90 X2=150 Y2=100\n2 X2VALUE=CPOS(1)\nN3 G91 X2=10\n4 X2VAL2=CPOS(1,1)\n"
            'N5 X2=5 Y2=10\n6 Y2VALUE=CPOS("Y2",1)\n7 X2VAL3=CPOS("X2")\nM30\n')
    r = run(text, channel=2)
    assert r["status"] == "ok", r["error"]
    v = r["variables"]
    assert (v["X2VALUE"], v["X2VAL2"], v["Y2VALUE"], v["X2VAL3"]) == (150.0, 160.0, 110.0, 165.0)


def test_cpos_physical_axis_of_channel_1_from_channel_2_l1428(run):
    r = run("8 XVALUE=CPOS(1,0)\nM30\n", channel=2)
    assert r["error"]["code"] == "1970"


def test_positions_read_before_a_wait_are_stale_l1219(run):
    """Manual §4.1: MPOS read without WAIT gives the executed (old) position; CPOS the prepared one."""
    text = ("N10 G1 G90 X100 F1000\n20 BEFORE=MPOS(\"X\")\n30 PREP=CPOS(\"X\")\n"
            "40 IF MPOS(\"X\")=100 THEN\n50 PRN#(0,\"Position reached\")\n60 ENDIF\n"
            "70 WAIT\n80 AFTER=MPOS(\"X\")\n90 IF MPOS(\"X\")=100 THEN\n100 PRN#(0,\"Position reached\")\n"
            "110 ENDIF\nM30\n")
    r = run(text)
    v = r["variables"]
    assert (v["BEFORE"], v["PREP"], v["AFTER"]) == (0.0, 100.0, 100.0)
    assert r["output"] == ["Position reached"]  # only the test after the WAIT sees the position


def test_mpos_example_l1556_on_channel_2(run):
    text = ("N10 G0 G90 X2=150 Y2=100\n20 WAIT\n30 X2VALUE=MPOS(\"X2\")\nN40 G91 X2=10 Y2=10\n50 WAIT\n"
            "60 X2VAL2=MPOS(1)\n70 Y2VALUE = MPOS(\"Y2\",1,2)\n80 XVALUE = MPOS(1,0)\nM30\n")
    r = run(text, channel=2)
    assert r["status"] == "ok", r["error"]
    v = r["variables"]
    # X is physical axis 1 on channel 1: nothing moves it here, it keeps its configured position 0
    assert (v["X2VALUE"], v["X2VAL2"], v["Y2VALUE"], v["XVALUE"]) == (150.0, 160.0, 110.0, 0.0)


def test_wpos_foreign_channel_and_shifts_l1493(run):
    text = ("N5 G54\nN10 G1 G90 X10 Y20 Z30 F1000\n20 WAIT\n30 Z2POS=WPOS(3,1,2)\n40 XW=WPOS(\"X\")\n"
            "50 XM=MPOS(\"X\")\n60 ZS=SPOS(3)\nM30\n")
    r = run(text, offsets={"G54": [100.0, 0.0, -50.0]})
    v = r["variables"]
    assert v["Z2POS"] == 33.0  # Z2 on channel 2 holds its configured position
    assert (v["XW"], v["XM"], v["ZS"]) == (10.0, 110.0, -20.0)  # WCS = MCS - axis zero shift


def test_wpos_physical_axis_with_channel_is_an_error(run):
    assert run("10 A=WPOS(1,0,2)\nM30\n")["error"]["code"] == "CPL040"


def test_apos_spos_examples_l1679(run):
    text = ("N1 G1 G90 X7 Y8 F1000\n2 WAIT\n30 ACT4=APOS(4)\n50 ACT8=APOS(\"A\")\n60 POS1=SPOS(1)\n"
            "70 POS5=SPOS(\"Y2\")\n80 POS8=SPOS(8)\nM30\n")
    v = run(text)["variables"]
    assert (v["ACT4"], v["ACT8"], v["POS1"], v["POS5"], v["POS8"]) == (12.5, 89.5, 7.0, -7.0, 90.0)


def test_units_follow_g70(run):
    v = run("N1 G1 G90 X25.4 F100\n2 WAIT\nN3 G70\n4 WAIT\n5 XI=MPOS(1)\n6 AI=SPOS(8)\nM30\n")[
        "variables"]
    assert v["XI"] == pytest.approx(1.0) and v["AI"] == 90.0  # rotary axes stay in degrees


def test_unknown_axis_is_1938(run):
    r = run('10 A=MPOS("Q")\nM30\n')
    assert r["error"]["code"] == "1938"
    assert run("10 A=CPOS(9)\nM30\n")["error"]["code"] == "1938"


def probe_machine(reference, channel=1, events=()):
    return reference(channel, scenario=[{"time": 0.0, "kind": "probe", **e} for e in events])


def test_cprobe_example_l1451_probe_switched(run_text, reference):
    text = ("N5 G92 X0 Y0 Z0\nN10 G75 X100 Y100 Z50 F1000\n20 IF SD(9) = 1 THEN\n"
            "N30 (MSG, Measuring probe was not deflected!)\n40 GOTO .ERROR\n50 ELSE\n60 ZMEAS = CPROBE(3)\n"
            "70 ENDIF\n80 XP=PROBE(1)\n90 XPP=PPOS(1)\nM30\n105 .ERROR\n106 FAILED%=1\nM30\n")
    m = probe_machine(reference, events=[{"X": 40.0, "Y": 40.0, "Z": 20.0}])
    r = run_text(text, name="p.cpl", machine=m)
    v = r["variables"]
    assert r["status"] == "ok", r["error"]
    assert v["ZMEAS"] == 20.0 and v["XP"] == 40.0 and v["XPP"] == 40.0 and "FAILED%" not in v
    assert r["position"] == {"X": 40.0, "Y": 40.0, "Z": 20.0}  # the move stopped at the switch point


def test_probe_not_deflected_goes_to_error_l2309(run_text, reference):
    text = ("N4 G75 X120 F1000\n60 IF SD(9) = 1 THEN\nN7 (MSG, PROBE WAS NOT DEFLECTED)\n80 GOTO .ERROR\n"
            "90 ELSE\n100 XMEAS = PPOS(1)\n110 ENDIF\nM30\n115 .ERROR\n120 FAILED%=1\nM30\n")
    r = run_text(text, name="p.cpl", machine=probe_machine(reference))
    assert r["variables"]["FAILED%"] == 1 and r["position"]["X"] == 120.0


def test_ppos_excludes_shifts_cprobe_includes_g92(run_text, reference):
    text = ("N1 G54\nN2 G0 X0\nN3 G92 X5\nN4 G75 X50 F500\n5 PR=PROBE(1)\n6 PP=PPOS(1)\n7 CP=CPROBE(1)\nM30\n")
    m = reference(1, offsets={"G54": [10.0, 0.0, 0.0]},
                  scenario=[{"time": 0.0, "kind": "probe", "X": 40.0}])
    v = run_text(text, name="p.cpl", machine=m)["variables"]
    # MCS 40; axis ZS 10 -> PPOS 30 (WCS); G92 X5 at WCS 0 makes the PCS 5 ahead -> CPROBE 35
    assert (v["PR"], v["PP"], v["CP"]) == (40.0, 30.0, 35.0)


def test_probe_on_axis_without_probe_enable(run_text, reference):
    m = reference(1, cpl={"axes": [{"name": "X", "probe": False}, {"name": "Y"}, {"name": "Z"}]},
                  scenario=[{"time": 0.0, "kind": "probe", "X": 4.0}])
    r = run_text("N1 G75 X10 F100\n2 A=CPROBE(1)\nM30\n", name="p.cpl", machine=m)
    assert r["error"]["code"] == "CPL040"


def test_ppos_considers_the_program_coordinate_shift_l1571(run_text, reference):
    """L1571-1576: PPOS considers the axis zero shifts, the tool compensation and the program coordinate
    shift G168/G268 (and not G92, L1578-1583 list only transformations as not considered)."""
    text = ("N1 G54\nN2 G168 X10\nN3 G268 X2\nN4 G0 X0\nN5 G75 X50 F500\n6 PR=PROBE(1)\n7 PP=PPOS(1)\n"
            "8 CP=CPROBE(1)\n9 WAIT\n10 WP=WPOS(1)\nM30\n")
    m = reference(1, offsets={"G54": [10.0, 0.0, 0.0]}, scenario=[{"time": 0.0, "kind": "probe", "X": 40.0}])
    v = run_text(text, name="p.cpl", machine=m)["variables"]
    # MCS 40 - axis ZS 10 - G168 10 - G268 2 = 18; the probe stopped the move, so WPOS (WCS, which holds the
    # program coordinate shift, CPL manual §4.2, L1256-1337) is 40 - 10 = 30, and the PCS 18
    assert (v["PR"], v["PP"], v["CP"], v["WP"]) == (40.0, 18.0, 18.0, 30.0)


def test_cprobe_needs_the_probe_enabled_on_every_axis_of_the_channel_l1441(run_text, reference):
    """L1441: CPROBE needs "probe can be activated" for all axes of the channel, else a run-time error;
    PROBE and PPOS read the axes that have it."""
    m = reference(1, cpl={"axes": [{"name": "X"}, {"name": "Y"}, {"name": "Z", "probe": False}]},
                  scenario=[{"time": 0.0, "kind": "probe", "X": 4.0, "Y": 3.0}])
    r = run_text("N1 G75 X10 Y10 F100\n2 A=PROBE(2)\n3 B=PPOS(1)\n4 C=CPROBE(2)\nM30\n", name="p.cpl", machine=m)
    assert (r["variables"]["A"], r["variables"]["B"]) == (3.0, 4.0)
    assert r["error"]["code"] == "CPL040" and r["error"]["line"] == 4 and "Z" in r["error"]["message"]
