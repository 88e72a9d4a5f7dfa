"""ncvm.records: plain slotted classes that compare, hash and print as the dataclasses they replace."""

from __future__ import annotations

import dataclasses
import pickle

import pytest

from ncvm.machine.model import Axis
from ncvm.machine.schema import Field, Number, Table
from ncvm.records import FrozenRecord, Record


class Point(Record):
    __slots__ = ("x", "y")

    def __init__(self, x: float, y: float = 0.0):
        self.x = x
        self.y = y


class Point3(Point):
    __slots__ = ("z",)

    def __init__(self, x: float, y: float, z: float):
        super().__init__(x, y)
        self.z = z


class Key(FrozenRecord):
    __slots__ = ("name",)

    def __init__(self, name: str):
        self.name = name


@dataclasses.dataclass
class DPoint:
    x: float
    y: float = 0.0


def test_a_record_compares_and_prints_as_a_dataclass():
    assert Point(1.0, 2.0) == Point(1.0, 2.0) and Point(1.0) != Point(1.0, 2.0)
    assert repr(Point(1.0, 2.0)) == repr(DPoint(1.0, 2.0)).replace("DPoint", "Point")
    assert Point(1.0, 2.0) != DPoint(1.0, 2.0)  # another class is never equal, as with dataclasses


def test_a_subclass_record_has_the_fields_of_its_bases_first():
    assert repr(Point3(1, 2, 3)) == "Point3(x=1, y=2, z=3)"
    assert Point3(1, 2, 3) != Point3(1, 2, 4)


def test_a_record_is_unhashable_and_a_frozen_record_hashes_by_its_fields():
    with pytest.raises(TypeError):
        hash(Point(1.0))
    assert {Key("a"), Key("a"), Key("b")} == {Key("a"), Key("b")}


def test_records_pickle_and_have_no_instance_dict():
    assert pickle.loads(pickle.dumps(Point3(1, 2, 3))) == Point3(1, 2, 3)
    with pytest.raises(AttributeError):
        Point(1.0).w = 2


def test_the_machine_records_keep_their_dataclass_semantics():
    assert Axis("X", max=10.0) == Axis("X", max=10.0) and Axis("X") != Axis("Y")
    assert repr(Axis("X")).startswith("Axis(name='X', kind='linear', min=-1000000000.0")
    table = Table((Field("a", Number(min=0), "doc"),))
    assert table == Table((Field("a", Number(min=0), "doc"),)) and hash(table) == hash(Table((Field(
        "a", Number(min=0), "doc"),)))


def test_replace_gives_a_new_record_with_the_changes_as_dataclasses_replace_does():
    from ncvm.records import replace
    from ncvm.sinks.limits import LimitViolation

    v = LimitViolation("X", 501.0, 500.0, "p.ngc", 3, point=(501.0, 0.0, 0.0), move=2)
    moved = replace(v, axis="A1", frame="machine")
    assert moved == LimitViolation("A1", 501.0, 500.0, "p.ngc", 3, "machine", (501.0, 0.0, 0.0), 2)
    assert v.axis == "X" and v.frame == ""


def test_the_diagnostics_records_keep_the_dataclasses_fields_equality_hash_and_repr():
    """Span, Diagnostic and the call stack's Frame are records (issue 18: no dataclass built at start-up)."""
    from ncvm import diagnostics
    from ncvm.records import replace as replace_record

    for cls in (diagnostics.Span, diagnostics.Diagnostic, diagnostics.Frame):
        assert not dataclasses.is_dataclass(cls)
    span = diagnostics.Span("p.ngc", 3, 5)
    assert repr(span) == "Span(file='p.ngc', line=3, column=5, end_column=None)" and str(span) == "p.ngc:3:5"
    assert {span, diagnostics.Span("p.ngc", 3, 5)} == {span}
    a, b = diagnostics.Diagnostic("NC001", "bad", span), diagnostics.Diagnostic("NC001", "bad", span)
    assert a == b and a.notes == [] and a.notes is not b.notes and a.severity == "error"
    assert replace_record(a, span=replace_record(span, file="<text>")).span == diagnostics.Span("<text>", 3, 5)
    assert repr(diagnostics.Frame("MAIN", None)) == "Frame(unit='MAIN', span=None)"
    assert pickle.loads(pickle.dumps(a)) == a
