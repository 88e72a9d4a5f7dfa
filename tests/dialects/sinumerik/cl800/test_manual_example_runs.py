"""The manual's example programs of chapters 4, 5, 7 and 8 (ncvm's reading; the CL 800 manual is silent) run, and their results are
the ones the manual states (or are computed by hand here).

The object programs are subroutines: their LOCAL parameters are popped back at ``M17``. The debug hook
sees the R parameters before every block, so ``_states`` gives the values a program had before each of
its blocks, the last one being the pop + ``M17`` block.
"""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from ncvm.api import check, compile_program, run
from ncvm.dialects.sinumerik.cl800.codegen import marked
from ncvm.runtime.session import RunOptions

HERE = Path(__file__).parent
MANUAL = HERE / "manual"
GOLDEN = HERE / "golden"


def _states(source: Path, tmp_path: Path, machine: str | None = None, main: str | None = None):
    """Run ``source`` (or ``main`` calling its object program); the R parameters before each block."""
    tmp_path.mkdir(parents=True, exist_ok=True)
    seen: list[dict] = []
    opts = RunOptions(state_dir=tmp_path / ".s", hook=lambda f, line, v: seen.append(dict(v)))
    mpath = None
    if machine is not None:
        mpath = tmp_path / "machine.toml"
        mpath.write_text(machine)
    if main is None:
        result, _ = run(source, machine=mpath, options=opts)
    else:
        compile_program(source, out=tmp_path / f"L{_number(source)}.spf")
        (tmp_path / "main.mpf").write_text(main)
        result, _ = run(tmp_path / "main.mpf", dialect="sin800", machine=mpath, options=opts)
    assert result["status"] == "ok", result["error"]
    return result, seen


def _number(source: Path) -> int:
    for line in source.read_text(encoding="latin-1").splitlines():
        if line.strip().startswith("PROGRAM"):
            return int(line.split()[1].rstrip(";"))
    raise AssertionError(source)


def _ever(states: list[dict], **expected) -> None:
    """Some block of the run began with every one of these values."""
    assert any(all(s.get(k, 0.0) == pytest.approx(v, rel=1e-7, abs=1e-9) for k, v in expected.items())
               for s in states), f"{expected} never seen"


def test_4_1_structure_sums_the_transfer_parameters(tmp_path):
    """L800-828: value = term_1 + term_2 + term_3; the caller presets R0, R25, R49 (5 + 7 + 11 = 23)."""
    _result, states = _states(MANUAL / "m4_1_structure.cl8", tmp_path, main="%MPF1\nR0=5 R25=7 R49=11\nL1\nM30\n")
    assert states[-2]["R50"] == 23.0  # before the pop + M17 block of L1


def test_5_2_1_par_sums_named_transfer_parameters(tmp_path):
    src = MANUAL / "m5_2_1_par.cl8"
    text = src.read_text()
    assert "R0" in text and "R25" in text and "R49" in text
    _result, states = _states(src, tmp_path, main="%MPF1\nR0=1.5 R25=2 R49=-4\nL1\nM30\n")
    _ever(states, R50=-0.5)


def test_5_3_4_clear_xchg_and_mib(tmp_path):
    """L2224-2301: CLEAR(R60) gives 0; XCHG(R30, R20) with R30 = 10, R20 = 30 gives R30 = 30, R20 = 10;
    CLEAR MIB(100, 110) then R50 = MIB(101) is 0; MIB(102) = 5 stays in the input buffer memory."""
    machine = '[[axis]]\nname = "X"\n[sin800]\nmib = { "101" = 7, "102" = 1 }\n'
    result, states = _states(MANUAL / "m5_3_4_transfer.cl8", tmp_path, machine=machine)
    assert result["variables"]["R30"] == 30.0 and result["variables"]["R20"] == 10.0
    assert result["variables"]["R10"] == 100.0
    assert all(s.get("R60", 0.0) in (0.0, 100.0) for s in states) and states[-1].get("R60", 0.0) == 0.0
    assert states[-1].get("R50", 0.0) == 0.0  # MIB 101 was 7 before CLEAR MIB
    # MIB(102) = 5 is read back by a second program on the same NC (the MIB is kept)
    (tmp_path / "p2.mpf").write_text("%MPF2\n@211 R1 K102 @211 R2 K101\nM30\n")
    r2, _ = run(tmp_path / "p2.mpf", machine=tmp_path / "machine.toml", options=RunOptions(state_dir=tmp_path / ".s"))
    assert r2["variables"]["R1"] == 5.0 and r2["variables"]["R2"] == 0.0


