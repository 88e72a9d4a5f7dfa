"""One row of the @ code table: what the code is, its operands, and who lowers and runs it.

Operand notation letters (manual §10.1.3, L6375-6382): ``K`` <Const> (constant only), ``R`` <R-Par>
(R parameter only), ``V`` <Var> (R parameter or pointer), ``W`` <Value> (constant, R parameter or
pointer), ``J`` the jump operand of ``@100`` (constant or R parameter). ``None`` marks the codes with a
variable operand list (``@040``/``@042``, ``@111``).
"""

from __future__ import annotations

from dataclasses import dataclass

from ..errors import ReadError


@dataclass(frozen=True, slots=True)
class AtCode:
    """``lower``: the code generator's ``lower_<lower>`` method that turns the code into Python;
    ``run``: the run-time function that executes it (groups 3, 4, 7, a), a method of the
    channel or of one of its parts (``offsets.zo_read``); ``expr``: the Python
    template of a jump condition (group 1) or a result (group 6); ``overflows``: the result may leave the
    double range for finite operands; ``underflows``: it may come out below the smallest R magnitude
    0.00000001 (L7079) for operands in range (SIN 180 is 1.2e-16 in doubles, 0 on the NC). ``cl800``: how a CL 800 program writes the code (``function``,
    ``read``, ``write``, ``nc_function``, ``procedure``, ``logic``) under ``name`` (default the
    statement), ``regs`` the R parameters a read or NC function writes, ``args`` the procedure's
    argument kinds where they are not the operand kinds (``b`` a bit access)."""

    code: str
    statement: str
    kinds: str | None
    line: int
    lower: str
    run: str | None = None
    expr: str | None = None
    overflows: bool = False
    underflows: bool = False
    cl800: str | None = None
    name: str | None = None
    regs: int = 1
    args: str | None = None

    @property
    def count(self) -> int | None:
        return None if self.kinds is None else len(self.kinds)

    @property
    def cl800_name(self) -> str:
        return self.name or self.statement

    def check(self, ops, col: int) -> None:
        """Refuse operands the code does not take (SIN003)."""
        code = self.code
        if self.kinds is None:
            _check_variable(code, ops, col)
            return
        if len(ops) != len(self.kinds):
            raise ReadError(col, f"@{code} ({self.statement}) needs {len(self.kinds)} operand(s) "
                                 f"({' '.join(_NAMES[k] for k in self.kinds) or 'none'}), got {len(ops)}", "SIN003")
        for i, (op, k) in enumerate(zip(ops, self.kinds)):
            if op.kind not in _ALLOWED[k]:
                raise ReadError(col, f"@{code} ({self.statement}): operand {i + 1} must be {_NAMES[k]}, "
                                     f"not {op.kind}", "SIN003")
        if code in ("041", "043") and ops[0].value > ops[1].value:
            raise ReadError(col, f"@{code} ({self.statement}): R{int(ops[0].value)} to R{int(ops[1].value)} is no "
                                 "range (the first R parameter must come first)", "SIN003")


_ALLOWED = {"K": "K", "R": "R", "V": "RP", "W": "KRP", "J": "KR"}
_NAMES = {"K": "<Const>", "R": "<R-Par>", "V": "<Var>", "W": "<Value>", "J": "<Const>/<R-Par>"}


def _check_variable(code: str, ops, col: int) -> None:
    if code in ("040", "042"):
        if not ops or ops[0].kind != "K" or ops[0].value != int(ops[0].value) or ops[0].value < 1:
            raise ReadError(col, f"@{code}: K<n> (number of R parameters) expected first", "SIN003")
        if len(ops) != 1 + int(ops[0].value) or any(o.kind != "R" for o in ops[1:]):
            raise ReadError(col, f"@{code}: K{int(ops[0].value)} must be followed by {int(ops[0].value)} "
                                 f"R parameters", "SIN003")
    elif code == "111":
        if len(ops) < 3 or len(ops) % 2 == 0 or ops[0].kind not in "RP":
            raise ReadError(col, "@111 (CASE): <Var> followed by pairs of <Value> <Const block no.>", "SIN003")
        for o in ops[2::2]:
            if o.kind != "K":
                raise ReadError(col, "@111 (CASE): each jump target must be a constant block number", "SIN003")
