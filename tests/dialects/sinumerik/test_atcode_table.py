"""Every @ code of the table (CL 800 manual §10, L6332-6824) runs on a SINUMERIK 880 with data for it."""

from __future__ import annotations

from pathlib import Path

import pytest
from sin800_helpers import machine, run_mpf

from ncvm.dialects.sinumerik.atcodes import AT_CODES

MACHINE = """nc_md = { "100" = 3, "5001" = "00010010" }
cycle_md = { "10" = 4, "800" = "101" }
plc_md = { "100" = 5, "6000" = "11" }
drive_md = { "100" = 258, "2440" = 513 }
nc_sd = { "100" = 6, "5000" = "1" }
cycle_sd = { "10" = 7, "800" = "10" }
tool_offsets = [ { d = 1, p = [1, 20, 50.0] } ]
alarms = [3004]
[sin800.plc.1]
I = { "0" = "101", "1" = "0" }
Q = { "0" = "11", "1" = "0" }
P = { "0" = "1", "1" = "0" }
F = { "0" = "0", "1" = "0", "2" = "0" }
DB = { "10" = [1234, 18, 4660, 22136] }
T = { "3" = 1.5 }
C = { "4" = 9 }
[[scenario]]
time = 0.0
kind = "probe"
input = 1
position = { X = 1.0 }
[[scenario]]
time = 0.0
kind = "input"
byte = 1
bit = 0
value = 1
"""

