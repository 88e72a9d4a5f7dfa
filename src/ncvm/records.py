"""Plain classes that compare and print as dataclasses do, without what a dataclass costs at import.

A dataclass compiles its generated methods when its module is imported: about 0.7 ms a class, 1.2 ms a
frozen one, paid by every start-up whose path imports the module. A :class:`Record` subclass
lists its fields as ``__slots__`` and writes its ``__init__`` out; comparison and ``repr`` come from here.
"""

from __future__ import annotations


class Record:
    """Fields are the ``__slots__`` along the class's bases; equal when of the same class with equal fields;
    unhashable, as a dataclass with ``eq`` and without ``frozen``."""

    __slots__ = ()
    __hash__ = None

    def _fields(self) -> tuple[str, ...]:
        return tuple(f for c in reversed(type(self).__mro__) for f in c.__dict__.get("__slots__", ()))

    def __eq__(self, other):
        if other.__class__ is not self.__class__:
            return NotImplemented
        return all(getattr(self, f) == getattr(other, f) for f in self._fields())

    def __repr__(self) -> str:
        return f"{type(self).__qualname__}({', '.join(f'{f}={getattr(self, f)!r}' for f in self._fields())})"


def replace(record: Record, **changes) -> Record:
    """A new record of the same class with ``changes`` to its fields, as :func:`dataclasses.replace` (a
    record's ``__init__`` takes its fields by their names)."""
    return type(record)(**{**{f: getattr(record, f) for f in record._fields()}, **changes})


class FrozenRecord(Record):
    """A record hashed by its fields, as a frozen dataclass (for values built once and never changed)."""

    __slots__ = ()

    def __hash__(self) -> int:
        return hash(tuple(getattr(self, f) for f in self._fields()))