def test_5_3_7_1_arithmetic_program_50(tmp_path):
    """L3593-3620: 17 + 4 = 21, 21 - 4 = 17, 21 * 17 = 357, 357 / 3 = 119 (PAR registers survive)."""
    result, _ = _states(MANUAL / "m5_3_7_1_arithmetic.cl8", tmp_path)
    v = result["variables"]
    assert (v["R10"], v["R11"], v["R12"], v["R13"]) == (21.0, 17.0, 357.0, 119.0)


def test_5_3_7_2_functions_program_55(tmp_path):
    """L3659-3912: ABS(-253) = 253, ABS(-3.8435) = 3.8435, SQRT(25) = 5, SQRT(5), SQRTS(5, 10) = 11.1803,
    INC then DEC of 1 = 1, TRUNC(1.9) = 1, TRUNC(-2.3) = -2, then the trigonometric and log values."""
    _r, states = _states(MANUAL / "m5_3_7_2_functions.cl8", tmp_path)
    _ever(states, R50=253.0, R51=3.8435, R60=5.0, R61=math.sqrt(5.0))
    _ever(states, R62=math.hypot(5.0, 10.0), R63=-2.0, R70=1.0)
    assert states[-2]["R62"] == pytest.approx(11.1803, abs=1e-4)
    last = states[-1]
    assert last["R60"] == pytest.approx(45.0, rel=1e-6)  # ARC SIN(0.70710678)
    assert last["R61"] == pytest.approx(159.444, abs=1e-3)  # ANGLE(30, -80)
    assert last["R62"] == pytest.approx(2.302585, rel=1e-6) and last["R63"] == pytest.approx(12.18249, rel=1e-6)


def test_5_3_7_6_pattern_operations_program_59(tmp_path):
    _r, states = _states(MANUAL / "m5_3_7_6_logic_patterns.cl8", tmp_path)
    _ever(states, R52=10111111, R53=10011111, R54=100000, R55=11011111)
    # R56 = NOT R50 is computed in the pop + M17 block, after the hook's last look: the same @654 on the
    # same pattern is asserted in tests/dialects/sinumerik/test_sin800.py (B11010011)


def test_5_3_7_6_boolean_operations_program_60(tmp_path):
    """L3976-3995 with 1 XORB 0 = 1 (the manual prints 0: CL 800 manual L3992)."""
    _r, states = _states(MANUAL / "m5_3_7_6_logic_boolean.cl8", tmp_path)
    _ever(states, R52=1, R53=1, R54=0, R55=1, R56=0)


def test_5_3_7_6_chains_program_82(tmp_path):
    """L4003-4022 with R10 = B00000011, R15 = B00000101, R20 = B00000110, R25 = 1, by hand:
    R30 = R10 OR R20 AND R15 = 011 OR (110 AND 101 = 100) = 111;  R10 = NOTB R30 = 0;
    R30 = NOT (0 OR 11101101) AND 00011111 = 00010010 AND 00011111 = 10010;
    R30 = NOTB (R10 NANDB R25) = NOTB (0 NANDB 1 = 1) = 0."""
    _r, states = _states(MANUAL / "m5_3_7_6_logic_chains.cl8", tmp_path / "a",
                         main="%MPF1\nR10=11 R15=101 R20=110 R25=1\nL82\nM30\n")
    assert states[-1].get("R10", 0.0) == 0.0 and states[-1].get("R30", 0.0) == 0.0  # the caller's M30 block
    # the first and third statements, into registers of their own (the program overwrites R30)
    single = tmp_path / "one.cl8"
    single.write_text("PROGRAM 83;\nCHANNEL NC 0;\nPAR PATTERN: R10, R15, R20, R30, R31;\nBEGIN\n"
                      "R30 = R 10 OR R20 AND R15;\nR31 = NOT (R40 OR B11101101) AND B00011111;\nEND.\n"
                      .replace("R40", "R10"))
    result, _ = _states(single, tmp_path, main="%MPF2\nR10=0 R15=101 R20=110\nL83\nM30\n")
    assert result["variables"]["R30"] == 100.0  # AND binds tighter than OR: 0 OR (110 AND 101 = 100)
    assert result["variables"]["R31"] == 10010.0


