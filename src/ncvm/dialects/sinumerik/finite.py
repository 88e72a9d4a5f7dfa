"""Which R arithmetic needs the range check (an inf/NaN result is the CL 800 error, L7079).

Every R value is finite (each producer is checked or cannot leave the double
range), so a check is needed only where a result may overflow, and only once
per block for a value that flows on: a non-finite value stays non-finite
through ``+ - *`` (``inf * 0`` is NaN) and through division by a non-zero
constant, so the check of a later assignment of the same block that reads it
reports the same fault on the same line. Only runs of consecutive assignments
are considered: any other item (a DIN word, an @ code) may read the value.
"""

from __future__ import annotations

from .reader import Arith, Operand

#: below half an ulp of the largest double, adding to a finite value rounds to at most that double
_SAFE_ADDEND = 2.0 ** 969


def cannot_overflow(terms: list[tuple[str, Operand]]) -> bool:
    """A finite-operand expression whose result is finite: one term, or one R parameter scaled down by a
    constant (``R*c``, ``c*R`` with ``|c| <= 1``; ``R/c`` with ``|c| >= 1``) or shifted by a small constant."""
    if len(terms) == 1:
        return True
    if len(terms) != 2 or terms[0][0] == "-":
        return False
    (_, a), (op, b) = terms
    consts = [t for t in (a, b) if t.kind == "K"]
    if len(consts) != 1 or "P" in (a.kind, b.kind):
        return False
    c = abs(consts[0].value)
    if op == "*":
        return c <= 1.0
    if op == "/":
        return b.kind == "K" and c >= 1.0
    return c < _SAFE_ADDEND  # + and -


def _carries(terms: list[tuple[str, Operand]], r: int) -> bool:
    """A non-finite R<r> makes this expression's result non-finite: it is read other than as a divisor,
    and every division after it is by a non-zero constant."""
    for k, (op, t) in enumerate(terms):
        if t.kind == "R" and int(t.value) == r and op != "/":
            return all(o != "/" or (u.kind == "K" and u.value != 0.0) for o, u in terms[k + 1:])
    return False


def _reads(terms: list[tuple[str, Operand]], r: int) -> bool:
    return any(t.kind == "R" and int(t.value) == r for _, t in terms)


def checked(run: list[Arith]) -> list[bool]:
    """For consecutive assignments of one block: which must check their result."""
    need = [False] * len(run)
    covered = [False] * len(run)  # a non-finite result reaches a later check of the run
    for i in range(len(run) - 1, -1, -1):
        r = run[i].target
        for j in range(i + 1, len(run)):
            terms = run[j].terms
            if _reads(terms, r):
                covered[i] = _carries(terms, r) and (need[j] or covered[j])
                break
            if run[j].target == r:
                break  # overwritten unread: the control stops at the overflow all the same
        need[i] = not covered[i] and not cannot_overflow(run[i].terms)
    return need
