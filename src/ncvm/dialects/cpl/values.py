"""CPL values at run time: NUL, binary32 REAL, type conversions on assignment, numeric fields.

Character fields and MID$ views are the chapter-5 holders of :mod:`.io.strings`.

NUL is Python ``None``: generated arithmetic on it raises TypeError, which the runtime reports as VARIABLE
NOT ASSIGNED (pyfaults); the helpers here raise that error themselves (errors.nul_used). REAL values are Python floats rounded to binary32 when stored (CPL manual §2.4.3, L650-737).
"""

from __future__ import annotations

import struct

from .errors import CplError, nul_used
from .io.strings import CharacterField, CharacterTable
from .io.values import CplText

_F32 = struct.Struct("f")
_pack = _F32.pack  # native: a value beyond the range packs as infinity, without OverflowError
_unpack = _F32.unpack
INT_MIN = -2147483648
INT_MAX = 2147483647


def f32(v):
    """Round to binary32, as a REAL variable stores it. Generated code rounds a store into a REAL local
    through a C float instead (cpl.codegen.real_store) and calls this for what that refuses or makes
    infinite, so that this names the error."""
    try:
        r = _unpack(_pack(v))[0]
    except OverflowError:
        raise CplError("CPL042", "value outside the REAL range (+/-1e38)") from None
    except struct.error:
        if v is None:
            raise nul_used() from None
        raise CplError("CPL021", f"{type_name(v)} value where a number is expected") from None
    if r - r != 0.0:  # infinity or NaN: a DOUBLE result beyond the REAL range packs without OverflowError
        raise CplError("CPL042", "value outside the REAL range (+/-1e38)")
    return r


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
    """A value stored into an INTEGER variable: no implicit REAL -> INTEGER (CPL manual §2.4.3, L650-737; §2.5, L738-770)."""
    if v.__class__ is int:
        if INT_MIN <= v <= INT_MAX:
            return v
        raise CplError("CPL027", f"{v} outside -2147483648..2147483647")
    if v is None:
        return None
    raise CplError("CPL021", f"{type_name(v)} value assigned to an INTEGER variable (use INT or ROUND)")


def to_real(v):
    if v.__class__ is int and -16777216 <= v <= 16777216:  # exact in binary32: no rounding to do
        return float(v)
    if v.__class__ is float or v.__class__ is int:
        try:
            r = _unpack(_pack(v))[0]  # f32 without the call: every REAL parameter view comes here
        except OverflowError:
            return f32(v)
        return r if r - r == 0.0 else f32(v)
    if v is None:
        return None
    raise CplError("CPL021", f"{type_name(v)} value assigned to a REAL variable")


def to_double(v):
    if v.__class__ is float:
        if v - v != 0.0:  # infinity or NaN: the result left the DOUBLE range
            raise CplError("CPL042", "value outside the DOUBLE range (+/-1e308)")
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
    """A condition must be BOOLEAN (CPL manual §2.5.7, L1006-1028)."""
    if v is True or v is False:
        return v
    if v is None:
        raise nul_used()
    raise CplError("CPL032", f"condition is {type_name(v)}, not BOOLEAN")


def not_nul(v):
    """An operand of = or <> other than the NUL keyword: NUL is VARIABLE NOT ASSIGNED (CPL manual §2.5, L758-769)."""
    if v is None:
        raise nul_used()
    return v


def word(v):
    """An [expr] value in an NC word must be a number."""
    if v.__class__ is float or v.__class__ is int:
        return v
    if v is None:
        raise nul_used()
    raise CplError("CPL032", f"NC word value is {type_name(v)}, not a number")


def word_real(v):
    """``word(to_real(v))`` in one call: a parameter's REAL view as an NC word value (the common case)."""
    if v.__class__ is int and -16777216 <= v <= 16777216:  # exact in binary32: no rounding to do
        return float(v)
    r = to_real(v)
    if r is None:
        raise nul_used()
    return r


def logic(op: str, a, b):
    """AND/OR/XOR: logical on BOOLEAN, bitwise on INTEGER, an error when mixed (CPL manual §2.4.3, L650-737)."""
    if a is None or b is None:
        raise nul_used()
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
        raise nul_used()
    raise CplError("CPL032", f"NOT of {type_name(a)}")


def index(i):
    """A field index: an INTEGER >= 0 (numeric fields accept 0..n, CPL manual §2.4.3, L680-707; §5.1, L3350-3370)."""
    if i.__class__ is int and i >= 0:
        return i
    if i is None:
        raise nul_used()
    raise CplError("CPL031", f"index {i!r}")


def sv(v):
    """The string a string variable currently holds (resolving character fields and MID$ views)."""
    if isinstance(v, CplText):
        return v.text
    return v


def new_field(sizes: list[int], kind: str):
    """A DIMensioned field: numeric 0..n per dimension; character fields as io.strings holders (chapter 5)."""
    if kind == "S":
        if len(sizes) == 1:
            return CharacterField(sizes[0])
        return CharacterTable(sizes[0], sizes[1])
    if len(sizes) == 1:
        return [None] * (sizes[0] + 1)
    return [[None] * (sizes[1] + 1) for _ in range(sizes[0] + 1)]


def report(v):
    """A variable's value for the JSON result."""
    if isinstance(v, CplText):
        return v.text
    if v.__class__ is CharacterTable:
        return [row.text for row in v.rows]
    if v.__class__ is list:
        return [report(x) for x in v]
    return v