#: operands for every non-branching code: enough to run it once on the machine above
SAMPLES = {
    "00f": "", "040": "K2 R50 R51", "042": "K2 R50 R51", "041": "R52 R53", "043": "R52 R53",
    "200": "R10", "201": "R10 K2", "202": "R10 R11", "203": "R10 R12 K1", "210": "K0 K4", "211": "R10 K1",
    "212": "K1 K9",
    "300": "R10 K100", "301": "R10 K5001", "302": "R10 K5001 K1", "303": "R10 K0 K10", "304": "R10 K0 K800",
    "305": "R10 K0 K800 K0", "306": "R10 K100", "307": "R10 K6000", "308": "R10 K6000 K1", "309": "R10 K100",
    "30a": "R10 K2440 K1", "30b": "R10 K2440 K0 K0", "310": "R10 K100", "311": "R10 K5000", "312": "R10 K5000 K0",
    "313": "R10 K0 K10", "314": "R10 K0 K800", "315": "R10 K0 K800 K1", "320": "R10 K0 K1 K2",
    "330": "R10 K1 K1 K0", "331": "R10 K1 K1", "332": "R10 K1", "333": "R10 K1", "334": "R10 K1", "336": "R10 K3",
    "337": "R10 K0 K1 K1", "338": "R10 K0 K1 K1", "342": "R10 K0 K0", "345": "R10 K0 K0", "34b": "R10 K1 K0 K4",
    "34c": "R10 K1 K0 K0", "360": "R10 K1", "361": "R10 K1", "362": "R10 K1", "363": "R10 K0", "364": "R10 K0",
    "367": "R10 K0", "36a": "R10 K0", "36b": "R10 K0 K0", "371": "R10 K0 K1", "372": "R10",
    "380": "R10 K1 K0 K0", "381": "R10 K1 K0 K1", "382": "R10 K1 K0 K0", "383": "R10 K1 K10 K0 K1",
    "390": "R10 K1 K0", "391": "R10 K1 K0", "392": "R10 K1 K0", "393": "R10 K1 K0", "394": "R10 K1 K10 K0",
    "395": "R10 K1 K10 K0", "3a0": "R10 K1 K0 K0", "3a1": "R10 K1 K0 K0", "3a2": "R10 K1 K0 K0",
    "3a3": "R10 K1 K0 K0", "3a4": "R10 K1 K3", "3a5": "R10 K1 K4", "3b0": "R10 K1 K10 K0 K2 K0",
    "3b1": "R10 K1 K10 K2 K2 K100", "3b2": "R10 K1 K10 K0", "3c0": "R10", "3d0": "R10",
    "3e1": "R10 K1 K0 K0", "3e2": "R10 K1 K0 K0", "3e3": "R10 K1 K0 K0", "3e4": "R10 K0",
    "400": "K100 K4", "401": "K5001 K11", "402": "K5001 K0 K1", "403": "K0 K10 K5", "404": "K0 K800 K1",
    "405": "K0 K800 K1 K1", "406": "K100 K6", "407": "K6000 K1", "408": "K6000 K0 K0", "409": "K100 K2",
    "40a": "K2440 K0 K11", "40b": "K2440 K0 K2 K1", "410": "K100 K2", "411": "K5000 K11", "412": "K5000 K1 K1",
    "413": "K0 K10 K1", "414": "K0 K800 K1", "415": "K0 K800 K0 K1", "420": "K0 K1 K5 K0.5",
    "423": "K0 K1 K5 K0.25", "430": "K1 K1 K0 K1", "431": "K1 K1 K1 K0.5", "432": "K1 K1 K0", "434": "K1 K0",
    "435": "K1 K0", "437": "K0 K1 K1 K10", "438": "K0 K1 K1 K5", "439": "K0 K1 K1 K3", "43a": "K0 K1 K1 K1",
    "440": "K1 K5", "442": "K0 K1000", "446": "K10", "448": "K1 K0", "44b": "K1 K0 K4 K1",
    "44c": "K1 K0 K0 K1", "482": "K1 K0 K1 K1", "483": "K1 K10 K1 K0 K1", "493": "K1 K1 K11",
    "494": "K1 K10 K1 K1", "495": "K1 K10 K1 K10", "4a3": "K1 K1 K3 K12.5", "4b0": "K1 K10 K0 K2 K0 K-5",
    "4b1": "K1 K10 K0 K2 K100 K1234", "4b2": "K1 K10 K2 K1.5", "4c0": "K5001", "4e1": "K0 K1 K100",
    "610": "R10 K-3", "613": "R10 K4", "614": "R10 K3 K4", "620": "R10", "621": "R10", "622": "R10",
    "630": "R10 K30", "631": "R10 K60", "632": "R10 K45", "634": "R10 K1", "637": "R10 K1 K1", "640": "R10 K1",
    "641": "R10 K0", "650": "R10 R12 K1", "651": "R10 R12 K1", "652": "R10 R12 K1", "653": "R10 R12 K1",
    "654": "R10 K1", "655": "R10 R13 K0", "656": "R10 R13 K0", "657": "R10 R13 K0", "658": "R10 R13 K0",
    "659": "R10 K0", "660": "R10 K0", "661": "R10 K0", **{f"67{x}": "R10 R13 K1" for x in "0123456"},
    "706": "", "710": "R60 R70", "711": "R80 R60 R90 X1 Y1", "713": "R10", "714": "", "715": "",
    "720": "R10 K1 X5", "730": "K1 K0", "736": "K0 K1 K0",
    "a15": "K0 K1", "a1b": "", "a20": "K1", "a25": "K0", "a26": "K1 K1 K2", "a27": "K0 K1 K2", "a28": "K0",
    "a29": "", "a40": "K1",
}


#: drive machine data exist on the 810/820 only (ch.6 table L4826-4828)
DRIVE_MD = ("309", "30a", "30b", "409", "40a", "40b")


def _write(tmp_path: Path, text: str, files: dict | None = None, control: str = "880") -> dict:
    """``MACHINE`` holds the [sin800] data after the control line and the sections that follow it."""
    return run_mpf(tmp_path, text, machine_text=machine(control=control, extra=MACHINE), name="p.mpf",
                   files=files, state=".s")


def test_every_code_has_a_sample():
    branching = {c for c in AT_CODES if c[0] == "1"}
    assert set(SAMPLES) | branching | {"447"} == set(AT_CODES)


def test_pang_without_a_plane_axis_is_a_cl800_error(tmp_path):
    # the angle completes a straight line only with exactly one axis of the plane (tests/.../test_rotation.py)
    result = _write(tmp_path, "%MPF1\n@401 K5001 K11\n@447 K30\nM30\n")  # MDNBY(5001) = 11: address A
    assert result["error"]["code"] == "CL800" and "exactly one of the axes X, Y" in result["error"]["message"]
    assert result["error"]["line"] == 3


