"""Parameters as NC word values (manual §2.1.1, example with P1..P3 in [ ]): REAL view, NUL and type errors."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("args, code", [("[5]", "CPL020"), ('[5, "A"]', "CPL021")])
def test_parameter_word_errors(run_text, tmp_path, args, code):
    (tmp_path / "SUBW").write_text("N10 G0 X[P1] Y[P2]\n")
    r = run_text(f"10 CALL SUBW {args}\nM30\n", name="main.cpl")
    assert r["status"] == "error" and r["error"]["code"] == code


def test_parameter_word_is_the_real_view(run_text, tmp_path):
    """P1 without suffix is REAL: 0.1 arrives as the binary32 value 0.100000001490116..."""
    (tmp_path / "SUBW").write_text("N10 G1 X[P1] Y[P2] F100\n")
    r = run_text("10 CALL SUBW [0.1, 7]\nM30\n", name="main.cpl")
    assert r["status"] == "ok", r["error"]
    assert r["position"]["X"] == pytest.approx(0.10000000149011612, abs=1e-15)
    assert r["position"]["Y"] == 7.0
