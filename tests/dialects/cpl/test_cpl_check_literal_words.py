"""``ncvm check`` of a CPL program reports what the run refuses from a block's literal words -- G20's axes
(L2372), G22's K (docs/decisions.md "Typ3 G22 K<n>"), H's compensation group (L1573) -- by the handlers'
own rules (nc/profiles/typ3osa.py), and leaves computed words to the run (the manual's
``N40 G20 [AXP(A%,E)] [AXP(B%,E)]``, L2374, and C19's ``N2 G22 K[COMPTAB%]``, L1146)."""

from __future__ import annotations

from pathlib import Path

from ncvm.api import check

MACHINE = '[[axis]]\nname = "X"\n[[axis]]\nname = "Y"\n[[axis]]\nname = "Z"\n'


def _check(tmp_path: Path, text: str):
    (tmp_path / "machine.toml").write_text(MACHINE)
    prog = tmp_path / "p.cpl"
    prog.write_text(text)
    return [(d.code, d.severity, d.span.line, d.span.column) for d in
            check(prog, dialect="cpl", machine=tmp_path / "machine.toml")]


def test_literal_words_the_run_refuses_are_reported_at_their_word(tmp_path):
    text = "N10 G0 X0 Y0 Z0\nN20 G20 X0 Z0\nN30 H99 Z0\nN40 G22 K7\nN50 G20 X0\nM30\n"
    assert _check(tmp_path, text) == [("NC004", "warning", 2, 5), ("NC009", "error", 3, 5),
                                      ("NC009", "error", 4, 5), ("NC009", "error", 5, 5)]


def test_computed_words_are_left_to_the_run(tmp_path):
    text = ("1 A%=1 : B%=2 : E=0 : C%=0 : H%=1\nN10 G0 X0 Y0 Z0\nN20 G20 [AXP(A%,E)] [AXP(B%,E)]\n"
            "N30 G22 K[C%]\nN40 H[H%] Z0\nN50 G17 G22 K4\nN60 H0 Z0\nM30\n")
    assert _check(tmp_path, text) == []
