"""An R value computed beyond the R parameter range is the CL 800 error on the block that computes it
(L7079: "The value range is from +/- 0.00000001 to +/- 99999999"), by default and not only under
``strict_nc``: a value beyond it is never stored, and one that leaves the double range (inf, NaN) is no
position or feed either."""

from __future__ import annotations

import pytest
from sin800_helpers import R, run_mpf

from ncvm.dialects.sinumerik.finite import stays_in_range
from ncvm.dialects.sinumerik.reader import Operand

#: R3 = 99999999, the largest R value: R3*R3 and R3+1 leave the range
BIG = "%MPF1\nN10 R1=99999999 R0=0\nN20 R2=1\nN30 R3=R1\n"


@pytest.mark.parametrize("block", [
    "R4=R3*R3",                      # alone
    "R4=R3+1",                       # one more than the largest value
    "R4=-R3-1",                      # one less than the smallest
    "R4=R3*R3 R5=R4+1",              # flows into another assignment
    "R4=R3*R3 R5=R1/R4",             # as a divisor
    "R4=R3*R3 R4=1",                 # overwritten unread
    "R4=R3*R3 R4=R4-R3*R3",          # back in range in the next assignment: stopped all the same
    "R4=R3*R3 @610 R5 R4",           # read by an @ code
    "R4=R3*R3 X=R4",                 # read by a DIN word
    "R4=R3*1.5",                     # scaled up
    "R4=R3/0.5",                     # divided by less than 1
    "R4=R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3",  # inf
    "R4=R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R3*R0",  # NaN
    "@620 R3",                       # INC of the largest value (L6730)
    "R4=-R3 @621 R4",                # DEC of the smallest (L6731)
])
def test_a_value_beyond_the_r_range_stops_with_the_cl800_error_L7079(tmp_path, block):
    r = run_mpf(tmp_path, BIG + f"N40 {block}\nN50 G1 X=R4 Y=R5 F100\nM30\n")
    assert r["status"] == "error" and r["error"]["code"] == "CL800", r["error"]
    assert "outside the R parameter range +/-99999999" in r["error"]["message"]
    assert r["error"]["line"] == 5
    assert r["motion"]["feed_moves"] == 0
    assert abs(R(r, 4)) <= 99999999 and abs(R(r, 3)) <= 99999999


def test_values_at_the_edges_of_the_range_are_stored_L7079(tmp_path):
    r = run_mpf(tmp_path, BIG + "N40 R4=R3*0.5 R5=R3/7 R6=R3-1 R7=1-R3 R8=-R3 R9=R3+R2-1 R10=R3*R2 R11=R1\n"
                                "N50 @621 R6 @620 R7\nM30\n", ok=True)
    assert [R(r, n) for n in (4, 6, 7, 8, 9, 10, 11)] == [49999999.5, 99999997.0, -99999997.0, -99999999.0,
                                                          99999999.0, 99999999.0, 99999999.0]


def test_without_strict_nc_values_keep_their_digits(tmp_path):
    """The range check does not round: strict_nc (8 significant digits, decisions.md) stays an option."""
    r = run_mpf(tmp_path, "%MPF1\nN10 R1=1 R2=R1/3\nM30\n", ok=True)
    assert R(r, 2) == 1 / 3


@pytest.mark.parametrize("terms, safe", [
    ([("", "R", 1)], True),
    ([("", "K", 99999999)], True),
    ([("", "K", 100000000)], False),
    ([("-", "R", 1)], True),
    ([("", "P", 1)], True),
    ([("", "R", 1), ("*", "K", 0.5)], True),
    ([("", "K", -1), ("*", "R", 1)], True),
    ([("", "R", 1), ("*", "K", 1.5)], False),
    ([("", "R", 1), ("/", "K", 7)], True),
    ([("", "R", 1), ("/", "K", 0.5)], False),
    ([("", "K", 7), ("/", "R", 1)], False),
    ([("", "R", 1), ("+", "K", 1)], False),
    ([("", "R", 1), ("+", "K", 0)], True),
    ([("", "R", 1), ("+", "R", 2)], False),
    ([("", "R", 1), ("*", "K", 0.5), ("*", "K", 0.5)], False),
])
def test_stays_in_range(terms, safe):
    assert stays_in_range([(op, Operand(kind, value)) for op, kind, value in terms]) is safe


