"""The Bosch Typ3 osa G table (nc/profiles/typ3osa.py, issue 14 §1): planes, zero shifts, units, the H
word, and the refusals that name the control's meaning. The groups are those of the SD(1) supplementary
table (CPL manual L2302-2306); each test names the manual line of the function it runs."""

from __future__ import annotations

import math

import pytest

from ncvm.nc.profiles.typ3osa import TYP3OSA

AXP_SUB = """\
10 A%=P1% : B%=P2%
20 C=P3:D=P4:RA=P5 : E=0
N40G20 [AXP(A%,E)] [AXP(B%,E)]
N50 G2 [AXP(A%,C)] [AXP(B%,D)] R[RA] F1000
60 WAIT
70 #G% = SD(1,10,1) : #MAIN% = SD(11,1,2) : #SECOND% = SD(11,2,2)
M30
"""


@pytest.fixture
def run(run_text, reference):
    def go(text, sub=None, **machine):
        m = reference(**machine)
        if sub is not None:
            (m.program_path[0] / "AXPSUB").write_text(sub)
        return run_text(text, name="p.cpl", machine=m)
    return go


@pytest.mark.parametrize(("axes", "end", "plane", "main"), [((1, 2), "X20 Y0", 17, 1), ((3, 1), "X0 Z20", 18, 3),
                                                             ((2, 3), "Y20 Z0", 19, 2)])
def test_axp_example_cuts_a_half_circle_in_the_plane_of_g20_l2372(run, axes, end, plane, main):
    """§4.10 L2367-2375 (the extra ``]`` of ``R[RA]]`` is a typo in block N19 of the example): G20 switches to the plane of
    axes P1/P2 with the pole at 0,0; G2 to 20 mm along the main axis with R10 is a half circle of 10 pi mm,
    in mm (the ISO G20 made it 797.96 mm, inch)."""
    r = run(f"N1 G0 X0 Y0 Z0\n10 CALL AXPSUB [{axes[0]}, {axes[1]}, 20, 0, 10]\nM30\n", AXP_SUB)
    assert r["status"] == "ok", r["error"]
    assert r["motion"]["feed_length"] == pytest.approx(10 * math.pi, abs=1e-9)  # 31.42 mm
    for word in end.split():
        assert r["position"][word[0]] == pytest.approx(float(word[1:]), abs=1e-9)
    assert r["variables"]["#G%"] == 20 and r["variables"]["#MAIN%"] == main and r["variables"]["#SECOND%"] == axes[1]


def test_g20_to_a_plane_other_than_g17_g19_is_refused_naming_it_l2372(run):
    r = run("N1 G0 X0 Y0\nN2 G20 Y0 X0\nN3 G2 X20 Y0 R10 F100\nM30\n")
    assert r["error"]["code"] == "NC004" and r["error"]["line"] == 2
    assert "main axis Y" in r["error"]["message"] and "not supported by ncvm" in r["error"]["message"]


def test_g17_after_g20_reports_g17_l2302(run):
    r = run("N1 G20 Z0 X0\n2 WAIT\n3 A%=SD(1,10,1)\nN4 G17\n5 WAIT\n6 B%=SD(1,10,1)\nM30\n")
    assert (r["variables"]["A%"], r["variables"]["B%"]) == (20, 17)


def test_g53_is_zero_shift_off_and_modal_l2302(run):
    """G53 is the axis zero shift "off" of group 15 (G53-G59), modal as its group: N3 still moves without the
    shift. (LinuxCNC's G53 is one block in machine coordinates.)"""
    r = run("N1 G54 G0 X0\n2 WAIT\n3 A=MPOS(1) : G1%=SD(1,15,1)\nN4 G53 X0\nN5 X5\n6 WAIT\n7 B=MPOS(1) : G2%=SD(1,15,1)\n"
            "M30\n", offsets={"G54": [100.0, 0.0, 0.0]})
    assert r["status"] == "ok", r["error"]
    v = r["variables"]
    assert (v["A"], v["B"], v["G1%"], v["G2%"]) == (100.0, 5.0, 54, 53)


