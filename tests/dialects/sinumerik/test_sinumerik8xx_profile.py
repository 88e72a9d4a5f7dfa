"""The SINUMERIK 810-880 G table (nc/profiles/sinumerik8xx.py, issue 14 §1): the internal G groups of ACG /
@36b (CL 800 planning guide §11.5, L7392-7410); each test names the manual line of what it runs."""

from __future__ import annotations

import pytest
from sin800_helpers import R, machine, run_mpf

from ncvm.nc.profiles.sinumerik8xx import SINUMERIK8XX

LATHE = machine("XZ")


def test_g92_is_the_spindle_speed_limit_under_g96_l7392(tmp_path):
    """G92 (group 6 with G04, G25, G26, G58, G59, G74) limits the spindle speed under G96: at radius 50 mm a
    cutting speed of 180 m/min asks 180000 / (2 pi 50) = 573 rev/min, G92 S500 holds it at 500 (ACSS @364)."""
    r = run_mpf(tmp_path, "%MPF1\nG0 X50\nG92 S500\nG96 S180 M3\n@714\n@364 R2 K0\nM30\n", machine_text=LATHE,
                ok=True)
    assert R(r, 2) == pytest.approx(500.0)
    r = run_mpf(tmp_path, "%MPF1\nG0 X50\nG96 S180 M3\n@714\n@364 R2 K0\nM30\n", machine_text=LATHE, ok=True)
    assert R(r, 2) == pytest.approx(180000.0 / (2 * 3.141592653589793 * 50.0))


def test_g92_with_axis_words_is_not_linuxcnc_set_position_l7392(tmp_path):
    r = run_mpf(tmp_path, "%MPF1\nG0 X50\nG92 X0\nM30\n", machine_text=LATHE)
    assert r["error"]["code"] == "NC009" and r["error"]["line"] == 3
    assert "spindle speed limitation" in r["error"]["message"] and r["position"]["X"] == 50.0


@pytest.mark.parametrize(("g", "words"), [("G10", "polar coordinates at rapid"), ("G12", "polar coordinates"),
                                          ("G74", "reference point"), ("G147", "soft approach"),
                                          ("G51", "scale modification"), ("G63", "tapping")])
def test_functions_ncvm_does_not_run_stop_naming_the_meaning_l7392(tmp_path, g, words):
    r = run_mpf(tmp_path, f"%MPF1\nG0 X0\n{g} X10 F100\nM30\n", machine_text=LATHE)
    assert r["error"]["code"] == "NC004" and r["error"]["line"] == 3
    assert words in r["error"]["message"] and "not supported by ncvm" in r["error"]["message"]
    assert "G10 L2" not in r["error"]["message"]


def test_acg_reads_the_power_on_function_of_groups_ncvm_keeps_no_state_of_l7392(tmp_path):
    """ACG (@36b) of group 7 (G60 G63 G64 G62) and 9 (G80-G89) at power-on: G60 and G80; of group 5 the
    settable zero offset G54; of group 0 after G01 the G01."""
    r = run_mpf(tmp_path, "%MPF1\nG01 X1 F100\n@714\n@36b R1 K0 K7 @36b R2 K0 K9 @36b R3 K0 K5 @36b R4 K0 K0\nM30\n",
                machine_text=LATHE, ok=True)
    assert (R(r, 1), R(r, 2), R(r, 3), R(r, 4)) == (60.0, 80.0, 54.0, 1.0)


def test_every_internal_group_of_the_table_has_its_rows_l7392():
    table = {0: [0, 1, 10, 11, 2, 3, 33, 34, 35, 6, 12, 13, 5, 7], 1: [9], 2: [17, 18, 19, 16], 3: [40, 41, 42],
             4: [53], 5: [54, 55, 56, 57], 6: [4, 25, 26, 58, 59, 92, 74], 7: [60, 63, 64, 62], 8: [70, 71],
             9: list(range(80, 90)), 10: [90, 91, 68], 11: [94, 95, 96, 97],
             12: [147, 247, 347, 148, 248, 348, 48, 110, 111], 13: [50, 51], 14: list(range(150, 160)),
             15: [130, 131], 16: [230, 231], 17: [330, 331], 18: list(range(930, 935))}
    for group, numbers in table.items():
        for g in numbers:
            assert SINUMERIK8XX.group_of(g) == str(group), g


def test_an_address_no_function_reads_stops_the_run_and_check_warns_of_it(tmp_path):
    """Q is no address of the SINUMERIK blocks ncvm runs: NC007 where it stands (after N10 moved), and a
    warning of ``ncvm check`` in the same code; an axis the machine lacks stays the error NC011."""
    from ncvm.api import check

    r = run_mpf(tmp_path, "%MPF1\nN10 G1 X1 F100\nN20 X2 Q7\nN30 M30\n", machine_text=LATHE)
    assert r["error"]["code"] == "NC007" and r["error"]["line"] == 3 and r["position"]["X"] == 1.0
    (tmp_path / "q.mpf").write_text("%MPF1\nN10 G1 X1 F100\nN20 X2 Q7 Y3\nN30 M30\n")
    diags = check(tmp_path / "q.mpf", dialect="sin800", machine=tmp_path / "machine.toml")
    assert sorted((d.code, d.span.line, d.severity) for d in diags) == [("NC007", 3, "warning"),
                                                                        ("NC011", 3, "error")]
