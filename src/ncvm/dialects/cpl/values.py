"""CPL values at run time: NUL, binary32 REAL, character fields with a current length, MID$ views.

NUL is Python ``None``: arithmetic on it raises TypeError, which the runtime reports as VARIABLE NOT
ASSIGNED. REAL values are Python floats rounded to binary32 when stored (digest §4.2).
"""

from __future__ import annotations

import struct

from .errors import CplError

_F32 = struct.Struct("f")
_pack = _F32.pack
_unpack = _F32.unpack
INT_MIN = -2147483648
INT_MAX = 2147483647


def f32(v):
    """Round to binary32, as a REAL variable stores it."""
    try:
        return _unpack(_pack(v))[0]
    except OverflowError:
        raise CplError("CPL029", "value outside the REAL range (+/-1e38)") from None
    except struct.error:
        if v is None:
            raise TypeError("NUL") from None
        raise CplError("CPL021", f"{type_name(v)} value where a number is expected") from None


def type_name(v) -> str:
    if v is None:
        return "NUL"
    if isinstance(v, bool):
        return "BOOLEAN"
    if isinstance(v, int):
        return "INTEGER"
    if isinstance(v, float):
        return "REAL"
    return "CHARACTER"


def to_int(v):
    """A value stored into an INTEGER variable: no implicit REAL -> INTEGER (digest §4.3)."""
    if v.__class__ is int:
        if INT_MIN <= v <= INT_MAX:
            return v
        raise CplError("CPL027", f"{v} outside -2147483648..2147483647")
    if v is None:
        return None
    raise CplError("CPL021", f"{type_name(v)} value assigned to an INTEGER variable (use INT or ROUND)")


def int_overflow(v):
    raise CplError("CPL027", f"{v} outside -2147483648..2147483647")


def to_real(v):
    if v.__class__ is float or v.__class__ is int:
        return f32(v)
    if v is None:
        return None
    raise CplError("CPL021", f"{type_name(v)} value assigned to a REAL variable")


def to_double(v):
    if v.__class__ is float:
        return v
    if v.__class__ is int:
        return float(v)
    if v is None:
        return None
    raise CplError("CPL021", f"{type_name(v)} value assigned to a DOUBLE variable")


def to_bool(v):
    if v.__class__ is bool or v is None:
        return v
    raise CplError("CPL021", f"{type_name(v)} value assigned to a BOOLEAN variable")


def to_str(v):
    v = sv(v)
    if v.__class__ is str or v is None:
        return v
    raise CplError("CPL021", f"{type_name(v)} value assigned to a CHARACTER variable")


def cond(v):
    """A condition must be BOOLEAN (digest §5.2)."""
    if v is True or v is False:
        return v
    if v is None:
        raise TypeError("NUL")
    raise CplError("CPL032", f"condition is {type_name(v)}, not BOOLEAN")


def word(v):
    """An [expr] value in an NC word must be a number."""
    if v.__class__ is float or v.__class__ is int:
        return v
    if v is None:
        raise TypeError("NUL")
    raise CplError("CPL032", f"NC word value is {type_name(v)}, not a number")


def logic(op: str, a, b):
    """AND/OR/XOR: logical on BOOLEAN, bitwise on INTEGER, an error when mixed (digest §4.2)."""
    if a is None or b is None:
        raise TypeError("NUL")
    ta, tb = a.__class__, b.__class__
    if ta is not tb or ta not in (bool, int):
        raise CplError("CPL032", f"{op} of {type_name(a)} and {type_name(b)}")
    if op == "AND":
        return a & b
    if op == "OR":
        return a | b
    return a ^ b


def lnot(a):
    if a.__class__ is bool:
        return not a
    if a.__class__ is int:
        return ~a
    if a is None:
        raise TypeError("NUL")
    raise CplError("CPL032", f"NOT of {type_name(a)}")


def index(i):
    """A field index: an INTEGER >= 0 (numeric fields accept 0..n, digest §4.6)."""
    if i.__class__ is int and i >= 0:
        return i
    if i is None:
        raise TypeError("NUL")
    raise CplError("CPL031", f"index {i!r}")


class CharField:
    """A DIMensioned character field: up to ``size`` characters, of which the first ``len(s)`` are assigned."""

    __slots__ = ("size", "s")

    def __init__(self, size: int):
        self.size = size
        self.s: str | None = None

    def set(self, v) -> None:
        v = sv(v)
        if v is None:
            self.s = None
            return
        if v.__class__ is not str:
            raise CplError("CPL021", f"{type_name(v)} value assigned to a character field")
        self.s = v[: self.size]

    def __repr__(self) -> str:
        return f"CharField({self.size}, {self.s!r})"


class MidView:
    """``C$ = MID$(A$, 2, 5)`` into a non-dimensioned variable: a live view into the field (manual L3373-3401)."""

    __slots__ = ("field", "start", "count")

    def __init__(self, field: CharField, start: int, count: int | None):
        self.field = field
        self.start = start
        self.count = count

    def value(self):
        return mid(self.field.s, self.start, self.count)


def sv(v):
    """The string a string variable currently holds (resolving MID$ views and fields)."""
    c = v.__class__
    if c is MidView:
        return v.value()
    if c is CharField:
        return v.s
    return v


def check_pos(v, what: str) -> int:
    if v.__class__ is not int or not 1 <= v <= 1024:
        if v is None:
            raise TypeError("NUL")
        raise CplError("CPL023", f"{what} {v!r} outside 1..1024")
    return v


def mid(s, start, count=None):
    """MID$ read: count clipped at the end; a start past the end gives NUL (manual §5.2)."""
    start = check_pos(start, "MID$ start")
    if count is not None:
        count = check_pos(count, "MID$ count")
    s = sv(s)
    if s is None:
        return None
    if s.__class__ is not str:
        raise CplError("CPL032", "MID$ of a non-string")
    if start > len(s):
        return None
    return s[start - 1:] if count is None else s[start - 1:start - 1 + count]


def mid_write(field, start, count, value) -> None:
    """MID$(field, start[, count]) = value: overwrite or extend in place (manual §5.3)."""
    if field.__class__ is not CharField:
        if field is None:
            raise CplError("CPL035", "MID$ target")
        raise CplError("CPL025", "MID$(...)= needs a DIMensioned character field")
    start = check_pos(start, "MID$ start")
    if count is not None:
        count = check_pos(count, "MID$ count")
    value = sv(value)
    if value is None:
        raise TypeError("NUL")
    cur = field.s or ""
    if start > len(cur) + 1:
        raise CplError("CPL024", f"start {start} beyond current length {len(cur)} + 1")
    n = len(value) if count is None else min(count, len(value))
    piece = value[:n]
    new = cur[: start - 1] + piece + cur[start - 1 + len(piece):]
    field.s = new[: field.size]


def new_field(sizes: list[int], kind: str):
    """A DIMensioned field: numeric 0..n per dimension; character fields as CharField rows."""
    if kind == "S":
        if len(sizes) == 1:
            return CharField(sizes[0])
        return [CharField(sizes[1]) for _ in range(sizes[0] + 1)]
    if len(sizes) == 1:
        return [None] * (sizes[0] + 1)
    return [[None] * (sizes[1] + 1) for _ in range(sizes[0] + 1)]


def report(v):
    """A variable's value for the JSON result."""
    c = v.__class__
    if c is CharField or c is MidView:
        return sv(v)
    if c is list:
        return [report(x) for x in v]
    return v
