"""Manual example programs that no other test ran as program text (audit of digest §9 against the suite).

Each test runs the manual's program, repaired only where the digest (§9, §11) or the comment says why, and
asserts the result the manual states.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from ncvm.api import run as run_program
from ncvm.dialects.cpl.io.graphics import TABLE_CODES
from ncvm.runtime.session import RunOptions


@pytest.fixture
def run(run_text, reference):
    return lambda text, channel=1, **kw: run_text(text, name="p.cpl", machine=reference(channel, **kw))


def input_at(time: float, address: str, value: bool) -> dict:
    return {"time": time, "kind": "input", "address": address, "value": value}


# -- 9.1 language core -----------------------------------------------------------------------------------


C1SUB = "5 XVALUE=P1 : FEED=P2 : COMPTAB=P3 : M3=3\nN10 G1 X[XVALUE]F[ FEED*2+1000]M[M3]\n"


def test_c1_expressions_in_nc_words_of_a_sub_program_l359(run_text, reference):
    """§2.1.1 L359-369, called with P1..P3 = 20, 100, 3: N10 is G1 X20 F1200 M3 (M3 is a variable named like
    the M function). Lines 15/16 read the feed and the spindle sense back (SD(5,1,2), SD(12,1))."""
    m = reference()
    (m.program_path[0] / "C1SUB").write_text(C1SUB + "15 WAIT\n16 #F% = SD(5,1,2) : #SP% = SD(12,1)\nM30\n")
    r = run_text("10 CALL C1SUB [20, 100, 3]\nM30\n", name="p.cpl", machine=m)
    assert r["status"] == "ok", r["error"]
    assert r["variables"] == {"#F%": 1200, "#SP%": 3} and r["position"]["X"] == 20.0


def test_c1_g22_of_the_example_is_not_in_the_nc_kernel_l366(run_text, reference):
    """N20 G22 K[COMPTAB] is a Bosch DIN function the shared NC kernel lacks (docs/decisions.md, CPL):
    the run stops there with NC004 after N10 has moved."""
    m = reference()
    (m.program_path[0] / "C1SUB").write_text(C1SUB + "N20 G22 K[COMPTAB]\nM30\n")
    r = run_text("10 CALL C1SUB [20, 100, 3]\nM30\n", name="p.cpl", machine=m)
    assert r["error"]["code"] == "NC004" and r["error"]["line"] == 3 and r["position"]["X"] == 20.0


GOLDEN = Path(__file__).parents[2] / "programs" / "cpl"


def test_c5_permanent_values_survive_a_new_run_l517(tmp_path):
    """§2.4.3 L517-533 and L639-652 (the golden variables.cpl, with the wmhperm.dat of L623-637): a second
    program finds the permanent values; the local and the global one are gone."""
    options = RunOptions(state_dir=tmp_path / ".ncvm")
    first, _ = run_program(GOLDEN / "variables.cpl", machine=GOLDEN / "machine.toml", options=options)
    assert first["status"] == "ok", first["error"]
    reader = tmp_path / "reader.cpl"
    reader.write_text("10 A% = @36% : B% = @ABCD% : C% = @2 : D = @WZKOR(3,2) : E$ = @PSTR1$ : F$ = @PSTR2$(3)\n"
                      "20 G! = @IJKL! : H? = @MNOP? : I% = @WZNR%(2)\n"
                      "30 LGONE? = NUMBER1% = NUL : GGONE? = #NUMBER2% = NUL\nM30\n", encoding="latin-1")
    r, _ = run_program(reader, machine=GOLDEN / "machine.toml", options=options)
    assert r["status"] == "ok", r["error"]
    v = r["variables"]
    assert (v["A%"], v["B%"], v["C%"], v["E$"], v["F$"], v["I%"]) == (3, 4, 2, "ABC", "DE", 6)
    assert v["D"] == pytest.approx(7.6) and v["G!"] == 5.12345 and v["H?"] is True
    assert v["LGONE?"] is True and v["GGONE?"] is True


def test_c13_for_with_a_variable_step_into_file_p222_l940(run_text, reference):
    """§2.5.5 L940-958 with its file: the printed records need STEP%=2 at the start (the text shows 1, which
    would give 1/1, 2/1, ...; digest §11 B13) and ``SORT`` is SQRT (OCR). NJUST: numbers in 9 places."""
    m = reference()
    r = run_text('10 OPENW(1,"P222",130)\n20 STEP%=2 : START%=1 : END%=3500 : NJUST\n'
                 "30 FOR COUNTER%=START% STEP STEP% TO END%\n40 STEP%=ROUND(STEP%*SQRT(STEP%))\n"
                 '50 PRN#(1,"COUNTER: ",COUNTER%," STEP SIZE: ",STEP%)\n60 NEXT\n70 CLOSE(1)\nM30\n',
                 name="p.cpl", machine=m)
    assert r["status"] == "ok", r["error"]
    pairs = [(1, 3), (4, 5), (9, 11), (20, 36), (56, 216), (272, 3175), (3447, 178902)]
    records = [f"COUNTER: {c:9d} STEP SIZE: {s:9d}" for c, s in pairs]
    assert (m.file_root / "P222").read_text(encoding="latin-1") == "\n".join(records) + "\n\x03\n"


WHILE_SD9 = "5 I=0\nN10 G75 X100 F1000\n30 WHILE SD(9)=0\n40 I=I+1\n50 END\nM30\n"


def test_c14_while_polls_sd9_l984(run_text, reference):
    """§2.5.5 L984: ``WHILE SD(9)=0`` (no DO; I set to 0 first, the fragment leaves it NUL) loops while the
    condition holds (digest §11 A8, the annotation says the opposite). Probe not switched: SD(9)=1, no pass.
    Switched: SD(9) stays 0 in the simulation, so the loop runs until the step limit."""
    r = run_text(WHILE_SD9, name="p.cpl", machine=reference())
    assert r["status"] == "ok" and r["variables"] == {"I": 0.0}
    m = reference(scenario=[{"time": 0.0, "kind": "probe", "X": 40.0}])
    r = run_text(WHILE_SD9, name="p.cpl", machine=m, max_steps=1000)
    assert r["error"]["code"] == "RUN001" and r["variables"]["I"] > 400


def _with_p999(reference, body: str):
    m = reference()
    (m.program_path[0] / "P999").write_text(body, encoding="latin-1")
    return m


@pytest.mark.parametrize("a", [1, 0])
def test_c18_call_inside_if_l1089(run_text, reference, a):
    """§3.3 L1093-1095: CALL in its own block inside IF; P999 runs only when A% = 1."""
    m = _with_p999(reference, "N10 G1 X10 F100\nM30\n")
    r = run_text(f"10 A%={a}\n50 IF A% = 1 THEN\n51 CALL P999\n52 ENDIF\nM30\n", name="p.cpl", machine=m)
    assert r["status"] == "ok", r["error"]
    assert r["position"]["X"] == (10.0 if a == 1 else 0.0)


def test_c18_call_din_of_a_pure_din_program_l1105(run_text, reference):
    """§3.3 L1105-1108: CALL P999 DIN excludes P999 from linking; a DIN-only P999 still runs."""
    m = _with_p999(reference, "N10 G1 X10 F100\nM30\n")
    r = run_text("10 A%=1\n50 IF A% = 1 THEN\n51 CALL P999 DIN\n52 ENDIF\nM30\n", name="p.cpl", machine=m)
    assert r["status"] == "ok", r["error"]
    assert r["position"]["X"] == 10.0 and r["motion"]["feed_moves"] == 1


@pytest.mark.parametrize("main", ["51 CALL P999 DIN\n", "51 CALL P999\n"])
def test_c18_din_excluded_program_with_cpl_is_a_runtime_error_l1101(run_text, reference, main):
    """§3.3 L1101 and L1112-1116: a sub-program holding CPL that is excluded from linking (by ``DIN`` on the
    call or by the ``(DIN)`` remark in its first line) gives an error "at program runtime": only when the
    call is reached."""
    body = "N10 G1 X10 F100\n20 B%=1\nM30\n" if "DIN" in main else "N10 (DIN)\nN20 G1 X10 F100\n30 B%=1\nM30\n"
    m = _with_p999(reference, body)
    prog = "10 A%={}\n50 IF A% = 1 THEN\n" + main + "52 ENDIF\nM30\n"
    r = run_text(prog.format(1), name="p.cpl", machine=m)
    assert r["status"] == "error" and r["error"]["code"] == "CPL030" and r["error"]["line"] == 3
    r = run_text(prog.format(0), name="p.cpl", machine=m)
    assert r["status"] == "ok", r["error"]


PDIM_MAIN = 'N10 (DIN)\nN20 G90\nN50 P SP["TEST"]\nM30\n'


def _with_sp(reference, body: str):
    m = reference()
    (m.program_path[0] / "SP").write_text(body, encoding="latin-1")
    return m


@pytest.mark.parametrize("sub", [
    "10 PDIM P1$(4)\n20 #P1$ = P1$\nM30\n",
    "10 PDIM P1$(4)\n20 GOTO .TAKE\n30 #P1$ = \"NO\"\n40 .TAKE\n50 #P1$ = P1$\nM30\n",  # also in GOTO code
])
def test_c20_pdim_string_from_a_program_selected_without_linking_l1161(run_text, reference, sub):
    """§3.4 L1161-1175: the caller is marked (DIN); with PDIM P1$(4) the sub-program's P1$ is "TEST"."""
    r = run_text(PDIM_MAIN, name="p.cpl", machine=_with_sp(reference, sub))
    assert r["status"] == "ok", r["error"]
    assert r["variables"] == {"#P1$": "TEST"}