def test_pang_needs_a_known_angle_address(tmp_path):
    result = _write(tmp_path, "%MPF1\n@447 K30 X5\nM30\n")  # this machine file sets MD byte 5001 = 00010010
    assert result["error"]["code"] == "CL800" and "5001 = 10010" in result["error"]["message"]


@pytest.mark.parametrize("code", sorted(SAMPLES))
def test_code_runs(tmp_path, code):
    prelude = "R12=101 R13=1 R70=20 R71=0 R72=0 R73=1\n"
    body = f"@{code} {SAMPLES[code]}".rstrip()
    if code in ("042", "043"):
        body = f"@{'040' if code == '042' else '041'} {SAMPLES[code]}\n" + body
    if code == "446":  # the programmed radius of a circle: a radius on a straight block is refused (NC009)
        body += " G2 X20 Y0"
    result = _write(tmp_path, f"%MPF1\n{prelude}G1 F100\n{body}\nM30\n", {"L20.spf": "%SPF20\nX10 Y0\nX0 Y10 M17\n"},
                    "810" if code in DRIVE_MD else "880")
    assert result["status"] == "ok", result["error"]


@pytest.mark.parametrize("code", sorted(c for c in AT_CODES if c[0] == "1" and c not in ("100", "111")))
def test_branch_code_falls_through_or_jumps(tmp_path, code):
    # R1 = 1, compared with K1: =, >=, <= hold (fall through); <>, >, < jump. FOR TO exits when R1 > 1 ...
    holds = {"1": True, "2": False, "3": False, "4": True, "5": False, "6": True}
    if code[1] in "234":
        expect_jump = not holds[code[2]]
        ops = "R1 K1"
    elif code in ("151", "161"):
        expect_jump = False
        ops = "R1 K1"
    else:  # external input 1.0 is 1 (scenario at t = 0)
        expect_jump = code in ("188", "198")
        ops = "K1 K0"
    result = _write(tmp_path, f"%MPF1\nR1=1\n@{code} {ops} K20 R2=1\nN20 M30\n")
    assert result["status"] == "ok", result["error"]
    assert result["variables"].get("R2", 0.0) == (0.0 if expect_jump else 1.0)


def test_sample_values(tmp_path):
    text = ("%MPF1\n@302 R20 K5001 K1 @3b0 R22 K1 K10 K2 K2 K0 @3b1 R23 K1 K10 K1 K1 K100\n"
            "@394 R24 K1 K10 K2 @395 R25 K1 K10 K2 @3a4 R26 K1 K3 @3a5 R27 K1 K4 @3c0 R28 @307 R29 K6000\n"
            "@4b0 K1 K10 K0 K2 K3 K-12.5 @3b0 R30 K1 K10 K0 K2 K3 @4b2 K1 K10 K2 K1.5 @3b2 R31 K1 K10 K2\n"
            "M30\n")
    r = _write(tmp_path, text)["variables"]
    assert r["R20"] == 1.0  # bit 1 of 00010010
    # DW2 high, DW3 low: 0x12345678 = 305419896 lies beyond the R range, the maximum is entered (L727)
    assert r["R22"] == 99999999.0
    assert r["R23"] == 12.0  # DW1 = 0x0012 read as BCD
    assert r["R24"] == 10010.0 and r["R25"] == 110100.0  # 0x1234: left 0x12, right 0x34
    assert r["R26"] == 1.5 and r["R27"] == 9.0 and r["R28"] == pytest.approx(3004.01) and r["R29"] == 11.0
    assert r["R30"] == -12.5 and r["R31"] == 1.5


def test_drive_md_bytes(tmp_path):
    r = _write(tmp_path, "%MPF1\n@30a R3 K2440 K1 @40b K2440 K0 K2 K1 @40a K2440 K1 K11 @309 R1 K2440 "
                         "@30b R2 K2440 K0 K2\nM30\n", control="810")
    assert r["variables"]["R3"] == 10.0  # high byte of 513 = 00000010
    assert r["variables"]["R1"] == 3 * 256 + 5 and r["variables"]["R2"] == 1.0  # 513 = 0x0201 -> 0x0305
