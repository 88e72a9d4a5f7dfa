"""Manual §4.9-4.14: SD, SDR, MCA, NCF, AXP, IC, PLC, CLOCK/DATE/TIME, GETERR, MCODS, MCOPS; [cpl] keys."""

from __future__ import annotations

import pytest

from ncvm.diagnostics import UsageError


def test_sd_examples_l2296(run):
    text = ("N1 G1 G91 X10 F500 S1000 M3\n2 WAIT\n10 A%=SD(1,2,1)\n20 B%=SD(1,4,1)\n30 C%=SD(2,1)\n"
            "40 D%=SD(5,1,1)\nN50 G0 G90 G18\n60 E%=SD(1,2,1)\n61 F%=SD(1,2,2)\n62 PL1%=SD(11,1,1)\n"
            "63 PL2%=SD(11,1,2)\n64 CH%=SD(8)\n65 SP%=SD(12,1)\n66 N%=SD(20)\n67 L%=SD(22,\"Z\")\n"
            "68 PH%=SD(24,2,2)\n69 AC%=SD(25,\"A\")\n70 SR=SDR(2,1)\n71 S3%=SD(5,3,1)\nM30\n")
    v = run(text, cpl={"override": {"feed": 80}})["variables"]
    assert (v["A%"], v["B%"], v["C%"], v["D%"]) == (1, 91, 80, 400)  # 80 % of F500
    # before a WAIT the active group 2 is still G1, the last programmed one is already G0
    assert (v["E%"], v["F%"]) == (1, 0)
    assert (v["PL1%"], v["PL2%"]) == (3, 1)  # G18 is programmed (Z, X) but the active plane is still G17
    assert (v["CH%"], v["SP%"], v["N%"], v["L%"], v["PH%"], v["AC%"]) == (1, 3, 3, 3, 5, 3)
    assert v["SR"] == 80.0 and v["S3%"] == 1000


def test_g_groups_with_one_state_in_the_kernel_sd1_and_ncf(run):
    """SD(1,g,·) and NCF (L2090-2113, L2300-2306): the feed type group 7 is G94, the path-control group 25
    G64 (the kernel knows only these); a group the kernel does not apply at all gives -1 and ""."""
    text = ('N1 G64 G1 X1 F100\n2 WAIT\n3 A%=SD(1,25,1)\n4 B%=SD(1,7,2)\n5 DIM C$(4)\n6 C$=NCF("G65")\n'
            '7 DIM D$(4)\n8 D$=NCF("G95")\n9 E%=SD(1,9,1)\n10 DIM F$(4)\n11 F$=NCF("G6")\nM30\n')
    v = run(text)["variables"]
    assert (v["A%"], v["B%"], v["C$"], v["D$"], v["E%"], v["F$"]) == (64, 94, "G64", "G94", -1, "")


def test_sd9_before_any_measuring_block_is_g75_not_active_l2229(run):
    """L2229: SD(9)=0 "G75 not active", SD(9)=1 "G75 active" (the probe has not switched yet). Before any G75
    ran no measurement is active: 0 (it read 1, "not switched"); a G75 whose probe never switched gives 1."""
    v = run("1 A%=SD(9)\nN2 G75 X10 F1000\n3 B%=SD(9)\nM30\n")["variables"]
    assert (v["A%"], v["B%"]) == (0, 1)


def test_mca_old_number_example_l2077(run):
    v = run("10 BLOCKNR%=100100004\n20 ERG%=MCA(BLOCKNR%,0)\n30 ROT%=MCA(100300004,7)\n"
            '40 N$=MCA(100300001,3)\nM30\n')["variables"]
    assert (v["ERG%"], v["ROT%"], v["N$"]) == (1, 2, "X2")  # X is linear (1), A rotary (2)
    assert run("10 A%=MCA(100300004,99)\nM30\n")["error"]["code"] == "CPL040"