def test_5_3_7_7_clear_bit_and_set_bit(tmp_path):
    _r, states = _states(MANUAL / "m5_3_7_7_bits.cl8", tmp_path)
    _ever(states, R60=100111, R70=100)


def test_5_3_8_2_prep_cyc_metric_diameter(tmp_path):
    """L4268-4284: under G71 with diameter programming R52 = 1, R53 = 2."""
    machine = '[[axis]]\nname = "X"\n[[axis]]\nname = "Z"\n[sin800]\nnc_md = { "diameter_axis1" = 1 }\n'
    _r, states = _states(MANUAL / "m5_3_8_2_prep_cyc.cl8", tmp_path, machine=machine)
    assert states[-1]["R52"] == 1.0 and states[-1]["R53"] == 2.0


def test_5_3_1_5_for_downto_ten_passes(tmp_path):
    """L1862-1879: FOR R50 := 10 DOWNTO 1 makes 10 passes. length_Z and depth_X are LOCALs (0 after the
    push), so each pass moves only X by +100 (G91 G00): X = 10 * 100 = 1000, then Z0 in G90."""
    result, states = _states(MANUAL / "m5_3_1_5_for_downto.cl8", tmp_path)
    assert result["position"]["X"] == pytest.approx(1000.0) and result["position"]["Z"] == 0.0


def test_5_3_8_3_meas_m_difference(tmp_path):
    """L4380-4395: X/Z commands 100/200 (axes 1 and 2); the probe switches at (40, 80) on the path:
    X_ACT = 40, Z_ACT = 80, DIFF_X = 100 - 40 = 60, DIFF_Z = 200 - 80 = 120."""
    machine = ('[[axis]]\nname = "X"\n[[axis]]\nname = "Z"\n[sin800]\ncontrol = "880"\n'
               '[[scenario]]\ntime = 0.0\nkind = "probe"\ninput = 1\nposition = { X = 40.0, Z = 80.0 }\n')
    _r, states = _states(MANUAL / "m5_3_8_3_meas_m.cl8", tmp_path, machine=machine)
    last = states[-1]  # DIFF_X/DIFF_Z are computed in the pop + M17 block itself
    assert (last["R93"], last["R94"], last["R70"], last["R71"]) == (40.0, 80.0, 100.0, 200.0)
    assert last["R70"] - last["R93"] == 60.0 and last["R71"] - last["R94"] == 120.0
    assert _r["position"] == {"X": 40.0, "Z": 80.0}  # the block stopped where the probe switched


def test_5_3_2_1_if_then_else_writes_md_2240(tmp_path):
    """Worked example (b), PROGRAM 505: MD 2240 = 1500 when the D number is >= 20, else 1000."""
    machine = ('[[axis]]\nname = "X"\n[[axis]]\nname = "Y"\n[[axis]]\nname = "Z"\n[sin800]\n'
               'tool_offsets = [ { d = 25, p = [1, 20, 10.0] }, { d = 3, p = [2, 20, 10.0] } ]\n')
    for d, expected in ((25, 1500.0), (3, 1000.0)):
        folder = tmp_path / f"d{d}"
        folder.mkdir()
        _states(GOLDEN / "b_if_then_else.cl8", folder, machine=machine, main=f"%MPF1\nD{d}\nL505\n@300 R1 K2240\nM30\n")
        r, _ = run(folder / "main.mpf", dialect="sin800", machine=folder / "machine.toml",
                   options=RunOptions(state_dir=folder / ".s"))
        assert r["variables"]["R1"] == expected


def test_golden_a_pointers_state_before_m17(tmp_path):
    """Worked example (a): R70 = 20 and R71 = R80 = 0 just before the final block."""
    _r, states = _states(GOLDEN / "a_pointers.cl8", tmp_path)
    assert states[-1]["R70"] == 20.0 and states[-1].get("R71", 0.0) == 0.0 and states[-1]["R50"] == 70.0


def test_golden_e_repeat_sets_bit_2(tmp_path):
    """Worked example (e): B00011001 with bit 2 set is B00011101; one pass."""
    result, states = _states(GOLDEN / "e_repeat_bit.cl8", tmp_path)
    assert states[-1]["R70"] == 11101.0 and result["steps"] <= 4


