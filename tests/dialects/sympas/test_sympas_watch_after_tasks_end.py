"""The card watches its moves whether or not a task still runs (issue 15; soft limits L1490, EVLSS
L1584-1586; SSF entries §6.6.62-64; home search §6.6 JHL/JHR), and reads sll/slr in the program's
coordinates (rw_SymPas manual L1668-1672; L2144-2158; L1413: dp, sll/slr exposed in u = m - zerooffset, stored in machine coordinates).

A move started without W by a program that then ends goes on on the card: what the card does to it on
the way (stop it at a soft limit, act on an SSF entry between spooled profiles, latch the home position)
happens all the same.
"""

from __future__ import annotations

import pytest

TOM = '[sympas]\nsoft_limit_reaction = "TOM"\n'


def test_a_jog_left_running_is_stopped_at_slr_L1490(sap):
    r = sap("""program S;
begin
  A1.slr := 100.0;
  JA(A1 := 300.0);
end.
""", machine_toml=TOM)
    assert r["error"] is None
    assert r["position"]["A1"] == 100.0
    assert any("software limit slr = 100 of A1" in line for line in r["output"])


def test_a_spooled_chain_left_running_is_stopped_at_sll_L1490(sap):
    r = sap("""program S;
begin
  A2.sll := -20.0;
  TRVL := 100.0; TRAC := 1000.0; TRTVL := 100.0;
  SMLR(A2 := -10.0);
  SMLR(A2 := -30.0);
  SSMS(A2);
end.
""", machine_toml=TOM)
    assert r["error"] is None
    assert r["position"]["A2"] == -20.0
    assert r["motion"]["bounds"]["A2"][0] == -20.0  # the path ends where the axis stands


def test_an_ssf_entry_after_the_program_ended_still_acts_L2101(sap):
    # SSF(SSFP = 1) writes CI1 when the spooler reaches it: after the first profile, 1.1 s into the chain
    r = sap("""program S;
begin
  TRVL := 100.0; TRAC := 1000.0;
  SMLR(A1 := 100.0); SSF(A1 := 42, SSFP = 1); SMLR(A1 := 10.0);
  SSMS(A1);
end.
""")
    assert r["error"] is None
    assert r["sympas"]["ci"] == {"1": 42}
    assert r["position"]["A1"] == pytest.approx(110.0)


def test_slr_written_and_read_in_the_users_coordinates_A62(sap):
    # SZPA(A1 := 100): dp 0 is machine 100. A1.slr := 200 puts the limit at dp 200 = machine 300; it reads
    # back 200, TOM stops A1 there, and the message names the limit as the program does.
    r = sap("""program S;
begin
  SZPA(A1 := 100.0);
  A1.slr := 200.0;
  TRVL := 100.0; TRAC := 1000.0;
  MLAW(A1 := 250.0);
  writeln('dp ', A1.dp, ' slr ', A1.slr);
  SZPA(A1 := 0.0);
  writeln('slr after SZPA 0: ', A1.slr);
end.
""", machine_toml=TOM)
    assert r["error"] is None
    assert r["output"][0].endswith("software limit slr = 200 (machine 300) of A1 reached at 3.050320 s: TOM stops A1")
    assert r["output"][1] == "dp 200 slr 200"
    assert r["output"][2] == "slr after SZPA 0: 300"  # the limit stays where it is on the machine


def test_a_braked_stop_is_reported_where_the_axis_stands_on_whole_counts_L1399(sap):
    # SMD brakes past the limit to a point between two counts: the axis stands on whole counts (L1399) and
    # the toolpath ends there, so the bounds enclose the reported position.
    r = sap("""program S;
begin
  A1.slr := 100.0; A1.sdec := 700.0;
  TRVL := 77.0; TRAC := 1000.0;
  MLAW(A1 := 200.0);
end.
""", machine_toml='[sympas]\nsoft_limit_reaction = "SMD"\n')
    a1 = r["sympas"]["axes"]["A1"]
    assert a1["machine_position"] == round(a1["machine_position"], 3)
    assert r["motion"]["bounds"]["A1"][1] == a1["machine_position"]
    assert a1["bounds_program"][1] == a1["position"]