def test_c20_without_pdim_the_string_is_an_invalid_variable_l1159(run_text, reference):
    """§3.4 L1149-1159: from a caller selected without linking, a string constant needs PDIM; "missing
    entirely" gives the part program error "invalid variable". A linked caller needs no PDIM."""
    m = _with_sp(reference, "20 #P1$ = P1$\nM30\n")
    r = run_text(PDIM_MAIN, name="p.cpl", machine=m)
    assert r["error"]["code"] == "CPL026" and r["error"]["message"].startswith("invalid variable")
    r = run_text(PDIM_MAIN.replace("N10 (DIN)\n", ""), name="p.cpl", machine=m)
    assert r["status"] == "ok" and r["variables"] == {"#P1$": "TEST"}


# -- 9.2 NC-integrated functions -------------------------------------------------------------------------


def test_n2_wait_duration_with_and_without_result_l1232(run):
    """§4.1 L1234-1235: WAIT(,1000,E%) holds 1000 ms and sets E% to 1; WAIT(,TIME%) holds TIME% ms."""
    r = run("10 WAIT(,1000,E%)\nM30\n")
    assert r["variables"]["E%"] == 1 and r["cycle_time_s"] == pytest.approx(1.0)
    r = run("5 TIME%=250\n10 WAIT(,TIME%)\nM30\n")
    assert r["variables"] == {"TIME%": 250} and r["cycle_time_s"] == pytest.approx(0.25)