def test_5_3_3_1_goto_skips_to_the_label(tmp_path):
    """L2192-2207 (label spelled the same at declaration and use): the statements between GOTO
    and the label are skipped; with R1 >= 0 the IF does not jump and they run."""
    src = tmp_path / "goto.cl8"
    src.write_text("PROGRAM 2;\nCHANNEL NC 0;\nPAR INTEGER: R1, R2, R3;\nLABEL: Dest;\nBEGIN\n"
                   "  IF R1 < 0 THEN GOTO Dest; ENDIF;\n  R2 = 7;\n  Dest: R3 = 9;\nEND.\n")
    for r1, r2 in ((-1, 0.0), (1, 7.0)):
        result, _ = _states(src, tmp_path / f"r{r1}", main=f"%MPF1\nR1={r1}\nL2\nM30\n")
        assert result["variables"].get("R2", 0.0) == r2 and result["variables"]["R3"] == 9.0


def test_5_1_2_header_with_ess_and_id(tmp_path):
    """L1108-1114: PROGRAM 1; CHANNEL NC 1; ESS; ID (...): the statement part starts with @00f."""
    src = tmp_path / "ess.cl8"
    src.write_text("PROGRAM 1;\nCHANNEL NC 1;\nESS;\nID (0-EXAMPLE-22.07.85-KUB-SIEM:MA:850:02);\n"
                   "BEGIN\n  (: G4 X1 :); LF;\nEND.\n")
    text = compile_program(src, out=tmp_path / "L1.spf").read_text().splitlines()
    assert text[0] == "%SPF1" and text[1].startswith("@00f")
    result, _ = run(src, options=RunOptions(state_dir=tmp_path / ".s"))
    assert result["status"] == "ok" and result["cycle_time_s"] == pytest.approx(1.0)


def test_5_2_2_lists_30_and_35(tmp_path):
    """L1321-1345: a central list (EXTERNAL 30, file VARICEN) and a channel-independent global list
    (EXTERNAL 35, CHANNEL NC 0, file VARIKUP); the "..." of the ID and the ":" lines filled in."""
    (tmp_path / "VARICEN").write_text("EXTERNAL 30;\nID (0-VARICEN-28.03.85-KUB-SIEMENS);\nPW (SECRET5);\n"
                                      "(* declaration of central variables *)\nCENTRAL REAL: R900:=c_one;\n"
                                      "ENDEXTERN\n")
    (tmp_path / "VARIKUP").write_text("EXTERNAL 35;\nCHANNEL NC 0;\nID (0-VARIKUP-03.04.85-KUB-SIEMENS);\n"
                                      "PW (PARAME1);\n(* declaration of channel-independent global variables *)\n"
                                      "GLOBAL REAL: R150:=g_one;\nENDEXTERN\n")
    prog = tmp_path / "use.cl8"
    prog.write_text('PROGRAM 9;\nCHANNEL NC 1;\nCENTRAL: "VARICEN";\nGLOBAL: "VARIKUP";\nBEGIN\n'
                    "  g_one = c_one * 2;\nEND.\n")
    for p in (tmp_path / "VARICEN", tmp_path / "VARIKUP", prog):
        assert [d for d in check(p) if d.severity == "error"] == []
    obj = compile_program(prog, out=tmp_path / "L9.spf").read_text()
    assert "R150=R900*2" in obj


def test_5_3_8_2_int_sec_program_30(tmp_path):
    """L4212-4253: contour L20 (N5 X400 Y50 B100, N10 X300 Y300, N15 X100 Y400) from (X750, Y50), path
    along Y250 to X0: inters_X = 320, inters_Y = 250 (on the element (400, 50) -> (300, 300):
    X = 400 - 100 * (250 - 50) / (300 - 50) = 320)."""
    (tmp_path / "L20.spf").write_text("L20\nN5 X400 Y50 B100\nN10 X300 Y300\nN15 X100 Y400 M17\n")
    src = tmp_path / "int_sec.cl8"  # beside its contour sub-program
    src.write_text((MANUAL / "m5_3_8_2_int_sec.cl8").read_text())
    result, states = _states(src, tmp_path)
    last = states[-1]
    assert (last["R70"], last["R71"], last["R72"]) == (1.0, 250.0, pytest.approx(320.0))
    assert result["position"]["X"] == 750.0 and result["position"]["Y"] == 250.0  # INT SEC does not move


