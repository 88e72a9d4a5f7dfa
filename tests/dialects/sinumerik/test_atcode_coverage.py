"""Effects of the @ codes that no other test asserted (audit of CL 800 manual §10, L6332-6824 against the test suite).

Each test runs a hand-written main program on a SINUMERIK 880 (channel 1, axes X Y Z) and asserts what
the manual says the code does: R parameters, positions, data read back, or the V24 / panel output.
Where the manual gives an example with its data, the example is used (section and line in the test).
"""

from __future__ import annotations

from pathlib import Path

import pytest
from sin800_helpers import R, machine, run_mpf

from ncvm.api import run
from ncvm.runtime.session import RunOptions

MACHINE = machine(extra="""channel = 1
nc_md = { "2241" = 1200, "5002" = "00100000", "5010" = "00000001" }
cycle_md = { "400" = 17, "801" = "00000101", "802" = "00000010", "1000" = 33, "7000" = "00000011" }
plc_md = { "20" = 40, "3000" = "00010010", "3001" = "00010110" }
drive_md = { "2521" = 4000, "2441" = 772, "2442" = 4 }
nc_sd = { "3041" = 2500, "5013" = "11000111", "5001" = "00000001" }
cycle_sd = { "400" = 12.5, "802" = "00000100" }
tool_offsets = [ { area = 1, d = 2, p = [4711, 20, 30.0, 12.5, 4.0] } ]
zero_offsets = { EXTERNAL = [0.0, 7.0, 0.0], DRF = [0.0, 0.25, 0.0], PRESET = [3.0, 0.0, 0.0] }
[sin800.plc.1]
I = { "4" = "00000000", "5" = "00000000" }
Q = { "2" = "00100000", "6" = "00010010", "7" = "00110100" }
P = { "3" = "10000001", "8" = "00000001", "9" = "00000010" }
F = { "10" = "11110000", "20" = "11111111", "21" = "11111110" }
DB = { "2" = [0, 0, 0, 0, 20] , "30" = [0, 0, 0, 0] }
""")


PLAIN = MACHINE.replace("zero_offsets = { EXTERNAL = [0.0, 7.0, 0.0], DRF = [0.0, 0.25, 0.0], "
                        "PRESET = [3.0, 0.0, 0.0] }\n", "")


#: the manual's MDP/MDPBY and MDD examples are for the SINUMERIK 810 (L2350, L2376)
S810 = PLAIN.replace('control = "880"', 'control = "810"')


def _run(tmp_path: Path, text: str, machine: str = MACHINE, state: str = ".s") -> dict:
    return run_mpf(tmp_path, text, machine_text=machine, name="p.mpf", state=state)


def _ok(tmp_path: Path, text: str, machine: str = MACHINE) -> dict:
    return run_mpf(tmp_path, text, machine_text=machine, name="p.mpf", state=".s", ok=True)


def _cl800_error(tmp_path: Path, text: str) -> str:
    result = _run(tmp_path, text)
    assert result["status"] == "error" and result["error"]["code"] == "CL800", result["error"]
    return result["error"]["message"]


# -- main group 0: push / pop ---------------------------------------------------------------------


def test_push_saves_and_zeroes_pop_restores(tmp_path):
    """L6386-6413: push saves the listed R parameters and sets them to 0; pop restores them."""
    r = _ok(tmp_path, "%MPF1\nR50=5 R52=6 R53=7 R54=8\n@040 K2 R50 R52 @041 R53 R54 R1=R50+R52+R53+R54\n"
                      "R50=1 R53=2 @043 R53 R54 @042 K2 R50 R52 R2=R50+R52+R53+R54\nM30\n")
    assert R(r, 1) == 0.0 and R(r, 2) == 26.0
    assert [R(r, n) for n in (50, 52, 53, 54)] == [5.0, 6.0, 7.0, 8.0]


def test_ess_runs_without_effect_on_the_program(tmp_path):
    """@00f only enables the start by softkey (L1100-1104): the program's results are the same."""
    r = _ok(tmp_path, "%MPF1\n@00f R1=2 G0 X5\nM30\n")
    assert R(r, 1) == 2.0 and r["position"]["X"] == 5.0


# -- main group 2: general data transfer ----------------------------------------------------------


