"""CPL built-in functions of chapters 2-3 and 5 as a table: name -> implementation, arity, result type, manual place.

Result type "=" means the type of the first argument; "RD" means DOUBLE when the argument is DOUBLE, else REAL.
Functions that read the machine (MPOS) take the runtime as their first argument ("rt" flag).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable

from .errors import CplError
from .values import CharField, check_pos, mid, sv, type_name


def _num(v, name: str):
    if v.__class__ is int or v.__class__ is float:
        return v
    if v is None:
        raise TypeError("NUL")
    raise CplError("CPL032", f"{name} of {type_name(v)}")


def _int32(v: float, name: str) -> int:
    if not -2147483648 <= v <= 2147483647:
        raise CplError("CPL027", f"{name} result {v} outside the INTEGER range")
    return int(v)


def f_abs(x):
    return abs(_num(x, "ABS"))


def f_int(x):
    return _int32(math.trunc(_num(x, "INT")), "INT")


def f_round(x):
    x = _num(x, "ROUND")
    r = math.floor(abs(x) + 0.5)
    return _int32(r if x >= 0 else -r, "ROUND")


def f_sqrt(x):
    try:
        return _msqrt(x)
    except (ValueError, TypeError):
        x = _num(x, "SQRT")
        raise CplError("CPL029", f"SQRT of the negative number {x}") from None


_msqrt = math.sqrt


_RAD = math.pi / 180.0
_DEG = 180.0 / math.pi


def f_sin(x):
    return math.sin(_num(x, "SIN") * _RAD)


def f_cos(x):
    return math.cos(_num(x, "COS") * _RAD)


def f_tan(x):
    x = _num(x, "TAN")
    if math.fmod(abs(x), 180.0) == 90.0:
        raise CplError("CPL029", f"TAN({x}) is not defined")
    return math.tan(x * _RAD)


def f_asin(x):
    x = _num(x, "ASIN")
    if not -1.0 <= x <= 1.0:
        raise CplError("CPL029", f"ASIN({x}) outside -1..1")
    return math.asin(x) * _DEG


def f_acos(x):
    x = _num(x, "ACOS")
    if not -1.0 <= x <= 1.0:
        raise CplError("CPL029", f"ACOS({x}) outside -1..1")
    return math.acos(x) * _DEG


def f_atan(x):
    return math.atan(_num(x, "ATAN")) * _DEG


def f_bcd(x):
    """Binary to packed BCD: BCD(49) = 73 (0x49), manual §2.5.3."""
    if x.__class__ is not int:
        _num(x, "BCD")
        raise CplError("CPL032", "BCD needs an INTEGER")
    if not 0 <= x <= 99999999:
        raise CplError("CPL023", f"BCD({x}): 0..99999999")
    return int(str(x), 16)


def f_bin(x):
    """Packed BCD to binary: BIN(49) = 31 (0x31 -> 31), manual §2.5.3."""
    if x.__class__ is not int:
        _num(x, "BIN")
        raise CplError("CPL032", "BIN needs an INTEGER")
    if x < 0:
        raise CplError("CPL023", f"BIN({x}) of a negative number")
    digits = f"{x:x}"
    if any(c > "9" for c in digits):
        raise CplError("CPL023", f"BIN({x}): {x:#x} is not BCD")
    return int(digits)


def _s(v, name: str):
    v = sv(v)
    if v is None or v.__class__ is str:
        return v
    raise CplError("CPL032", f"{name} of {type_name(v)}")


def f_len(s):
    s = _s(s, "LEN")
    return -1 if s is None else len(s)


def f_asc(s):
    s = _s(s, "ASC")
    return -1 if not s else ord(s[0])


def f_chr(n):
    if n.__class__ is not int:
        _num(n, "CHR$")
        raise CplError("CPL032", "CHR$ needs an INTEGER")
    if not 0 <= n <= 255:
        raise CplError("CPL023", f"CHR$({n}) outside 0..255")
    return chr(n)


def f_mid(s, start, count=None):
    return mid(_s(s, "MID$"), start, count)


def f_instr(find, s, start=1):
    find, s = _s(find, "INSTR"), _s(s, "INSTR")
    start = check_pos(start, "INSTR start")
    if find is None or s is None:
        return 0
    return s.find(find, start - 1) + 1


def f_trim(s, mode=None):
    s = _s(s, "TRIM$")
    if s is None:
        return None
    mode = _s(mode, "TRIM$") if mode is not None else None
    if mode is None:
        return s.strip(" ")
    if mode.upper() == "L":
        return s.lstrip(" ")
    if mode.upper() == "R":
        return s.rstrip(" ")
    raise CplError("CPL023", f"TRIM$ option {mode!r} (L or R)")


def f_val(s):
    """Text to number: skip blanks and zeros, one sign, digits and '.', stop at anything else (manual §5)."""
    s = _s(s, "VAL")
    if s is None:
        return None
    i, n = 0, len(s)
    while i < n and s[i] == " ":
        i += 1
    sign = 1
    if i < n and s[i] in "+-":
        sign = -1 if s[i] == "-" else 1
        i += 1
        while i < n and s[i] == " ":
            i += 1
    j = i
    while j < n and (s[j].isdigit() or (s[j] == "." and "." not in s[i:j])):
        j += 1
    text = s[i:j]
    if not any(c.isdigit() for c in text):
        return None
    return sign * (float(text) if "." in text else int(text))


#: standard output formats (digest §11.D7): INTEGER 9 places, REAL 4.3, DOUBLE 9.6
STANDARD = {"I": (9, 0), "R": (8, 3), "D": (16, 6)}


def format_number(v, width: int, decimals: int) -> str:
    """Right-justified in ``width`` places with ``decimals`` decimals; '*' when it does not fit (§6.3)."""
    text = f"{v:.{decimals}f}" if decimals or isinstance(v, float) else str(v)
    if decimals == 0 and isinstance(v, float):
        text = f"{v:.0f}"
    return text.rjust(width) if len(text) <= width else "*" * width


def f_str(*args):
    """STR$([format,] value): a number as text, in a '#'/'.' template or the standard format (manual §5.8)."""
    *given, vtype = args
    if len(given) == 1:
        value, fmt = given[0], None
    else:
        fmt, value = _s(given[0], "STR$"), given[1]
    value = _num(value, "STR$")
    if fmt is None:
        width, decimals = STANDARD["I" if isinstance(value, int) else ("D" if vtype == "D" else "R")]
        return format_number(value, width, decimals)
    i = next((k for k, c in enumerate(fmt) if c == "#"), -1)
    if i < 0:
        return fmt
    j = i
    while j < len(fmt) and fmt[j] in "#.":
        j += 1
    field = fmt[i:j]
    decimals = len(field) - field.index(".") - 1 if "." in field else 0
    return fmt[:i] + format_number(value, len(field), decimals) + fmt[j:]


def f_mpos(rt, sel, axtype=1, chan=None):
    """MPOS: the interpolated command position of an axis in the machine coordinate system (manual §4.2.2).

    Reads what block *execution* has reached: without a WAIT, blocks still queued are not in it (§4.1).
    """
    return rt.machine_position(sel)


def f_cpos(rt, sel, seltype=1):
    """CPOS: the last programmed absolute position of a coordinate, at block preparation (manual §4.2.1)."""
    return rt.programmed_position(sel)


def f_axo(rt, sel, seltype=1):
    """AXO: the last activated G92 shift of a coordinate, at block preparation (manual §4.2.1)."""
    return rt.g92_shift(sel)


@dataclass(frozen=True, slots=True)
class Builtin:
    impl: Callable
    min_args: int
    max_args: int
    result: str  # I R D B S, "=" first argument's type, "RD", "?" decided at run time
    section: str
    rt: bool = False


FUNCTIONS: dict[str, Builtin] = {
    "ABS": Builtin(f_abs, 1, 1, "=", "§2.5.1 L793"),
    "INT": Builtin(f_int, 1, 1, "I", "§2.5.1 L804"),
    "ROUND": Builtin(f_round, 1, 1, "I", "§2.5.1 L814"),
    "SQRT": Builtin(f_sqrt, 1, 1, "RD", "§2.5.1 L824"),
    "SIN": Builtin(f_sin, 1, 1, "RD", "§2.5.1 L835"),
    "COS": Builtin(f_cos, 1, 1, "RD", "§2.5.1 L835"),
    "TAN": Builtin(f_tan, 1, 1, "RD", "§2.5.1 L835"),
    "ASIN": Builtin(f_asin, 1, 1, "RD", "§2.5.1 L835"),
    "ACOS": Builtin(f_acos, 1, 1, "RD", "§2.5.1 L835"),
    "ATAN": Builtin(f_atan, 1, 1, "RD", "§2.5.1 L835"),
    "BCD": Builtin(f_bcd, 1, 1, "I", "§2.5.3 L877"),
    "BIN": Builtin(f_bin, 1, 1, "I", "§2.5.3 L889"),
    "LEN": Builtin(f_len, 1, 1, "I", "§5.4 L3431"),
    "MID$": Builtin(f_mid, 2, 3, "S", "§5.2 L3371"),
    "INSTR": Builtin(f_instr, 2, 3, "I", "§5.5 L3451"),
    "ASC": Builtin(f_asc, 1, 1, "I", "§5.6 L3480"),
    "CHR$": Builtin(f_chr, 1, 1, "S", "§5.7 L3502"),
    "VAL": Builtin(f_val, 1, 1, "?", "§5.9 L3541"),
    "TRIM$": Builtin(f_trim, 1, 2, "S", "§5.10 L3571"),
    "STR$": Builtin(f_str, 1, 2, "S", "§5.8 L3514"),
    "MPOS": Builtin(f_mpos, 1, 3, "R", "§4.2.2 L1539", rt=True),
    "CPOS": Builtin(f_cpos, 1, 2, "R", "§4.2.1 L1404", rt=True),
    "AXO": Builtin(f_axo, 1, 2, "R", "§4.2.1 L1388", rt=True),
}

from .system import SYSTEM_FUNCTIONS  # noqa: E402 - chapter 4 (the system package uses Builtin)

FUNCTIONS.update(SYSTEM_FUNCTIONS)

__all__ = ["FUNCTIONS", "Builtin", "CharField"]
