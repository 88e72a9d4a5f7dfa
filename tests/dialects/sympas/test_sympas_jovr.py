"""A new jog override acts on the running jog (jovr, manual §6.3.3: the jog velocity is jvl * jovr)."""

from __future__ import annotations

import pytest


def test_jovr_changed_during_a_jog_slows_it_down(sap):
    """JA to 100 at 100 mm/s (jac 1000); after 0.5 s jovr = 0.5: it brakes to 50 mm/s (at 48.75 mm,
    0.55 s), runs on to its target at 50 mm/s and arrives at 1.6 s instead of 1.1 s."""
    r = sap("""program J;
var t0: timer; dt: integer;
begin
  A1.jvl := 100.0; A1.jac := 1000.0; A1.jovr := 1.0;
  t0 := CLOCK;
  JA(A1 := 100.0);
  WT(7812);
  A1.jovr := 0.5;
  repeat until A1.axstb.1;
  dt := CLOCK - t0;
  writeln(A1.dp);
end.
""")
    assert r["output"] == ["100"]
    assert r["variables"]["dt"] / 15625.0 == pytest.approx(1.6, abs=2e-3)