def test_ncf_example_l2108(run):
    r = run('N5 G0 X1\n10 DIM A$(4)\nN15 G1 X2 F100\n20 A$=NCF("G1")\n21 B$=NCF("G91")\nN80 [A$] X5\nM30\n')
    assert r["variables"]["A$"] == "G1" and r["variables"]["B$"] == "G90"
    assert r["motion"]["feed_moves"] == 2


def test_axp_example_l2367(run_text, reference):
    """The manual's plane-independent circle (the extra ']' in R[RA]] is a typo in block N19 of the example)."""
    sub = ("10 A%=P1% : B%=P2%\n20 C=P3:D=P4:RA=P5\n30 E=0\nN40 G17 [AXP(A%,E)] [AXP(B%,E)]\n"
           "N50 G2 [AXP(A%,C)] [AXP(B%,D)] R[RA] F1000\nM30\n")
    m = reference()
    (m.program_path[0] / "CIRC").write_text(sub, encoding="latin-1")
    r = run_text('10 CALL CIRC[1,2,20,0,10]\n20 T$=AXP(3,1.5)\nM30\n', name="p.cpl", machine=m)
    assert r["status"] == "ok", r["error"]
    assert r["position"]["X"] == pytest.approx(20.0) and r["position"]["Y"] == pytest.approx(0.0)
    assert r["motion"]["arc_moves"] == 1 and r["variables"]["T$"] == "Z1.5"


def test_ic_read_and_write_l2408(run_text, reference):
    m = reference(scenario=[{"time": 0.0, "kind": "input", "address": "IC(5,1,2)", "value": True}])
    r = run_text("40 A?=IC(5,1,2)\n41 B?=IC(6,1,2)\n50 IC(80,0,1)=TRUE\n60 C?=IC(80,3,1)\n61 D?=IC(81,3)\nM30\n",
                 name="p.cpl", machine=m)
    assert r["variables"] == {"A?": True, "B?": False, "C?": True, "D?": False}


@pytest.mark.parametrize("expr, ok", [
    ("IC(0,0,3)", True), ("IC(0,0,4)", False), ("IC(0,0,0)", True), ("IC(95,3,3)", True), ("IC(0,3,4)", False),
    ("IC(0,1,8)", True), ("IC(0,1,9)", False), ("IC(0,4,0)", False), ("IC(0,2,1)", True), ("IC(0,2,2)", False),
    ("IC(0,6,1)", True), ("IC(0,7,2)", False), ("IC(5,9)", True), ("IC(0,8,0)", False)])
def test_ic_index_ranges_l2396(run, expr, ok):
    """L2396-2405: index = channel 0..max channel, axis 1..max axis, spindle 1..max spindle, otherwise 1
    (the reference configuration has channels 1..3, physical axes 1..8 and one spindle)."""
    r = run(f"10 A?={expr}\nM30\n")
    assert (r["error"] is None) if ok else (r["error"]["code"] == "CPL023"), r["error"]


@pytest.mark.parametrize("stmt", ["IC(80,3,1)=TRUE", "IC(79,0,1)=TRUE", "IC(96,0,1)=TRUE"])
def test_ic_write_only_channel_outputs_81_to_96(run, stmt):
    assert run(f"1 {stmt}\nM30\n")["error"]["code"] == "CPL040"


def test_plc_examples_l2459(run):
    v = run("40 I%=PLC(1,,10,1)\n90 J%=PLC(4,98,2,2)\n100 PLC(4,99,0,4)=-2\n110 K%=PLC(4,99,0,4)\n"
            "120 L%=PLC(4,99,3,1)\nM30\n", cpl={"plc": {"I:10": 7, "D98:2": 1, "D98:3": 2}})["variables"]
    assert (v["I%"], v["J%"], v["K%"], v["L%"]) == (7, 258, -2, 254)  # big-endian word 0x0102
    assert run("1 PLC(4,97,0,1)=1\nM30\n")["error"]["code"] == "CPL040"  # DM 97 is not writable


