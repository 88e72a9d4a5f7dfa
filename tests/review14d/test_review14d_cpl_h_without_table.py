"""The Bosch H word after `G22 K0` (no tool compensation table selected).

The manual's C19 example ends its sub-program with `N2 G22 K[COMPTAB%]` and the call passes 0 (L1137-1146);
docs/decisions.md reads G22 K<n> as the selection of "the tool compensation table the H word reads: K4
(power-on), K5, K0 none". A later `H1` ("Hx", L1573: the length of compensation group 1 of the selected
table) then has no table to read: ncvm applies a length of 0 and runs on, so the tool's 40 mm length of K4
group 1 silently disappears from every later move. Issue 14 §1: "never silently ignore a word"; the run must
stop at the H word, naming that no table is selected."""

from __future__ import annotations

from review14d_run import run

from tests.review14.review14_helpers import MACHINE

TOOL = MACHINE + "[[tool]]\nnumber = 1\nlength = 40.0\nradius = 5.0\n"


def test_l1146_h1_after_g22_k0_does_not_run_with_a_silent_zero_length(tmp_path):
    text = "N10 T1 M6\nN20 G0 X0 Y0 Z0\nN30 G22 K0\nN40 H1 Z0\nN50 M30\n"
    result, rows, _stderr = run(tmp_path, "h.cpl", text, machine=TOOL)
    offsets = [r["length"] for r in rows if r["call"] == "tool_offset"]
    assert result["status"] != "ok", f"H1 without a table ran with tool length(s) {offsets}"
    assert result["error"]["line"] == 4, result["error"]
