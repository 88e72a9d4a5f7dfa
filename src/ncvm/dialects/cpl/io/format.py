"""Formatted output shared by PRN#, DSP, PRN and STR$ (manual L4015-4040, L4539-4612, L3514-3539).

A *format template* is a run of ``#`` with at most one ``.`` between ``#`` s (``###.###``,
``##``) inside a STRING argument. Every template of every string argument joins one queue;
each numeric argument takes the first waiting template and is printed *there*; a numeric
argument with no template waiting prints in its standard format where it stands. BOOLEAN and
STRING arguments are never formatted. Templates left over print as the ``#`` text itself.

Standard formats (CPL manual L3524-3528; L4554-4556): INTEGER 9 positions, REAL ``####.###`` (8), DOUBLE
``#########.######`` (16), right-justified with leading blanks; BOOLEAN prints TRUE/FALSE;
NUL prints nothing. A value too large for its standard format is printed whole (never cut).
Rounding is half away from zero on the decimal digits the value really has (a REAL is read
as the shortest decimal that gives back the same binary32 number, so 1.231 stays 1.231).
"""

from __future__ import annotations

import re
import struct
from collections import deque
from decimal import ROUND_HALF_UP, Context, Decimal
from typing import Iterable

from ....records import Record
from .errors import fail
from .values import kind_of, text_of

TEMPLATE = re.compile(r"#+(?:\.#+)?")

#: type letter -> (digits before the point, digits after it)
STANDARD = {"I": (9, 0), "R": (4, 3), "D": (9, 6)}


def real_decimal(value: float) -> Decimal:
    """The shortest decimal that names the same binary32 number as ``value`` (a REAL has ~7 digits)."""
    try:
        target = struct.unpack("<f", struct.pack("<f", value))[0]
    except OverflowError:
        return Decimal(repr(value))
    for digits in range(6, 10):
        text = f"{target:.{digits}g}"
        if struct.unpack("<f", struct.pack("<f", float(text)))[0] == target:
            return Decimal(text)
    return Decimal(repr(target))


def decimal_of(value, kind: str) -> Decimal:
    if kind == "I":
        return Decimal(int(value))
    if kind == "R":
        return real_decimal(float(value))
    return Decimal(repr(float(value)))


def format_number(value, kind: str, int_digits: int, decimals: int, *, pad: bool = True) -> str | None:
    """``value`` with ``decimals`` decimals in ``int_digits`` positions before the point.

    Returns None when the integer part (with its minus sign, which takes a ``#``) does not fit.
    """
    if kind == "I":  # exact already: no rounding to do
        text = str(int(value))
        if len(text) > int_digits:
            return None
        if decimals:
            text = f"{text}.{'0' * decimals}"
        return text.rjust(int_digits + (decimals + 1 if decimals else 0)) if pad else text
    if value != value or value in (float("inf"), float("-inf")):
        return None
    exact = decimal_of(value, kind)
    # room for every digit of the rounded value: a DOUBLE has up to 309 before the point
    room = Context(prec=max(exact.adjusted(), 0) + decimals + 2)
    q = exact.quantize(Decimal(1).scaleb(-decimals), rounding=ROUND_HALF_UP, context=room)
    if q.is_zero():
        q = abs(q)  # no "-0.00"
    text = format(q, f".{decimals}f")
    if len(text.split(".")[0]) > int_digits:
        return None
    width = int_digits + (decimals + 1 if decimals else 0)
    return text.rjust(width) if pad else text


def template_shape(template: str) -> tuple[int, int]:
    before, _, after = template.partition(".")
    return len(before), len(after)


def standard_text(value, kind: str, *, ljust: bool = False, trim: bool = False) -> str:
    """``value`` in the standard format of its type (widened, never cut, if it is too large). ``trim``: the
    output to files, whose trailing zeros are suppressed (L4001): blanks in the formatted field, so the point
    keeps its column, nothing under LJUST; a point with no decimals left goes too."""
    if kind == "B":
        return "TRUE" if value else "FALSE"
    if kind == "N":
        return ""
    if kind == "S":
        return text_of(value) or ""
    int_digits, decimals = STANDARD[kind]
    text = format_number(value, kind, int_digits, decimals, pad=not ljust)
    if text is None:
        text = format_number(value, kind, 400, decimals, pad=False) or "*"
    if trim and decimals and "." in text:
        width = len(text)
        text = text.rstrip("0").rstrip(".")
        if not ljust:
            text = text.ljust(width)
    return text.lstrip() if ljust else text


class Formatted(Record):
    __slots__ = ("text", "overflows")

    def __init__(self, text: str, overflows: int):
        self.text = text
        self.overflows = overflows  # templates that got '*' because the value did not fit


def format_items(items: Iterable, *, ljust: bool = False, on_overflow: str = "star", trim: bool = False) -> Formatted:
    """Concatenate the arguments of PRN#/DSP/PRN/STR$ by the template-queue rule.

    ``on_overflow``: ``"star"`` fills a template whose value does not fit with ``*`` and counts
    it (PRN# then warns PRN FORMAT INCORRECT); ``"error"`` raises ``format not permitted`` (DSP).
    ``ljust``: LJUST is active, numbers lose their leading blanks. ``trim``: numbers in their standard format
    lose their trailing zeros (output to files, L4001); a template keeps the decimals it asks for.
    """
    pieces: list[str] = []
    waiting: deque[tuple[int, str]] = deque()
    overflows = 0
    for item in items:
        kind = kind_of(item)
        if kind == "S":
            text = text_of(item) or ""
            if "#" not in text:  # no template in it (most strings)
                if text:
                    pieces.append(text)
                continue
            pos = 0
            for m in TEMPLATE.finditer(text):
                if m.start() > pos:
                    pieces.append(text[pos:m.start()])
                waiting.append((len(pieces), m.group()))
                pieces.append(m.group())
                pos = m.end()
            if pos < len(text):
                pieces.append(text[pos:])
        elif kind in "IRD" and waiting:
            index, template = waiting.popleft()
            int_digits, decimals = template_shape(template)
            text = format_number(item, kind, int_digits, decimals, pad=not ljust)
            if text is None:
                if on_overflow == "error":
                    raise fail("FORMAT_NOT_PERMITTED", f"{item!r} in {template}")
                overflows += 1
                text = "*" * len(template)
            pieces[index] = text
        else:
            pieces.append(standard_text(item, kind, ljust=ljust, trim=trim))
    return Formatted("".join(pieces), overflows)


class OutputMode(Record):
    """Program-wide output state shared by PRN#, DSP and PRN: LJUST on/off (L3997-4003)."""

    __slots__ = ("ljust",)

    def __init__(self, ljust: bool = False):
        self.ljust = ljust

    def LJUST(self) -> None:  # noqa: N802 - the CPL statement
        self.ljust = True

    def NJUST(self) -> None:  # noqa: N802 - the CPL statement
        self.ljust = False