def test_clear_xchg_bit_and_clear_mib(tmp_path):
    """@200 CLEAR, @202 XCHG (R and pointer operands), @203 bit access, @210 CLEAR MIB (L2224-2301)."""
    machine = MACHINE.replace("channel = 1\n", 'channel = 1\nmib = { "100" = 1, "105" = 2, "110" = 3, "111" = 4 }\n')
    r = _ok(tmp_path, "%MPF1\nR60=100 @200 R60 R30=10 R20=30 @202 R30 R20\n"
                      "R70=71 R71=1 R72=2 @202 P70 R72 R73=1011 @203 R74 R73 K1 @203 R75 R73 K2\n"
                      "@210 K100 K110 @211 R1 K100 @211 R2 K105 @211 R3 K110 @211 R4 K111\nM30\n", machine)
    assert R(r, 60) == 0.0 and R(r, 30) == 30.0 and R(r, 20) == 10.0
    assert R(r, 71) == 2.0 and R(r, 72) == 1.0  # XCHG([R70] = R71, R72)
    assert R(r, 74) == 1.0 and R(r, 75) == 0.0  # 00001011: bit 1 set, bit 2 clear
    assert [R(r, n) for n in (1, 2, 3, 4)] == [0.0, 0.0, 0.0, 4.0]  # MIB 100..110 cleared, 111 kept


# -- main group 3 / 4: machine and setting data ---------------------------------------------------


def test_cycle_machine_data_reads(tmp_path):
    """L2331-2345: MDZ(0,400), MDZBY(1,801), MDZBI(1,802,1); central data with channel 0."""
    r = _ok(tmp_path, "%MPF1\n@303 R50 K0 K400 @304 R51 K1 K801 @305 R52 K1 K802 K1 @305 R53 K0 K802 K0\n"
                      "@303 R54 K0 K1000 @304 R55 K0 K7000\nM30\n")
    assert [R(r, n) for n in range(50, 56)] == [17.0, 101.0, 1.0, 0.0, 33.0, 11.0]


def test_plc_machine_data_reads_manual_example(tmp_path):
    """L2350-2365: MDP(20) = 40; MDPBY(3000) on 00010010 gives 10010; MDPBI(3001,2) on 00010110 gives 1."""
    r = _ok(tmp_path, "%MPF1\n@306 R93 K20 @307 R94 K3000 @308 R95 K3001 K2 @308 R96 K3001 K0\nM30\n", S810)
    assert [R(r, n) for n in (93, 94, 95, 96)] == [40.0, 10010.0, 1.0, 0.0]


def test_setting_data_reads_manual_example(tmp_path):
    """L2387-2413: SEN(3041), SENBY(5013) = 11000111, SENBI(5001,0) = 1; SEZ(1,400), SEZBY(0,802),
    SEZBI(0,802,2)."""
    r = _ok(tmp_path, "%MPF1\n@310 R80 K3041 @311 R81 K5013 @312 R82 K5001 K0 @313 R50 K1 K400\n"
                      "@314 R51 K0 K802 @315 R52 K0 K802 K2 @315 R53 K0 K802 K1\nM30\n")
    assert [R(r, n) for n in (80, 81, 82)] == [2500.0, 11000111.0, 1.0]
    assert [R(r, n) for n in (50, 51, 52, 53)] == [12.5, 100.0, 1.0, 0.0]


def test_machine_data_writes_read_back(tmp_path):
    """@403-@409 write what @303-@309 read (L3036-3124); bits change one bit of the byte. Cycle MD and
    PLC MD 6000-8999 on the 880; drive MD and PLC MD 2000-3999 on the 810."""
    r = _ok(tmp_path, "%MPF1\n@403 K0 K401 K-7.5 @404 K1 K803 K1001 @405 K0 K801 K1 K1 @406 K2000 K12\n"
                      "@407 K6002 K10000001 @408 K6002 K1 K1\n"
                      "@303 R1 K0 K401 @304 R2 K0 K803 @304 R3 K0 K801 @306 R4 K2000 @307 R5 K6002\nM30\n")
    assert [R(r, n) for n in range(1, 6)] == [-7.5, 1001.0, 111.0, 12.0, 10000011.0]
    r = _ok(tmp_path, "%MPF1\n@408 K3000 K0 K1 @409 K2521 K3000 @307 R6 K3000 @309 R7 K2521\nM30\n", S810)
    assert (R(r, 6), R(r, 7)) == (10011.0, 3000.0)


@pytest.mark.parametrize("control,text,message", [
    ("810", "@303 R1 K0 K400", "cycle machine data exist on the SINUMERIK 850/880 only"),
    ("820", "@413 K0 K400 K1", "cycle setting data exist on the SINUMERIK 850/880 only"),
    ("880", "@309 R1 K2521", "drive machine data exist on the SINUMERIK 810/820 only"),
    ("880", "@307 R1 K3000", "plc_md address 3000 outside 6000-8999"),
    ("810", "@406 K2000 K1", "plc_md address 2000 outside 0-1999")])
