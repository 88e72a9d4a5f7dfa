"""The manual's command reference examples (§6.6: loops, jog and home, path moves, spooler, stops, zero
points, common buffer, task control, WRITE, WT) and homing searches in progress (ncvm's reading; the rw_SymPas manual is silent).
Each test runs the manual's own lines (cited by line of the German manual). Where a fragment is
not a whole program, it is completed into one: the completion is named in the test. Expected
values are the manual's, or computed by hand in the test (CLOCK ticks of 64 us, 15625 per second).
"""

from __future__ import annotations

import math

import pytest
from sympas_examples import SEC, axes_toml, errors_of, prog

# --- §6.6: command reference examples -------------------------------------------------------------


def test_cl_ol_examples_L1679_L1994(sap):
    # L1994 OL(A1, A2) opens the loops; L1679 CL(A1, A2) closes them again (axstb.3 = loop closed)
    r = sap(prog("OL(A1, A2); o1 := A1.axstb.3; o2 := A2.axstb.3; o3 := A3.axstb.3;"
                 "CL(A1, A2); c1 := A1.axstb.3; c2 := A2.axstb.3;",
                 "var o1, o2, o3, c1, c2: boolean;"))
    assert r["variables"] == {"o1": False, "o2": False, "o3": True, "c1": True, "c2": True}


def test_clv_then_js_example_L1686(sap):
    # L1686: clv (A1, A2); js (A1, A2); closes the loops of channels 1 and 2, then stops them at once
    r = sap(prog("OL(A1, A2);\nclv (A1, A2);\njs (A1, A2);\nc1 := A1.axstb.3; c2 := A2.axstb.3; x := A1.dp;",
                 "var c1, c2: boolean; x: double;"))
    assert r["status"] == "ok", r["error"]
    assert r["variables"] == {"c1": True, "c2": True, "x": 0.0}


def test_contcnct_with_constant_L1693(sap):
    # L1693: CONTCNCT(TASK0) with `const TASK0 = 0` and CONTCNCT(1). Completion: task 1 stops itself
    # with STOP, task 0 continues it through the constant-free form; task 0 is the caller itself,
    # so CONTCNCT(TASK0) has no effect on it (it is running).
    text = """{$TASK 0}
program Main;
const
    TASK0 = 0;
var n: integer;
begin
  STARTCNCT(1);
  WT(100);
  n := CI4;
  CONTCNCT(TASK0);
  CONTCNCT(1);
  WT(100);
  writeln('n=', n, ' CI4=', CI4);
end.
{$TASK 1}
program Worker;
begin
  CI4 := 1;
  STOP;
  CI4 := 2;
end.
"""
    r = sap(text)
    assert r["status"] == "ok", r["error"]
    assert r["output"] == ["n=1 CI4=2"]


JOG = "A1.jvl := 100.0; A1.jac := 1000.0; A2.jvl := 100.0; A2.jac := 1000.0;"


def test_ja_both_axes_example_L1739(sap):
    # L1739: JA(A1:=100.0, A2:=100.0); each axis jogs on its own profile: 100 mm at 100 mm/s with
    # 1000 mm/s^2 takes 1.0 + 0.1 s; after 0.5 s (7812 ticks) an axis is at 5 + 0.4 * 100 = 45 mm
    r = sap(prog(JOG + "\nJA(A1:=100.0, A2:=100.0);\nWT(7812);\nx := A1.dp; y := A2.dp;", "var x, y: double;"))
    assert r["status"] == "ok", r["error"]
    assert r["variables"]["x"] == pytest.approx(45.0, abs=0.2)
    assert r["variables"]["y"] == pytest.approx(45.0, abs=0.2)
    assert r["position"]["A1"] == 100.0 and r["position"]["A2"] == 100.0