def test_g154_and_g254_add_their_rows_and_g153_g253_end_them_l2856(run):
    """G154..G159 and G254..G259 add the rows of the active ZS table (FXC rows 154..159, 254..259, L1759) to
    the shift of G54..G59; MCODS 15 lists the three active rows (L2856); G153/G253 switch them off."""
    text = ('1 FXC("X",155)=10 : FXC("X",256)=1\nN2 G54 G155 G256 G0 X0\n3 WAIT\n4 A=MPOS(1)\n'
            "5 DIM BUF(9) : V=0\n6 R%=MCODS(15,1,V,BUF,9)\n7 S%=SD(1,16,1) : T%=SD(1,17,1)\n"
            "N8 G153 X0\n9 WAIT\n10 B=MPOS(1)\nN11 G253 X0\n12 WAIT\n13 C=MPOS(1) : U%=SD(1,16,1)\nM30\n")
    r = run(text, offsets={"G54": [100.0, 0.0, 0.0]})
    assert r["status"] == "ok", r["error"]
    v = r["variables"]
    assert (v["A"], v["B"], v["C"]) == (111.0, 101.0, 100.0)
    assert (v["S%"], v["T%"], v["U%"]) == (155, 256, 153)
    assert v["BUF"][1:10] == [100.0, 0.0, 0.0, 10.0, 0.0, 0.0, 1.0, 0.0, 0.0]


def test_two_shifts_of_one_group_in_a_block_are_an_error_l2302(run):
    r = run("N1 G154 G155 X0\nM30\n")
    assert r["error"]["code"] == "CPL040" and "G group 16" in r["error"]["message"]


def test_h_word_is_the_tool_length_compensation_l1573(run):
    """H<n> applies the length H of compensation group n (TC selection 1, L1854) on the tool axis; H0 ends it;
    MCODS 9 reports the group (L2835). Before, CPL ignored the H word."""
    text = ("N1 H3 G0 Z0\n2 WAIT\n3 A=MPOS(3) : DIM B%(1) : V=0 : R%=MCODS(9,1,V,B%,1) : H%=B%(1)\n"
            "N4 H0 Z0\n5 WAIT\n6 C=MPOS(3) : V=0 : R%=MCODS(9,1,V,B%,1) : I%=B%(1)\nM30\n")
    r = run(text, tool=[{"number": 3, "length": 25.0}])
    assert r["status"] == "ok", r["error"]
    v = r["variables"]
    assert (v["A"], v["C"], v["H%"], v["I%"]) == (25.0, 0.0, 3, -1)


def test_h_word_with_a_tool_change_in_its_block_takes_its_compensation_group_l1573(run):
    """``T1 M6 H3``: H names compensation group 3 of the selected table (TC selection 1, L1854), not the tool
    in the spindle, so the tool change in the same block does not change the length (25, not tool 1's 7)."""
    r = run("N1 T1 M6 H3 G0 Z0\n2 WAIT\n3 A=MPOS(3)\nM30\n",
            tool=[{"number": 1, "length": 7.0}, {"number": 3, "length": 25.0}])
    assert r["status"] == "ok", r["error"]
    assert r["variables"]["A"] == 25.0


def test_h_word_beyond_the_compensation_groups_stops_l1854(run):
    r = run("N1 H49 G0 Z0\nM30\n")
    assert r["error"]["code"] == "NC009" and "1..48" in r["error"]["message"]


def test_g70_g71_units_l2302(run):
    r = run("N1 G70 G1 X1 F10\nN2 G71 Y5\nM30\n")
    assert r["status"] == "ok", r["error"]
    assert r["motion"]["bounds"]["X"] == [0.0, 25.4] and r["motion"]["bounds"]["Y"] == [0.0, 5.0]


def test_group_reports_of_sd1_at_power_on_l2302(run):
    """SD(1,n,1) of the groups whose power-on state ncvm keeps: G66 (override, group 5), G94 (feed, 7), G40
    (radius compensation, 8), G64 (path mode, 25), G153 / G253 (16, 17); -1 for a group not applied (L2216)."""
    r = run("10 A%=SD(1,5,1) : B%=SD(1,7,1) : C%=SD(1,8,1) : D%=SD(1,25,1) : E%=SD(1,16,1) : F%=SD(1,17,1)\n"
            "20 G%=SD(1,12,1)\nM30\n")
    v = r["variables"]
    assert (v["A%"], v["B%"], v["C%"], v["D%"], v["E%"], v["F%"], v["G%"]) == (66, 94, 40, 64, 153, 253, -1)


@pytest.mark.parametrize(("g", "words"), [("G63", "override"), ("G5", "G group 2"),
                                          ("G12", "polar"), ("G43", "H word"), ("G356", "coordinate transformation")])