def test_machine_data_of_another_control_is_the_cl800_error(tmp_path, control, text, message):
    """Ch.6 table (L4817-4845) and ch.10 (L6506-6508): which controls have which data, at which addresses."""
    machine = PLAIN.replace('control = "880"', f'control = "{control}"')
    r = _run(tmp_path, f"%MPF1\n{text}\nM30\n", machine)
    assert r["error"]["code"] == "CL800" and message in r["error"]["message"]


def test_drive_machine_data_reads_manual_example(tmp_path):
    """L2376-2385: MDD(2521); MDDBY(2441,0) is the low byte (772 = 0x0304: low 00000100, high 00000011);
    MDDBI(2442,0,2) bit 2 of the low byte of 4."""
    r = _ok(tmp_path, "%MPF1\n@309 R60 K2521 @30a R61 K2441 K0 @30a R63 K2441 K1 @30b R62 K2442 K0 K2\nM30\n",
            S810)
    assert [R(r, n) for n in (60, 61, 62, 63)] == [4000.0, 100.0, 1.0, 11.0]


def test_setting_data_writes_read_back(tmp_path):
    """@410-@415 (L3126-3152): SEN, SENBY, SENBI, SEZ, SEZBY, SEZBI."""
    r = _ok(tmp_path, "%MPF1\n@410 K3041 K1800 @411 K5013 K111 @412 K5001 K0 K0 @412 K5001 K3 K1\n"
                      "@413 K0 K401 K2.5 @414 K0 K803 K11 @415 K1 K802 K0 K1\n"
                      "@310 R1 K3041 @311 R2 K5013 @311 R3 K5001 @313 R4 K0 K401 @314 R5 K0 K803 @314 R6 K0 K802\n"
                      "M30\n")
    assert [R(r, n) for n in range(1, 7)] == [1800.0, 111.0, 1000.0, 2.5, 11.0, 101.0]


def test_data_write_errors(tmp_path):
    """L723-728: writing 2 to a bit, or a non-pattern to a byte, is the CL 800 error."""
    assert "not 0 or 1" in _cl800_error(tmp_path, "%MPF1\n@412 K5001 K0 K2\nM30\n")
    assert "not a bit pattern" in _cl800_error(tmp_path, "%MPF1\n@411 K5013 K12\nM30\n")


# -- tool offsets -----------------------------------------------------------------------------------


def test_tool_offset_write_then_read(tmp_path):
    """L3154-3182: TOS(1,2,3) = value loads P3 of D2 in TO area 1; TOAD adds. L2436: R80 = TOS(1,2,3)."""
    r = _ok(tmp_path, "%MPF1\n@320 R80 K1 K2 K3 @420 K1 K2 K3 K20 @423 K1 K2 K3 K0.5 @320 R81 K1 K2 K3\n"
                      "@320 R82 K1 K2 K0\nM30\n")
    assert R(r, 80) == 12.5 and R(r, 81) == 20.5 and R(r, 82) == 4711.0


# -- zero offsets -------------------------------------------------------------------------------------


def test_zero_offset_reads(tmp_path):
    """L2469-2525: ZOPR (G58/G59), ZOE (external), ZOD (DRF), ZOPS (PRESET), ZOS = settable + programmable
    + external + tool offset, without DRF and PRESET."""
    r = _ok(tmp_path, "%MPF1\n@432 K1 K2 K20 @432 K2 K2 K1.5 @331 R80 K1 K2 @331 R81 K2 K2 @332 R60 K2\n"
                      "@333 R61 K2 @334 R65 K1 @430 K1 K2 K0 K500 G54\n@336 R82 K2 @336 R83 K1\nM30\n")
    assert [R(r, n) for n in (80, 81, 60, 61, 65)] == [20.0, 1.5, 7.0, 0.25, 3.0]
    assert R(r, 82) == 500.0 + 20.0 + 1.5 + 7.0  # settable + G58 + G59 + external (no DRF)
    assert R(r, 83) == 0.0  # PRESET 3.0 of axis 1 is not part of ZOS