def test_ja_examples_back_to_back_L1739(sap):
    """Jog (ncvm's reading; the manual is silent): a new JA on a jogging axis re-targets it on the fly, and A2 starts too."""
    # L1739 lists JA(A1:=100.0); then JA(A1:=100.0, A2:=100.0); run one after the other, the second
    # re-targets the jogging A1 (to the same 100) and starts A2 two ticks later
    r = sap(prog(JOG + "\nJA(A1:=100.0);\nJA(A1:=100.0, A2:=100.0);\nWT(7812);\nx := A1.dp; y := A2.dp;",
                 "var x, y: double;"))
    assert r["status"] == "ok", r["error"]
    assert r["variables"]["x"] == pytest.approx(45.0, abs=0.2)
    assert r["variables"]["y"] == pytest.approx(45.0, abs=0.2)
    assert r["position"]["A1"] == 100.0 and r["position"]["A2"] == 100.0


def test_ja_examples_back_to_back_with_busy_move_override_L1739(sap):
    # the same two JAs on a card configured with busy_move = "override": the second takes over A1
    r = sap(prog(JOG + "\nJA(A1:=100.0);\nJA(A1:=100.0, A2:=100.0);\nWT(7812);\nx := A1.dp; y := A2.dp;",
                 "var x, y: double;"), machine_toml='\n[sympas]\nbusy_move = "override"\n')
    assert r["status"] == "ok", r["error"]
    assert r["variables"]["x"] == pytest.approx(45.0, abs=0.2)
    assert r["variables"]["y"] == pytest.approx(45.0, abs=0.2)


def test_jaw_examples_L1749(sap_on):
    # L1749: JAW(A2:=-1000.0); JAW(A1:=1e3, A2 := 1.3e4); on a machine of +-20000 mm
    text = prog("A1.jvl := 1000.0; A2.jvl := 1000.0;\nJAW(A2:=-1000.0);\ny1 := A2.dp;\nJAW(A1:=1e3, A2 := 1.3e4);"
                "\nx := A1.dp; y := A2.dp;", "var x, y, y1: double;")
    r = sap_on(text, axes_toml(3, limit=20000.0))
    assert r["status"] == "ok", r["error"]
    assert r["variables"] == {"y1": -1000.0, "x": 1000.0, "y": 13000.0}


def test_jr_with_integer_distance_L1812(sap):
    # L1812: JR(A1 := 100); the integer 100 is widened to the position
    r = sap(prog(JOG + "\nJAW(A1 := 5.0);\nJR(A1 := 100);\nJSW(A2);\nWT(20000);\nx := A1.dp;", "var x: double;"))
    assert r["status"] == "ok", r["error"]
    assert r["variables"]["x"] == 105.0


def test_js_and_jsw_examples_L1828_L1836(sap):
    # L1828 JS(A1), L1836 JSW(A1): a jog at 100 mm/s stopped with sdec = 500 mm/s^2 brakes over
    # 100^2 / (2 * 500) = 10 mm in 0.2 s. JA at 0: 0.1 s accel (5 mm), WT(15625) -> at 1 s: 95 mm.
    text = prog(JOG + "A1.sdec := 500.0;\nJA(A1 := 500.0);\nWT(15625);\nJS(A1);\nmoving := A1.dv;\nJSW(A1);"
                "\nx := A1.dp; v := A1.dv;",
                "var x, v, moving: double;")
    r = sap(text)
    assert r["status"] == "ok", r["error"]
    assert r["variables"]["moving"] == pytest.approx(100.0, abs=2.0)  # JS does not wait
    assert r["variables"]["x"] == pytest.approx(105.0, abs=0.3)
    assert r["variables"]["v"] == 0.0


HOME = """
[sympas]
ref_positions = {A1 = 30.0, A2 = -20.0}
"""


def test_homing_examples_jhl_jhlw_jhr_jhrw_L1776_L1804(sap):
    # L1776 JHL(A1), L1786 JHLW(A2), L1795 JHR(A2), L1804 JHRW(A1). The REF switch of A2 lies at
    # -20 (to the left), of A1 at +30 (to the right). Homing sets the REF point to 0 ([R]).
    # JHL(A1) searches to the left, away from its switch: it must not home A1; JS stops it.
    text = prog("JHL(A1);\nWT(100);\nJSW(A1);\nh1 := A1.axstb.4;\n"
                "JHLW(A2);\ny := A2.dp; h2 := A2.axstb.4;\n"
                "JHR(A2);\nWT(100);\nJSW(A2);\n"
                "JHRW(A1);\nx := A1.dp; h3 := A1.axstb.4; hv := A1.hvl; ha := A1.hac;",
                "var x, y, hv, ha: double; h1, h2, h3: boolean;")
    r = sap(text, machine_toml=HOME)
    assert r["status"] == "ok", r["error"]
    v = r["variables"]
    assert (v["h1"], v["h2"], v["h3"]) == (False, True, True)
    # latched at REF = 0, then braked with hac: the axes stop hvl^2 / (2 hac) behind it (ncvm's reading; the rw_SymPas manual is silent)
    overrun = round(v["hv"] ** 2 / (2 * v["ha"]), 3)  # the stop rounded to whole counts (L1399)
    assert v["y"] == pytest.approx(-overrun) and v["x"] == pytest.approx(overrun)


