"""The syntax tree's nodes (plain slotted classes since issue 18) keep a dataclass's behaviour.

CPL001 ("cannot compile <expression>") prints a node's repr, and the parser's tests compare nodes, so the
fields, their defaults, equality and repr must stay those the dataclasses had.
"""

from __future__ import annotations

import pytest

from ncvm.dialects.cpl import ast as A
from ncvm.dialects.cpl.parser import parse_program


def test_repr_names_every_field_in_order_like_a_dataclass():
    assert repr(A.Num(1, "I")) == "Num(value=1, type='I')"
    assert repr(A.Bin("+", A.Num(1, "I"), A.Nul())) == "Bin(op='+', left=Num(value=1, type='I'), right=Nul())"
    assert repr(A.Goto(3, 1, 20, "line", 40)) == "Goto(line=3, col=1, cpl=20, kind='line', target=40)"


def test_equality_is_field_wise_and_only_within_one_class():
    assert A.Num(2.5, "R") == A.Num(2.5, "R")
    assert A.Num(2.5, "R") != A.Num(2.5, "I")
    assert A.If(1, 1, 10, A.BoolLit(True)) == A.If(1, 1, 10, A.BoolLit(True))
    assert A.While(1, 1, 10, A.BoolLit(True)) != A.If(1, 1, 10, A.BoolLit(True))
    assert A.Else() != A.EndIf()


def test_list_fields_default_to_a_fresh_list_and_nodes_take_no_other_attributes():
    a, b = A.NcBlock(line=1, col=1), A.NcBlock(line=2, col=1)
    a.words.append(A.NcWord("X", 1.0))
    assert b.words == [] and a.loose == [] and A.CallStmt().args == [] and A.Proc().args == []
    with pytest.raises(AttributeError):
        a.unknown = 1
    with pytest.raises(TypeError):
        hash(A.Num(1, "I"))


def test_a_parsed_program_compares_equal_to_itself_parsed_again():
    text = "N1 G90\n10 A% = 1 + 2 * 3\n20 IF A% > 5 THEN\n30 B = SIN(A%)\n40 ENDIF\nN2 X[A%] Y1\nM30\n"
    first, second = parse_program("p.cpl", text), parse_program("p.cpl", text)
    assert first.stmts == second.stmts
    assert any(isinstance(s, A.If) for s in first.stmts)