def test_clock_measures_a_block_l2476(run):
    text = "20 WAIT\n30 START_TIME%=CLOCK\nN4 G1 X50 F3000\n40 WAIT\n50 ENDTIME%=CLOCK\n60 DIFF%=ENDTIME%-START_TIME%\nM30\n"
    r = run(text)
    assert r["variables"]["DIFF%"] == pytest.approx(1000, abs=60)  # 50 mm at 3000 mm/min (+ acceleration)
    assert r["variables"]["DIFF%"] == round(r["cycle_time_s"] * 1000)


def test_date_and_time_from_the_simulated_clock_l2496(run):
    """L2496: DATE gives the date "in DD.MM form"; ``[cpl] date_format = "DD.MM.YY"`` adds the year."""
    start = 1795442399.0  # 2026-11-23 13:59:59 UTC
    v = run("10 WAIT(,2000)\n30 A$=DATE\n40 B$=TIME\nM30\n", clock={"start": start})["variables"]
    assert v == {"A$": "23.11", "B$": "14.00.01"}
    v = run("30 A$=DATE\nM30\n", clock={"start": start}, cpl={"date_format": "DD.MM.YY"})["variables"]
    assert v == {"A$": "23.11.26"}


ERRORS = [{"number": 1856, "channel": 1, "category": 2}, {"number": 1938, "channel": 2, "category": 6},
          {"number": 1970, "channel": 1, "category": 6}, {"number": 1971, "channel": 2, "category": 6}]


def test_geterr_examples_l2594(run):
    """The second example prints CATEGORY%=0 but reports only part-program errors: ncvm reads the damaged text so and
    repairs it to CATEGORY%=6, which gives the stated result ERG% = 2."""
    text = ("10 DIM ERRNO%(5,3)\n30 CHAN%=2:CATEGORY%=6\n40 ERG%=GETERR(CHAN%,CATEGORY%,ERRNO%,1)\n"
            "41 FIRST%=ERRNO%(1,1)\n50 ERG%=GETERR(CHAN%,CATEGORY%,ERRNO%,5)\n60 FOR I%=1 TO ERG%\n"
            "70 IF ERRNO%(I%,3)=6 THEN\n80 PRN#(0,\"Part program error: \",ERRNO%(I%,1))\n90 ENDIF\n100 NEXT I%\n"
            "110 ALL%=GETERR(-1,,ERRNO%,5)\n120 BAD%=GETERR(0,0,ERRNO%)\nM30\n")
    r = run(text, cpl={"errors": ERRORS})
    assert r["status"] == "ok", r["error"]
    v = r["variables"]
    assert v["FIRST%"] == 1938 and v["ERG%"] == 2 and v["ALL%"] == 4 and v["BAD%"] == -1
    assert r["output"] == ["Part program error:      1938", "Part program error:      1971"]


def test_mcops_reset_clears_the_channels_errors(run):
    v = run("10 DIM E%(5,3)\n20 R%=MCOPS(2,2)\n30 N%=GETERR(-1,0,E%,5)\nM30\n", cpl={"errors": ERRORS})["variables"]
    assert v["R%"] == 0 and v["N%"] == 2


def test_mcods_sav_state_example_l3234(run):
    text = ("10 DIM BUF%(2)\n20 VERSION=0\n30 ERR_VAR%=MCODS(32,2,VERSION,BUF%,2)\n40 S1%=BUF%(1)\n"
            "50 R%=MCOPS(4,2,\"SUB2\",1)\n55 VERSION=0\n60 ERR_VAR%=MCODS(32,2,VERSION,BUF%,2)\n70 S2%=BUF%(1)\n"
            "80 E2%=MCODS(32,9,VERSION,BUF%,2)\nM30\n")
    r = run(text)
    v = r["variables"]
    assert v["ERR_VAR%"] == 0 and v["VERSION"] != 0.0
    assert v["S1%"] == 1  # not active (CPL manual §4.14, L2687-3127: INACTIVE = 1)
    assert v["R%"] == 6 and v["S2%"] == 1  # SUB2 does not exist: nothing selected
    assert v["E2%"] == 1  # channel 9 does not exist