def test_jhi_and_jhiw_examples_L1758_L1767(sap):
    # L1758 JHI(A1 := 1.0, A2 := 1.5); L1767 JHIW(A1 := 5.0). With index pulses every 0.4 mm
    # starting from 0.25 mm away, the search finds the pulse within Pos and homes the axis there.
    machine = "[sympas]\nindex_period = 0.4\n"
    text = prog("JAW(A1 := 0.25, A2 := 0.25);\nJHI(A1 := 1.0, A2 := 1.5);\nWT(15625);\n"
                "h1 := A1.axstb.4; h2 := A2.axstb.4; x := A1.dp;\nJAW(A1 := 0.25);\nJHIW(A1 := 5.0);\nh3 := A1.axstb.4;",
                "var h1, h2, h3: boolean; x: double;")
    r = sap(text, machine_toml=machine)
    assert r["status"] == "ok", r["error"]
    v = r["variables"]
    assert (v["h1"], v["h2"], v["h3"]) == (True, True, True)


def test_spooled_circle_after_mca_L1866(sap):
    # L1866: MCA(A1 := 50.0, A2 := 0.0, PHI := 720.0); SMCA(A1 := 0.0, A2 := 10.0, PHI := 0.1);
    # Completion: SSMSW starts the spooled arc after the circle. The MCA ends back at (0, 0); SMCA
    # turns (0, -10) about its centre (0, 10) by 0.1 deg: (10 sin 0.1deg, 10 - 10 cos 0.1deg).
    r = sap(prog("MCA(A1 := 50.0, A2 := 0.0, PHI := 720.0);\nSMCA(A1 := 0.0, A2 := 10.0, PHI := 0.1);\n"
                 "SSMSW(A1, A2);\nx := A1.dp; y := A2.dp;", "var x, y: double;"))
    assert r["status"] == "ok", r["error"]
    a = math.radians(0.1)
    assert r["variables"]["x"] == pytest.approx(10 * math.sin(a), abs=1e-3)
    assert r["variables"]["y"] == pytest.approx(10 - 10 * math.cos(a), abs=1e-3)
    assert r["motion"]["arc_moves"] == 2


def test_helix_then_spooled_helix_examples_L1921(sap):
    # L1921: MHA(A1 := 50.0, A2 := 0.0, PHI := 720.0, A3 := 10); SMHA(A1 := 0.0, A2 := 10.0, PHI := 0.1,
    # A3 := 10); completion: SSMSW. MHA ends at (0, 0, 10); SMHA turns (0, -10) about (0, 10) by
    # 0.1 deg with A3 staying at 10: (10 sin 0.1deg, 10 - 10 cos 0.1deg, 10)
    r = sap(prog("MHA(A1 := 50.0, A2 := 0.0, PHI := 720.0, A3 := 10);\n"
                 "SMHA(A1 := 0.0, A2 := 10.0, PHI := 0.1, A3 := 10);\nSSMSW(A1, A2, A3);\n"
                 "x := A1.dp; y := A2.dp; z := A3.dp;", "var x, y, z: double;"))
    assert r["status"] == "ok", r["error"]
    a = math.radians(0.1)
    v = r["variables"]
    assert (v["x"], v["y"], v["z"]) == pytest.approx((10 * math.sin(a), 10 - 10 * math.cos(a), 10.0), abs=1e-3)
    assert r["motion"]["arc_moves"] == 2


