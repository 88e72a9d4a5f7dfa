"""The simulated card: axes, qualifiers, motion in time through the canon interface (manual §6.3, §6.6)."""

from __future__ import annotations

import math

import pytest

SEC = 15625


def prog(body: str, decls: str = "") -> str:
    return f"program T;\n{decls}\nbegin\n{body}\nend.\n"


def test_acceptance_program_of_the_digest(sap, acceptance_program):
    # the project's acceptance program (its motion part included)
    r = sap(acceptance_program)
    assert r["status"] == "ok", r["error"]
    assert r["output"] == ["acc=15 d=5 ok=TRUE", "moved"]
    # about 1 s of busy waiting, then sqrt(500) mm at 100 mm/s with 1000 mm/s^2: 0.3236 s
    assert r["cycle_time_s"] == pytest.approx(1.0 + math.sqrt(500) / 100 + 0.1, abs=0.005)
    assert r["motion"]["feed_moves"] == 1
    assert r["motion"]["feed_length"] == pytest.approx(math.sqrt(500))
    assert r["position"] == {"A1": 10.0, "A2": 20.0, "A3": 0.0}


def test_waiting_move_takes_the_trapezoid_time(sap):
    r = sap(prog("TRVL := 100.0; TRAC := 1000.0; t0 := CLOCK; MLAW(A1 := 10.0, A2 := 20.0); dt := CLOCK - t0;",
                 "var t0: timer; dt: integer;"))
    expected = (math.sqrt(500) / 100 + 0.1) * SEC
    assert expected <= r["variables"]["dt"] <= expected + 3


def test_move_without_wait_runs_while_the_program_goes_on(sap):
    # after 0.1 s the profile has just finished accelerating: 5 mm along the path
    r = sap(prog("TRVL := 100.0; TRAC := 1000.0; MLA(A1 := 100.0); WT(1562); p := A1.dp; v := A1.dv;"
                 "pe := A1.axstb.1; MLA(A1 := 0.0); refused := A1.axstb.15;",
                 "var p, v: double; pe, refused: boolean;"))
    assert r["variables"]["p"] == pytest.approx(5.0, abs=0.05)
    assert r["variables"]["v"] == pytest.approx(100.0, abs=0.5)
    assert r["variables"]["pe"] is False            # provisional axst bit 0: profile end
    assert r["variables"]["refused"] is True        # a second move on a moving axis is refused
    assert r["position"]["A1"] == 100.0


def test_relative_moves_and_units(sap):
    # PU = 1 (inch): MLR by 1 inch moves 25.4 mm; TU = 1 (min): TRVL in PU/min
    r = sap(prog("MLRW(A1 := 10.0); PU := 1; TU := 1; TRVL := 60.0; TRAC := 36000.0; t0 := CLOCK;"
                 "MLRW(A1 := 1.0); dt := CLOCK - t0; PU := 0; x := A1.dp;",
                 "var t0: timer; dt: integer; x: double;"))
    assert r["variables"]["x"] == pytest.approx(35.4)
    # 25.4 mm at 25.4 mm/s with 254 mm/s^2: 1 s + 0.1 s
    assert r["variables"]["dt"] == pytest.approx(1.1 * SEC, abs=3)


def test_circle_two_full_turns_manual_example(sap):
    # §6.6.31: MCA(A1 := 50.0, A2 := 0.0, PHI := 720.0) makes two turns around (50, 0)
    r = sap(prog("MCAW(A1 := 50.0, A2 := 0.0, PHI := 720.0); phi := PHI;", "var phi: double;"))
    assert r["motion"]["arc_moves"] == 1
    assert r["motion"]["feed_length"] == pytest.approx(2 * 2 * math.pi * 50)
    assert r["position"] == {"A1": 0.0, "A2": 0.0, "A3": 0.0}
    assert r["variables"]["phi"] == 720.0  # inline system parameters persist
    assert r["motion"]["bounds"]["A1"] == pytest.approx([0.0, 100.0])


def test_relative_circle_quarter(sap):
    r = sap(prog("MLAW(A1 := 10.0, A2 := 0.0); MCRW(A1 := -10.0, A2 := 0.0, PHI := 90.0); x := A1.dp; y := A2.dp;",
                 "var x, y: double;"))
    assert (r["variables"]["x"], r["variables"]["y"]) == pytest.approx((0.0, 10.0))


def test_helix_angle_mode_manual_example(sap):
    # §6.6.39: MHA(A1 := 50.0, A2 := 0.0, PHI := 720.0, A3 := 10)
    r = sap(prog("MHAW(A1 := 50.0, A2 := 0.0, PHI := 720.0, A3 := 10);"))
    assert r["position"] == pytest.approx({"A1": 0.0, "A2": 0.0, "A3": 10.0})
    assert r["motion"]["feed_length"] == pytest.approx(math.hypot(4 * math.pi * 50, 10))


