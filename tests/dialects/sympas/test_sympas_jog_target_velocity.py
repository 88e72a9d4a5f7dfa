"""Jog target velocity jtv != 0 (rw_SymPas manual, MODEREG bits 11 and 28, L1395-1405).

JR of 10 mm with jvl 10, jac 100, jtv 5: 0 -> 10 mm/s in 0.1 s (0.5 mm), 10 -> 5 in 0.05 s (0.375 mm),
cruise 9.125 mm in 0.9125 s: the target is reached after 1.0625 s at 5 mm/s, and the axis runs on.
"""

from __future__ import annotations

import pytest

SEC = 15625
HEAD = "CL(A1); A1.jvl := 10.0; A1.jac := 100.0; A1.jtv := 5.0; A1.sdec := 100.0;"


def prog(body: str) -> str:
    return f"program T;\nvar t0: integer;\nbegin\n{HEAD}\n{body}\nend.\n"


def test_jog_arrives_with_jtv_and_runs_on(sap):
    r = sap(prog("t0 := CLOCK;\nJRW(A1 := 10.0);\n"
                 "writeln(CLOCK - t0, ' ', A1.dv, ' ', A1.axstb.1, ' ', A1.axstb.12);\n"
                 "t0 := CLOCK;\nrepeat until CLOCK - t0 >= 15625;\nwriteln(A1.dp);"))
    assert r["status"] == "ok", r["error"]
    t, v, pe, saf = r["output"][0].split()
    assert int(t) == pytest.approx(1.0625 * SEC, abs=8)
    assert float(v) == pytest.approx(5.0)
    assert (pe, saf) == ("TRUE", "TRUE")  # profile end reached, SAF raised, while it still moves
    assert float(r["output"][1]) == pytest.approx(15.0, abs=0.005)  # one more second at 5 mm/s


def test_js_stops_the_running_on_axis_with_sdec(sap):
    # from 5 mm/s with sdec 100: 0.05 s, 0.125 mm
    r = sap(prog("JRW(A1 := 10.0);\nx := A1.dp;\nJSW(A1);\nwriteln(A1.dp - x, ' ', A1.dv);")
            .replace("var t0: integer;", "var t0: integer; x: double;"))
    d, v = r["output"][0].split()
    assert float(d) == pytest.approx(0.125, abs=0.001)
    assert float(v) == 0.0


def test_jsatsaf_stops_all_axes_and_sets_errorreg_bit_19(sap):
    r = sap(prog("MODEREG := $10000000;\nJRW(A1 := 10.0);\nWT(2000);\nwriteln(A1.dp, ' ', ERRORREG);"))
    x, err = r["output"][0].split()
    assert float(x) == pytest.approx(10.125, abs=0.001)
    assert int(err) == 1 << 19


def test_forbid_target_vel_executes_rs_and_sets_errorreg_bit_1(sap):
    # RS halts every task: the writeln after the jog is never reached, the axis stands at its target
    r = sap(prog("MODEREG := $800;\nJRW(A1 := 10.0);\nWT(2000);\nwriteln('not reached');"))
    # the reset is reported (issue 15), the writeln is not reached
    assert len(r["output"]) == 1 and "RS: system reset by ForbidTargetVel (MODEREG bit 11)" in r["output"][0]
    assert r["ended"].startswith("ended by RS (system reset) at ")
    assert r["position"]["A1"] == pytest.approx(10.0, abs=0.001)