@pytest.mark.parametrize("cmd", ["MCA3D", "MCR3D"])
def test_3d_circle_examples_as_printed_L1880_L1894(sap, cmd):
    # L1880/L1894 verbatim (note `PN1 = 1.0` with '='): from (0,0,0) about the centre (50,0,0),
    # normal (1,0,1)/sqrt2, 720 deg. The start lies off the plane through the centre, so the circle
    # runs in the parallel plane through the start ([R]): its centre is (25,0,-25), its radius
    # |(-25,0,25)| = 25 sqrt2. Two turns end at the start; X spans 25 +- 25, Z -25 +- 25.
    r = sap(prog(f"{cmd}(A1 := 50.0, A2 := 0.0, A3 := 0.0, PN1 = 1.0, PN2 = 0.0, PN3 = 1.0, PHI := 720.0);"))
    assert r["status"] == "ok", r["error"]
    radius = 25 * math.sqrt(2)
    assert r["position"] == pytest.approx({"A1": 0.0, "A2": 0.0, "A3": 0.0}, abs=1e-3)
    assert r["motion"]["feed_length"] == pytest.approx(2 * 2 * math.pi * radius, rel=2e-3)
    assert r["motion"]["bounds"]["A1"] == pytest.approx([0.0, 50.0], abs=0.05)
    assert r["motion"]["bounds"]["A2"] == pytest.approx([-radius, radius], abs=0.05)
    assert r["motion"]["bounds"]["A3"] == pytest.approx([-50.0, 0.0], abs=0.05)


def test_mcr_then_smcr_examples_L1908(sap):
    # L1908: MCR(A1 := 50.0, A2 := 0.0, PHI := 360.0); SMCR(A1 := 0.0, A2 := 10.0, PHI := 45.0);
    # the full circle about (50, 0) ends at (0, 0); the spooled arc about (0, 10) turns (0, -10) by
    # 45 deg counter-clockwise: (10 sin 45, 10 - 10 cos 45) = (7.0711, 2.9289). Completion: SSMSW.
    r = sap(prog("MCR(A1 := 50.0, A2 := 0.0, PHI := 360.0); SMCR(A1 := 0.0, A2 := 10.0, PHI := 45.0);\n"
                 "SSMSW(A1, A2);\nx := A1.dp; y := A2.dp;", "var x, y: double;"))
    assert r["status"] == "ok", r["error"]
    h = 10 * math.sqrt(0.5)
    assert (r["variables"]["x"], r["variables"]["y"]) == pytest.approx((h, 10 - h), abs=1e-3)
    assert r["motion"]["feed_length"] == pytest.approx(2 * math.pi * 50 + math.pi / 4 * 10, rel=1e-4)


def test_mla_then_smla_example_L1947(sap):
    # L1947: MLA(A1:=1000.0, A2:=3.2e2); SMLA(A1:=100.0, A2:=-335.0); completion: SSMSW
    r = sap(prog("MLA(A1:=1000.0, A2:=3.2e2);\nSMLA(A1:=100.0, A2:=-335.0);\nSSMSW(A1, A2);\nx := A1.dp; y := A2.dp;",
                 "var x, y: double;"))
    assert r["status"] == "ok", r["error"]
    assert (r["variables"]["x"], r["variables"]["y"]) == (100.0, -335.0)
    assert r["motion"]["feed_length"] == pytest.approx(math.hypot(1000, 320) + math.hypot(900, 655))


def test_mlaw_example_L1955(sap):
    # L1955: MLAW(A1:=-0.3e3, A2:=100.4); 316.37 mm at 100 mm/s, 1000 mm/s^2: 3.1637 + 0.1 s
    r = sap(prog("t0 := CLOCK;\nMLAW(A1:=-0.3e3, A2:=100.4);\ndt := CLOCK - t0; x := A1.dp; y := A2.dp;",
                 "var t0: timer; dt: integer; x, y: double;"))
    assert (r["variables"]["x"], r["variables"]["y"]) == (-300.0, 100.4)
    expected = (math.hypot(300, 100.4) / 100 + 0.1) * SEC
    assert expected <= r["variables"]["dt"] <= expected + 25


