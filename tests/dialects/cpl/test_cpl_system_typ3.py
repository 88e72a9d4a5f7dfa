"""SD/SDR groups 68, 168, 268, 131, 200, 328, 581 (manual §4.9 L2259-2297, L2328-2347) on the Typ3 G
functions G168/G268, G131, G328, G581 and the configured work areas (forms: docs/decisions.md)."""

from __future__ import annotations

import pytest


def test_coordinate_shifts_68_168_268(run):
    text = ("N10 G168 X10 Y-2.5\nN20 G268 X1.5 Z4\n30 A%=SD(168,1,1)\n31 B%=SD(168,2,1)\n32 C%=SD(68,1,1)\n"
            "33 D=SDR(68,1,1)\n34 E=SDR(268,1,3)\n35 WAIT\n36 F%=SD(168,2,2)\n37 G=SDR(68,2,2)\n"
            "38 H%=SD(268,2,3)\nN40 G90 G1 X5 Y5 Z0 F1000\n41 WAIT\n42 MX=MPOS(1)\n43 MY=MPOS(2)\n44 MZ=MPOS(3)\n"
            "45 WX=WPOS(1)\nM30\n")
    r = run(text)
    v = r["variables"]
    assert (v["A%"], v["B%"]) == (10, 0)  # programmed at once, active only after execution (WAIT)
    assert v["C%"] == 12 and v["D"] == 11.5  # G168 + G268 = 10 + 1.5, as INTEGER rounded half away from 0
    assert v["E"] == 4.0 and v["F%"] == -3 and v["G"] == -2.5 and v["H%"] == 4
    # PCS = WCS - G168 - G268: X5 lands at 5 + 10 + 1.5, Y5 at 5 - 2.5, Z0 at 0 + 4
    assert (v["MX"], v["MY"], v["MZ"]) == (16.5, 2.5, 4.0)
    assert v["WX"] == 16.5  # the WCS includes the program coordinate shifts (CPL manual §4.2, L1256-1337)


def test_coordinate_shift_in_inch_and_cleared(run):
    text = "N10 G70 G168 X1\n20 WAIT\n30 A=SDR(168,2,1)\nN40 G71\n41 WAIT\n42 B=SDR(168,2,1)\nN50 G168\n" \
           "60 C%=SD(168,1,1)\n61 D%=SD(168,2,1)\nM30\n"
    v = run(text)["variables"]
    assert v["A"] == 1.0 and v["B"] == pytest.approx(25.4)  # 1 inch, read back in mm after G71
    assert (v["C%"], v["D%"]) == (0, 25)  # G168 alone clears the programmed shift; the active one still 25.4


def test_shift_of_an_axis_that_is_not_applied(run):
    assert run("1 A%=SD(168,1,4)\nM30\n")["error"]["code"] == "1938"  # channel 1 has 3 axes
    assert run("1 A%=SD(168,3,1)\nM30\n")["error"]["code"] == "CPL023"


def test_g131_axis_of_rotation_symmetry(run):
    text = ("N10 G131 A30 I5\n20 A%=SD(131,1)\n21 B%=SD(131,2)\n22 WAIT\n23 C%=SD(131,2)\n24 O=SDR(131,3)\n"
            "25 P=SDR(131,4)\nN30 G130\n40 WAIT\n41 D%=SD(131,2)\n42 Q=SDR(131,3)\nM30\n")
    v = run(text, channel=3)["variables"]  # channel 3: logical axis 1 is the rotary axis A
    assert (v["A%"], v["B%"], v["C%"], v["O"], v["P"]) == (1, 0, 1, 30.0, 5.0)
    assert (v["D%"], v["Q"]) == (0, 0.0)
    assert run("N10 G131 X30\nM30\n")["error"]["code"] == "CPL040"  # X is not rotary


def test_g328_precision_barrier(run):
    text = "N10 G328 I0.25 K1.5\n20 A=SDR(328)\n21 B%=SD(328,2)\nN30 G328 K3\n40 C=SDR(328,1)\n41 D=SDR(328,2)\nM30\n"
    v = run(text)["variables"]
    assert (v["A"], v["B%"], v["C"], v["D"]) == (0.25, 2, 0.25, 3.0)  # a missing word keeps its value


def test_g581_axis_coupling(run):
    text = ("N10 G581 Y0.5 I1 J2 K-1\n20 M%=SD(581,0,1)\n21 N%=SD(581,0,2)\n22 S%=SD(581,2,0)\n"
            "23 F=SDR(581,2,2)\n24 H=SDR(581,2,1)\n25 K=SDR(581,2,3)\n26 Z%=SD(581,3,0)\nN30 G580\n"
            "31 E%=SD(581,2,0)\nM30\n")
    v = run(text)["variables"]
    assert (v["M%"], v["N%"], v["S%"], v["F"], v["H"], v["K"], v["Z%"]) == (1, 0, 1, 2.0, 0.5, -1.0, 0)
    assert v["E%"] == 0  # G580 removed the coupling
    assert run("N10 G581 Y0 I9\nM30\n")["error"]["code"] == "1938"
    assert run("1 A%=SD(581,2,4)\nM30\n")["error"]["code"] == "CPL023"


