"""Run-time helpers the generated code calls: 32-bit integer and timer arithmetic, conversions,
math functions (§6.6, radians, double results) and WRITE number formatting (rw_SymPas manual L2216; L2224)."""

from __future__ import annotations

import math
import struct

from ...diagnostics import RuntimeFault

_F32 = struct.Struct("<f")


class TaskFault(RuntimeFault):
    """A run-time error of the manual's table 40; the task runner adds file, line and call stack."""

    def __init__(self, number: int, message: str):
        super().__init__(str(number), message)
        self.number = number


def fault(number: int, message: str):
    raise TaskFault(number, message)


class Goto(Exception):
    """A goto out of a loop inside a dispatch block (the target is already in ``_pc``)."""


GOTO = Goto()


def wrap32(x: int) -> int:
    return ((x + 0x80000000) & 0xFFFFFFFF) - 0x80000000


def idiv(a: int, b: int) -> int:
    """Integer '/' truncates toward zero (L852-856); /0 is error 32768."""
    if b == 0:
        fault(32768, "integer division by 0")
    q = abs(a) // abs(b)
    q = q if (a >= 0) == (b >= 0) else -q
    return wrap32(q)


def imod(a: int, b: int) -> int:
    """``i mod j = i - (i/j)*j``: the result has the sign of the dividend."""
    if b == 0:
        fault(32768, "mod 0")
    r = abs(a) % abs(b)
    return r if a >= 0 else -r


def rdiv(a, b) -> float:
    if b == 0:
        fault(32768, "division by 0")
    return a / b


def f32(x) -> float:
    """Round to IEEE binary32 when stored into a ``single`` (rw_SymPas manual L556)."""
    try:
        return _F32.unpack(_F32.pack(x))[0]
    except OverflowError:
        return math.copysign(math.inf, x)


def t2i(t: int) -> int:
    """Timer -> Integer: the same 32 bits read as signed."""
    return t - 0x100000000 if t & 0x80000000 else t


def toint(x: float) -> int:
    """INTEGER(real): truncate toward zero, saturate to the 32-bit range (rw_SymPas manual L762-769)."""
    if x != x:
        return 0
    if x >= 2147483647:
        return 2147483647
    if x <= -2147483648:
        return -2147483648
    return int(x)


def fmt(x: float, digits: int = 10) -> str:
    """Single and Double in WRITE: C's %g with 10 significant digits (rw_SymPas manual L2216; L2224)."""
    return "%.*g" % (digits, x)


def _safe(fn):
    def call(*args):
        try:
            return float(fn(*args))
        except (ValueError, ZeroDivisionError):
            return math.nan
        except OverflowError:
            return math.inf
    call.__name__ = fn.__name__
    return call


#: math functions (§6.6.3 ff.): name -> implementation; invalid arguments give NaN/inf, no error
MATH = {
    "ABS": lambda x: abs(float(x)),
    "ACOS": _safe(math.acos), "ASIN": _safe(math.asin), "ATAN": _safe(math.atan),
    "COS": _safe(math.cos), "COSH": _safe(math.cosh), "EXP": _safe(math.exp),
    "LN": _safe(lambda x: math.log(x) if x > 0 else (math.nan if x < 0 else -math.inf)),
    "POWER": _safe(math.pow), "SIN": _safe(math.sin), "SINH": _safe(math.sinh),
    "SQR": lambda x: float(x) * x, "SQRT": _safe(math.sqrt), "TAN": _safe(math.tan), "TANH": _safe(math.tanh),
}
# fast paths (SQRT, SIN and COS are generated inline: codegen._INLINE)
MATH["ATAN"] = math.atan  # cannot fail, not even on inf
MATH["TANH"] = math.tanh


#: the card counts positions in whole counts held in a double, which are whole only up to 2**53 (the manual
#: gives no range): a target beyond it is an invalid parameter (Table 40, $8000), not a position
MAX_COUNTS = 2.0 ** 53


def beyond_counts(target: float):
    fault(32768, f"target position {target:g} is beyond the card's position range ({MAX_COUNTS:.0f} counts)")


def arc_counts(radius: float, phi: float, phi_deg: float) -> float:
    """The path of an arc of ``radius`` counts through ``phi`` radians. A path beyond the position range
    (PHI := 1e300 turns) is an invalid parameter like such a target, not a move of endless time."""
    arc = abs(radius * phi)
    if not arc <= MAX_COUNTS:
        fault(32768, f"PHI := {phi_deg:g}: an arc of {arc:g} counts is beyond the card's position range "
                     f"({MAX_COUNTS:.0f} counts)")
    return arc


def axis_values(items: tuple) -> tuple:
    """The (axis, value) items of a move or zero-point command: NaN or inf (a math function's "no valid
    return value") is an invalid parameter (Table 40, $8000), not a position."""
    for _, v in items:
        if not math.isfinite(v):
            fault(32768, f"axis value {v} is not a valid parameter")
    return items


def namespace(card) -> dict:
    """The globals every generated unit runs in."""

    def ovf(x: int) -> int:
        card.sys["ERRORREG"] |= 1 << 30  # simulator flag: integer overflow (rw_SymPas manual L734)
        return wrap32(x)

    ns = {"_ovf": ovf, "_idiv": idiv, "_imod": imod, "_rdiv": rdiv, "_f32": f32, "_t2i": t2i, "_toint": toint,
          "_msqrt": math.sqrt, "_msin": math.sin, "_mcos": math.cos, "_NAN": math.nan, "_fmt": fmt, "_DIGITS": int(card.cfg.write_digits), "_fault": fault, "_axis_values": axis_values, "_Goto": Goto, "_GOTO": GOTO, "__builtins__": __builtins__}
    for name, fn in MATH.items():
        ns["_F_" + name] = fn
    return ns