def test_mlr_smlr_and_mlrw_examples_L1963_L1971(sap_on):
    # L1963: MLR(A1:=2000.0, A2:=3.2e2); SMLR(A1:=300.0, A2:=-35.3); L1971: MLRW(A1:=-3.45e3, A2:=100.4e-1)
    # on a machine of +-20000 mm: 2000 + 300 - 3450 = -1150; 320 - 35.3 + 10.04 = 294.74
    text = prog("MLR(A1:=2000.0, A2:=3.2e2);\nSMLR(A1:=300.0, A2:=-35.3);\nSSMSW(A1, A2);\n"
                "MLRW(A1:=-3.45e3, A2:=100.4e-1);\nx := A1.dp; y := A2.dp;", "var x, y: double;")
    r = sap_on(text, axes_toml(3, limit=20000.0))
    assert r["status"] == "ok", r["error"]
    assert r["variables"]["x"] == pytest.approx(-1150.0)
    assert r["variables"]["y"] == pytest.approx(294.74)


def test_ms_and_msw_examples_L1979_L1987(sap):
    # L1979 MS(A1, A2), L1987 MSW(A1, A2): a path at 100 mm/s is stopped with the group's smallest
    # sdec (MODEREG bit 15 clear): sdec = 500 brakes over 10 mm. At 1 s the path is at 95 mm.
    text = prog("A1.sdec := 500.0; A2.sdec := 2000.0;\nMLA(A1 := 500.0, A2 := 0.0);\nWT(15625);\nMS(A1, A2);"
                "\nmoving := A1.dv;\nMSW(A1, A2);\nx := A1.dp;",
                "var x, moving: double;")
    r = sap(text)
    assert r["status"] == "ok", r["error"]
    assert r["variables"]["moving"] == pytest.approx(100.0, abs=2.0)  # MS does not wait
    assert r["variables"]["x"] == pytest.approx(105.0, abs=0.3)


def test_ra_example_L2009(sap):
    # L2009: RA(A1, A2) resets the axes: the move stops at once, the loops open ([R])
    r = sap(prog("MLA(A1 := 500.0, A2 := 500.0);\nWT(15625);\nRA(A1, A2);\nx := A1.dp; WT(1000); x2 := A1.dp;"
                 "c := A1.axstb.3;",
                 "var x, x2: double; c: boolean;"))
    assert r["status"] == "ok", r["error"]
    assert r["variables"]["x2"] == r["variables"]["x"]
    assert r["variables"]["x"] < 100.0
    assert r["variables"]["c"] is False


def test_common_buffer_examples_at_offset_500_L2025_L2033_L2196_L2203(sap):
    # L2196 WRCBI(500, -1000), L2025 cbi := RDCBI(500); L2203 WRCBS(500, 3.99), L2033 cbs := RDCBS(500)
    r = sap(prog("WRCBI(500, -1000);\ncbi := RDCBI(500);\nWRCBS(500, 3.99);\ncbs := RDCBS(500);",
                 "var\n    cbi: integer;\n    cbs : single;"))
    assert r["status"] == "ok", r["error"]
    assert r["variables"]["cbi"] == -1000
    assert r["variables"]["cbs"] == pytest.approx(3.99, rel=1e-7)


def test_wrcbd_example_offset_500_is_misaligned_L2210(sap):
    # L2210 WRCBD(500, 100.2e-128): 500 is not divisible by 8: run-time error 2048
    r = sap(prog("WRCBD(500, 100.2e-128);"))
    assert r["error"]["code"] == "2048"


NAMED = axes_toml(3, names=["X", "Y", "Z"])


def test_axis_names_from_the_configuration_rptodp_L2039(sap_on):
    # L2039 RPTODP (X, Z): the axis channels named X and Z in mcfg; with the ideal plant rp = dp
    r = sap_on(prog("MLAW(X := 12.5, Z := -3.0);\nRPTODP (X, Z);\nx := X.dp; z := Z.dp; rx := X.rp;",
                    "var x, z, rx: double;"), NAMED)
    assert r["status"] == "ok", r["error"]
    assert r["variables"] == {"x": 12.5, "z": -3.0, "rx": 12.5}


