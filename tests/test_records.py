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
