"""CPL manual examples, NC-integrated functions (CPL manual §4, L1184-3343: WAIT, PPOS, PROBE, FXCR, axis channels, MCODS).

Each test runs the manual's program, repaired only where an OCR slip or the
comment says why, and asserts the result the manual states.
"""

from __future__ import annotations

import pytest


def input_at(time: float, address: str, value: bool) -> dict:
    return {"time": time, "kind": "input", "address": address, "value": value}


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
    is M0, ``N24`` is N240 and ``N250 WAIT`` the CPL line 250 (block N27 of the example). The type, channel and size
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