def test_szpa_and_szpr_examples_with_named_axes_L2150_L2158(sap_on):
    # L2150 SZPA (X := 100, Y := -20): the zero lies at machine 100 / -20, so at machine 0 the
    # positions read -100 / 20. L2158 SZPR (X := 100, Y := -20) shifts once more: -200 / 40.
    r = sap_on(prog("SZPA (X := 100, Y := -20);\nx1 := X.dp; y1 := Y.dp;\nSZPR (X := 100, Y := -20);\n"
                    "x2 := X.dp; y2 := Y.dp;", "var x1, y1, x2, y2: double;"), NAMED)
    assert r["status"] == "ok", r["error"]
    assert r["variables"] == {"x1": -100.0, "y1": 20.0, "x2": -200.0, "y2": 40.0}


def test_ssf_output_example_on_four_axes_L2091(sap_on):
    # L2091: SSF(A1:=1, A4:=2, SSFP := 1001) sets O1 of axis 1 and O2 of axis 4 when it is reached
    r = sap_on(prog("SSF(A1:=1, A4:=2, SSFP := 1001);\nb1 := A1.digo; b4 := A4.digo;\nSSMSW(A1, A4);\n"
                    "a1 := A1.digo; a4 := A4.digo;", "var b1, b4, a1, a4: integer;"), axes_toml(4))
    assert r["status"] == "ok", r["error"]
    assert r["variables"] == {"b1": 0, "b4": 0, "a1": 1, "a4": 2}


def test_ssf_spool_halt_on_three_axes_L2091(sap):
    # L2091: SSF(A1:=0, A2:=0, A3:=0, SSFP:=1000) halts the spoolers of A1, A2 and A3; the
    # segment behind it waits for the next SSMS (SSMSW would wait for it too, L2101: SSMS and WT here)
    r = sap(prog("SMLA(A1 := 1.0, A2 := 1.0, A3 := 1.0);\nSSF(A1:=0, A2:=0, A3:=0, SSFP:=1000);\n"
                 "SMLA(A1 := 2.0, A2 := 2.0, A3 := 2.0);\nSSMS(A1, A2, A3); WT(15625);\nz1 := A3.dp;\nSSMSW(A1, A2, A3);\n"
                 "z2 := A3.dp;", "var z1, z2: double;"))
    assert r["status"] == "ok", r["error"]
    assert (r["variables"]["z1"], r["variables"]["z2"]) == (1.0, 2.0)


def test_ssms_and_ssmsw_examples_L2099_L2108(sap_on):
    # L2099: SMLA(1000, 1000); SMLR(200, 500); SSMS(A1, A2) -> (1200, 1500), SSMS does not wait.
    # L2108 the same with SMLR first and SSMSW. Rest to rest (TRTVL = 0), each segment takes
    # L / 100 + 0.1 s: sqrt(2) * 10 + 0.1 and sqrt(200^2 + 500^2) / 100 + 0.1
    text = prog("SMLA(A1:=1000.0, A2:=1000.0);\nSMLR(A1:=200.0, A2:=500.0);\nSSMS(A1, A2);\nbusy := A1.dv;\nWT(10);"
                "\nwhile not (A1.axstb.1 and A2.axstb.1 and (A1.mcis = 0)) do ;\nx1 := A1.dp; y1 := A2.dp;\n"
                "JAW(A1 := 0.0, A2 := 0.0);\nt0 := CLOCK;\n"
                "SMLR(A1:=1000.0, A2:=1000.0);\nSMLR(A1:=200.0, A2:=500.0);\nSSMSW(A1, A2);\ndt := CLOCK - t0;"
                "\nx2 := A1.dp; y2 := A2.dp;",
                "var x1, y1, x2, y2, busy: double; t0: timer; dt: integer;")
    r = sap_on(text, axes_toml(3, limit=20000.0))
    assert r["status"] == "ok", r["error"]
    v = r["variables"]
    assert (v["x1"], v["y1"], v["x2"], v["y2"]) == (1200.0, 1500.0, 1200.0, 1500.0)
    expected = (math.hypot(1000, 1000) / 100 + 0.1 + math.hypot(200, 500) / 100 + 0.1) * SEC
    assert expected <= v["dt"] <= expected + 60


