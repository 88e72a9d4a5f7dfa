"""An R value computed beyond the double range is the CL 800 error on the block that computes it (L7079),
wherever the range check sits: on the assignment, or on a later assignment of the same block that the
infinite or NaN value flows into."""

from __future__ import annotations

import pytest
from sin800_helpers import run_mpf

from ncvm.dialects.sinumerik.finite import cannot_overflow, checked
from ncvm.dialects.sinumerik.reader import Arith, Operand

#: R3 = 1e288: R3*R3 is infinity
BIG = "%MPF1\nN10 R1=99999999 R0=0\nN20 R2=R1*R1*R1*R1\nN30 R3=R2*R2*R2*R2*R2*R2*R2*R2*R2\n"


@pytest.mark.parametrize("block", [
    "R4=R3*R3",                      # alone
    "R4=R3*R3 R5=R4+1",              # flows into an assignment that is not checked itself
    "R4=R3*R3 R5=R1/R4",             # as a divisor: 1/inf is 0
    "R4=R3*R3 R5=R4/R0",             # divided by an R parameter (0 here)
    "R4=R3*R3 R4=1",                 # overwritten unread
    "R4=R3*R3 R5=R4*R1 R4=1",        # flows into a checked assignment
    "R4=R3*R3 @610 R5 R4",           # read by an @ code
    "R4=R3*R3 X=R4",                 # read by a DIN word
    "R4=R3*R3 R5=R4-R4",             # inf - inf is NaN
    "R4=-R3*R3*R3",                  # a negative overflow
    "R4=R3*R3 R5=R4*0",              # inf * 0 is NaN
])
def test_the_overflowing_block_stops_with_the_cl800_error(tmp_path, block):
    r = run_mpf(tmp_path, BIG + f"N40 {block}\nN50 G1 X=R4 Y=R5 F100\nM30\n")
    assert r["status"] == "error" and r["error"]["code"] == "CL800", r["error"]
    assert r["error"]["line"] == 5
    assert r["motion"]["feed_moves"] == 0


def test_scaled_and_shifted_values_stay_in_range(tmp_path):
    """The assignments that need no check: the largest values scaled down or shifted a little."""
    r = run_mpf(tmp_path, "%MPF1\nN10 R1=99999999 R2=R1*R1*R1*R1\nN20 R3=R2*R2*R2*R2*R2*R2*R2*R2*R2*R1*R1\n"
                          "N30 R4=R3*0.5 R5=R3/7 R6=R3+1 R7=1-R3 R8=-R3\nM30\n", ok=True)
    assert r["status"] == "ok"


def _a(target: int, *terms: tuple[str, str, float]) -> Arith:
    return Arith(target, [(op, Operand(kind, value)) for op, kind, value in terms], 1)


@pytest.mark.parametrize("terms, safe", [
    ([("", "R", 1)], True),
    ([("", "R", 1), ("*", "K", 0.5)], True),
    ([("", "K", -1), ("*", "R", 1)], True),
    ([("", "R", 1), ("*", "K", 1.5)], False),
    ([("", "R", 1), ("/", "K", 7)], True),
    ([("", "R", 1), ("/", "K", 0.5)], False),
    ([("", "K", 7), ("/", "R", 1)], False),
    ([("", "R", 1), ("+", "K", 1e15)], True),
    ([("", "R", 1), ("-", "K", 1e300)], False),
    ([("", "R", 1), ("+", "R", 2)], False),
    ([("-", "R", 1), ("*", "K", 0.5)], False),
    ([("", "P", 1), ("*", "K", 0.5)], False),
    ([("", "R", 1), ("*", "K", 0.5), ("*", "K", 0.5)], False),
])
def test_cannot_overflow(terms, safe):
    assert cannot_overflow([(op, Operand(kind, value)) for op, kind, value in terms]) is safe


def test_a_value_flowing_into_a_checked_assignment_is_checked_there():
    run = [_a(90, ("", "R", 6), ("*", "K", 2.5)), _a(2, ("", "R", 2), ("+", "R", 90), ("-", "K", 1.25))]
    assert checked(run) == [False, True]
    run = [_a(90, ("", "R", 6), ("*", "K", 2.5)), _a(2, ("", "R", 2), ("/", "R", 90))]
    assert checked(run) == [True, True]
    run = [_a(90, ("", "R", 6), ("*", "K", 2.5)), _a(2, ("", "R", 90), ("/", "K", 3))]
    assert checked(run) == [True, False]


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