def test_n2_wait_for_signals_l1236(run):
    """§4.1 L1236-1237: WAIT(IC(1,1,1)=TRUE) and WAIT(IC(2,0,2)=(E1? OR E2?)) hold until the signal comes
    (the scenario sets it at 200 ms and 300 ms)."""
    r = run("10 WAIT(IC(1,1,1)=TRUE)\nM30\n", scenario=[input_at(0.2, "IC(1,1,1)", True)])
    assert r["status"] == "ok" and r["cycle_time_s"] == pytest.approx(0.2)
    r = run("5 E1?=FALSE : E2?=TRUE\n10 WAIT(IC(2,0,2)=(E1? OR E2?))\nM30\n",
            scenario=[input_at(0.3, "IC(2,0,2)", True)])
    assert r["status"] == "ok" and r["cycle_time_s"] == pytest.approx(0.3)


WAIT_NOT = '10 WAIT(NOT IC(3,2,1),,C%)\n20 IF C%=0 THEN\n30 DSP(10,10,"COND. ALREADY OK")\n40 ENDIF\nM30\n'


def test_n2_wait_not_ic_result_0_or_2_l1238(run):
    """§4.1 L1238: C% is 0 when the signal was already FALSE at the call (the message shows), 2 when it
    became FALSE while waiting (here at 400 ms)."""
    r = run(WAIT_NOT)
    assert r["variables"]["C%"] == 0 and r["output"] == ["COND. ALREADY OK"]
    r = run(WAIT_NOT, scenario=[input_at(0.0, "IC(3,2,1)", True), input_at(0.4, "IC(3,2,1)", False)])
    assert r["variables"]["C%"] == 2 and r["output"] == [] and r["cycle_time_s"] == pytest.approx(0.4)