def test_task_control_examples_with_constants_L2115_L2142(sap):
    # L2115 STARTCNCT(Task1), L2135 STOPCNCT(Task3), L2142 STOPTOSS(Task3), L2128 STEPCNCT(Task3),
    # each with its constant. Task 3 counts in CI7; after STOPTOSS nothing runs until STEPCNCT.
    text = """{$TASK 0}
program Main;
const
    Task1 = 1;
    Task3 = 3;
var a, b, c, one: integer;
begin
  STARTCNCT(Task1);
  STARTCNCT(Task3);
  WT(5);
  STOPCNCT(Task3);
  a := CI7;
  STOPTOSS(Task3);
  WT(50);
  b := CI7;
  STEPCNCT(Task3);
  WT(50);
  c := CI7;
  one := CI8;
end.
{$TASK 1}
program One;
begin CI8 := 1; end.
{$TASK 3}
program Counter;
begin
  while TRUE do CI7 := CI7 + 1;
end.
"""
    v = sap(text)["variables"]
    assert v["a"] > 0 and v["b"] == v["a"] and v["c"] == v["b"] + 1 and v["one"] == 1


def test_trovr_example_L2189(sap):
    # L2189: TROVR := 0.9; UTROVR(A1, A2); the path speed drops to 90 mm/s: 90 mm take
    # 90 / 90 + 90 / 1000 = 1.09 s (the acceleration is not scaled)
    r = sap(prog("TROVR := 0.9; // -10%\nUTROVR(A1, A2);\nt0 := CLOCK;\nMLAW(A1 := 90.0, A2 := 0.0);\n"
                 "dt := CLOCK - t0;", "var t0: timer; dt: integer;"))
    assert r["status"] == "ok", r["error"]
    assert 1.09 * SEC <= r["variables"]["dt"] <= 1.09 * SEC + 25


def test_write_and_writeln_examples_L2217_L2225(sap):
    # L2217 write('Dies ist ein String', C10); write('Istposition', A1.rp); (C10 read as CI0, A-58)
    # L2225 writeln('Dies ist ein String: ', C10); writeln('Istposition: ', A1.rp);
    # CI0 = 7 and A1 at 12.5; no separators are added
    r = sap(prog("CI0 := 7;\nMLAW(A1 := 12.5);\nwrite ('Dies ist ein String', CI0);\nwrite ('Istposition', A1.rp);\n"
                 "writeln ('Dies ist ein String: ', CI0);\nwriteln ('Istposition: ', A1.rp);"))
    assert r["status"] == "ok", r["error"]
    assert r["output"] == ["Dies ist ein String7Istposition12.5Dies ist ein String: 7", "Istposition: 12.5"]


def test_wt_example_L2233(sap):
    # L2233: CONST sec = 15625; WT(5*sec) waits 5 s = 78125 ticks. t0 is read at tick 1, WT starts
    # at tick 2 and wakes at tick 2 + 78125; dt is read at that tick or the next one.
    r = sap(prog("t0 := CLOCK;\nWT(5*sec); // 5s warten\ndt := CLOCK - t0;",
                 "CONST sec = 15625;\nvar t0: timer; dt: integer;"))
    assert r["status"] == "ok", r["error"]
    assert r["variables"]["dt"] in (5 * SEC + 1, 5 * SEC + 2)


def test_task_directive_selects_task_1_L2251(sap):
    # L2251: {$TASK Task1}; puts the program into task 1; a run-time fault then names task 1
    r = sap("program P;\nconst\n    Task1 = 1;\n{$TASK Task1};      // oder {$TASK 1}\nvar i: integer;\n"
            "begin\n  i := 0;\n  i := 1 mod i;\nend.\n")
    assert r["error"]["code"] == "32768"
    assert "task 1" in r["error"]["message"]


def test_lprs_example_three_axes_L1859(sap):
    # L1859: LPRS (A1, A2, A3) records the three axes on one time grid (1000 values each, L1299)
    r = sap(prog("LST := 0.0; LET := 1.0;\nLPRS (A1, A2, A3);\nMLRW(A1 := 3.0, A2 := 4.0, A3 := 12.0);"))
    assert r["status"] == "ok", r["error"]
    recs = r["recordings"]
    assert set(recs) == {"A1", "A2", "A3"}
    grids = [[s[0] for s in recs[n]["samples"]] for n in ("A1", "A2", "A3")]
    assert len(grids[0]) == 1000 and grids[0] == grids[1] == grids[2]
    # the path is 13 mm long; at any sample the axes stand in the ratio 3 : 4 : 12
    x, y, z = (recs[n]["samples"][600][1] for n in ("A1", "A2", "A3"))
    assert x > 0 and (y / x, z / x) == pytest.approx((4 / 3, 4.0))


