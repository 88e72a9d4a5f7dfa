"""The Python errors a generated CPL statement raises by its own operations, as the program's run-time errors.

Generated code computes with plain Python operators, so that a step costs nothing for checks: NUL is ``None``
and arithmetic on it raises TypeError, an index beyond a field raises IndexError, ``1 / 0`` ZeroDivisionError,
``math.sqrt(-1)`` (called directly) ValueError. Such an error is the program's only when the generated code
raised it itself: the innermost frame of its traceback is generated code (runtime.locate.raised_by_generated).
The same Python error raised inside a function of ncvm's (a value helper, the NC kernel, the planner, a sink)
is a bug in ncvm and must never read as the program's error: the helpers raise CplError with the manual's
code for every fault of the program they find (errors.nul_used and the others).
"""

from __future__ import annotations

from collections.abc import Mapping

from ...runtime.locate import raised_by_generated
from .errors import NUL_USED

#: CPL035: a field variable read or written before its DIM is None (values.new_field makes the field)
FIELD_BEFORE_DIM = "a field is used before its DIM"


def program_error(e: BaseException, sources: Mapping) -> tuple[str, str] | None:
    """The CPL code and detail of ``e`` when a generated statement raised it by its own operation on the
    program's values; None when it is ncvm's own fault (an internal error)."""
    if not raised_by_generated(e.__traceback__, sources):
        return None
    if isinstance(e, ZeroDivisionError):
        return "CPL028", ""
    if isinstance(e, IndexError) and str(e).startswith("list "):  # a DIMensioned field (a list) beyond its size
        return "CPL031", ""
    if isinstance(e, OverflowError):
        return "CPL042", "number too large"  # a float result beyond the DOUBLE range
    if isinstance(e, ValueError):  # math.sqrt, the one library function generated code calls on a value
        return "CPL029", "argument outside the domain of the function (SQRT of a negative number?)"
    text = str(e)
    if isinstance(e, (TypeError, AttributeError)) and "NoneType" in text:
        if text.startswith(_NUL_OPERAND):
            return "CPL020", NUL_USED  # an operand of + - * / < ... or of an inline ABS, INT, SQRT is NUL
        if text.endswith(_FIELD_ACCESS) or text.startswith("'NoneType' object has no attribute 'row'"):
            return "CPL035", FIELD_BEFORE_DIM  # a field local still None: X(1), T$(1) before DIM X(3)
    return None


#: Python's messages for an operation with a None operand (checked only after a fault, never per step)
_NUL_OPERAND = ("unsupported operand type", "bad operand type for ", "'<' not", "'<=' not", "'>' not",
                "'>=' not", "must be real number", "int() argument must be")
#: and for a subscript of None: a field variable read or written before its DIM
_FIELD_ACCESS = ("object is not subscriptable", "object does not support item assignment")