WAIT_ERG = ('5 E7?=TRUE\n10 WAIT(IC(4,4,1)=E7?,250,ERG%)\n20 IF ERG%=0 THEN\n30 DSP(10,10,"DID NOT WAIT ")\n'
            '40 ENDIF\n50 IF ERG%=2 THEN\n60 DSP(10,10,"WAITED >250ms")\n70 ENDIF\nM30\n')


@pytest.mark.parametrize(("events", "erg", "shown", "held"), [
    ([input_at(0.0, "IC(4,4,1)", True)], 0, ["DID NOT WAIT "], 0.0),  # already fulfilled at the call
    ([], 1, [], 0.25),  # the 250 ms elapsed
    ([input_at(0.1, "IC(4,4,1)", True)], 2, ["WAITED >250ms"], 0.1),  # met while waiting
])
def test_n2_wait_result_0_1_2_l1239(run, events, erg, shown, held):
    """§4.1 L1239: ERG% = 0, 1 or 2, and the program's DSP texts (the manual's second text says
    ">250ms" for ERG% = 2; the program prints it as written)."""
    r = run(WAIT_ERG, scenario=events)
    assert r["variables"]["ERG%"] == erg and r["output"] == shown
    assert r["cycle_time_s"] == pytest.approx(held)


PPOS_CH3 = ("N10 G1 G75 A250 F500\n20 IF SD(9) = 1 THEN\nN30 (MSG, Measuring probe was not deflected!)\n"
            "40 GOTO .ERROR\n50 ELSE\n60 AMEAS = PPOS(1,1)\n70 ENDIF\nM30\n80 .ERROR\n90 FAILED%=1\nM30\n")


def test_n8_ppos_on_channel_3_l1602(run):
    """§4.2.2 L1604-1612 on channel 3 (A axis) of the reference configuration; the ``...`` after line 70 is
    replaced by M30 and the .ERROR label the example jumps to."""
    r = run(PPOS_CH3, channel=3, scenario=[{"time": 0.0, "kind": "probe", "A": 180.0}])
    assert r["status"] == "ok", r["error"]
    assert r["variables"] == {"AMEAS": 180.0} and r["position"]["A"] == 180.0  # the move stops at the switch
    r = run(PPOS_CH3, channel=3)
    assert r["variables"] == {"FAILED%": 1} and r["output"] == ["Measuring probe was not deflected!"]
    assert r["position"]["A"] == 250.0


PROBE_CH2 = ("N60 F500\nN70 G75 Y2=250\n80 IF SD(9)=1 THEN\nN90 (MSG, Measuring probe was not deflected!)\n"
             "100 GOTO .ERROR\n110 ELSE\n120 Y2MEAS=PROBE(2)\n130 ENDIF\nM30\n140 .ERROR\n150 FAILED%=1\nM30\n")


def test_n8_probe_on_channel_2_l1634(run):
    """§4.2.2 L1634-1643 on channel 2. Repairs: the OCR lost the '=' of ``Y2=250`` (Y2 is an extended axis
    name), and the fragment gets ``N60 F500`` in place of the earlier blocks it omits (G75 moves at feed).
    PROBE gives the machine coordinate, so an axis zero shift of Y2 does not change it."""
    probe = [{"time": 0.0, "kind": "probe", "Y2": 100.0}]
    r = run(PROBE_CH2, channel=2, scenario=probe)
    assert r["status"] == "ok", r["error"]
    assert r["variables"] == {"Y2MEAS": 100.0}
    r = run(PROBE_CH2, channel=2, scenario=probe, offsets={"G54": [0.0, 10.0, 0.0]})
    assert r["variables"] == {"Y2MEAS": 100.0} and r["position"]["Y2"] == 90.0
    r = run(PROBE_CH2, channel=2)
    assert r["variables"] == {"FAILED%": 1} and r["output"] == ["Measuring probe was not deflected!"]