def test_5_3_8_1_pos_msys_ignores_the_zero_offset(tmp_path):
    """L4090-4103: the tool change point X1000 Z500 refers to machine zero, whatever G54 is active."""
    machine = '[[axis]]\nname = "X"\n[[axis]]\nname = "Z"\n[offsets]\nG54 = [10.0, -20.0]\n[sin800]\n'
    result, _ = _states(MANUAL / "m5_3_8_1_pos_msys.cl8", tmp_path, machine=machine,
                        main="%MPF1\nG54 G0 X0 Z0\nL508\n@714 @361 R1 K1 @361 R2 K2\nM30\n")
    assert result["variables"]["R1"] == 1000.0 and result["variables"]["R2"] == 500.0
    assert result["position"] == {"X": 990.0, "Z": 520.0}  # workpiece coordinates under G54


def test_8_editor_screen_tos_clearing_loop(tmp_path):
    """The editor screen of ch.8 (L5599-5620) shows a loop that clears P0..P15 of one tool offset:
    WHILE R86 < R87 DO TOS(TO_RANGE, DELETE_D, R86) = 0; R86 = R86 + R98. Run with R98 = 1 on D 5."""
    src = tmp_path / "tos.cl8"
    src.write_text("PROGRAM 8;\nCHANNEL NC 0;\nPAR INTEGER: R10:=TO_RANGE, R11:=DELETE_D;\n"
                   "PAR INTEGER: R20:=P_SUM;\nLOCAL INTEGER: R86, R87, R98;\nBEGIN\n"
                   "  R86=0;\n  R87=16;\n  R98=1;\n  WHILE R86<R87 DO\n    BEGIN\n"
                   "      TOS(TO_RANGE, DELETE_D, R86)=0;\n      R86=R86+R98;\n    END;\n"
                   "  P_SUM = TOS(TO_RANGE, DELETE_D, 0) + TOS(TO_RANGE, DELETE_D, 3)\n"
                   "          + TOS(TO_RANGE, 4, 3);\n"
                   "END.\n")
    machine = ('[[axis]]\nname = "X"\n[sin800]\ntool_offsets = [ { d = 5, p = [7, 20, 40.0, 2.5, 0, 1.5, 0, 0, 0,'
               ' 0, 0, 0, 0, 0, 0, 9] }, { d = 4, p = [8, 20, 30.0, 4.0] } ]\n')
    result, _ = _states(src, tmp_path, machine=machine, main="%MPF1\nR10=0 R11=5\nL8\n@320 R1 K0 K5 K15\nM30\n")
    assert result["variables"]["R20"] == 4.0  # D5 P0 and P3 cleared; D4 P3 = 4 untouched
    assert result["variables"].get("R1", 0.0) == 0.0  # P15 of D5 (was 9) cleared too


def test_5_3_9_io_statements(tmp_path):
    """L4438-4590: WRT PIC (1, 20); RECALL PIC; PORT (1); OUTP PARA (1, 100, 120); OUTP ETX; PORT (2);
    OUTP ZOA (0); OUTP DATA (2, 1, 10); CHAN = 2; PORT (1); INP (0) (the manual's examples, in one frame)."""
    src = tmp_path / "io.cl8"
    src.write_text("PROGRAM 9;\nCHANNEL NC 1;\nBEGIN\n  WRT PIC (1, 20);\n  RECALL PIC;\n  PORT (1);\n"
                   "  OUTP PARA (1, 100, 102);\n  OUTP ETX;\n  PORT (2); OUTP ZOA (0);\n"
                   "  OUTP DATA (2, 1, 10);\n  CHAN = 2;\n  PORT (1); INP (0);\nEND.\n")
    obj = compile_program(src, out=tmp_path / "L9.spf").read_text()
    assert obj == marked("%SPF9\n@a15 K1 K20 @a1b @a20 K1 @a27 K1 K100 K102 @a29 @a20 K2 @a25 K0 @a26 K2 K1 K10 "
                          "@a40 K2 @a20 K1 @a28 K0 M17\n")
    (tmp_path / "L5.spf").write_text("%SPF5\nM17\n")
    machine = ('[[axis]]\nname = "X"\n[[axis]]\nname = "Y"\n[offsets]\nG54 = [1.5, 0.0]\n[sin800]\n'
               'r = { R101 = 7 }\nv24_input = "R102=3\\n"\n')
    result, _ = _states(src, tmp_path, machine=machine)
    assert result["output"] == ["[panel] standard menu 20", "[panel] the display shown before the first WRT PIC",
                                "[panel] channel 2"]
    assert result["variables"]["V24"] == ["PORT 1", "R100=0", "R101=7", "R102=0", "\x03", "PORT 2",
                                          "G54 X1.5 Y0", "G55 X0 Y0", "G56 X0 Y0", "G57 X0 Y0",
                                          "%SPF5", "M17", *obj.splitlines(), "PORT 1"]  # L5 and L9 itself
    assert result["variables"]["R102"] == 3.0  # read in by INP (0)


