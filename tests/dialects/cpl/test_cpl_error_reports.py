"""Where CPL errors point (file:line:col, the CPL line number), every error of a program listed by check, and
nesting beyond what Python blocks and its parser take (NESTING TOO DEEP, 2153).
"""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("text, line, col", [
    ("10 X=3: X=NUL : Y = X + 1\n", 1, 17),  # the third statement of the block
    ("10 X=1\n20 REPEAT\n30 X=X+1\n40 UNTIL Y=3\n", 4, 4),  # the UNTIL condition
    ("10 X=1 : IF Y=3 THEN X=2 ENDIF\n", 1, 10),  # an IF condition after another statement
    ("10 X=1 : WHILE Y<3 DO X=2 END\n", 1, 10),
    ("10 X=1\n20 GOTO 40\n30 Z=1\n40 X=SQRT(-1)\n", 4, 4),  # with a GOTO: the dispatch form of the program
    ("10 X=1\nN20 G1 X[U] F100\n", 2, 1),  # an [expr] word of an NC block
    ("10 X=1\nN20 G22 K1\n", 2, 1),  # an NC block the NC kernel refuses when it is executed
])
def test_runtime_errors_carry_the_column(run, text, line, col):
    r = run(text)
    assert r["status"] == "error"
    assert (r["error"]["line"], r["error"]["column"]) == (line, col)


def test_runtime_error_in_a_sub_program_points_into_it(run, reference):
    m = reference()
    (m.program_path[0] / "SUBERR").write_text("10 A=1 : B=SQRT(-A)\n")
    r = run("10 X=1\n20 CALL SUBERR\nM30\n")
    assert r["error"]["code"] == "CPL029" and r["error"]["file"].endswith("SUBERR")
    assert (r["error"]["line"], r["error"]["column"]) == (1, 10) and "(CPL line 10)" in r["error"]["message"]
    assert r["error"]["stack"] == ["called from p.cpl at " + str(reference().program_path[0] / "p.cpl") + ":2:4"]


@pytest.mark.parametrize("text, code, col", [
    ("10 X=1 : CALL P999\n", "CPL014", 10),  # §3.3 L1086
    ("10 X=1 : WAIT\n", "CPL009", 10),  # §4.1 L1201
])
def test_block_rules_point_at_the_statement(run, reference, text, code, col):
    (reference().program_path[0] / "P999").write_text("10 A=1\n")
    r = run(text)
    assert r["error"]["code"] == code and r["error"]["column"] == col and "(CPL line 10)" in r["error"]["message"]


def test_every_lexical_error_is_reported_with_its_cpl_line(tmp_path, reference):
    """A character the lexer cannot read no longer hides the errors of the blocks after it."""
    from ncvm.api import check
    path = tmp_path / "lx.cpl"
    path.write_text("10 @101=1\n20 X=$\n30 Y=(1\n40 Z=1:\nW=@0\n")
    diags = check(path, machine=reference())
    assert [(d.span.line, d.span.column) for d in diags] == [(1, 4), (2, 6), (3, 7), (5, 3)]
    assert [d.message.endswith(f"(CPL line {n})") for d, n in zip(diags, (10, 20, 30, 40))] == [True] * 4


def test_numbered_line_after_a_colon_is_named_as_such(run):
    """§2.1.2 L375-380: after a block that ends with ':' comes a line without a line number."""
    r = run("10 X=1:\n20 Y=2\n")
    assert r["error"]["code"] == "CPL001" and r["error"]["line"] == 2
    assert "has no line number" in r["error"]["message"]


def test_deeply_nested_structures_run_in_the_flat_form(run):
    """120 nested IFs (Python allows 100 nested blocks): the program is generated as a dispatch loop and
    runs; the manual sets no IF nesting limit (CASE only: 10, §2.5.7 L1044)."""
    depth = 120
    text = "".join(f"{i} IF TRUE THEN\n" for i in range(1, depth + 1)) + "500 X% = 1\n"
    text += "".join(f"{600 + i} ENDIF\n" for i in range(depth)) + "M30\n"
    r = run(text)
    assert r["status"] == "ok", r["error"]
    assert r["variables"] == {"X%": 1}


