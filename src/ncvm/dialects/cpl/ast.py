"""The CPL syntax tree: expressions, and statements as a flat list per program.

Structured statements (IF, CASE, FOR, WHILE, REPEAT) span many blocks and may hold NC blocks, so the
parser emits them as flat markers (``If``, ``Else``, ``EndIf`` ...); the linker pairs the markers.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from .lexer import VarName


# -- expressions ---------------------------------------------------------
@dataclass(slots=True)
class Num:
    value: int | float
    type: str  # "I" or "R"


@dataclass(slots=True)
class Str:
    value: str


@dataclass(slots=True)
class BoolLit:
    value: bool


@dataclass(slots=True)
class Nul:
    pass


@dataclass(slots=True)
class Var:
    var: VarName
    index: list | None = None  # index expressions, or None
    col: int = 0


@dataclass(slots=True)
class Func:
    name: str
    args: list  # expressions or None for an empty position
    col: int = 0


@dataclass(slots=True)
class Unary:
    op: str  # "-", "+", "NOT"
    operand: object


@dataclass(slots=True)
class Bin:
    op: str
    left: object
    right: object


# -- statements ----------------------------------------------------------
@dataclass(slots=True)
class Stmt:
    line: int = 0  # physical line
    col: int = 0
    cpl: int | None = None  # CPL line number of the block


@dataclass(slots=True)
class Assign(Stmt):
    target: Var | None = None
    expr: object = None
    mid: tuple | None = None  # (start, count) for MID$(target, start, count) = expr


@dataclass(slots=True)
class Goto(Stmt):
    kind: str = ""  # "line", "n", "label"
    target: object = None


@dataclass(slots=True)
class CallStmt(Stmt):
    name: str = ""
    args: list = field(default_factory=list)
    din: bool = False


@dataclass(slots=True)
class Dim(Stmt):
    items: list = field(default_factory=list)  # (VarName, [sizes])


@dataclass(slots=True)
class Pdim(Stmt):
    var: VarName | None = None
    size: int = 0


@dataclass(slots=True)
class Wait(Stmt):
    neg: bool = False
    ic: list | None = None  # IC(...) argument expressions
    state: object = None
    duration: object = None
    result: Var | None = None
    plain: bool = True


@dataclass(slots=True)
class Proc(Stmt):
    name: str = ""
    args: list = field(default_factory=list)
    no_end: bool = False  # ';' before ')'


@dataclass(slots=True)
class LabelDef(Stmt):
    name: str = ""


@dataclass(slots=True)
class If(Stmt):
    cond: object = None


@dataclass(slots=True)
class Else(Stmt):
    pass


@dataclass(slots=True)
class EndIf(Stmt):
    pass


@dataclass(slots=True)
class Case(Stmt):
    expr: object = None


@dataclass(slots=True)
class CaseLabel(Stmt):
    values: list = field(default_factory=list)


@dataclass(slots=True)
class Otherwise(Stmt):
    pass


@dataclass(slots=True)
class EndCase(Stmt):
    pass


@dataclass(slots=True)
class For(Stmt):
    var: Var | None = None
    start: object = None
    step: object = None
    end: object = None


@dataclass(slots=True)
class Next(Stmt):
    var: Var | None = None


@dataclass(slots=True)
class While(Stmt):
    cond: object = None


@dataclass(slots=True)
class WEnd(Stmt):
    pass


@dataclass(slots=True)
class Repeat(Stmt):
    pass


@dataclass(slots=True)
class Until(Stmt):
    cond: object = None


@dataclass(slots=True)
class NcWord:
    address: str
    value: float | None = None
    expr: object = None


@dataclass(slots=True)
class NcBlock(Stmt):
    """An NC block: constant words, [expr] words, standalone [expr] words, a message, a sub-program call."""

    n: int | None = None
    skip: bool = False
    words: list = field(default_factory=list)  # NcWord
    loose: list = field(default_factory=list)  # standalone [expr]
    msg: str | None = None
    wait: bool = False
    call: tuple | None = None  # (program name, [args], modal flag) for G/M/P calls
    ends: bool = False  # M2 / M30


@dataclass
class Program:
    """One parsed program: flat statements plus where each CPL line number, N number and label starts."""

    path: str
    stmts: list = field(default_factory=list)
    lines: dict = field(default_factory=dict)  # CPL line number -> [stmt index]
    nblocks: dict = field(default_factory=dict)  # N number -> [stmt index]
    labels: dict = field(default_factory=dict)  # label -> [stmt index]
    din_only: bool = False  # "(DIN)" in the first line
    typ2: bool = False  # "(TYP2)" in the first line: an old CC 200/220 graphics program (manual §7 L4464-4468)
    has_cpl: bool = False
    diagnostics: list = field(default_factory=list)