def _inputs(*events: tuple[float, int, int, int]) -> str:
    """A machine whose external inputs change at the given (time, byte, bit, value)."""
    return '[[axis]]\nname = "X"\n[sin800]\n' + "".join(
        f'[[scenario]]\ntime = {t}\nkind = "input"\nbyte = {b}\nbit = {k}\nvalue = {v}\n' for t, b, k, v in events)


def test_5_3_1_3_while_int_loops_while_the_input_is_1(tmp_path):
    """L1732-1746: WHILE INT R70.2 (R70 = 1: byte 1, bit 2) dwells 1 s while input 1.2 is 1; it falls to 0 at
    3.5 s: passes at 0, 1, 2, 3 s. WHILE INT NOT 2.7 dwells while 2.7 is 0; it rises at 5.5 s: passes at
    4 and 5 s. End at 6 s."""
    _r, _ = _states(MANUAL / "m5_3_1_3_while_int.cl8", tmp_path, machine=_inputs((0.0, 1, 2, 1), (3.5, 1, 2, 0),
                                                                               (5.5, 2, 7, 1)))
    assert _r["cycle_time_s"] == pytest.approx(6.0)


@pytest.mark.parametrize("level,seconds", [(1, 1.0), (0, 2.0)])
def test_5_3_2_2_if_int_takes_the_branch_of_the_input(tmp_path, level, seconds):
    """L2072-2081: IF INT 1.2: THEN (G04 F1) with a 1 signal, ELSE (G04 F2) with a 0 signal."""
    _r, _ = _states(MANUAL / "m5_3_2_2_if_int.cl8", tmp_path, machine=_inputs((0.0, 1, 2, level)))
    assert _r["cycle_time_s"] == pytest.approx(seconds)


def test_5_3_2_1_if_on_a_bit_and_a_boolean(tmp_path):
    """L1962-2056: IF R70.3 with R70 = B00011111 (bit 3 = 1) and IF R71 with R71 = 1 take their THEN
    branches (G04 F1 each, not the ELSE's F2); the other IFs have empty branches: 2 s in all."""
    _r, _ = _states(MANUAL / "m5_3_2_1_if_forms.cl8", tmp_path, main="%MPF2\nL1\nM30\n")
    assert _r["cycle_time_s"] == pytest.approx(2.0)


@pytest.mark.parametrize("r10,r11,r14,seconds", [(2, 1, 0, 1.0), (1, 2, 15, 2.0), (1, 2, 14.9, 3.0)])
def test_7_2_nested_if_in_the_else_branch(tmp_path, r10, r11, r14, seconds):
    """L5286-5335: R10 > R11 -> first branch (1 s); else R14 >= 15 -> second (2 s); else third (3 s)."""
    _r, _ = _states(MANUAL / "m7_2_if_nesting.cl8", tmp_path, main=f"%MPF1\nR10={r10} R11={r11} R14={r14}\nL30\nM30\n")
    assert _r["cycle_time_s"] == pytest.approx(seconds)


def test_7_1_structure_program_150(tmp_path):
    """L5244-5282 with Name = 3, X_value = 84: y_value = 84 + 3 * 2 = 90; z_value = SIN(90) + 3 = 4.
    The DIN code ``NOTE`` stands for "DIN programming" (its comment) and is no NC block (N without a
    number: SIN001); it runs here as the note ``(NOTE)``."""
    for name in ("VARCEN", "LISTE1"):
        (tmp_path / name).write_text((MANUAL / name).read_text())
    src = tmp_path / "structure.cl8"
    src.write_text((MANUAL / "m7_1_structure.cl8").read_text().replace("(:NOTE:)", "(:(NOTE):)"))
    _r, states = _states(src, tmp_path, main="%MPF1\nR0=3 R10=84\nL150\nM30\n")
    _ever(states, R61=90.0, R60=4.0)