def test_helix_target_mode_full_and_half_circle(sap):
    # §6.6.39 examples: full circle ccw radius 10; half circle clockwise (PHI := -1e-100), spooled
    r = sap(prog("MHRW(A1 := 0.0, A2 := 0.0, PHI := 0.0, A3 := 10, DTCA1 := -10, DTCA2 := 0);"
                 "x1 := A1.dp; y1 := A2.dp; z1 := A3.dp;"
                 "SMHR(A1 := 20.0, A2 := 0.0, PHI := -1e-100, A3 := 10, DTCA1 := 10, DTCA2 := 0);"
                 "SSMSW(A1, A2, A3);",
                 "var x1, y1, z1: double;"))
    assert (r["variables"]["x1"], r["variables"]["y1"], r["variables"]["z1"]) == pytest.approx((0.0, 0.0, 10.0))
    assert r["position"] == pytest.approx({"A1": 20.0, "A2": 0.0, "A3": 20.0})
    assert r["motion"]["arc_moves"] == 2
    # the clockwise half circle from (0,0) around (10,0) passes through (10, 10)
    assert r["motion"]["bounds"]["A2"] == pytest.approx([-10.0, 10.0])


def test_3d_circle_tilted_plane(sap):
    # §6.6.33: MCA3D with PN = (1, 0, 1): the circle's plane is tilted 45 degrees about A2
    r = sap(prog("MCA3DW(A1 := 10.0, A2 := 0.0, A3 := -10.0, PN1 = 1.0, PN2 = 0.0, PN3 = 1.0, PHI := 180.0);"
                 "x := A1.dp; z := A3.dp;", "var x, z: double;"))
    assert r["status"] == "ok", r["error"]
    assert (r["variables"]["x"], r["variables"]["z"]) == pytest.approx((20.0, -20.0), abs=1e-3)
    assert r["motion"]["feed_length"] == pytest.approx(math.pi * math.sqrt(200), rel=2e-3)


def test_jog_absolute_and_stop(sap):
    # jog in axis units with jvl (rapid 10000 mm/min = 166.7 mm/s) and jac (1000 mm/s^2)
    r = sap(prog("JAW(A1 := 100.0); t1 := CLOCK; JA(A2 := 1000.0); WT(15625); JSW(A2); y := A2.dp;",
                 "var t1: timer; y: double;"))
    v = 10000 / 60
    assert r["variables"]["t1"] == pytest.approx((100 / v + v / 1000) * SEC, abs=3)
    s_at_1s = 0.5 * 1000 * (v / 1000) ** 2 + v * (1 - v / 1000)
    assert r["variables"]["y"] == pytest.approx(s_at_1s + v * v / 2000, abs=0.5)
    assert r["motion"]["rapid_moves"] == 2


def test_homing_left_to_the_reference_switch(sap):
    r = sap(prog("JHLW(A1); x := A1.dp; homed := A1.axstb.4; hv := A1.hvl; ha := A1.hac; MLAW(A1 := 1.0);",
                 "var x, hv, ha: double; homed: boolean;"),
            machine_toml="[sympas]\nref_positions = {A1 = -5.0}\n")
    v = r["variables"]
    # REF (-5) becomes 0 where the search passes it; braking with hac stops it hvl^2 / (2 hac) further left,
    # rounded to whole counts at the profile end (L1399)
    assert v["homed"] is True and v["x"] == pytest.approx(-round(v["hv"] ** 2 / (2 * v["ha"]), 3))
    assert r["position"]["A1"] == pytest.approx(1.0)


def test_zero_offsets_szpa_szpr_shp(sap):
    r = sap(prog("SZPA(A1 := 100); a := A1.dp; SZPR(A1 := 10); b := A1.dp; z := A1.zerooffset;"
                 "MLAW(A1 := 0.0); m := A1.dp; SHP(A2 := 1000.0); c := A2.dp;",
                 "var a, b, z, m, c: double;"))
    assert r["variables"] == {"a": -100.0, "b": -110.0, "z": 110.0, "m": 0.0, "c": 1000.0}


def test_azo_selects_a_zero_offset_table(sap):
    r = sap(prog("const Offsets1 = 1;", "") .replace("begin\nconst Offsets1 = 1;", "const Offsets1 = 1;\nbegin")
            .replace("end.", "azo(Offsets1); x := A1.dp; MLAW(A1 := 0.0);\nend.")
            .replace("program T;\n", "program T;\nvar x: double;\n"),
            machine_toml="[sympas]\nzero_offsets = {1 = [5.0, 0.0, 0.0]}\n")
    assert r["variables"]["x"] == -5.0
    assert r["position"]["A1"] == 0.0  # in the program's coordinates
    assert r["motion"]["bounds"]["A1"] == [0.0, 5.0]  # the machine moved to the table's zero


