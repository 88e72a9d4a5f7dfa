"""The rw_SymPas syntax tree (rw_SymPas manual §5.3, L468-1259). The checker fills in ``ty`` and ``sym``."""

from __future__ import annotations

from dataclasses import dataclass, field


@dataclass(eq=False)
class Node:
    file: str
    line: int
    col: int


# -- expressions ---------------------------------------------------------------
@dataclass(eq=False)
class Num(Node):
    value: int | float = 0
    ty: str = ""


@dataclass(eq=False)
class Str(Node):
    value: str = ""
    ty: str = "string"


@dataclass(eq=False)
class Name(Node):
    name: str = ""
    ty: str = ""
    sym: object = None


@dataclass(eq=False)
class Qual(Node):
    """``Spec.qual`` or ``Spec.squal.bit``."""

    axis: Name | None = None
    qual: str = ""
    bit: object = None  # int literal or Name of an integer constant
    ty: str = ""
    bitno: int = 0


@dataclass(eq=False)
class Unary(Node):
    op: str = ""
    operand: object = None
    ty: str = ""


@dataclass(eq=False)
class Bin(Node):
    op: str = ""
    left: object = None
    right: object = None
    ty: str = ""


@dataclass(eq=False)
class Call(Node):
    """A call of a routine, built-in function, cast or command; ``args`` are expressions or Named."""

    name: str = ""
    args: list = field(default_factory=list)
    parens: bool = False
    ty: str = ""
    sym: object = None


@dataclass(eq=False)
class Named(Node):
    """``Spec := expr`` or ``SYSPAR := expr`` inside a command's argument list."""

    name: str = ""
    value: object = None
    eq_sign: bool = False
    sym: object = None


# -- statements ----------------------------------------------------------------
@dataclass(eq=False)
class Assign(Node):
    target: object = None
    value: object = None
    label: str | None = None


@dataclass(eq=False)
class CallStmt(Node):
    call: Call | None = None
    label: str | None = None


@dataclass(eq=False)
class Goto(Node):
    target: str = ""
    label: str | None = None


@dataclass(eq=False)
class Compound(Node):
    body: list = field(default_factory=list)
    label: str | None = None


@dataclass(eq=False)
class If(Node):
    cond: object = None
    then: object = None
    other: object = None
    label: str | None = None


@dataclass(eq=False)
class While(Node):
    cond: object = None
    body: object = None
    label: str | None = None


@dataclass(eq=False)
class Repeat(Node):
    body: list = field(default_factory=list)
    cond: object = None
    label: str | None = None


@dataclass(eq=False)
class For(Node):
    var: object = None  # Name or Qual(.an)
    start: object = None
    stop: object = None
    down: bool = False
    body: object = None
    label: str | None = None


@dataclass(eq=False)
class Empty(Node):
    label: str | None = None


# -- declarations --------------------------------------------------------------
@dataclass(eq=False)
class ConstDecl(Node):
    name: str = ""
    value: object = None  # Num, Name (constant or TRUE/FALSE), with sign folded
    sign: int = 1


@dataclass(eq=False)
class VarDecl(Node):
    names: list = field(default_factory=list)
    ty: str = ""


@dataclass(eq=False)
class LabelDecl(Node):
    names: list = field(default_factory=list)


@dataclass(eq=False)
class Param(Node):
    name: str = ""
    ty: str = ""


@dataclass(eq=False)
class Routine(Node):
    name: str = ""
    params: list = field(default_factory=list)
    result: str | None = None  # None: procedure
    forward: bool = False
    decls: list = field(default_factory=list)
    body: Compound | None = None


@dataclass(eq=False)
class Program(Node):
    name: str = ""
    task: object = None  # int, constant name, or None
    fullsystem: bool = False
    decls: list = field(default_factory=list)  # ConstDecl/VarDecl/LabelDecl/Routine in source order
    body: Compound | None = None