def test_5_3_7_1_extended_arithmetic_program_81(tmp_path):
    """L3630-3648 with Z_VALUE = 0, R20 = 3, R30 = 10, by hand: 0 + 3 * 10 = 30; SIN(30) + 5 = 5.5;
    (5.5 + 3) * 10 = 85; (85 + 5 / 3) * 10 / 80.009."""
    result, _ = _states(MANUAL / "m5_3_7_1_extended.cl8", tmp_path, main="%MPF1\nR10=0 R20=3 R30=10\nL81\nM30\n")
    assert result["variables"]["R10"] == pytest.approx((85 + 5 / 3) * 10 / 80.009, rel=1e-9)


def test_5_3_8_4_rel_and_inta(tmp_path):
    """L4411-4436: REL(1, 2) holds the program after its block (G00 X5 Z20) until input 1.2 is 1 (at 7.5 s);
    INTA(1, 1, 0) ends the next block's motion when input 1.0 is 1, which it is already: the axes stay
    at X5 Z20."""
    machine = _inputs((0.0, 1, 0, 1), (7.5, 1, 2, 1)).replace('name = "X"\n', 'name = "X"\n[[axis]]\nname = "Z"\n')
    result, _ = _states(MANUAL / "m5_3_8_4_rel_inta.cl8", tmp_path, machine=machine)
    assert result["cycle_time_s"] == pytest.approx(7.5)
    assert result["position"] == {"X": 5.0, "Z": 20.0}


def test_5_2_2_lists_program_81(tmp_path):
    """L1359-1395 with refpl = R150 = 50 (channel-independent global), drill_Z = R100 = 20 (channel
    global): start_Z = 50, Transf. = R0 = 50, depth = 50 - 20 = 30 into the central Load_1 = R900, which
    the called L200 sees."""
    (tmp_path / "L200.spf").write_text("%SPF200\nR1=R900+R0\nM17\n")
    machine = '[[axis]]\nname = "X"\n[sin800]\nr = { R150 = 50, R100 = 20 }\n'
    result, _ = _states(MANUAL / "m5_2_2_lists.cl8", tmp_path, machine=machine, main="%MPF1\nL81\nM30\n")
    v = result["variables"]
    assert (v["R0"], v["R900"], v["R1"]) == (50.0, 30.0, 80.0)


def test_5_3_1_1_repeat_prep_ref_int_sec(tmp_path):
    """L1449-1466, with the ":" lines filled in: contour L21 in the X/Z plane (G18) from (X750, Z50):
    (400, 50), (300, 300), (100, 400); the path from X250 Z500 to X250 Z0 crosses only the third
    element, at Z = 300 + 100 * (300 - 250) / (300 - 100) = 325. The REPEAT test follows INT SEC in the
    same block: the loop ends on the element found (R80..R83 = 300, 300, 100, 400), and PRAP moves to
    R91/R92 = X250 Z325."""
    src = tmp_path / "repeat.cl8"
    src.write_text("PROGRAM 502;\nCHANNEL NC 0;\n"
                   "LOCAL REAL: R50:=L_No, R51, R52, R53, R70, R80, R90, R91, R92;\nBEGIN\n"
                   "  LF; (: G18 G0 X250 Z500 :); LF;\n  L_No = 21; R51 = 750; R52 = 50; R53 = 1;\n"
                   "  REPEAT\n  BEGIN\n    R80 = PREP REF (L_No); LF;\n"
                   "    R90 = INT SEC (R80,R70); (:X250 Z0:);\n  END;\n  UNTIL R90=1;\n"
                   "PRAP (1) = R91; PRAP (2) = R92; LF;\nEND.\n")
    (tmp_path / "L21.spf").write_text("L21\nN5 X400 Z50\nN10 X300 Z300\nN15 X100 Z400 M17\n")
    machine = '[[axis]]\nname = "X"\n[[axis]]\nname = "Z"\n'
    result, states = _states(src, tmp_path, machine=machine)
    assert result["position"] == {"X": 250.0, "Z": pytest.approx(325.0)}
    last = states[-1]
    assert [last.get(f"R{n}", 0.0) for n in (80, 81, 82, 83, 90)] == [300.0, 300.0, 100.0, 400.0, 1.0]