def test_zero_offset_writes_move_the_workpiece_frame(tmp_path):
    """ZOPR(1,1) = 50 (L3214) and ZOD(2) = R61 (L3222) shift the axes' machine positions for the same
    programmed position at once; ZOPS(1) = 100 (L3230) is effective after program end (L3240): the
    next run's X10 is at machine X 10 + 100, this run's at 10 + 50."""
    r = _ok(tmp_path, "%MPF1\nR61=2 @432 K1 K1 K50 @434 K2 R61 @435 K1 K100\nG0 X10 Y10\n"
                      "@714 @361 R1 K1 @361 R2 K2 @331 R3 K1 K1 @333 R4 K2 @334 R5 K1\nM30\n", PLAIN)
    assert [R(r, n) for n in (3, 4, 5)] == [50.0, 2.0, 100.0]
    assert R(r, 1) == 10.0 + 50.0 and R(r, 2) == 10.0 + 2.0
    r = _ok(tmp_path, "%MPF2\nG0 X10\n@714 @361 R1 K1 @334 R5 K1 @331 R3 K1 K1\nM30\n", PLAIN)
    assert R(r, 5) == 100.0 and R(r, 3) == 50.0  # both kept by the NC (store)
    assert R(r, 1) == 10.0 + 50.0 + 100.0


def test_rotation_angles_programmable_read_and_settable_additive(tmp_path):
    """ZOPRDW(1,2,1) (L2540), ZOFADW adds to the settable angle (L3262)."""
    r = _ok(tmp_path, "%MPF1\n@439 K0 K2 K1 K15 @338 R70 K1 K2 K1 @437 K0 K1 K1 K10 @438 K0 K1 K1 K5\n"
                      "@337 R71 K0 K1 K1\n@439 K0 K2 K1 K0 @437 K0 K1 K1 K0\nM30\n")
    assert R(r, 70) == 15.0 and R(r, 71) == 15.0


# -- programmed setpoints ------------------------------------------------------------------------------


def test_prss_prad_prip_setpoints(tmp_path):
    """@442 PRSS(0) = 200 programs S (L3325); @448 PRIP(1/2) the centre, @446 PRAD the radius of the arc
    (L3335-3360): a G02 quarter circle from (10, 0) around (0, 0) to (0, -10)."""
    r = _ok(tmp_path, "%MPF1\n@442 K0 K200 M3\n@342 R1 K0 K0\nG0 X10 Y0\n"
                      "@440 K1 K0 @440 K2 K-10 @448 K1 K-10 @448 K2 K0 G02 F100\n@714 @361 R2 K1 @361 R3 K2\nM30\n", PLAIN)
    assert R(r, 1) == 200.0
    assert (R(r, 2), R(r, 3)) == (pytest.approx(0.0, abs=1e-9), pytest.approx(-10.0))
    assert r["motion"]["feed_length"] == pytest.approx(10.0 * 3.141592653589793 / 2, rel=1e-6)


def test_prad_programs_the_radius_address(tmp_path):
    """@446 PRAD() = 2 (L3330): the radius word of the block (B on the 8xx): a G02 half circle."""
    r = _ok(tmp_path, "%MPF1\nG0 X0 Y0\n@440 K1 K4 @446 K2 G02 F100\nM30\n")
    assert r["position"]["X"] == pytest.approx(4.0)
    assert r["motion"]["feed_length"] == pytest.approx(2.0 * 3.141592653589793, rel=1e-6)


def test_prss_write_checks_the_spindle(tmp_path):
    """PRSS(<Value3>) = value: spindle 0-6, 0 = the master spindle (L3318-3326, L6670); the simulated NC
    has spindle 1 only, as for the PRSS read."""
    assert "spindle 2 does not exist" in _cl800_error(tmp_path, "%MPF1\n@442 K2 K200 M3\nM30\n")
    assert "outside 0-6" in _cl800_error(tmp_path, "%MPF1\n@442 K7 K200 M3\nM30\n")
    r = _ok(tmp_path, "%MPF1\nR50=1\n@442 R50 K200 M3\n@342 R1 K0 K1\nM30\n")
    assert R(r, 1) == 200.0


def test_pcda_pcds_write_then_read(tmp_path):
    """L3362-3378 and L2571-2587: PCDA(1,1,6) = 1 then R50 = PCDA(1,1,6) reads 1; the same for PCDS."""
    r = _ok(tmp_path, "%MPF1\n@34b R49 K1 K1 K6 @44b K1 K1 K6 K1 @34b R50 K1 K1 K6 @44c K1 K0 K2 K1\n"
                      "@34c R51 K1 K0 K2 @34c R52 K1 K0 K3\nM30\n")
    assert [R(r, n) for n in (49, 50, 51, 52)] == [0.0, 1.0, 1.0, 0.0]