def test_functions_ncvm_does_not_run_stop_naming_the_meaning_l2302(run, g, words):
    r = run(f"N1 G0 X0\nN2 {g} X10\nM30\n")
    assert r["error"]["code"] == "NC004" and r["error"]["line"] == 2
    assert words in r["error"]["message"] and "not supported by ncvm" in r["error"]["message"]


def test_every_group_of_the_supplementary_table_has_its_rows_l2302():
    """The supplementary table of SD(1) (L2302-2306): every G number it lists is a row of the profile, in
    the group the table gives."""
    table = {2: [0, 1, 2, 3, 5, 11, 12, 13, 73], 3: [70, 71], 4: [90, 91, 189, 190, 191], 5: [63, 66], 6: [543],
             7: [93, 94, 95], 8: [40, 41, 42], 9: [6, 7], 10: [17, 18, 19, 20], 11: [8, 9], 13: [14, 15],
             15: list(range(53, 60)), 16: list(range(153, 160)), 17: list(range(253, 260)), 18: [60, 67],
             19: [37, 38, 39], 20: [61, 62], 25: [64, 65], 26: [68, 69],
             28: [*range(145, 846, 100), 146], 29: [114, 115], 30: [160, 167]}
    for group, numbers in table.items():
        for g in numbers:
            assert TYP3OSA.group_of(g) == str(group), g


def test_an_address_no_function_reads_stops_the_run_and_check_warns_of_it(run, run_text, reference, tmp_path):
    """Issue 14 §1 "never silently ignore a word", §5 "check sees what run will refuse": E is no address of
    the Typ3 osa profile (its addresses: the axes, F S T H D I J K R, P, G M N L); the run stops there with
    NC007 after the block before it moved, and check warns in the same code."""
    from ncvm.api import check

    r = run("N1 G1 X1 F100\nN2 G1 X2 E5\nM30\n")
    assert r["error"]["code"] == "NC007" and r["error"]["line"] == 2 and r["position"]["X"] == 1.0
    assert "not supported by ncvm" in r["error"]["message"]
    prog = tmp_path / "e.cpl"
    prog.write_text("N1 G1 X1 F100\nN2 G1 X2 E5\nM30\n")
    diags = check(prog, dialect="cpl", machine=reference())
    assert [(d.code, d.span.line, d.span.column, d.severity) for d in diags] == [("NC007", 2, 10, "warning")]


def test_g90_g91_dimensions_and_g92_set_actual_value_l2302_l2817(run):
    """G90/G91 (group 4, L2302) and G92 "set actual value" (MCODS 1, L2817): after G92 X0 at X10 the program
    position 5 is machine position 15; SD(1,4,1) reports 91 while incremental."""
    r = run("N1 G91 G1 X5 F100\nN2 X5\n3 WAIT\n4 A%=SD(1,4,1)\nN5 G90 G92 X0\nN6 X5\n7 WAIT\n8 B=MPOS(1) : C%=SD(1,4,1)\n"
            "M30\n")
    assert r["status"] == "ok", r["error"]
    v = r["variables"]
    assert (v["A%"], v["B"], v["C%"]) == (91, 15.0, 90)


#: G functions the CPL manual names in the group table (L2302-2306) without their behaviour
NAMED_WITHOUT_BEHAVIOUR = (5, 6, 7, 14, 15, 68, 69, 73, 114, 115, 189, 190, 191)


@pytest.mark.parametrize("g", NAMED_WITHOUT_BEHAVIOUR)
def test_functions_the_manual_names_without_behaviour_are_refused_by_name(run, g):
    """No guessing: the run stops at the block with NC004 saying "not supported by ncvm", naming the group of
    the SD table and that the CPL manual does not describe it; the block before it ran."""
    row = TYP3OSA.refused(g)
    assert row is not None and row.code == "NC004"
    r = run(f"N1 G1 X5 F1000\nN2 G{g}\nN3 X9\nM30\n")
    assert r["error"]["code"] == "NC004" and r["error"]["line"] == 2
    message = r["error"]["message"]
    assert message.startswith(f"G{g} (") and "not supported by ncvm" in message
    assert f"G group {row.group}" in message or row.meaning.split(";")[0] in message
    assert "the CPL manual does not describe it" in message
    assert r["position"]["X"] == 5.0
