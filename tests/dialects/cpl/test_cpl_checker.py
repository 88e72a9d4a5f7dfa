"""The checker pass between linker and codegen: it resolves the type of every expression and reports the
type errors of every statement; codegen only emits code for a program the checker passed."""

from __future__ import annotations

import ast
import inspect

from ncvm.dialects.cpl import ast as A
from ncvm.dialects.cpl import codegen
from ncvm.dialects.cpl.checker import check
from ncvm.dialects.cpl.linker import link


def linked(tmp_path, machine, text: str):
    path = tmp_path / "p.cpl"
    path.write_text(text)
    res = link(str(path), text, machine)
    assert not res.diagnostics
    return res.units[str(path)]


def test_every_statement_reports_its_first_type_error_in_source_order(tmp_path, reference):
    ln = linked(tmp_path, reference(), '10 A% = "X"\n20 IF 1 THEN\n30 ENDIF\n40 B? = 1 + TRUE\n50 C$ = 2\nM30\n')
    _, diags = check(ln)
    assert [(d.code, d.span.line) for d in diags] == [("CPL021", 1), ("CPL032", 2), ("CPL032", 4), ("CPL021", 5)]
    assert diags[0].message == "INVALID ASSIGNMENT: CHARACTER value assigned to an INTEGER variable (CPL line 10)"


def test_the_types_are_resolved_for_codegen(tmp_path, reference):
    ln = linked(tmp_path, reference(), "10 D! = 2 * 1.5\n20 E = D! / 2\n30 S$ = MID$(\"ABC\", 2, 1)\nM30\n")
    types, diags = check(ln)
    assert not diags
    exprs = [s.expr for s in ln.prog.stmts if isinstance(s, A.Assign)]
    assert [types[e] for e in exprs] == ["R", "D", "S"]
    uc, more = codegen.generate(ln, types)
    assert not more and "def unit(P, _main):" in uc.text


def test_codegen_raises_no_errors_of_its_own():
    """Codegen only emits: refusing a program is the checker's job (compile-time limits of Python aside)."""
    tree = ast.parse(inspect.getsource(codegen))
    assert not [n.lineno for n in ast.walk(tree) if isinstance(n, ast.Raise)]