def test_drive_status_bits_read_the_machine_state(tmp_path):
    """@3e1 RSDA / @3e2 RSDS / @3e3 RSDD read status bits of the digital drives (L2974-3032), 0/1."""
    machine = MACHINE.replace("channel = 1\n", 'channel = 1\nsob = { "3e1:1:0:2" = 1, "3e2:1:3:7" = 1, '
                                               '"3e3:2:1:0" = 1 }\n')
    r = _ok(tmp_path, "%MPF1\n@3e1 R1 K1 K0 K2 @3e1 R2 K1 K0 K3 @3e2 R3 K1 K3 K7 @3e3 R4 K2 K1 K0\nM30\n", machine)
    assert [R(r, n) for n in (1, 2, 3, 4)] == [1.0, 0.0, 1.0, 1.0]


def test_satc_write_is_kept(tmp_path):
    """@4e1 SATC(1, R50) = R51 (L3575): the spindle acceleration time constant of a gear stage; the value
    range 0-16000 (L6704)."""
    _ok(tmp_path, "%MPF1\nR50=2 R51=1600 @4e1 K1 R50 R51\nM30\n")
    assert "16001" in _cl800_error(tmp_path, "%MPF1\n@4e1 K1 K2 K16001\nM30\n")


# -- actual values and program data -------------------------------------------------------------------


def test_acpw_acp_and_ppch(tmp_path):
    """@360 ACPW: workpiece position; @362 ACP: machine position; @372 PPCH: the program's channel."""
    machine = PLAIN + "[offsets]\nG54 = [100.0, 0.0, 0.0]\n"
    r = _ok(tmp_path, "%MPF1\nG54 G0 X5\n@714 @360 R1 K1 @362 R2 K1 @372 R3\nM30\n", machine)
    assert (R(r, 1), R(r, 2), R(r, 3)) == (5.0, 105.0, 1.0)


# -- PLC ------------------------------------------------------------------------------------------------


def test_plc_bits_bytes_words_reads(tmp_path):
    """PLCQ, PLCW, PLCQB, PLCPB, PLCFB, PLCIW/PLCQW/PLCPW/PLCFW (word = byte n high, n+1 low; L645-649)."""
    r = _ok(tmp_path, "%MPF1\n@381 R1 K1 K2 K5 @381 R2 K1 K2 K4 @383 R3 K1 K2 K4 K2 @383 R4 K1 K2 K4 K3\n"
                      "@391 R5 K1 K2 @392 R6 K1 K3 @393 R7 K1 K10\n"
                      "@3a0 R8 K1 K4 K0 @3a1 R9 K1 K6 K0 @3a2 R10 K1 K8 K0 @3a3 R11 K1 K20 K0 @3a1 R12 K1 K6 K2\n"
                      "@3a1 R13 K1 K6 K101\nM30\n")
    assert [R(r, n) for n in (1, 2, 3, 4)] == [1.0, 0.0, 1.0, 0.0]  # Q2.5; DB2 DW4 = 20 = bit 2 and 4
    assert [R(r, n) for n in (5, 6, 7)] == [100000.0, 10000001.0, 11110000.0]
    assert R(r, 8) == 0.0 and R(r, 9) == 0x1234 and R(r, 10) == 0x0102
    assert R(r, 11) == -2.0  # FW20 = 0xFFFE, 16-bit two's complement
    assert R(r, 12) == pytest.approx(466.0)  # 4660 with DIM 2: one digit after the decimal point
    assert R(r, 13) == 1234.0  # QW6 as BCD


def test_plc_missing_peripheral_byte_is_the_cl800_error(tmp_path):
    """L2809: reading a peripheral byte that does not exist puts the PLC into STOP."""
    assert "STOP" in _cl800_error(tmp_path, "%MPF1\n@392 R1 K1 K100\nM30\n")


def test_plc_writes_read_back(tmp_path):
    """@483 PLCW bit, @494/@495 left/right byte of a DW, @4a3 PLCFW, @4b1 PLCDB (BCD, 2 DWs)."""
    r = _ok(tmp_path, "%MPF1\n@483 K1 K30 K0 K15 K1 @494 K1 K30 K1 K10010 @495 K1 K30 K1 K110100\n"
                      "@4a3 K1 K40 K0 K-300 @4b1 K1 K30 K2 K2 K100 K12345678\n"
                      "@383 R1 K1 K30 K0 K15 @3b0 R2 K1 K30 K0 K1 K0 @3b0 R3 K1 K30 K1 K1 K0 @3a3 R4 K1 K40 K0\n"
                      "@3b1 R5 K1 K30 K2 K2 K100 @394 R6 K1 K30 K1 @395 R7 K1 K30 K1\nM30\n")
    assert R(r, 1) == 1.0 and R(r, 2) == -32768.0  # bit 15 set: 0x8000 signed
    assert R(r, 3) == 0x1234 and R(r, 4) == -300.0 and R(r, 5) == 12345678.0
    assert (R(r, 6), R(r, 7)) == (10010.0, 110100.0)