@pytest.mark.parametrize(("block", "message"), [
    ("R1=89.9999999 @632 R2 R1", "TAN(89.9999999) is not defined"),   # L3821: 0 to +/-89.999999
    ("@632 R2 K-270.00001", "TAN(-270.00001) is not defined"),       # L3821: +/-270.0001 to +/-360
    ("@632 R2 K400", "TAN(400) is not defined"),
    ("@641 R2 K100", "INV LN(100): the result is outside the R parameter range +/-99999999"),  # L7079
    ("@641 R2 K18.5", "INV LN(18.5): the result is outside the R parameter range +/-99999999"),
    ("@614 R2 K80000000 K80000000", "outside the R parameter range +/-99999999"),  # SQRTS: 1.13e8
    ("@630 R2 K361", "SIN(361): the angle must lie between -360 and +360 degrees"),  # L3779
    ("R1=-720 @631 R2 R1", "COS(-720): the angle must lie between -360 and +360 degrees"),  # L3800
])
def test_function_results_and_angles_beyond_the_manual_ranges_are_the_cl800_error(tmp_path, block, message):
    """L7077-7080: an R value lies within +/-99999999; L3779/L3800/L3821: the angle ranges of SIN, COS, TAN.
    A result or an argument beyond them stops the run with the CL 800 error instead of being stored."""
    result = run_mpf(tmp_path, f"%MPF1\nN10 {block}\nN20 M30\n")
    assert result["error"]["code"] == "CL800" and message in result["error"]["message"], result["error"]
    assert result["error"]["line"] == 2 and result["variables"].get("R2", 0.0) == 0.0


def test_function_results_at_the_edges_of_the_manual_ranges(tmp_path):
    """TAN(89.999999) = 57295779.5, INV LN(18.42) = 99931948.8, SIN(-360), COS(360): all within range."""
    result = run_mpf(tmp_path, "%MPF1\n@632 R1 K89.999999 @641 R2 K18.42 @630 R3 K-360 @631 R4 K360 "
                               "@632 R5 K90.00001\nM30\n", ok=True)
    v = result["variables"]
    assert v["R1"] == pytest.approx(57295779.5, rel=1e-7) and v["R2"] == pytest.approx(99931948.77, rel=1e-8)
    assert v["R3"] == pytest.approx(0.0, abs=1e-12) and v["R4"] == 1.0
    assert v["R5"] == pytest.approx(-5729577.9, rel=1e-6)


def test_a_machine_file_r_value_beyond_the_range_is_refused_L7079(tmp_path):
    """R parameters the run starts with (machine file ``r``) lie in the range as well: a usage error, with
    or without strict_nc (before, 123456789012 was loaded and read on silently)."""
    from ncvm.diagnostics import UsageError

    with pytest.raises(UsageError, match=r"R5: .* outside the R parameter range \+/-99999999"):
        run_mpf(tmp_path, "%MPF1\nN10 R6=R5\nM30\n", "r = {R5 = 123456789012.0}\n")


def test_cl800_arithmetic_beyond_the_range_stops_at_the_source_line_L7079(tmp_path):
    """A CL 800 assignment compiles to R arithmetic: the same check, reported at the .cl8 statement."""
    from ncvm.api import run
    from ncvm.runtime.session import RunOptions

    (tmp_path / "machine.toml").write_text('[[axis]]\nname = "X"\n[[axis]]\nname = "Y"\n[[axis]]\nname = "Z"\n')
    (tmp_path / "p.cl8").write_text("PROGRAM 204;\nCHANNEL NC 1;\nLOCAL REAL: R60, R61;\nBEGIN\n  R61 = 20000;\n"
                                    "  R60 = R61 * R61;\n  (:G1 F100:); PRAP (1)=R60; LF;\nEND.\n")
    r, _ = run(tmp_path / "p.cl8", machine=tmp_path / "machine.toml", options=RunOptions(state_dir=tmp_path / ".s"))
    assert r["error"]["code"] == "CL800" and r["error"]["file"].endswith("p.cl8") and r["error"]["line"] == 6
    assert r["motion"]["feed_moves"] == 0


@pytest.mark.parametrize("words, read, expected", [
    ([32767, 65535], "@3b0 R2 K1 K10 K0 K2 K0", 99999999.0),     # PLCDF of 2 DW: 2147483647
    ([32768, 0], "@3b0 R2 K1 K10 K0 K2 K0", -99999999.0),        # -2147483648
    ([32639, 65535], "@3b2 R2 K1 K10 K0", 99999999.0),           # a PLC float of 3.4e38
    ([0x1234, 0x5678, 0x9012], "@3b1 R2 K1 K10 K0 K3 K100", 99999999.0),  # 12 BCD digits
])
def test_a_plc_value_beyond_the_r_range_enters_the_maximum_and_goes_on_L727(tmp_path, words, read, expected):
    """L727: "An overflow PLC ==> NC at reading causes the maximum value to be entered into the R parameter
    and an NC alarm issued, which does not interrupt the program." Before, the value was stored as read."""
    plc = f'[sin800.plc.1]\nDB = {{ "10" = {words} }}\n'
    r = run_mpf(tmp_path, f"%MPF1\nN10 {read}\nN20 R3=1\nM30\n", plc, ok=True)
    assert R(r, 2) == expected and R(r, 3) == 1.0
    assert len(r["output"]) == 1 and r["output"][0].startswith(f"NC alarm: @{read[1:4]} read ")
