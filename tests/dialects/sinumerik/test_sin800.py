"""Unit tests of the SINUMERIK 800 NC: @ codes against the manual's examples, calls, faults, persistence."""

from __future__ import annotations

import math
from pathlib import Path

import pytest
from sin800_helpers import MACHINE, R, run_mpf

from ncvm.api import run
from ncvm.dialects import get_dialect
from ncvm.dialects.sinumerik.reader import Arith, AtInstr, Word, read_program
from ncvm.machine.config import load_machine
from ncvm.runtime.session import RunOptions, Session


def _run(tmp_path: Path, text: str, name: str = "prog.mpf", machine: str = MACHINE, files: dict | None = None,
         state: str = ".ncvm"):
    return run_mpf(tmp_path, text, machine_text=machine, name=name, files=files, state=state)


def test_reader_splits_items():
    prog, diags = read_program("p", "%SPF5\nN0010 @201 R13 P37 R10=R50+R51 X=-R91 Q1=25 G01 (NOTE)\n")
    assert not diags and prog.kind == "SPF" and prog.number == 5
    blk = prog.blocks[0]
    assert blk.n == 10
    at, ar, x, q, g = blk.items[:5]
    assert isinstance(at, AtInstr) and at.code == "201" and [o.kind for o in at.operands] == ["R", "P"]
    assert isinstance(ar, Arith) and ar.target == 10 and len(ar.terms) == 2
    assert isinstance(x, Word) and x.address == "X" and x.rref == (-1.0, 91)
    assert isinstance(q, Word) and q.address == "Q1" and q.value == 25.0
    assert g.address == "G" and g.value == 1.0


def test_manual_math_examples(tmp_path):
    # SIN(45), SIN(15.55), COS(30), TAN(45), ARC SIN, ANGLE(30,-80), LN(10), INV LN(2.5), SQRTS(5,10), ABS, TRUNC
    r = _run(tmp_path, "%MPF1\n@630 R1 K45 @630 R2 K15.55 @631 R3 K30 @632 R4 K45 @634 R5 K0.70710678\n"
                       "@637 R6 K30 K-80 @640 R7 K10 @641 R8 K2.5 @614 R9 K5 K10 @610 R10 K-253\n"
                       "R11=1.9 @622 R11 R12=-2.3 @622 R12 @613 R13 K25\nM30\n")
    assert R(r, 1) == pytest.approx(0.70710678, rel=1e-6)
    assert R(r, 2) == pytest.approx(0.26807920, rel=1e-6)
    assert R(r, 3) == pytest.approx(0.86602540, rel=1e-6)
    assert R(r, 4) == pytest.approx(1.0, rel=1e-6)
    assert R(r, 5) == pytest.approx(45.0, rel=1e-6)
    assert R(r, 6) == pytest.approx(159.444, abs=1e-3)
    assert R(r, 7) == pytest.approx(2.302585, rel=1e-6)
    assert R(r, 8) == pytest.approx(12.18249, rel=1e-6)
    assert R(r, 9) == pytest.approx(11.1803, rel=1e-5)
    assert R(r, 10) == 253.0 and R(r, 11) == 1.0 and R(r, 12) == -2.0 and R(r, 13) == 5.0


def test_manual_pattern_examples(tmp_path):
    # B00101100 with B10110011: OR B10111111, XOR B10011111, AND B00100000, NAND B11011111, NOT B11010011
    r = _run(tmp_path, "%MPF1\nR1=101100 @650 R2 R1 K10110011 @651 R3 R1 K10110011 @652 R4 R1 K10110011\n"
                       "@653 R5 R1 K10110011 @654 R6 R1 R20=1 @656 R7 R20 K0 R8=1100111 @660 R8 K6 @661 R9 K2\nM30\n")
    assert [R(r, n) for n in range(2, 7)] == [10111111.0, 10011111.0, 100000.0, 11011111.0, 11010011.0]
    assert R(r, 7) == 1.0  # 1 XORB 0 = 1 (CL 800 manual L3992)
    assert R(r, 8) == 100111.0 and R(r, 9) == 100.0