def test_mcods_blocks_until_the_data_changes(run):
    """Example 2 (L3251): an unchanged version waits; here the own channel's positions change once the
    queued block executes; when nothing can change any more it is the simulator deadlock."""
    text = ("10 DIM P(8)\n20 V=0\n30 E%=MCODS(1,-1,V,P,8)\nN40 G1 X10 F600\n50 E%=MCODS(1,-1,V,P,8)\n"
            "60 X=P(1)\n70 E%=MCODS(1,-1,V,P,8)\nM30\n")
    r = run(text)
    assert r["error"]["code"] == "CPL039" and r["error"]["line"] == 7
    r = run(text.replace("70 E%=MCODS(1,-1,V,P,8)\n", ""))
    assert r["variables"]["X"] == 10.0  # the second call returned once N40 had moved X


def test_mcods_axis_names_example_l3257(run):
    text = ("30 VERSION=0\n40 DIM AXNAME$(512)\n60 ERR=MCODS(33,-1,VERSION,AXNAME$,512)\n70 IF ERR=0 THEN\n"
            "90 DIM AXNMB%(3)\n100 VERSION=0\n110 ERR=MCODS(45,-1,VERSION,AXNMB%,3)\n120 ANZ=AXNMB%(2)\n130 ENDIF\n"
            "180 FOR I%=0 TO (ANZ-1)\n190 NAME$=MID$(AXNAME$,I%*9+1,8)\n200 IF ASC(NAME$)<>0 THEN\n"
            "220 PRN#(0,I%+1,\". Axis name: \",NAME$)\n230 ENDIF\n240 NEXT\nN260 M30\n")
    r = run(text)
    assert r["status"] == "ok", r["error"]
    assert r["output"][0] == "        1. Axis name: X       " and len(r["output"]) == 8
    assert r["output"][6].endswith("Axis name: U_CH1   ")


def test_mcods_waiting_state_example_l3298(run):
    text = ("10 CHAN%=1\n20 VERSION%=0\n30 STATES%=0\nN35 G1 X5 F100\n40 ERR=MCODS(87,CHAN%,VERSION%,STATES%,1)\n"
            "50 IF ERR=0 THEN\n60 MASK%=1\n70 WHILE MASK% <= STATES% DO\n80 CASE (STATES% AND MASK%) OF\n"
            "90 LABEL 1:PRN#(0,\"dwell time\")\n210 LABEL 4096:PRN#(0,\"Waiting for interface signal\")\n"
            "240 ENDCASE\n250 MASK%=MASK%*2\n260 END\n265 ENDIF\nM30\n")
    r = run(text)
    assert r["status"] == "ok", r["error"]
    assert r["variables"]["STATES%"] == 4096 and r["output"] == ["Waiting for interface signal"]


def test_mcops_operating_mode(run):
    v = run("1 A%=MCOPS(7,2,1)\n2 DIM M%(1)\n3 V%=0\n4 E%=MCODS(31,2,V%,M%,1)\n5 B%=MCOPS(7,1,1)\n"
            "6 C%=MCOPS(7,2,99)\nM30\n")["variables"]
    assert (v["A%"], v["M%"], v["B%"], v["C%"]) == (0, [None, 1], 13, 18)  # 13: own channel is running


def test_unknown_cpl_key_is_an_error_naming_it(run_text, reference):
    with pytest.raises(UsageError, match="zs_tabels"):
        run_text("1 A=1\nM30\n", name="p.cpl", machine=reference(cpl={"zs_tabels": {}}))
    with pytest.raises(UsageError, match=r"cpl\.axes\[0\]\.kanal = 1: unknown key"):
        run_text("1 A=1\nM30\n", name="p.cpl", machine=reference(cpl={"axes": [{"name": "X", "kanal": 1}]}))


