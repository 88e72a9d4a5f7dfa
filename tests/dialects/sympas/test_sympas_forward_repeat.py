"""A definition that repeats 'forward' (manual L1185-1191: the forward heading, later the heading again
without it, then the block) is reported at the stray word, not at the end of the function."""

from __future__ import annotations


def test_repeated_forward_is_reported_at_the_stray_word_L1191(sap_check, tmp_path):
    text = ("program F;\nfunction G(x: integer): integer; forward;\nfunction G(x: integer): integer; forward;\n"
            "begin\n  G := x;\nend;\nbegin\n  CI0 := G(1);\nend.\n")
    assert sap_check(text) == [("SP001", 3)]
    from ncvm.api import check
    d = [d for d in check(tmp_path / "prog.sap") if d.severity == "error"][0]
    assert d.span.column == 34 and "'forward' in the definition of G" in d.message


def test_forward_then_definition_is_fine_L1191(sap_check):
    assert sap_check("program F;\nfunction G(x: integer): integer; forward;\nfunction G(x: integer): integer;\n"
                     "begin\n  G := x;\nend;\nbegin\n  CI0 := G(1);\nend.\n") == []