FXCR_EXAMPLE = """10 NPV_BASIS$="/usr/user/NPV_TAB_K2.npv"
11 IF FILEACCESS(NPV_BASIS$)=-1 THEN
12 FXCR(2,NPV_BASIS$)
13 FXDEL("NPV_TAB_K2.npv",2)
14 FXINS("NPV_TAB_K2.npv",3,"U",0)
15 ELSE
16 IF FILEACCESS("NPV2_TAB_K2.npv")=-1 THEN
17 FXCR(NPV_BASIS$,"NPV2_TAB_K2.npv")
18 ENDIF
19 ENDIF
20 F1%=FILEACCESS(NPV_BASIS$) : F2%=FILEACCESS("NPV2_TAB_K2.npv")
M30
"""


def test_n11_fxcr_fxdel_fxins_with_fileaccess_l1809(run_text, reference, tmp_path):
    """§4.3 L1809-1827 as printed, with line 20 added to read FILEACCESS back (OCR repairs: ``NPV BASIS$`` and
    ``NPV TAB K2.npv`` are written with '_', line 13 gets its ')'). The program lies in /usr/user, the
    current directory in which the example's bare file names find the tables. The first run creates the
    channel-2 table file and changes its columns (X2 Y2 Z2 -> X2 Z2 U); the second finds it and creates
    NPV2 with its layout; the third changes nothing. The tables are files: FILEACCESS gives 6 (R, W)."""
    (tmp_path / "files/usr/user").mkdir(parents=True)
    name = "files/usr/user/p.cpl"
    runs = [run_text(FXCR_EXAMPLE, name=name, machine=reference()) for _ in range(3)]
    assert [r["status"] for r in runs] == ["ok"] * 3, [r["error"] for r in runs]
    assert [(r["variables"]["F1%"], r["variables"]["F2%"]) for r in runs] == [(6, -1), (6, 6), (6, 6)]
    r = run_text('1 N%=3\n2 A=FXC("U",54,"NPV2_TAB_K2.npv")\n3 B=FXC(2,54,"NPV2_TAB_K2.npv")\n'
                 '4 C=FXC("Y2",54,"NPV2_TAB_K2.npv")\nM30\n', name=name, machine=reference())
    assert r["variables"] == {"N%": 3, "A": 0.0, "B": 0.0}  # columns U and 2 (Z2) exist
    assert r["error"]["code"] == "1938" and r["error"]["line"] == 4  # Y2 was deleted
    heading = (tmp_path / "files/usr/user/NPV2_TAB_K2.npv").read_text(encoding="latin-1").split("\n")[1]
    assert heading.split() == ["G", "X2", "Z2", "U:R"]


AXIS_CHANNEL = """10 REM Program queries number of axes in the system and the
15 REM axis numbers of the channel axes. Based on this information
20 REM the channel axes are traversed first to position 0 and then
40 REM to position <channel number>
50 CHAN=SD(8): REM Own channel number
60 IDCHAX=43: REM Ncs_MCoEvGetChanAxis_Id
70 IDMAXAX=45: REM Ncs MCoEvGetMaxAxisNumber Id
80 DIM BUF(16): REM Buffer axis-channel assignment
90 SIZE=16
100 ANZ=0: REM Maximum index of the physical axes
120 REM ChanAxis
130 VERSION=0
140 A=MCODS (IDCHAX, CHAN, VERSION, BUF, SIZE)
150 VERSION=0
160 A=MCODS (IDMAXAX, CHAN, VERSION, ANZ, 1)
170 FOR I%=1 TO ANZ
180 IF BUF(I%) = CHAN THEN
N190 F1000 [AXP(I%,0,0)]: REM Traverse channel axes to 0
200 ENDIF
210 NEXT
220 FOR I%=1 TO ANZ
230 IF BUF(I%) = CHAN THEN
N240 M0
250 WAIT
N260 F1000 [AXP(I%,CHAN,0)]:REM Traverse channel axes to CHAN
270 ENDIF
280 NEXT
N290 M30
"""