def test_canonical_object_examples_run(tmp_path):
    """Worked example (c) FOR TO: 10 passes of three motion blocks, then Z0; the object text as cl800 writes it."""
    spf = ("%SPF502\n@041 R50 R52 @201 R50 K1\nN5001 @151 R50 K10 K5002 @440 K3 R51 G91 G01 F500\n"
           "@440 K1 R52 F80\n@440 K1 K100 G00\n@620 R50 @100 K-5001\nN5002 @440 K3 K0 G90\n@043 R50 R52 M17\n")
    r = _run(tmp_path, spf, name="L502.spf")
    assert r["status"] == "ok", r["error"]
    assert r["motion"]["feed_moves"] == 20 and r["motion"]["rapid_moves"] == 11  # Z0 (G91) feeds count too
    assert r["position"]["X"] == pytest.approx(1000.0)
    assert r["position"]["Z"] == 0.0
    assert r["variables"]["R50"] == 0.0  # written by the loop, popped back to the caller's 0


def test_case_and_pointer_examples(tmp_path):
    """Worked example (a) pointers and (d) CASE, called from a main program."""
    spf3 = ("%SPF3\n@040 K5 R50 R51 R70 R71 R80 @201 R50 K70 @201 P50 K20 @201 R51 K80 @201 R71 P51 "
            "R700=R70 R701=R71\n@042 K5 R50 R51 R70 R71 R80 M17\n")
    spf500 = ("%SPF500\n@040 K2 R50 R53 @111 R0 K2 K1001 K0 K1002 K1 K1003 @100 K1004\n"
              "N1001 R50=R53+2 R800=R50 @100 K1004\nN1002 R50=R53+1 R800=R50 G91 G0 Z-1 @100 K1004\n"
              "N1003 R50=R53-2 R800=R50 @100 K1004\nN1004 @042 K2 R50 R53 M17\n")
    r = _run(tmp_path, "%MPF1\nR70=5\nL3\nR0=0\nL500\nM30\n", files={"L3.spf": spf3, "SUB500.txt": spf500})
    assert r["status"] == "ok", r["error"]
    assert R(r, 700) == 20.0 and R(r, 701) == 0.0 and R(r, 70) == 5.0
    assert R(r, 800) == 1.0 and r["position"]["Z"] == -1.0


def test_dialect_run_accepts_object_text(tmp_path):
    """The cl800 front end hands its object text to get_dialect("sin800").run(path, text, session)."""
    machine = load_machine(None)
    machine.program_path = [tmp_path]
    session = Session(machine, RunOptions(state_dir=tmp_path / ".ncvm"), dialect="cl800")
    get_dialect("sin800").run(str(tmp_path / "P505.spf"), "%SPF505\n@201 R10 K3 R11=R10*4\nM17\n", session)
    assert session.variables["R11"] == 12.0


def test_fault_has_line_and_call_stack(tmp_path):
    r = _run(tmp_path, "%MPF1\nN10 R1=0\nN20 L30\nM30\n", files={"L30.spf": "%SPF30\nR2=1\nR3=R2/R1\nM17\n"})
    err = r["error"]
    assert err["code"] == "CL800" and err["line"] == 3 and err["file"].endswith("L30.spf")
    assert err["stack"] == [f"called from %MPF1 at {tmp_path / 'prog.mpf'}:3"]


def test_central_r_parameters_persist(tmp_path):
    r1 = _run(tmp_path, "%MPF1\nR950=R950+1 R10=1\nM30\n")
    r2 = _run(tmp_path, "%MPF1\nR950=R950+1\nM30\n")
    assert R(r1, 950) == 1.0 and R(r2, 950) == 2.0 and R(r2, 10) == 0.0


def test_machine_data_write_persists(tmp_path):
    _run(tmp_path, "%MPF1\n@400 K2240 K1500 @430 K1 K1 K0 K10\nM30\n")
    r = _run(tmp_path, "%MPF1\n@300 R1 K2240 @330 R2 K1 K1 K0\nG0 X0\nM30\n")
    assert R(r, 1) == 1500.0 and R(r, 2) == 10.0
    assert r["motion"]["bounds"]["X"] == [0.0, 10.0]