# -- main group 6 -----------------------------------------------------------------------------------------


def test_dec_and_boolean_operations(tmp_path):
    """@621 DEC; @655 ORB, @657 ANDB, @658 NANDB, @659 NOTB on 1 and 0 (L3976-3995)."""
    r = _ok(tmp_path, "%MPF1\nR1=5 @621 R1 R50=1 R51=0\n@655 R52 R50 R51 @657 R54 R50 R51 @658 R55 R50 R51 "
                      "@659 R56 R50 @659 R57 R51 @657 R58 R50 K1 @655 R59 R51 K0\nM30\n")
    assert R(r, 1) == 4.0
    assert [R(r, n) for n in (52, 54, 55, 56, 57, 58, 59)] == [1.0, 0.0, 1.0, 0.0, 1.0, 1.0, 0.0]


@pytest.mark.parametrize("code,a,b,expected", [
    ("671", 3, 3, 1), ("671", 3, 4, 0), ("672", 3, 4, 1), ("672", 3, 3, 0), ("673", 4, 3, 1), ("673", 3, 3, 0),
    ("674", 3, 3, 1), ("674", 2, 3, 0), ("675", 2, 3, 1), ("675", 3, 3, 0), ("676", 3, 3, 1), ("676", 4, 3, 0),
    ("670", 5, 0, 1), ("670", 0, 7, 0)])
def test_boolean_comparison_assignment(tmp_path, code, a, b, expected):
    """@67x Var1 Var2 Value (L6772): Var1 = 1 when Var2 x Value holds, else 0; x = 0 "no comparison
    operator": Var1 is Var2 taken as a boolean (0 or not 0)."""
    r = _ok(tmp_path, f"%MPF1\nR1=7 R2={a} @{code} R1 R2 K{b}\nM30\n")
    assert R(r, 1) == float(expected)


# -- main group 7 -----------------------------------------------------------------------------------------


def test_pos_msys_block_in_machine_coordinates(tmp_path):
    """@706 POS MSYS (L4072-4103): the block's positions refer to machine zero; the next block is in the
    workpiece frame again."""
    machine = PLAIN + "[offsets]\nG54 = [100.0, 50.0, 0.0]\n"
    r = _ok(tmp_path, "%MPF1\nG54 G0 X0 Y0\n@706 X1000 Y500\n@714 @361 R1 K1 @361 R2 K2\nX1\n"
                      "@714 @361 R3 K1\nM30\n", machine)
    assert (R(r, 1), R(r, 2), R(r, 3)) == (1000.0, 500.0, 101.0)


# -- main group a: I/O and operator control -------------------------------------------------------------


def test_v24_output_of_zero_offsets_data_and_parameters(tmp_path):
    """PORT, OUTP ZOA, OUTP DATA, OUTP PARA, OUTP ETX (L4466-4560): what goes out over the V24 port."""
    r = _ok(tmp_path, "%MPF1\nR100=1.5 R101=-2\n@a20 K2 @a25 K0 @a26 K5 K2241 K2241 @a26 K6 K2 K2\n"
                      "@a27 K0 K100 K101 @a29\nM30\n",
            MACHINE.replace("tool_offsets = [ { area = 1, d = 2,", "tool_offsets = [ { area = 0, d = 2,")
            + "[offsets]\nG54 = [10.0, 20.0, 0.0]\n")
    out = r["variables"]["V24"]
    assert out[0] == "PORT 2" and out[-1] == "\x03"
    assert "R100=1.5" in out and "R101=-2" in out
    assert "G54 X10 Y20 Z0" in out  # settable ZO G54 (coarse + fine)
    assert "MD2241=1200" in out
    assert "D2 P0=4711 P1=20 P2=30 P3=12.5 P4=4" in out


def test_v24_output_of_the_settable_rotation_angles(tmp_path):
    """OUTP ZOA(<channel>) outputs the angles of the settable coordinate rotation of that channel."""
    r = _ok(tmp_path, "%MPF1\n@437 K0 K2 K1 K30\n@a20 K1 @a25 K1\n@437 K0 K2 K1 K0\nM30\n")
    assert "G55 ROT 30" in r["variables"]["V24"]