@pytest.mark.parametrize(("channel", "axes"), [(1, ("X", "Y", "Z")), (2, ("X2", "Y2", "Z2")), (3, ("A",))])
def test_n27_axis_channel_assignment_l3340(run, channel, axes):
    """§4.14.3 example 5 (L3342), its run-together OCR text split into lines; ``BUF(1%)`` is BUF(I%), ``MO``
    is M0, ``N24`` is N240 and ``N250 WAIT`` the CPL line 250 (digest §9.2 N27). The type, channel and size
    are REAL variables: MCODS takes their whole values. The channel's axes end at the channel number."""
    r = run(AXIS_CHANNEL, channel=channel)
    assert r["status"] == "ok", r["error"]
    v = r["variables"]
    assert v["CHAN"] == channel and v["ANZ"] == 8.0 and v["A"] == 0.0
    assert v["BUF"][1:9] == [1.0, 1.0, 1.0, 2.0, 2.0, 2.0, -1.0, 3.0]  # U_CH1 (7) is asynchronous
    assert r["position"] == {a: float(channel) for a in axes}
    assert r["motion"]["rapid_moves"] == 2 * len(axes)


def test_mcods_integer_parameters_refuse_a_fraction(run):
    r = run("10 DIM B%(2)\n20 V=0\n30 T=32.5\n40 E%=MCODS(T,1,V,B%,2)\nM30\n")
    assert r["error"]["code"] == "CPL032" and r["error"]["line"] == 4


# -- 9.3 strings ------------------------------------------------------------------------------------------


def test_s2_mid_write_right_after_the_last_character_l3419(run):
    """§5.3 L3419-3421: writing components 4-6 of "ABC" is allowed (the gap case is bad/mid_gap.cpl)."""
    assert run('1 DIM A$ (10)\n2 A$= "ABC"\n3 MID$ (A$,4,3) ="DEF"\nM30\n')["variables"] == {"A$": "ABCDEF"}


def test_s6_str_with_template_and_default_l3530(run):
    """§5.6 L3530-3539: A$ = "number = 12.333", B$ = "   2.500" (default format, 8 characters)."""
    r = run('10 DIM A$(50)\n20 DIM B$(21)\n30 A$ = STR$("number = ##.###",(37/3))\n40 B$ = STR$(2.5)\nM30\n')
    assert r["variables"] == {"A$": "number = 12.333", "B$": "   2.500"}


def test_s7_val_with_a_decimal_point_into_an_integer_l3549(run):
    """§5.6 L3549 and L3557: line 1 of the VAL example is INVALID ASSIGNMENT (lines 2-7 are val.cpl)."""
    r = run('1 I% = VAL("1.23DE")\n2 K% = VAL("123DE")\nM30\n')
    assert r["error"]["code"] == "CPL021" and r["error"]["line"] == 1
    assert r["error"]["message"].startswith("INVALID ASSIGNMENT")


STRING_VARIABLE = '1 A$="ABCDEFGHIJKLMN"\n2 B$=MID$(A$,2,1)\n3 C$=MID$(A$,4,4)\n'


def test_s9_string_variable_without_dim_l3599(run):
    """§5.8 L3601-3608: a STRING variable takes a string, CHR$ and MID$ parts of another."""
    r = run('1 A$="ABCDE"\n2 B$=CHR$(10)\n3 N%=ASC(B$)\nM30\n')
    assert r["variables"] == {"A$": "ABCDE", "B$": "\n", "N%": 10}
    r = run(STRING_VARIABLE + "M30\n")
    assert r["variables"] == {"A$": "ABCDEFGHIJKLMN", "B$": "B", "C$": "DEFG"}


@pytest.mark.parametrize("line4", ['4 MID$(A$,1,4)="ABCD"', "4 A$=MID$(A$,1,3) + MID$(A$,4,1)", "4 A$=B$ + A$"])
def test_s9_forbidden_forms_on_a_string_variable_l3610(run, line4):
    """§5.8 L3610-3614: each of the three lines 4 is a fault (the variable is not DIMensioned)."""
    r = run(STRING_VARIABLE + line4 + "\nM30\n")
    assert r["error"]["code"] == "CPL025" and r["error"]["line"] == 4