def test_rel_waits_for_scripted_input(tmp_path):
    machine = MACHINE + '[[scenario]]\ntime = 12.5\nkind = "input"\nbyte = 2\nbit = 1\nvalue = 1\n'
    r = _run(tmp_path, "%MPF1\nR1=1 @730 K2 K1 R2=1\nM30\n", machine=machine)
    assert r["status"] == "ok" and r["cycle_time_s"] == pytest.approx(12.5)


def test_dwell_advances_clock(tmp_path):
    r = _run(tmp_path, "%MPF1\nG04 X5\nR27=2.5 G4 F=R27\nM30\n")
    assert r["cycle_time_s"] == pytest.approx(7.5)


def test_step_limit_stops_runaway(tmp_path):
    (tmp_path / "p.mpf").write_text("%MPF1\nN10 R1=R1+1 @100 K-10\n")
    result, _ = run(tmp_path / "p.mpf", options=RunOptions(state_dir=tmp_path / ".n", max_steps=1000))
    assert result["error"]["code"] == "RUN001" and 1000 <= result["steps"] <= 1001


def test_arith_is_left_to_right(tmp_path):
    r = _run(tmp_path, "%MPF1\nR1=2+3*4 R2=-R1+20/2\nM30\n")
    assert R(r, 1) == 20.0 and R(r, 2) == 0.0


def test_tool_offset_d_word(tmp_path):
    machine = MACHINE + "tool_offsets = [ { d = 3, p = [7, 20, 40.0, 0, 0, 1.5] } ]\n"
    r = _run(tmp_path, "%MPF1\nD3 G0 Z0\nM30\n", machine=machine)
    assert r["motion"]["bounds"]["Z"][1] == pytest.approx(41.5)
    assert math.isclose(r["position"]["Z"], 0.0, abs_tol=1e-9)


def test_prep_ref_int_sec_manual_example(tmp_path):
    """Manual L4212-4252: contour L20 from (X750, Y50), path along Y250 from X750 to X0: X = 320, Y = 250."""
    contour = "L20\nN5 X400 Y50 B100\nN10 X300 Y300\nN15 X100 Y400 M17\n"
    main = ("%MPF30\nG0 Y250 X750\nR50=20 R52=750 R51=50 R53=1 R70=0\n"
            "N3001 @131 R70 K0 K3002 @710 R54 R50\n@711 R70 R54 R62 Y250 X0 @100 K-3001\nN3002 M30\n")
    r = _run(tmp_path, main, files={"L20.spf": contour})
    assert r["status"] == "ok", r["error"]
    assert R(r, 70) == 1.0 and R(r, 71) == 250.0 and R(r, 72) == pytest.approx(320.0)
    # the element found is the line after the B100 rounding (test_radius_address.py): from the rounding's end
    # (Y112.861, X374.856) to (Y300, X300), G1, not the last
    assert [R(r, n) for n in range(54, 62)] == pytest.approx([112.860932, 374.855627, 300.0, 300.0, 0.0, 0.0, 1.0,
                                                             0.0])
    assert r["position"]["X"] == 750.0  # INT SEC's destination words do not move the axes


def test_acas_after_g16_and_prep_cyc(tmp_path):
    r = _run(tmp_path, "%MPF1\nG16 X Y Z-\n@367 R10 K0 @713 R20\nM30\n")
    assert [R(r, n) for n in range(10, 15)] == [1.0, 2.0, 131.0, 0.0, 1.0]
    assert R(r, 20) == 1.0 and R(r, 21) == 1.0


def test_meas_m_stops_at_probe_trigger(tmp_path):
    machine = MACHINE + ('[[scenario]]\ntime = 0.0\nkind = "probe"\ninput = 1\nposition = { X = 42.5, Y = 10.0 }\n')
    r = _run(tmp_path, "%MPF1\nG1 F1000 Y10\n@720 R93 K1 X100 Y10\n@714 R1=R93\nM30\n", machine=machine)
    assert r["status"] == "ok", r["error"]
    assert R(r, 93) == 42.5 and R(r, 94) == 10.0 and R(r, 1) == 42.5
    assert r["position"]["X"] == 42.5