SERCOS = {"axes": [{"name": "X", "sercos": {"S-0-0030": "DKC 03.3", "P-0-0004": 7, "S-0-0017": [1, 51, 130]}},
                   {"name": "Y"}, {"name": "Z"}]}


def test_scs_example_l2160(run):
    text = ("N1 G1 X12.5 F1000\n2 WAIT\n10 POSITION% = SCS(1, \"S\", 51, ERROR%)\n11 PAR4%=SCS(\"X\",\"P\",4)\n"
            "12 V$=SCS(1,\"S\",30)\n13 SCSL(1,\"S\",17,\"S17.TXT\",R%)\nM30\n")
    r = run(text, cpl=SERCOS)
    assert r["status"] == "ok", r["error"]
    assert r["variables"] == {"POSITION%": 125000, "ERROR%": 0, "PAR4%": 7, "V$": "DKC 03.3", "R%": 0}


def test_scsl_writes_the_list_as_records(run_text, reference, tmp_path):
    m = reference(cpl=SERCOS)
    r = run_text('1 SCSL(1,"S",17,"S17.TXT")\nM30\n', name="p.cpl", machine=m)
    assert r["status"] == "ok", r["error"]
    assert (m.file_root / "S17.TXT").read_bytes() == b"1\n51\n130\n\x03\n"



@pytest.mark.parametrize("name", ["../../ESCAPED.TXT", "/../ESCAPED.TXT", "C:..\\ESCAPED.TXT"])
def test_scsl_never_writes_outside_the_file_root(run_text, reference, tmp_path, name):
    m = reference(cpl=SERCOS)
    m.file_root = tmp_path / "a" / "b" / "files"  # every way out of it still lies in tmp_path
    r = run_text(f'1 SCSL(1,"S",17,"{name}")\nM30\n', name="p.cpl", machine=m)
    assert r["status"] == "error" and "outside the file root" in r["error"]["message"], r["error"]
    assert not list(tmp_path.rglob("*ESCAPED*"))
    r = run_text(f'1 SCSL(1,"S",17,"{name}",R%)\nM30\n', name="p.cpl", machine=m)
    assert r["status"] == "ok" and r["variables"]["R%"] == 2, r["error"]

def test_scs_locked_service_channel(run):
    """While locked the result variable gets 1 and the value read last remains; without it: the error."""
    text = ("N1 G1 X1 F1000\n2 WAIT\n10 P%=SCS(1,\"S\",51,E%)\nN11 G1 X2\n12 WAIT(,1000)\n13 P%=SCS(1,\"S\",51,E%)\n"
            "14 Q%=SCS(1,\"S\",51)\nM30\n")
    r = run(text, cpl=SERCOS, scenario=[{"time": 1.0, "kind": "sercos", "locked": True}])
    assert r["error"]["code"] == "CPL041" and r["error"]["line"] == 7
    r = run(text.replace('14 Q%=SCS(1,"S",51)\n', ""), cpl=SERCOS,
            scenario=[{"time": 1.0, "kind": "sercos", "locked": True}])
    assert r["variables"] == {"P%": 10000, "E%": 1}


def test_scs_list_parameter_is_an_error(run):
    assert run('1 A%=SCS(1,"S",17,E%)\nM30\n', cpl=SERCOS)["error"]["code"] == "CPL040"


@pytest.mark.parametrize("cpl,name", [({"tool_database": [{"sector": 1, "plaec": 1}]}, r"tool_database\[0\]\.plaec"),
                                      ({"errors": [{"number": 1, "kat": 6}]}, r"errors\[0\]\.kat"),
                                      ({"override": {"rapid": 50}}, r"override\.rapid"),
                                      ({"zs_tables": {"V2": {"G53": [1.0]}}}, r"zs_tables\.V2\.G53"),
                                      ({"zs_tables": {"V2": {"G54": [1.0] * 9}}},
                                       r"zs_tables\.V2\.G54: \[1\.0, .*\] has more values than the 8 columns"),
                                      ({"channel": "one"}, 'cpl.channel = "one": must be an integer')])
