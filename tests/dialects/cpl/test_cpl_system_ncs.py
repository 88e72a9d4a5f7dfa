"""MCODS services of manual §4.14.3 (L2726-3127) added for compensations, spindle limits and gears, jog
speeds, messages, potentiometers, waiting states and program re-selection; MCOPS type 2 (re-selection)."""

from __future__ import annotations


def test_radius_compensation_11_12_none_active(run):
    v = run("1 N%=5:V=0\n2 E%=MCODS(11,1,V,N%,1)\n3 V=0\n4 R=1.5\n5 F%=MCODS(12,1,V,R,1)\nM30\n")["variables"]
    assert (v["E%"], v["N%"], v["F%"], v["R"]) == (0, -1, 0, 0.0)  # G40 active: -1 and 0.0 (L2845-2848)


def test_spindle_limits_19_20_and_speed_5(run):
    text = ("N1 S5000 M3\n2 WAIT\n3 DIM MX(1):V=0:E%=MCODS(19,0,V,MX,1)\n4 DIM MN(1):V=0:E%=MCODS(20,0,V,MN,1)\n"
            "5 DIM S(1):V=0:E%=MCODS(5,-1,V,S,1)\nN6 S100\n7 WAIT\n8 DIM T(1):V=0:E%=MCODS(5,-1,V,T,1)\nM30\n")
    v = run(text, cpl={"spindle": {"min": 200, "max": 4000}, "override": {"spindle": 90}})["variables"]
    assert v["MX"][1] == 4000.0 and v["MN"][1] == 200.0
    assert v["S"][1] == 4000.0  # 90 % of S5000 = 4500, held at the maximum 4000
    assert v["T"][1] == 200.0  # 90 % of S100 = 90, held at the minimum 200


def test_jog_speeds_27(run):
    axes = [{"name": "X", "channel": 1, "jog": 1200}, {"name": "Y", "channel": 1}, {"name": "Z", "channel": 1},
            {"name": "A", "channel": 3, "type": "rotary", "jog": 7200}]
    v = run("1 DIM J(4):V=0:E%=MCODS(27,-1,V,J,4)\nM30\n", cpl={"axes": axes})["variables"]
    assert v["J"][1:] == [1200.0, 1000.0, 1000.0, 20.0]  # A: 7200 degrees/min = 20 rpm


def test_messages_28(run):
    text = ("N1 (MSG, TOOL BREAK CHECK)\n2 DIM M$(80)\n3 V=0:E%=MCODS(28,1,V,M$,80)\n4 WAIT\n"
            "5 DIM N$(80)\n6 V=0:E%=MCODS(28,1,V,N$,80)\nM30\n")
    v = run(text)["variables"]
    assert v["M$"] == "" and v["N$"] == "TOOL BREAK CHECK"  # seen once the block has been executed


def test_dwell_and_auxiliary_function_39_40_87(run):
    text = ("N1 G4 F2\nN2 M50\n3 D1%=0:V=0:E%=MCODS(39,1,V,D1%,1)\n4 W1%=0:V=0:E%=MCODS(87,1,V,W1%,1)\n"
            "5 A1%=0:V=0:E%=MCODS(40,1,V,A1%,1)\n6 WAIT(,1000)\n7 D2%=0:V=0:E%=MCODS(39,1,V,D2%,1)\n"
            "8 A2%=0:V=0:E%=MCODS(40,1,V,A2%,1)\n9 W2%=0:V=0:E%=MCODS(87,1,V,W2%,1)\n10 WAIT(,1500)\n"
            "11 D3%=0:V=0:E%=MCODS(39,1,V,D3%,1)\n12 A3%=0:V=0:E%=MCODS(40,1,V,A3%,1)\n"
            "13 W3%=0:V=0:E%=MCODS(87,1,V,W3%,1)\nM30\n")
    v = run(text)["variables"]
    assert (v["D1%"], v["A1%"], v["W1%"]) == (1, 0, 1 + 4096)  # the dwell is executing, M50 waits behind it
    # 1 s into the 2 s dwell the dwell is still executing (the program reads the machine at its own time)
    assert (v["D2%"], v["A2%"], v["W2%"]) == (1, 0, 1 + 4096)  # M50 still waits in the queue
    # at 2.5 s the dwell has ended and M50 has been executed: the channel stands idle
    assert (v["D3%"], v["A3%"], v["W3%"]) == (0, 0, 0)