# --- homing searches in progress (ncvm's reading; the manual is silent) ----------------------------------------------

REF_RIGHT = "\n[sympas]\nref_positions = {A1 = 30.0}\n"
# hvl 10 mm/s, hac 100 mm/s^2: after 1 s of search the axis has run 0.5 mm + 0.9 s * 10 mm/s = 9.5 mm
SEARCH = "A1.hvl := 10.0; A1.hac := 100.0;\nJHR(A1);\nh0 := A1.axstb.4;\nWT(15625);\nx := A1.dp; h1 := A1.axstb.4;\n"


def test_jhr_search_in_progress_is_not_homed_yet(sap):
    r = sap(prog(SEARCH, "var h0, h1: boolean; x: double;"), machine_toml=REF_RIGHT)
    assert r["status"] == "ok", r["error"]
    v = r["variables"]
    assert (v["h0"], v["h1"]) == (False, False)
    assert v["x"] == pytest.approx(9.5, abs=0.01)


def test_homing_search_stopped_before_the_switch_is_not_homed(sap):
    r = sap(prog(SEARCH + "JSW(A1);\nh2 := A1.axstb.4;", "var h0, h1, h2: boolean; x: double;"),
            machine_toml=REF_RIGHT)
    assert r["status"] == "ok", r["error"]
    assert r["variables"]["h2"] is False


def test_homing_stops_behind_the_latched_reference(sap):
    # hvl 10 mm/s, hac 100 mm/s^2: latched at REF (lp = 0), stops 10^2 / 200 = 0.5 mm behind it
    r = sap(prog("A1.hvl := 10.0; A1.hac := 100.0;\nJHRW(A1);\nx := A1.dp; lp := A1.lp;", "var x, lp: double;"),
            machine_toml=REF_RIGHT)
    assert r["status"] == "ok", r["error"]
    assert r["variables"]["lp"] == 0.0
    assert r["variables"]["x"] == pytest.approx(0.5, abs=0.01)


def test_common_buffer_is_task_specific_L2013(sap):
    # L2013/L2020: RDCBx/WRCBx work on the CNC task's own COMMON BUFFER of 1000 bytes: what task 0
    # writes at offset 500 (the manual's WRCBI(500, -1000)) is not in task 1's buffer, and back
    text = """{$TASK 0}
program Main;
var mine, other: integer;
begin
  WRCBI(500, -1000);
  STARTCNCT(1);
  WT(100);
  mine := RDCBI(500);
  other := CI9;
end.
{$TASK 1}
program Reader;
begin
  CI9 := RDCBI(500);
  WRCBI(500, 7);
end.
"""
    r = sap(text)
    assert r["status"] == "ok", r["error"]
    assert r["variables"] == {"mine": -1000, "other": 0}


def test_jhiw_gives_up_after_pos_L1754(sap):
    # L1754: the index search stops once the distance Pos is exceeded. JHIW(A1 := 5.0) from 0.25 mm
    # with index pulses 10 mm apart finds none: the axis stops at 5.25, not homed, search failed
    # (provisional axst bit 15 = home search failed, axstb.16)
    r = sap(prog("JAW(A1 := 0.25);\nJHIW(A1 := 5.0);\nh := A1.axstb.4; f := A1.axstb.16; x := A1.dp;",
                 "var h, f: boolean; x: double;"), machine_toml="\n[sympas]\nindex_period = 10.0\n")
    assert r["status"] == "ok", r["error"]
    assert r["variables"] == {"h": False, "f": True, "x": 5.25}


def test_wt_takes_an_integer_L2230(tmp_path):
    # L2230: the parameter of WT is an Integer value in units of 64 us; a Double is a compile error
    assert errors_of(tmp_path, prog("d := 2.5;\nWT(d);", "var d: double;")) == [("SP003", 5)]