def test_bad_cpl_records_name_the_key(run_text, reference, cpl, name):
    with pytest.raises(UsageError, match=name):
        run_text("1 A=1\nM30\n", name="p.cpl", machine=reference(cpl=cpl))


def test_mcods_distance_to_go_and_travel_flags(run):
    """Type 83 (distance to go) and 47 (travel command): the queued G1 has not run before the WAIT."""
    text = ("10 DIM D(3)\n11 DIM T%(8)\n12 DIM Q(3)\nN20 G1 X30 Y-4 F600\n30 V=0\n40 E%=MCODS(83,1,V,D,3)\n"
            "50 V=0\n60 E%=MCODS(47,-1,V,T%,8)\n70 WAIT\n80 V=0\n90 E%=MCODS(83,1,V,Q,3)\nM30\n")
    v = run(text)["variables"]
    assert v["D"] == [None, 30.0, -4.0, 0.0] and v["T%"] == [None, 1, 1, 1, 0, 0, 0, 0, 0]
    assert v["Q"] == [None, 0.0, 0.0, 0.0]


def test_axp_with_an_extended_axis_name(run):
    """On channel 2 the axes are X2, Y2, Z2: AXP gives 'X2=10.5', which the NC block takes as X2 10.5."""
    r = run("10 A%=1\nN20 G1 F1000 [AXP(A%,10.5)] [AXP(2,-3)]\n30 T$=AXP(A%,10.5)\nM30\n", channel=2)
    assert r["status"] == "ok", r["error"]
    assert r["variables"]["T$"] == "X2=10.5" and r["position"]["X2"] == 10.5 and r["position"]["Y2"] == -3.0


def test_mcods_drive_texts_and_cyclic_values(run):
    text = ("10 DIM T$(40)\n11 DIM P%(8)\n12 DIM N$(80)\nN13 G1 X2 F600\n14 WAIT\n20 V=0\n"
            "21 E1%=MCODS(55,-1,V,T$,40,0)\n22 V=0\n23 E2%=MCODS(62,-1,V,P%,8,0,51)\n24 V=0\n"
            "25 E3%=MCODS(78,1,V,N$,27)\nM30\n")
    r = run(text, cpl=SERCOS)
    v = r["variables"]
    assert (v["E1%"], v["E2%"], v["E3%"]) == (0, 0, 0)
    assert v["T$"] == "DKC 03.3" and v["P%"] == [None, 20000, 0, 0, None, None, None, None, None]  # 3 axes
    assert v["N$"] == "X       \0Y       \0Z       \0"


@pytest.mark.parametrize("call", ["SDR(Q)", "SD(Q)", "MCA(Q,0)"])
def test_unassigned_group_or_number_is_variable_not_assigned(run, call):
    assert run(f"10 R={call}\nM30\n")["error"]["code"] == "CPL020"


def test_sd13_follows_the_operating_mode_mcops7(run):
    """L2241: SD(13) 0 single block/step, 1 automatic, 2 program block; the running program may switch
    between the automatic sub-modes with MCOPS(7) (L3212-3228): 10 single block, 6 program block, 5 automatic."""
    text = ("1 A%=SD(13)\n2 E1%=MCOPS(7,1,10)\n3 B%=SD(13)\n4 E2%=MCOPS(7,1,6)\n5 C%=SD(13)\n6 E3%=MCOPS(7,1,5)\n"
            "7 D%=SD(13)\n8 E4%=MCOPS(7,1,1)\n9 F%=SD(13)\nM30\n")
    v = run(text)["variables"]
    assert (v["A%"], v["B%"], v["C%"], v["D%"], v["F%"]) == (1, 0, 2, 1, 1)
    assert (v["E1%"], v["E2%"], v["E3%"], v["E4%"]) == (0, 0, 0, 13)  # jog is refused while the program runs