def test_inp_reads_r_parameters_from_the_v24_input(tmp_path):
    """INP(10) (L4540-4560): data read in over the V24 interface, here R parameters in tape format."""
    machine = MACHINE.replace("channel = 1\n", 'channel = 1\nv24_input = "R10=4.5\\nR11=-1\\n"\n')
    r = _ok(tmp_path, "%MPF1\n@a20 K1 @a28 K10 R12=R10+R11\nM30\n", machine)
    assert R(r, 10) == 4.5 and R(r, 11) == -1.0 and R(r, 12) == 3.5


def test_panel_menus_and_channel_display(tmp_path):
    """WRT PIC(1, 20) calls a standard menu, RECALL PIC returns, CHAN = 2 selects the display (L4440-4590)."""
    r = _ok(tmp_path, "%MPF1\n@a15 K1 K20 @a15 K0 K5 @a1b @a40 K2\nM30\n")
    assert r["output"] == ["[panel] standard menu 20", "[panel] user menu 5", "[panel] standard menu 20",
                           "[panel] channel 2"]


def test_inp_type_check_and_tape_format(tmp_path):
    """INP(<type>) checks the data type (L4545): R parameters are not NC machine data; MD, SD, TO and ZO
    lines load the NC's data."""
    tape = "MD2241=900\\nSD3041=10\\nD2 P0=5 P3=1.25\\nG55 X1 Y2 Z3\\nG56 ROT 45\\n"
    machine = MACHINE.replace("channel = 1\n", f'channel = 1\nto_area = 1\nv24_input = "{tape}"\n')
    r = _ok(tmp_path, "%MPF1\n@a28 K0 @300 R1 K2241 @310 R2 K3041 @320 R3 K0 K2 K3 @320 R4 K0 K2 K0\n"
                      "@330 R5 K2 K2 K0 @337 R6 K0 K3 K1 @437 K0 K3 K1 K0\nM30\n", machine)
    assert [R(r, n) for n in range(1, 7)] == [900.0, 10.0, 1.25, 5.0, 2.0, 45.0]
    machine = MACHINE.replace("channel = 1\n", 'channel = 1\nv24_input = "R10=4.5\\n"\n')
    (tmp_path / "machine.toml").write_text(machine)
    (tmp_path / "p.mpf").write_text("%MPF1\n@a28 K5\nM30\n")
    result, _ = run(tmp_path / "p.mpf", machine=tmp_path / "machine.toml", options=RunOptions(state_dir=tmp_path / "t"))
    assert result["error"]["code"] == "CL800" and "not NC machine data" in result["error"]["message"]


def test_outp_data_then_inp_on_another_nc(tmp_path):
    """What OUTP DATA writes, INP reads back: NC MD 2241 and 5002 of one NC loaded into another."""
    out = _ok(tmp_path, "%MPF1\n@a20 K1 @a26 K5 K2000 K5999\nM30\n")["variables"]["V24"][1:]
    assert out == ["MD2241=1200", "MD5002=100000", "MD5010=1"]
    tape = "\\n".join(out)
    other = '[[axis]]\nname = "X"\n[sin800]\nv24_input = "' + tape + '"\n'
    (tmp_path / "other").mkdir()
    r = _ok(tmp_path / "other", "%MPF1\n@a28 K5 @300 R1 K2241 @301 R2 K5002\nM30\n", other)
    assert (R(r, 1), R(r, 2)) == (1200.0, 100000.0)


def test_outp_data_subroutines(tmp_path):
    """OUTP DATA(2, 10, 20) outputs the subroutines L10 to L20 that exist, in number order."""
    (tmp_path / "L12.spf").write_text("%SPF12\nR1=1\nM17\n")
    (tmp_path / "L30.spf").write_text("%SPF30\nM17\n")
    r = _ok(tmp_path, "%MPF1\n@a20 K1 @a26 K2 K10 K20\nM30\n")
    assert r["variables"]["V24"] == ["PORT 1", "%SPF12", "R1=1", "M17"]


