"""CL 800 syntax tree. Every node carries its source line (and column) for diagnostics and the xref."""

from __future__ import annotations

from dataclasses import dataclass, field


@dataclass
class Node:
    line: int
    col: int


# -- expressions -------------------------------------------------------------
@dataclass
class Num(Node):
    value: float | int
    kind: str  # INTEGER REAL PATTERN


@dataclass
class Operand(Node):
    """An R parameter ``R7``, a named R parameter ``x_value`` or a pointer ``[p]``; ``reg`` set by the checker."""

    name: str | None
    r: int | None
    pointer: bool = False
    reg: int | None = None
    type: str = ""


@dataclass
class Bit(Node):
    var: Operand
    bit: object  # int or a CONST name (resolved to int by the checker)


@dataclass
class Unary(Node):
    op: str  # - NOT NOTB
    expr: object


@dataclass
class Binary(Node):
    op: str
    left: object
    right: object


@dataclass
class Call(Node):
    """A function (ABS, SIN, ...), a system memory read (MDN, ...) or a multi-register function (PREP REF, ...)."""

    name: str
    args: list


# -- statements --------------------------------------------------------------
@dataclass
class Stmt(Node):
    label: str | None = field(default=None, kw_only=True)
    depth: int = field(default=0, kw_only=True)  # enclosing control constructs


@dataclass
class Assign(Stmt):
    target: Operand
    expr: object


@dataclass
class SysWrite(Stmt):
    name: str
    args: list
    value: object


@dataclass
class Proc(Stmt):
    """A procedure statement: CLEAR, XCHG, INC, SET BIT, STOP DEC, PORT, ..."""

    name: str
    args: list


@dataclass
class Din(Stmt):
    text: str


@dataclass
class Lf(Stmt):
    pass


@dataclass
class Compound(Stmt):
    body: list


@dataclass
class If(Stmt):
    cond: object
    then: list
    orelse: list | None


@dataclass
class IfInt(Stmt):
    negated: bool
    byte: object
    bit: object
    then: list
    orelse: list | None


@dataclass
class Case(Stmt):
    var: Operand
    alts: list  # [(value, [stmts], line)]
    otherwise: list | None
    end_line: int = 0


@dataclass
class While(Stmt):
    cond: object
    body: list


@dataclass
class WhileInt(Stmt):
    negated: bool
    byte: object
    bit: object
    body: list


@dataclass
class Repeat(Stmt):
    body: list
    cond: object
    until_line: int = 0


@dataclass
class For(Stmt):
    var: Operand
    start: object
    stop: object
    down: bool
    body: list


@dataclass
class Goto(Stmt):
    target: str


# -- units -------------------------------------------------------------------
@dataclass
class Decl(Node):
    """One declared R parameter: class PAR/LOCAL/POINTER/GLOBAL/CENTRAL, type, number, optional name."""

    cls: str
    type: str
    r: int
    name: str | None
    file: str = ""


@dataclass
class Program(Node):
    number: int
    channel: int
    ess: bool = False
    ident: str | None = None
    password: str | None = None
    list_refs: list = field(default_factory=list)  # [(kind, name, line, col)]
    decls: list = field(default_factory=list)
    consts: dict = field(default_factory=dict)  # norm name -> (Num, line, col, raw)
    labels: dict = field(default_factory=dict)  # norm name -> (line, col, raw)
    body: list = field(default_factory=list)
    begin_line: int = 0
    end_line: int = 0


@dataclass
class ExtList(Node):
    number: int
    channel: int | None = None
    ident: str | None = None
    password: str | None = None
    decls: list = field(default_factory=list)