def test_work_areas_and_dead_ranges_200(run):
    areas = [{"type": "dead", "axes": ["X", "Y"], "centre": [100, 50], "extent": [20, 10]},
             {"type": "work", "centre": [0, 0], "extent": [500, 400], "active": False}]
    text = ("1 N%=SD(200,1)\n2 A1%=SD(200,2,1)\n3 A2%=SD(200,2,2)\n4 T1%=SD(200,3,1)\n5 T2%=SD(200,3,2)\n"
            "6 T3%=SD(200,3,3)\n7 C1%=SD(200,11,1)\n8 C2%=SD(200,12,1)\n9 E1%=SD(200,21,1)\n10 E2%=SD(200,22,2)\n"
            "N11 G70\n12 WAIT\n13 CI%=SD(200,11,1)\nM30\n")
    v = run(text, cpl={"areas": areas})["variables"]
    assert (v["N%"], v["A1%"], v["A2%"], v["T1%"], v["T2%"], v["T3%"]) == (1, 1, 0, 1, 2, 0)
    assert (v["C1%"], v["C2%"], v["E1%"], v["E2%"]) == (100, 50, 20, 400)
    assert v["CI%"] == 4  # 100 mm = 3.937 inch after G70
    assert run("1 A%=SD(200,3,11)\nM30\n", cpl={"areas": areas})["error"]["code"] == "CPL023"


def test_g_group_28_external_compensation_sd1_and_ncf(run):
    text = ('N10 G345\n20 A%=SD(1,28,2)\n21 B%=SD(1,28,1)\n22 DIM N$(5)\n23 N$=NCF("G146")\n24 WAIT\n'
            "25 C%=SD(1,28,1)\nN30 G146\n31 D%=SD(1,28,2)\nM30\n")
    v = run(text)["variables"]
    assert (v["A%"], v["B%"], v["N$"], v["C%"], v["D%"]) == (345, 146, "G345", 345, 146)


#: dead range 1: X 90..110, Y 45..55; work area 2: X -50..150, Y -20..80 (centre ± extension / 2)
ZONES = [{"type": "dead", "axes": ["X", "Y"], "centre": [100, 50], "extent": [20, 10]},
         {"type": "work", "axes": ["X", "Y"], "centre": [50, 30], "extent": [200, 100]}]


@pytest.mark.parametrize("text, expect", [
    # a straight move through the dead range (from (0,0) to (200,100): at X 100 it is at Y 50)
    ("N1 G1 F1000 X200 Y100\nM30\n", [("enters dead range 1", 1), ("leaves work area 2", 1)]),
    # along its edge Y45 and into the corner: touching is not entering; X150 Y45 stays in the work area
    ("N1 G1 F1000 X0 Y45\nN2 X150\nM30\n", []),
    # a clockwise half circle about (100,40), radius 10: from (90,40) over the top (100,50) to (110,40)
    ("N1 G0 X90 Y40\nN2 G2 X110 Y40 I10 J0 F500\nM30\n", [("enters dead range 1", 2)]),
    # the same circle counter-clockwise goes below, down to Y30: clear of the dead range
    ("N1 G0 X90 Y40\nN2 G3 X110 Y40 I10 J0 F500\nM30\n", []),
    # an arc whose end points and chord are outside both ranges but which bulges out of the work area:
    # centre (140,30), radius 15 from (140,15) counter-clockwise to (140,45) reaches X155 > 150
    ("N1 G0 X140 Y15\nN2 G3 X140 Y45 I0 J15 F500\nM30\n", [("leaves work area 2", 2)]),
    # Z moves do not matter to an X-Y area
    ("N1 G0 X95 Y0\nN2 Z-50\nM30\n", []),
])
def test_moves_checked_against_work_areas_and_dead_ranges_200(run, text, expect):
    """SD(200) L2266-2275: areas of type 1 dead range / 2 work area with a centre and an extension on two axes;
    a move into an active dead range or out of an active work area is a limit violation (docs/decisions.md)."""
    r = run(text, cpl={"areas": ZONES})
    assert r["status"] == "ok"
    got = r["limit_violations"]
    assert len(got) == len(expect)
    for message, (part, line) in zip(got, expect):
        assert part in message and message.endswith(f"p.cpl:{line})")
        box = "(X 90.0000..110.0000, Y 45.0000..55.0000)" if "dead" in part else "(X -50.0000..150.0000, Y -20.0000"
        assert box in message


def test_only_active_areas_watch_the_motion_and_the_first_block_is_named(run):
    zones = [dict(ZONES[0], active=False), ZONES[1]]
    r = run("N1 G1 F1000 X100 Y50\nN2 X160\nN3 X170\nM30\n", cpl={"areas": zones})
    [message] = r["limit_violations"]
    assert message.startswith("the path leaves work area 2 (X -50.0000..150.0000, Y -20.0000..80.0000) (first at ")
    assert message.endswith("p.cpl:2)")


def test_areas_are_machine_coordinates(run):
    """The areas are machine data: a zero shift moves the workpiece, not the dead range."""
    r = run("N1 G54 G1 F1000 X0 Y0\nM30\n", cpl={"areas": ZONES[:1]}, offsets={"G54": [100, 50, 0]})
    assert len(r["limit_violations"]) == 1 and "enters dead range 1" in r["limit_violations"][0]
    assert run("N1 G1 F1000 X0 Y0\nN2 X100\nM30\n", cpl={"areas": ZONES[:1]})["limit_violations"] == []
