"""Which R arithmetic needs the range check: a result beyond +/-99999999 (L7079: "The value range is from
+/- 0.00000001 to +/- 99999999"), infinity or NaN is the CL 800 error, never a stored value.

Every R value is in range (each producer is checked or cannot leave the range), so an assignment needs
the check unless its result provably stays in range: one term, or one R parameter scaled down by a
constant. A value out of range may come back into it in a later assignment of the block (``R5=R4-2``),
so each assignment that may leave the range checks its own result.
"""

from __future__ import annotations

from .ncdata import R_LIMIT, R_SMALLEST
from .reader import Operand


def stays_in_range(terms: list[tuple[str, Operand]]) -> bool:
    """An in-range-operand expression whose result is in range: an R parameter or a constant within the
    range (negated or not), or one R parameter scaled down by a constant (``R*c``, ``c*R`` with
    ``|c| <= 1``; ``R/c`` with ``|c| >= 1``)."""
    if len(terms) == 1:
        t = terms[0][1]
        return t.kind != "K" or abs(t.value) <= R_LIMIT
    if len(terms) != 2:
        return False
    (_, a), (op, b) = terms
    consts = [t for t in (a, b) if t.kind == "K"]
    if len(consts) != 1:
        return False
    c = abs(consts[0].value)
    if op == "*":
        return c <= 1.0
    if op == "/":
        return b.kind == "K" and c >= 1.0
    return c == 0.0  # + and -: any other constant can carry a value over the limit



def may_underflow(terms: list[tuple[str, Operand]]) -> bool:
    """Whether the result may come out nonzero below the smallest magnitude +/-0.00000001 (L7079), which
    the NC does not hold: any arithmetic of two or more terms, or a constant that small."""
    if len(terms) > 1:
        return True
    t = terms[0][1]
    return t.kind == "K" and 0.0 < abs(t.value) < R_SMALLEST
