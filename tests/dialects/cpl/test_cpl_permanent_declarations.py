"""Declarations of definable permanent variables (manual §2.4.3): names declared twice, names the manual rules out."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("anw, expected", [
    ("DEF REAL @EFGH ;the same declaration in both files\n", "ok"),
    ("DEF INT @EFGH\n", "CPL038"),  # one name, two types: which variable would @EFGH be?
    ("DEF REAL @EFGHIJKLMNOPQRSTU(3)\nDEF REAL @EFGHIJKLMNOPQRSTV\n", "CPL038"),  # 16 significant (L560-562)
])
def test_one_name_declared_twice(run, reference, anw, expected):
    root = reference().file_root
    root.mkdir(parents=True, exist_ok=True)
    (root / "wmhperm.dat").write_text("DEF REAL @EFGH ;simple REAL variable\n")
    (root / "anwperm.dat").write_text(anw)
    r = run("10 @EFGH = 4.1\nM30\n")
    assert (r["status"] if expected == "ok" else r["error"]["code"]) == expected


@pytest.mark.parametrize("text, words", [
    ("10 @_RES_DOUBLE = 1\n", "reserved for internal applications"),  # §2.4.3 L544
    ("10 @4$ = \"A\"\n", "INTEGER permanent variable"),  # @1..@100 are INTEGER (L542)
])
def test_permanent_names_the_manual_rules_out(run, text, words):
    r = run(text + "M30\n")
    assert r["error"]["code"] == "CPL001" and words in r["error"]["message"]