def test_axis_potentiometers_50(run):
    text = "1 DIM P(8):V=0:E%=MCODS(50,-1,V,P,8)\n2 DIM Q(4):V=0:E%=MCODS(50,1,V,Q,4)\nM30\n"
    v = run(text, cpl={"override": {"feed": 80, "axis": 50}})["variables"]
    assert v["P"][1:] == [5000.0] * 8  # 50 % in 1/100 %
    assert v["Q"][1:] == [8000.0, 8000.0, 8000.0, 5000.0]  # X Y Z: channel potentiometer, then U_CH1


def test_external_and_general_compensation_51_54(run):
    text = ("1 TC(1,245,0)=12.5\n2 TC(2,245,0)=4\n3 TC(1,347,0)=30\n4 TC(2,347,0)=6\n"
            "N6 G245 G347\n7 WAIT\n8 DIM X(2):V=0:E%=MCODS(51,1,V,X,2)\n9 DIM G(6):V=0:E%=MCODS(54,1,V,G,6)\n"
            "N10 G146\n11 WAIT\n12 DIM Y(2):V=0:E%=MCODS(51,1,V,Y,2)\nM30\n")
    v = run(text)["variables"]
    assert v["X"][1:] == [4.0, 12.5]  # radius, length (TC 1 = L3, 2 = R)
    assert v["G"][1:] == [6.0, 30.0, 0.0, 0.0, 0.0, 0.0]  # R, L3, L1, L2, TO, type (an L1 is NC005)
    assert v["Y"][1:] == [0.0, 0.0]  # G146 deselected it


def test_spindle_gears_64_to_67(run):
    text = ("1 DIM G(8):V=0:E%=MCODS(64,-1,V,G,8)\nN2 M42\n3 DIM C%(8):V=0:E%=MCODS(67,-1,V,C%,8)\n4 WAIT\n"
            "5 DIM H%(8):V=0:E%=MCODS(64,-1,V,H%,8)\n6 DIM A%(8):V=0:E%=MCODS(66,-1,V,A%,8)\n"
            "7 DIM P%(8):V=0:E%=MCODS(65,-1,V,P%,8)\nM30\n")
    v = run(text, cpl={"spindle": {"group": 2}})["variables"]
    assert v["G"][1] == 40.0 and v["C%"][1:3] == [1, 0]  # M40 at power-on; M42 is being switched
    assert v["H%"][1:3] == [42, 0] and v["A%"][1] == 0 and v["P%"][1:3] == [2, 0]


def test_program_reselection_70(run):
    text = ("1 R1%=0:V=0:E%=MCODS(70,2,V,R1%,1)\n2 X%=MCOPS(2,2,2)\n3 R2%=0:V=0:E%=MCODS(70,2,V,R2%,1)\n"
            "4 X%=MCOPS(5,2,1)\n5 R3%=0:V=0:E%=MCODS(70,2,V,R3%,1)\nM30\n")
    v = run(text)["variables"]
    assert (v["R1%"], v["R2%"], v["R3%"]) == (1, 0, 1)  # type 2 suppresses the automatic re-selection


def test_cancel_distance_to_go_prepares_the_blocks_again_with_new_corrections_mcops1(run):
    """L3135-3146: MCOPS(1) prepares the blocks again with the CPL values already substituted (X[POS] stays
    X10) but with corrections changed since; after it the program goes on, nothing is lost."""
    text = ("1 POS=10\nN2 G54 G1 X[POS] F1000\n3 POS=99\n4 FXC(1,54,1)=5\n5 R%=MCOPS(1,1)\n6 WAIT\n"
            "7 M=MPOS(1)\n8 C=CPOS(1)\nM30\n")
    v = run(text)["variables"]
    assert (v["R%"], v["M"], v["C"]) == (0, 15.0, 10.0)  # X10 + the new G54 shift 5