def test_programs_found_by_their_header_stay_inside_the_program_folder(tmp_path):
    """A sub-program call and OUTP DATA find programs by their %SPF header among the files of the program
    folders: a link there that leads out of the folder is no program (the host file was run and output)."""
    (tmp_path / "host.spf").write_text("%SPF77\nR1=5\nM17\n")
    work = tmp_path / "work"
    work.mkdir()
    (work / "X.spf").symlink_to(tmp_path / "host.spf")
    (work / "Y.spf").write_text("%SPF78\nR2=6\nM17\n")
    r = _ok(work, "%MPF1\nN10 L78\nN20 @a20 K1 @a26 K2 K70 K80\nM30\n")
    assert (R(r, 1), R(r, 2)) == (0.0, 6.0) and r["variables"]["V24"] == ["PORT 1", "%SPF78", "R2=6", "M17"]
    r = _run(work, "%MPF1\nN10 L77\nM30\n")
    assert r["status"] == "error" and R(r, 1) == 0.0


def test_pcda_write_bit_range(tmp_path):
    """PCDA(...) = value: bit address 4-6 (L3366, L6674)."""
    assert "PCDA bit 3 outside 4-6" in _cl800_error(tmp_path, "%MPF1\n@44b K1 K1 K3 K1\nM30\n")


def test_acg_reads_the_active_g_function_of_a_group(tmp_path):
    """@36b ACG(channel, group) (L2720-2734, groups of §11.5 L7388-7431): the G number active in the
    group; group 0 motion, 2 plane, 5 settable ZO, 8 inch/metric, 10 absolute/incremental."""
    machine = PLAIN + "[offsets]\nG55 = [0.0, 0.0, 0.0]\n"
    r = _ok(tmp_path, "%MPF1\nG71 G1 F100 G18 G55 G91 X1\n@714 @36b R1 K0 K0 @36b R2 K0 K2 @36b R3 K0 K5 @36b R4 K0 K8 "
                      "@36b R5 K1 K10\nG0 G17 G90 X0\n@714 @36b R6 K0 K0 @36b R7 K0 K2 @36b R8 K0 K10\nM30\n", machine)
    assert [R(r, n) for n in range(1, 9)] == [1.0, 18.0, 55.0, 71.0, 91.0, 0.0, 17.0, 90.0]


def test_inch_basic_system_md_bit(tmp_path):
    """MDNBI(5002,4) = 1 "if inch input is selected as basic setting in the NC system" (L2324-2326): the
    program starts in G70; X1 is 1 inch = 25.4 mm from machine zero (ACPM read in G71)."""
    inch = PLAIN.replace('"5002" = "00100000"', '"5002" = "00010000"')
    r = _ok(tmp_path, "%MPF1\n@302 R1 K5002 K4 @36b R2 K0 K8 G0 X1\nG71\n@714 @361 R3 K1\nM30\n", inch)
    assert (R(r, 1), R(r, 2), R(r, 3)) == (1.0, 70.0, pytest.approx(25.4))
    r = _ok(tmp_path, "%MPF1\n@36b R2 K0 K8 G0 X1\nG71\n@714 @361 R3 K1\nM30\n", PLAIN)
    assert (R(r, 2), R(r, 3)) == (71.0, 1.0)


def test_int_sec_result_seen_by_a_test_in_its_own_block(tmp_path):
    """@711 with its destination words, then @141 in the same block (the REPEAT template): the test sees
    this INT SEC's result, so the loop stops at the first element crossed (the second one, from X400)."""
    contour = "L20\nN5 X400 Y50\nN10 X300 Y300\nN15 X100 Y400 M17\n"
    (tmp_path / "L20.spf").write_text(contour)
    r = _ok(tmp_path, "%MPF1\nG0 Y250 X750\nR50=20 R51=50 R52=750 R53=1\n"
                      "N10 @710 R54 R50\n@711 R70 R54 R62 Y250 X0 @141 R70 K1 K-10 R9=R9+1\nM30\n", PLAIN)
    assert R(r, 70) == 1.0 and R(r, 72) == pytest.approx(320.0) and R(r, 54) == 50.0 and R(r, 55) == 400.0
    assert R(r, 9) == 1.0  # the words after the test run once, on the pass that found the point


@pytest.mark.parametrize("target,ok", [(0, True), (98, True), (99, False), (500, False), (900, True), (998, True),
                                       (999, False)])
def test_prep_cyc_result_registers(tmp_path, target, ok):
    """PREP CYC: "Permissible parameter range Rn = R0-R98 and R900-R998" (L4268)."""
    r = _run(tmp_path, f"%MPF1\n@713 R{target}\nM30\n", PLAIN)
    assert (r["status"] == "ok") == ok
    if not ok:
        assert r["error"]["code"] == "CL800" and "PREP CYC output" in r["error"]["message"]