@pytest.mark.parametrize(("text", "line"), [
    ('1 DIM XYZ$(15)\n2 B$="ABCDE"\n4 MID$(XYZ$,6,5)=B$\nM30\n', 3),  # L3646-3650: 1st-5th not assigned
    ('1 DIM XYZ$(100)\n3 MID$(XYZ$,1,6)="ABCDEF"\n5 MID$(XYZ$,9,5)="TESTE"\nM30\n', 3),  # L3688-3694: 7-8
])
def test_s10_character_area_not_used_l3646(run, text, line):
    """§5.8 "CHARACTER AREA NOT USED" (the manual's other wording of CHARACTER FIELD NOT ASSIGNED)."""
    r = run(text)
    assert r["error"]["code"] == "CPL024" and r["error"]["line"] == line
    assert r["error"]["message"].startswith("CHARACTER FIELD NOT ASSIGNED")


def test_s11_mid_write_into_a_16_character_field_l3728(run):
    """§5.8.1 L3728-3745: the figures with the field contents are lost; by the MID$ write rules line 5 gives
    "DAS ", line 6 writes 6 characters ("DAS IST EI"), line 7 twelve, filling all 16 ("the character field
    was cut off" refers to line 6). ``XYZS`` and ``EI''`` are OCR damage."""
    r = run('1 DIM XYZ$(16)\n2 A$="DAS "\n3 B$="IST EIN TEST"\n4 C$="EIN EI"\n5 MID$(XYZ$,1,4)=A$ : R5$=XYZ$\n'
            '6 MID$(XYZ$,5,6)=B$ : R6$=XYZ$\n7 MID$(XYZ$,5,12)=B$ : L%=LEN(XYZ$)\nM30\n')
    v = r["variables"]
    assert (v["R5$"], v["R6$"], v["XYZ$"], v["L%"]) == ("DAS ", "DAS IST EI", "DAS IST EIN TEST", 16)


# -- 9.5 dialog --------------------------------------------------------------------------------------------

def run_with_keys(tmp_path: Path, text: str, keys: str, subs: dict[str, str] | None = None):
    for name, body in (subs or {}).items():
        (tmp_path / name).write_text(body, encoding="latin-1")
    prog = tmp_path / "prog.cpl"
    prog.write_text(text, encoding="latin-1")
    (tmp_path / "prog.keys").write_text(keys)
    return run_program(prog, options=RunOptions(state_dir=tmp_path / ".ncvm", keys=tmp_path / "prog.keys"))


def test_d7_col_variants_l4942(tmp_path):
    """§8 COL examples L4942-4949 with DSP lines between them: selecting table 2 (7) or 3 (10) erases the
    screen; then softkey text 1 on 4, lines and circles 4, text 6 on 5."""
    text = ('5 DSP(1,1,"BEFORE")\n10 COL(,,,7)\n25 DSP(2,1,"AFTER7")\n30 COL(,,,10)\n40 DSP(3,1,"AFTER10")\n'
            '50 COL(,,,,1,4)\n70 COL(4)\n90 COL(,6,5)\n95 DSP(4,1,"COLOURED")\nM30\n')
    r, s = run_with_keys(tmp_path, text, "")
    assert r["status"] == "ok", r["error"]
    sc = s.screen
    assert sc.grid_lines()[:4] == ["", "", "AFTER10", "COLOURED"]
    assert sc.table == TABLE_CODES[10] != TABLE_CODES[7]
    assert (sc.softkey_color, sc.softkey_bg, sc.line_color) == (1, 4, 4)
    assert tuple(sc.cells[3, 0][:2]) == (6, 5) and tuple(sc.cells[2, 0][:2]) != (6, 5)