@pytest.mark.parametrize("expr", ["+".join(["1"] * 300), "-" * 5000 + "1", "NOT " * 3000 + "1"])
def test_expressions_too_deep_are_nesting_too_deep(run, expr):
    """§2.5.1 L782-791: the nesting a control allows depends on the memory an expression needs; beyond it the
    manual's error is RUNTIME ERROR 2153 NESTING TOO DEEP (L3773), at the block, before the start."""
    r = run(f"5 A% = 1\n10 X% = {expr}\nM30\n")
    assert r["error"]["code"] == "2153" and r["error"]["line"] == 2 and "(CPL line 10)" in r["error"]["message"]
    assert r["steps"] == 0


def test_check_lists_link_and_type_errors_together_in_source_order(tmp_path, reference):
    """A type error no longer hides behind a link error of another block (or another program)."""
    from ncvm.api import check
    m = reference()
    (m.program_path[0] / "SUBT").write_text('10 Y% = "B"\n')
    path = tmp_path / "ce.cpl"
    path.write_text('10 X% = "A"\n20 CALL NOPE\n30 CALL SUBT\n')
    diags = check(path, machine=m)
    assert [(d.code, d.span.line) for d in diags if d.span.file == str(path)] == [("CPL021", 1), ("CPL005", 2)]
    assert [d.code for d in diags if d.span.file.endswith("SUBT")] == ["CPL021"]


def test_check_reports_the_type_error_of_every_statement(tmp_path, reference):
    """One check lists every type error (a condition that is no BOOLEAN, the assignments of L655-667 that
    need a conversion), not only the first, each at its statement."""
    from ncvm.api import check
    path = tmp_path / "types.cpl"
    path.write_text('10 IF 3 THEN\n20 B% = 2\n30 ENDIF\n40 C$ = 4\n50 FOR I% = 1 TO "A"\n60 NEXT I%\n70 D% = "X"\n')
    diags = check(path, machine=reference())
    assert [(d.code, d.span.line, d.span.column) for d in diags] == [
        ("CPL032", 1, 4), ("CPL021", 4, 4), ("CPL032", 5, 4), ("CPL021", 7, 4)]


@pytest.mark.parametrize("text, col", [
    ("10 IF A%>1 AND B%<2 THEN X=1 ENDIF\n", 18),
    ("10 WHILE A%>1 OR B%<2 DO A%=0 END\n", 20),
    ("10 REPEAT\n20 A%=A%+1\n30 UNTIL A%=1 XOR A%=2\n", 0),
    ("10 C?=A%>1 AND B%<2\n", 18),
])
def test_comparisons_joined_by_and_or_need_parentheses_l851(tmp_path, reference, text, col):
    """L851/L872: AND binds like `*`, OR and XOR like `+`, tighter than a comparison, so `A%>1 AND B%<2` is
    `A% > (1 AND B%) < 2`; the manual writes every compound condition in parentheses (L4648). The error says
    so, at the second comparison, in every statement that takes a condition (it said "THEN expected")."""
    from ncvm.api import check
    path = tmp_path / "c.cpl"
    path.write_text(text)
    diags = check(path, machine=reference())
    assert [d.code for d in diags] == ["CPL001"]
    assert "comparisons joined by AND, OR or XOR need parentheses" in diags[0].message
    if col:
        assert diags[0].span.column == col
    path.write_text(text.replace("A%>1 AND B%<2", "(A%>1) AND (B%<2)").replace("A%>1 OR B%<2", "(A%>1) OR (B%<2)")
                    .replace("A%=1 XOR A%=2", "(A%=1) XOR (A%=2)"))
    assert check(path, machine=reference()) == []