def test_control_reset_of_the_own_channel_exits_the_main_program_mcops2(run):
    """L3155-3166: the interpolator stops, jobs not yet executed are discarded, the main program is exited
    and the channel's errors are deleted; on another channel the program goes on."""
    errors = [{"number": 1938, "channel": 1, "category": 6}, {"number": 1971, "channel": 2, "category": 6}]
    text = ("N1 G1 X10 F1000\n2 WAIT\nN3 X20\n4 A%=1\n5 R%=MCOPS(2,1)\n6 B%=1\nN7 X30\nM30\n")
    r = run(text, cpl={"errors": errors})
    assert r["status"] == "ok"
    assert r["output"] == ["control reset of channel 1: the main program is exited (MCOPS 2)"]
    v = r["variables"]
    assert v["A%"] == 1 and "B%" not in v and "R%" not in v
    assert r["position"]["X"] == 10.0  # N3 was prepared, not executed: discarded
    text = "1 R%=MCOPS(2,2)\n2 DIM E%(2,3)\n3 N%=GETERR(-1,0,E%,2)\n4 B%=1\nM30\n"
    v = run(text, cpl={"errors": errors})["variables"]
    assert (v["R%"], v["N%"], v["B%"], v["E%"][1][1]) == (0, 1, 1, 1938)


def test_control_reset_in_a_sub_program_ends_the_whole_run(run_text, reference, tmp_path):
    (tmp_path / "SUBR.cpl").write_text("1 R%=MCOPS(2,-2)\n2 D%=1\nM30\n")
    r = run_text("1 CALL SUBR\n2 C%=1\nM30\n", name="p.cpl", machine=reference(1))
    assert r["status"] == "ok" and "C%" not in r["variables"]
    assert r["output"] == ["control reset of the system: the main program is exited (MCOPS 2)"]


def test_block_search_on_the_running_own_channel_is_refused_mcops3(run):
    """L3168-3180: block search works in a selected program that has not been started; the own channel's
    main program is running: 15 "search block is not possible ... already started" (L2662)."""
    v = run('1 A%=MCOPS(3,1,"N50","N100")\n2 B%=MCOPS(3,2,"N50")\n3 C%=MCOPS(3,7)\nM30\n')["variables"]
    assert (v["A%"], v["B%"], v["C%"]) == (15, 10, 1)


def test_skip_block_and_optional_stop_signals_68_69(run, reference, run_text):
    """L3066-3069: output "activated" and input of skip block (68) and optional stop (69). The machine's
    block_skip setting decides 68; the NC kernel stops at every M1, so optional stop is on (1, 1)."""
    text = "1 DIM S%(2):DIM O%(2)\n2 V=0:A%=MCODS(68,1,V,S%,2)\n3 V=0:B%=MCODS(69,1,V,O%,2)\nM30\n"
    v = run(text)["variables"]
    assert (v["A%"], v["S%"][1:], v["B%"], v["O%"][1:]) == (0, [1, 1], 0, [1, 1])
    m = reference(1, setting_data={"block_skip": False})
    v = run_text(text, name="p.cpl", machine=m)["variables"]
    assert (v["S%"][1:], v["O%"][1:]) == ([0, 0], [1, 1])


def test_online_correction_values_and_status_89_90(run):
    """L3119-3122: per coordinate of the channel the online correction (WCS) and its status (0 inactive); the
    simulated machine has none, so 0.0 and 0 for X, Y, Z of channel 1, and the rest of the buffer untouched."""
    text = ("1 DIM W(4):DIM S%(4):W(4)=7:S%(4)=7\n2 V=0:A%=MCODS(89,1,V,W,4)\n3 V=0:B%=MCODS(90,1,V,S%,4)\nM30\n")
    v = run(text)["variables"]
    assert (v["A%"], v["W"][1:], v["B%"], v["S%"][1:]) == (0, [0.0, 0.0, 0.0, 7.0], 0, [0, 0, 0, 7])