def test_digital_outputs_and_bits(sap):
    # L336-339 and L1506-1513: bit N counts from 1 (O7 = mask $40)
    r = sap(prog("A1.digo := 0; A2.digo := $FFFFFF; A1.digob.7 := TRUE; a := A1.digo; b := A2.digo;"
                 "c := A1.digob.7; input := A2.digib.enable;",
                 "const enable = 1;\nvar a, b: integer; c, input: boolean;"))
    assert r["variables"] == {"a": 64, "b": 16777215, "c": True, "input": False}


def test_axis_variables_and_loop_over_an(sap):
    # §5.3.3.1.1 L718-724: VA.an := 0; ol(VA); for VA.an := 0 to 2 do cl(VA)
    r = sap(prog("VA.an := 0; ol(VA); open0 := A1.axstb.3; for VA.an := 0 to 2 do cl(VA); n := VA.an;"
                 "closed := A1.axstb.3 and A3.axstb.3; VA.an := 1; MLAW(A1 := 0.0, VA := 7.0);",
                 "var VA: AXIS; n: integer; open0, closed: boolean;"))
    assert r["variables"]["open0"] is False and r["variables"]["closed"] is True
    assert r["variables"]["n"] == 2
    assert r["position"]["A2"] == 7.0


def test_axis_variable_out_of_range_is_error_256(sap):
    r = sap(prog("VA.an := 7; cl(VA);", "var VA: AXIS;"))
    assert r["error"]["code"] == "256"


def test_spooler_with_ssf_and_ssms(sap):
    # §6.6.62-64: SSF(A1 := 999, SSFP = 1) writes CI1 when it reaches the spooler head
    r = sap(prog("SMLA(A1 := 10.0); SSF(A1 := 999, SSFP = 1); SMLR(A1 := 5.0); n := A1.mcis; free := A1.lsm;"
                 "before := CI1; SSMSW(A1); after := CI1; x := A1.dp;",
                 "var n, free, before, after: integer; x: double;"))
    v = r["variables"]
    assert (v["n"], v["before"], v["after"], v["x"]) == (2, 0, 999, 15.0)
    assert v["free"] == (128 - 3) * 64
    assert r["motion"]["feed_moves"] == 2


def test_ssf_spool_halt_and_output(sap):
    # the spooler halts after the first segment; SSMSW would wait for the rest too (L2101), SSMS does not
    r = sap(prog("SMLA(A1 := 10.0); SSF(A1 := 0, SSFP := 1000); SMLA(A1 := 20.0); SSMS(A1); WT(15625); x := A1.dp;"
                 "SSMSW(A1); y := A1.dp; SSF(A1 := 3, SSFP := 1001); SSMSW(A1); o := A1.digo;",
                 "var x, y: double; o: integer;"))
    assert (r["variables"]["x"], r["variables"]["y"], r["variables"]["o"]) == (10.0, 20.0, 4)


def test_override_and_filter_update(sap):
    r = sap(prog("TROVR := 0.5; UTROVR(A1, A2); t0 := CLOCK; MLAW(A1 := 10.0); dt := CLOCK - t0;"
                 "A1.kp := 5.0; A1.ki := 0.0; A1.kd := 0.0; A1.kpl := 0.0; A1.kfca := 0.0; A1.kfcv := 0.0;"
                 "UF(A1); kp := A1.kp;",
                 "var t0: timer; dt: integer; kp: double;"))
    # 10 mm at 50 mm/s, 1000 mm/s^2: 0.2 s + 0.05 s
    assert r["variables"]["dt"] == pytest.approx(0.25 * SEC, abs=3)
    assert r["variables"]["kp"] == 5.0


def test_system_registers(sap):
    r = sap(prog("n := NOA; v := OSVERSION; CI999 := 5; CD3 := 2.5; MODEREG := MODEREG or $100; m := MODEREG;"
                 "LEDGN := TRUE;", "var n, v, m: integer;"))
    assert r["variables"] == {"n": 3, "v": 253126, "m": 256}


def test_clock_wraps_around_and_timer_deadline_still_holds(sap):
    # §5.3.3.1.2 L738-752: t := CLOCK + 5*s; repeat until CLOCK > t; correct across the wrap-around
    r = sap(prog("t := CLOCK + 5*s; start := CLOCK; repeat until CLOCK > t; elapsed := CLOCK - start;",
                 "const s = 15625;\nvar t, start: timer; elapsed: integer;"),
            machine_toml="[sympas]\nclock_start = 4294967000\n")
    v = r["variables"]
    assert v["start"] > 4294967000 and v["t"] < 100_000  # the deadline lies after the wrap
    assert 5 * SEC < v["elapsed"] <= 5 * SEC + 10
    assert r["cycle_time_s"] == pytest.approx(5.0, abs=0.01)


def test_limit_violation_is_reported(sap):
    # SMD brakes with sdec from the soft limit (softlimits.py): the axis overshoots it, which is reported
    r = sap(prog("MLAW(A1 := 1100.0);"), machine_toml='[sympas]\nsoft_limit_reaction = "SMD"\n')
    assert r["limit_violations"] and "A1" in r["limit_violations"][0]
