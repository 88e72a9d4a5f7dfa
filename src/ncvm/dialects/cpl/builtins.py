"""CPL built-in functions as a table: name -> implementation, arity, result type, manual place.

Chapter 5 (strings) is implemented once, in :mod:`.io.strings`; chapters 6-9 (files, dialog, MMC)
take the run's :class:`~.io.context.CplIO` as their first argument ("io" flag).

Result type "=" means the type of the first argument; "RD" means DOUBLE when the argument is DOUBLE, else REAL.
Functions that read the machine (chapter 4, table in the system package) take the runtime as their first argument ("rt" flag).
"""

from __future__ import annotations

import math

from .errors import CplError, nul_used
from .io import strings as S
from .system import SYSTEM_FUNCTIONS
from .table import Builtin
from .values import not_nul, type_name


def _num(v, name: str):
    if v.__class__ is int or v.__class__ is float:
        return v
    if v is None:
        raise nul_used()
    raise CplError("CPL032", f"{name} of {type_name(v)}")


def _int32(v: float, name: str) -> int:
    if not -2147483648 <= v <= 2147483647:  # also false for NaN
        raise CplError("CPL027", f"{name} result {v} outside the INTEGER range")
    return int(v)


def f_abs(x):
    return abs(_num(x, "ABS"))


def f_int(x):
    x = _num(x, "INT")
    return _int32(x if x.__class__ is int else math.trunc(x) if x - x == 0.0 else x, "INT")


def f_round(x):
    x = _num(x, "ROUND")
    if x - x != 0.0:  # infinity or NaN: math.floor would raise before the range check
        return _int32(x, "ROUND")
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


# the file number or name of a file function is needed: NUL there is VARIABLE NOT ASSIGNED
def f_eof(io, n):
    return io.files.EOF(not_nul(n))


def f_filepos(io, n, mode=None):
    return io.files.FILEPOS(not_nul(n), mode)


def f_filesize(io, n, k=None):
    return io.files.FILESIZE(not_nul(n), k)


def f_erase(io, name):
    return io.files.ERASE(not_nul(name))


def f_filedate(io, name, mode=None):
    return io.files.FILEDATE(not_nul(name), mode)


def f_inkey(io):
    return io.screen.INKEY()


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
    "LEN": Builtin(S.length, 1, 1, "I", "§5.4 L3431", params="S"),
    "MID$": Builtin(S.mid, 2, 3, "S", "§5.2 L3371", params="SII"),
    "INSTR": Builtin(S.instr, 2, 3, "I", "§5.5 L3451", params="SSI"),
    "ASC": Builtin(S.asc, 1, 1, "I", "§5.6 L3480", params="S"),
    "CHR$": Builtin(S.chr_, 1, 1, "S", "§5.7 L3502", params="I"),
    "VAL": Builtin(S.val, 1, 1, "?", "§5.9 L3541", params="S"),
    "TRIM$": Builtin(S.trim, 1, 2, "S", "§5.10 L3571", params="SS"),
    "STR$": Builtin(S.str_, 1, 2, "S", "§5.8 L3514"),
    "EOF": Builtin(f_eof, 1, 1, "B", "§6 L4157", io=True, params="I"),
    "FILEPOS": Builtin(f_filepos, 1, 2, "I", "§6 L4197", io=True),
    "FILESIZE": Builtin(f_filesize, 1, 2, "I", "§6 L4305", io=True),
    "ERASE": Builtin(f_erase, 1, 1, "I", "§6 L4379", io=True),
    "FILEDATE": Builtin(f_filedate, 1, 2, "S", "§6 L4433", io=True, params="SI"),
    "INKEY": Builtin(f_inkey, 0, 0, "I", "§7 L4625", io=True),
}

FUNCTIONS.update(SYSTEM_FUNCTIONS)  # chapter 4

__all__ = ["FUNCTIONS", "Builtin"]
