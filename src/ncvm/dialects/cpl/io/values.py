"""How CPL values arrive at the I/O functions, and how their CPL type is told apart.

Conventions for the code generator:

* INTEGER = Python ``int``, BOOLEAN = ``bool``, REAL = ``float`` (binary32-rounded or not),
  DOUBLE = :class:`Double` (a ``float`` subclass; wrap a DOUBLE-typed expression where its
  type matters for output: ``Double(x)``), strings = ``str`` or any :class:`CplText` (character
  fields and MID$ views of :mod:`.strings`), NUL = ``None``.
"""

from __future__ import annotations

from .errors import fail


class Double(float):
    """A DOUBLE-typed value (``X!``): formatted with the DOUBLE standard format 9.6."""

    __slots__ = ()


class CplText:
    """Base of string holders (character fields, MID$ views): ``text`` is the current string or None (NUL)."""

    __slots__ = ()

    @property
    def text(self) -> str | None:  # pragma: no cover - overridden
        raise NotImplementedError


def text_of(value) -> str | None:
    """The string a string value stands for, None for NUL."""
    if value is None or isinstance(value, str):
        return value
    if isinstance(value, CplText):
        return value.text
    raise fail("INVALID_PARAMETER", f"a string is needed here, not {value!r}")


def is_text(value) -> bool:
    return isinstance(value, (str, CplText))


def kind_of(value) -> str:
    """One letter for the CPL type of ``value``: I R D B S, or N for NUL."""
    if value is None:
        return "N"
    if isinstance(value, bool):
        return "B"
    if isinstance(value, int):
        return "I"
    if isinstance(value, Double):
        return "D"
    if isinstance(value, float):
        return "R"
    if is_text(value):
        return "S"
    raise TypeError(f"not a CPL value: {value!r}")
