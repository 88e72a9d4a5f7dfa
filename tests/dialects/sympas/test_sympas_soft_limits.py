"""The soft-limit reactions stop the axis (slr/sll, manual L1490; EVLSS with TOM/SMA, L1584-1586)."""

from __future__ import annotations

import pytest

PROG = """program S;
begin
  A1.slr := 500.0;
  TRVL := 100.0; TRAC := 1000.0;
  MLAW(A1 := 600.0);
  writeln('at ', A1.dp, ' closed ', A1.axstb.3);
end.
"""


@pytest.mark.parametrize("reaction, closed", [("TOM", "FALSE"), ("SMA", "TRUE")])
def test_mlaw_beyond_slr_stops_at_the_limit_L1490(sap, reaction, closed):
    r = sap(PROG, machine_toml=f'[sympas]\nsoft_limit_reaction = "{reaction}"\n')
    assert r["error"] is None
    assert r["output"][0].endswith(f"prog.sap:5: software limit slr = 500 of A1 reached at 5.050256 s: "
                                   f"{reaction} stops A1")
    assert r["output"][1] == f"at 500 closed {closed}"  # TOM turns the motor off: the loop opens
    assert r["position"]["A1"] == pytest.approx(500.0)
    assert r["cycle_time_s"] == pytest.approx(5.05, abs=1e-3)
    assert r["limit_violations"] == []


def test_smd_brakes_with_sdec_past_the_limit_L1490(sap):
    r = sap(PROG.replace("A1.slr := 500.0;", "A1.slr := 500.0; A1.sdec := 500.0;"),
            machine_toml='[sympas]\nsoft_limit_reaction = "SMD"\n')
    # 100 mm/s braked with 500 mm/s^2: 10 mm past the limit
    assert r["position"]["A1"] == pytest.approx(510.0, abs=1e-6)


def test_a_spooled_chain_stops_at_the_limit_L1490(sap):
    r = sap("""program S;
begin
  A1.slr := 150.0;
  TRVL := 100.0; TRAC := 1000.0; TRTVL := 100.0;
  SMLR(A1 := 100.0);
  SMLR(A1 := 100.0, A2 := 10.0);
  SSMSW(A1, A2);
end.
""")
    assert r["position"]["A1"] == pytest.approx(150.0)
    assert r["position"]["A2"] == pytest.approx(5.0, abs=1e-6)
