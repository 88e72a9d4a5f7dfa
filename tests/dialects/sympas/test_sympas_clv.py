"""CLV closes the position loop and keeps the axis's velocity; a JS stops it (§6.6.9, L1681-1686, A-51).

By hand: jvl 10 mm/s, jac 100 mm/s^2, sdec 100 mm/s^2; 15625 ticks = 1 s. JA(A1 := 100) is at 4.5 mm with
10 mm/s after 0.5 s; statements add a few ticks (tolerances below).
"""

from __future__ import annotations

import pytest

HEAD = "CL(A1, A2); A1.jvl := 10.0; A1.jac := 100.0; A1.sdec := 100.0; A2.sdec := 100.0;"


def run(sap, body: str):
    r = sap(f"program T;\nvar t0: integer; x, y, v: double; pe: boolean;\nbegin\n{HEAD}\n{body}\nend.\n")
    assert r["status"] == "ok", r["error"]
    return r["output"], r


def test_clv_keeps_the_velocity_until_js(sap):
    # CLV at 0.5 s: no braking toward 100 mm, the axis runs on at 10 mm/s: at 2.0 s it is at 4.5 + 15 = 19.5 mm
    # (profile end set: nothing to wait for); JSW brakes with sdec over 10^2 / 200 = 0.5 mm to 20.0 mm.
    out, r = run(sap, """t0 := CLOCK; JA(A1 := 100.0);
repeat until CLOCK - t0 >= 7812;
CLV(A1);
repeat until CLOCK - t0 >= 31250;
x := A1.dp; v := A1.dv; pe := A1.axstb.1;
JSW(A1);
writeln(x, ' ', v, ' ', pe, ' ', A1.dp, ' ', A1.dv);""")
    x, v, pe, x2, v2 = out[0].split()
    assert float(x) == pytest.approx(19.5, abs=0.01)
    assert float(v) == pytest.approx(10.0, abs=1e-6)
    assert pe == "TRUE"
    assert float(x2) == pytest.approx(20.0, abs=0.01)
    assert float(v2) == 0.0


def test_clv_on_an_axis_at_rest_closes_the_loop_only(sap):
    out, _ = run(sap, "OL(A1);\nx := A1.dp;\nCLV(A1);\nwriteln(A1.axstb.3, ' ', A1.dp - x, ' ', A1.dv, ' ', A1.axstb.1);")
    assert out[0].split() == ["TRUE", "0", "0", "TRUE"]


def test_clv_on_a_path_keeps_every_axis_share(sap):
    # MLR 30/40 mm at TRVL 10, TRAC 100: at 1.0 s s = 0.5 + 9 = 9.5 mm -> A1 5.7 mm at 6 mm/s, A2 7.6 mm at 8 mm/s.
    # CLV(A1) there: both run on; one second later A1 = 11.7, A2 = 15.6.
    out, _ = run(sap, """TRVL := 10.0; TRAC := 100.0; t0 := CLOCK; MLR(A1 := 30.0, A2 := 40.0);
repeat until CLOCK - t0 >= 15625;
CLV(A1);
repeat until CLOCK - t0 >= 31250;
x := A1.dp; y := A2.dp;
JSW(A1, A2);
writeln(x, ' ', y, ' ', A1.dv, ' ', A2.dv);""")
    x, y, v1, v2 = (float(s) for s in out[0].split())
    assert x == pytest.approx(11.7, abs=0.01)
    assert y == pytest.approx(15.6, abs=0.01)
    assert (v1, v2) == (0.0, 0.0)


def test_manual_example_clv_then_js(sap):
    # L1686: "clv (A1, A2); // Achskanäle 1 und 2 in Lageregelung bringen  js (A1, A2); // danach die Achsen
    # sofort stoppen" - on axes at rest: loops closed (axst bit 2), nothing moves
    out, r = run(sap, "OL(A1, A2);\nclv (A1, A2);\njs (A1, A2);\nwriteln(A1.axstb.3, ' ', A2.axstb.3, ' ', A1.dv);")
    assert out[0].split() == ["TRUE", "TRUE", "0"]
    assert r["motion"]["feed_moves"] + r["motion"]["rapid_moves"] == 0
