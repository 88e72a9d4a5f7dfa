"""The R parameter range has a lower end too (L7079: "The value range is from +/- 0.00000001 to +/-
99999999"): a nonzero result below 0.00000001 is stored as the NC holds it, rounded to 8 decimal places
(0 or +/-0.00000001), whether arithmetic, a function or a read produced it; and a value beyond the range is
named in fixed notation, as the control shows numbers (issue 15, CL 800 number ranges)."""

from __future__ import annotations

import pytest
from sin800_helpers import R, run_mpf


@pytest.mark.parametrize("block, expected", [
    ("R1=0.00000001 R2=R1/3", 0.0),          # 3.3e-09: below the smallest magnitude
    ("R1=0.00000001 R2=R1*0.6", 0.00000001),  # 6e-09 rounds to the smallest magnitude
    ("R1=0.00000001 R2=-R1*0.4", 0.0),       # never -0.0 either
    ("R1=0.0001 R2=R1*R1", 0.00000001),      # 1e-08 exactly: kept
    ("R1=0.0001 R3=0.00001 R2=R1*R3", 0.0),  # 1e-09 from two R parameters
    ("R1=1.00000001 R2=R1-1", 0.00000001),   # in range: kept (to within the double's rounding)
    ("@630 R2 K180", 0.0),                   # SIN 180 is 1.2e-16 in doubles (L3779)
    ("@631 R2 K90", 0.0),                    # COS 90
    ("@641 R2 K-30", 0.0),                   # INV LN(-30) = 9.4e-14
])
def test_a_result_below_the_smallest_magnitude_is_what_the_nc_holds_L7079(tmp_path, block, expected):
    r = run_mpf(tmp_path, f"%MPF1\nN10 {block}\nN20 M30\n", ok=True)
    assert R(r, 2) == pytest.approx(expected, abs=1e-15)
    assert R(r, 2) == 0.0 or abs(R(r, 2)) >= 0.00000001 * (1 - 1e-9)
    assert str(R(r, 2)) != "-0.0"


def test_the_range_message_shows_the_value_in_fixed_notation_L7079(tmp_path):
    r = run_mpf(tmp_path, "%MPF1\nN10 R1=99999999 R2=R1*100.5\nN20 M30\n")
    assert r["error"]["code"] == "CL800"
    assert "10049999899.5 is outside the R parameter range" in r["error"]["message"]
    assert "e+" not in r["error"]["message"]