def test_debug_hook_sees_every_block(tmp_path):
    seen = []
    (tmp_path / "p.mpf").write_text("%MPF1\nN10 R1=1\nN20 L5\nN30 M30\n")
    (tmp_path / "L5.spf").write_text("%SPF5\nR2=R1+1\nM17\n")
    opts = RunOptions(state_dir=tmp_path / ".n", hook=lambda f, line, v: seen.append((Path(f).name, line, dict(v))))
    result, _ = run(tmp_path / "p.mpf", options=opts)
    assert result["status"] == "ok"
    assert [(f, line) for f, line, _v in seen] == [("p.mpf", 2), ("p.mpf", 3), ("L5.spf", 2), ("L5.spf", 3),
                                                    ("p.mpf", 4)]
    assert seen[1][2] == {"R1": 1.0} and seen[3][2] == {"R1": 1.0, "R2": 2.0}


def test_m94_loads_part_number_from_plc(tmp_path):
    """Manual L4305-4326: M94 transfers the part number from the PLC to R60, STOP DEC, then branch on it."""
    machine = MACHINE + 'm_functions = { 94 = { R60 = "DB20.DW1" } }\n[sin800.plc.1]\nDB = { "20" = [0, 150] }\n'
    r = _run(tmp_path, "%MPF1\nR60=0 R61=1\nM94\n@714 @126 R60 K100 K10 G0 G54 X1 @100 K20\nN10 G55 X2\n"
                       "N20 R62=R60+R61 M30\n", machine=machine)
    assert r["status"] == "ok", r["error"]
    assert R(r, 60) == 150.0 and R(r, 62) == 151.0 and r["position"]["X"] == 2.0


def test_fault_inside_a_run_of_constant_blocks_names_its_line(tmp_path):
    r = _run(tmp_path, "%MPF1\nG90 G0 X1\nY2\nG1 X3\nM30\n")  # G1 without any F word
    assert r["error"]["code"] == "NC006" and r["error"]["line"] == 4 and r["steps"] >= 3


@pytest.mark.parametrize("read", ["@367 R1 K2", "@36a R1 K2", "@36b R1 K2 K0", "@371 R1 K2 K1", "@a27 K2 K1 K3",
                                  "@303 R1 K2 K400", "@337 R1 K2 K1 K1"])
def test_another_channels_system_memory_is_the_cl800_error(tmp_path, read):
    """L2351, L2553, L2693: only channels of the same NC CPU can be read; the simulated CPU runs channel 1
    alone. Channel 0 and the own number (1) read the own channel; SOB's 99 the channel-independent bits."""
    r = _run(tmp_path, f"%MPF1\n{read}\nM30\n")
    assert r["error"]["code"] == "CL800" and "channel 2 is not on this NC CPU" in r["error"]["message"]
    own = read.replace("K2", "K1", 1)
    assert _run(tmp_path, f"%MPF1\n{own}\nM30\n")["status"] == "ok"


def test_acas_of_the_own_channel_by_number_and_sob_99(tmp_path):
    machine = MACHINE + 'sob = { "99:3" = 1 }\n'
    r = _run(tmp_path, "%MPF1\n@367 R10 K1 @371 R20 K99 K3\nM30\n", machine=machine)
    assert r["status"] == "ok", r["error"]
    assert [R(r, n) for n in range(10, 15)] == [1.0, 2.0, 3.0, 0.0, 1.0] and R(r, 20) == 1.0


def test_meas_m_rotary_axis_fills_two_registers(tmp_path):
    """L4366-4369: a rotary axis gives the position within a rotation and the number of rotations.
    X and the rotary axis C move; the probe switches at X 20, C 450 (1 rotation + 90 degrees)."""
    machine = ('[[axis]]\nname = "X"\n[[axis]]\nname = "C"\nkind = "rotary"\n[sin800]\ncontrol = "880"\n'
               '[[scenario]]\ntime = 0.0\nkind = "probe"\ninput = 1\nposition = { X = 20.0, C = 450.0 }\n')
    r = _run(tmp_path, "%MPF1\nG1 F1000\n@720 R93 K1 X40 C900\n@714\nM30\n", machine=machine)
    assert r["status"] == "ok", r["error"]
    assert [R(r, n) for n in (93, 94, 95)] == [20.0, 90.0, 1.0]
    assert r["position"]["C"] == 450.0