UNTPR = """1 Z%=0 : COL(0,7,0)
2 DSP(41,4,P1$) : DSP(41,13,P2$) : DSP(41,22,P3$)
3 DSP(41,31,P4$) : DSP(41,40,P5$) : DSP(41,49,P6$) : DSP(41,58,P7$) : DSP(41,67,P8$)
4 REPEAT
5 REPEAT
6 K%=INKEY
7 UNTIL ((K%=141) OR (K%=142) OR (K%=143) OR (K%=144) OR (K%=145) OR (K%=146) OR (K%=147) OR (K%=148) OR (K%=139))
8 JZ%=Z%-140 : JK%=K%-140
9 IF ((JZ%>0) AND (JZ%<9)) THEN COL(0,7,0)
10 FOR I%=0 TO 2
11 DSP(41+I%,(JZ%-1)*8+JZ%+1,"        ")
12 NEXT I%
13 IF Z%=141 THEN DSP(41,4,P1$) ENDIF
14 IF Z%=142 THEN DSP(41,13,P2$) ENDIF
15 IF Z%=143 THEN DSP(41,22,P3$) ENDIF
16 IF Z%=144 THEN DSP(41,31,P4$) ENDIF
17 IF Z%=145 THEN DSP(41,40,P5$) ENDIF
18 IF Z%=146 THEN DSP(41,49,P6$) ENDIF
19 IF Z%=147 THEN DSP(41,58,P7$) ENDIF
20 IF Z%=148 THEN DSP(41,67,P8$) ENDIF
21 ENDIF
22 IF ((JK%>0) AND (JK%<9)) THEN COL(0,0,7)
23 FOR I%=0 TO 2
24 DSP(41+I%,(JK%-1)*8+JK%+1,"        ")
25 NEXT I%
26 IF K%=141 THEN DSP(41,4,P1$) ENDIF
27 IF K%=142 THEN DSP(41,13,P2$) ENDIF
28 IF K%=143 THEN DSP(41,22,P3$) ENDIF
29 IF K%=144 THEN DSP(41,31,P4$) ENDIF
30 IF K%=145 THEN DSP(41,40,P5$) ENDIF
31 IF K%=146 THEN DSP(41,49,P6$) ENDIF
32 IF K%=147 THEN DSP(41,58,P7$) ENDIF
33 IF K%=148 THEN DSP(41,67,P8$) ENDIF
34 ENDIF
35 Z%=K%
36 UNTIL K%=139 : CLG
M30
"""


def test_d5_softkey_emulation_untpr_l4660(tmp_path):
    """§7.1 INKEY, L4660-4750: the sub-program UNTPR draws eight softkey texts on line 41, highlights the box of
    a pressed softkey (141..148) and restores the previous one, until LEVEL RETURN (139).

    Rebuilt from the OCR: the line numbers are dropped, each IF/ENDIF and the long UNTIL are on one line,
    ``FOR 1%`` / ``LO`` / ``PI$`` / ``F43`` / ``ENDI`` are I%, TO, P1$, the P6$ line and ENDIF, the duplicated
    ``IF Z%=144`` lines are 143/144, the second blanking loop uses JK% (the box of the new key), the main
    program sets E$ (not B$ twice) and passes all eight texts."""
    main = ('1 A$ = "SOFT1" : B$ = "SOFT2" : C$ = "SOFT3"\n'
            '2 D$ = "SOFT4" : E$ = "SOFT5" : F$ = "SOFT6" : G$ = "SOFT7" : H$ = "SOFT8"\n'
            '3 CALL UNTPR [ A$, B$, C$, D$, E$, F$, G$, H$ ]\nM30\n')
    r, s = run_with_keys(tmp_path, main, "SK3\nSK5\nLEVEL RETURN\n", {"UNTPR": UNTPR})
    assert r["status"] == "ok", r["error"]
    blank = ["        "] * 3
    assert r["output"] == (["SOFT1", "SOFT2", "SOFT3", "SOFT4", "SOFT5", "SOFT6", "SOFT7", "SOFT8"]
                           + blank + ["SOFT3"]  # SK3: box 3 highlighted
                           + blank + ["SOFT3"] + blank + ["SOFT5"]  # SK5: box 3 restored, box 5 highlighted
                           + blank + ["SOFT5"])  # LEVEL RETURN: box 5 restored, then CLG
    assert s.screen.grid_lines()[40] == ""  # CLG erased the screen


@pytest.mark.parametrize(("keys", "m"), [("IDLE 20\nKEY 66\n", 22.0), ("", 150.0)])
def test_d5_circles_until_key_b_l4764(tmp_path, keys, m):
    """§7.1 L4764-4768: circles of growing radius while no 'B' (66) is pressed and M < 150; each pass
    polls INKEY once (20 polls find no key, the 21st finds B)."""
    text = "10 M=2\n20 WHILE ((INKEY<>66) AND (M<150)) DO\n30 CIR(250,160,M) : M=M+1\n40 END\n50 CLG\nM30\n"
    r, _ = run_with_keys(tmp_path, text, keys)
    assert r["status"] == "ok", r["error"]
    assert r["variables"]["M"] == m
