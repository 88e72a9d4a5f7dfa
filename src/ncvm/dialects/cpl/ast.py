"""The CPL syntax tree: expressions, and statements as a flat list per program.

Structured statements (IF, CASE, FOR, WHILE, REPEAT) span many blocks and may hold NC blocks, so the
parser emits them as flat markers (``If``, ``Else``, ``EndIf`` ...); the linker pairs the markers.
"""

from __future__ import annotations

from ...records import Record
from .lexer import VarName


class Node(Record):
    """A node of the tree: fields compare and print as a dataclass's would.

    The nodes are plain classes with ``__slots__`` and a written-out ``__init__`` rather than dataclasses:
    creating 33 slotted dataclasses took about 13 ms of every CPL start-up (issue 18).
    """

    __slots__ = ()


# -- expressions ---------------------------------------------------------
class Num(Node):
    __slots__ = ("value", "type")

    def __init__(self, value: int | float, type: str):
        self.value = value
        self.type = type  # "I" or "R"


class Str(Node):
    __slots__ = ("value",)

    def __init__(self, value: str):
        self.value = value


class BoolLit(Node):
    __slots__ = ("value",)

    def __init__(self, value: bool):
        self.value = value


class Nul(Node):
    __slots__ = ()


class Var(Node):
    __slots__ = ("var", "index", "col")

    def __init__(self, var: VarName, index: list | None = None, col: int = 0):
        self.var = var
        self.index = index  # index expressions, or None
        self.col = col


class Func(Node):
    __slots__ = ("name", "args", "col")

    def __init__(self, name: str, args: list, col: int = 0):
        self.name = name
        self.args = args  # expressions or None for an empty position
        self.col = col


class Unary(Node):
    __slots__ = ("op", "operand")

    def __init__(self, op: str, operand: object):
        self.op = op  # "-", "+", "NOT"
        self.operand = operand


class Bin(Node):
    __slots__ = ("op", "left", "right")

    def __init__(self, op: str, left: object, right: object):
        self.op = op
        self.left = left
        self.right = right


# -- statements ----------------------------------------------------------
class Stmt(Node):
    __slots__ = ("line", "col", "cpl")

    def __init__(self, line: int = 0, col: int = 0, cpl: int | None = None):
        self.line = line  # physical line
        self.col = col
        self.cpl = cpl  # CPL line number of the block


class Assign(Stmt):
    __slots__ = ("target", "expr", "mid")

    def __init__(
        self,
        line: int = 0,
        col: int = 0,
        cpl: int | None = None,
        target: Var | None = None,
        expr: object = None,
        mid: tuple | None = None,
    ):
        Stmt.__init__(self, line, col, cpl)
        self.target = target
        self.expr = expr
        self.mid = mid  # (start, count) for MID$(target, start, count) = expr


class Goto(Stmt):
    __slots__ = ("kind", "target")

    def __init__(self, line: int = 0, col: int = 0, cpl: int | None = None, kind: str = "", target: object = None):
        Stmt.__init__(self, line, col, cpl)
        self.kind = kind  # "line", "n", "label"
        self.target = target


class CallStmt(Stmt):
    __slots__ = ("name", "args", "din")

    def __init__(
        self,
        line: int = 0,
        col: int = 0,
        cpl: int | None = None,
        name: str = "",
        args: list | None = None,
        din: bool = False,
    ):
        Stmt.__init__(self, line, col, cpl)
        self.name = name
        self.args = [] if args is None else args
        self.din = din


class Dim(Stmt):
    __slots__ = ("items",)

    def __init__(self, line: int = 0, col: int = 0, cpl: int | None = None, items: list | None = None):
        Stmt.__init__(self, line, col, cpl)
        self.items = [] if items is None else items  # (VarName, [sizes])


class Pdim(Stmt):
    __slots__ = ("var", "size")

    def __init__(self, line: int = 0, col: int = 0, cpl: int | None = None, var: VarName | None = None, size: int = 0):
        Stmt.__init__(self, line, col, cpl)
        self.var = var
        self.size = size


class Wait(Stmt):
    __slots__ = ("neg", "ic", "state", "duration", "result", "plain")

    def __init__(
        self,
        line: int = 0,
        col: int = 0,
        cpl: int | None = None,
        neg: bool = False,
        ic: list | None = None,
        state: object = None,
        duration: object = None,
        result: Var | None = None,
        plain: bool = True,
    ):
        Stmt.__init__(self, line, col, cpl)
        self.neg = neg
        self.ic = ic  # IC(...) argument expressions
        self.state = state
        self.duration = duration
        self.result = result
        self.plain = plain


class Proc(Stmt):
    __slots__ = ("name", "args", "no_end")

    def __init__(
        self,
        line: int = 0,
        col: int = 0,
        cpl: int | None = None,
        name: str = "",
        args: list | None = None,
        no_end: bool = False,
    ):
        Stmt.__init__(self, line, col, cpl)
        self.name = name
        self.args = [] if args is None else args
        self.no_end = no_end  # ';' before ')'


class LabelDef(Stmt):
    __slots__ = ("name",)

    def __init__(self, line: int = 0, col: int = 0, cpl: int | None = None, name: str = ""):
        Stmt.__init__(self, line, col, cpl)
        self.name = name


class If(Stmt):
    __slots__ = ("cond",)

    def __init__(self, line: int = 0, col: int = 0, cpl: int | None = None, cond: object = None):
        Stmt.__init__(self, line, col, cpl)
        self.cond = cond


class Else(Stmt):
    __slots__ = ()


class EndIf(Stmt):
    __slots__ = ()


class Case(Stmt):
    __slots__ = ("expr",)

    def __init__(self, line: int = 0, col: int = 0, cpl: int | None = None, expr: object = None):
        Stmt.__init__(self, line, col, cpl)
        self.expr = expr


class CaseLabel(Stmt):
    __slots__ = ("values",)

    def __init__(self, line: int = 0, col: int = 0, cpl: int | None = None, values: list | None = None):
        Stmt.__init__(self, line, col, cpl)
        self.values = [] if values is None else values


class Otherwise(Stmt):
    __slots__ = ()


class EndCase(Stmt):
    __slots__ = ()


class For(Stmt):
    __slots__ = ("var", "start", "step", "end")

    def __init__(
        self,
        line: int = 0,
        col: int = 0,
        cpl: int | None = None,
        var: Var | None = None,
        start: object = None,
        step: object = None,
        end: object = None,
    ):
        Stmt.__init__(self, line, col, cpl)
        self.var = var
        self.start = start
        self.step = step
        self.end = end


class Next(Stmt):
    __slots__ = ("var",)

    def __init__(self, line: int = 0, col: int = 0, cpl: int | None = None, var: Var | None = None):
        Stmt.__init__(self, line, col, cpl)
        self.var = var


class While(Stmt):
    __slots__ = ("cond",)

    def __init__(self, line: int = 0, col: int = 0, cpl: int | None = None, cond: object = None):
        Stmt.__init__(self, line, col, cpl)
        self.cond = cond


class WEnd(Stmt):
    __slots__ = ()


class Repeat(Stmt):
    __slots__ = ()


class Until(Stmt):
    __slots__ = ("cond",)

    def __init__(self, line: int = 0, col: int = 0, cpl: int | None = None, cond: object = None):
        Stmt.__init__(self, line, col, cpl)
        self.cond = cond


class NcWord(Node):
    __slots__ = ("address", "value", "expr")

    def __init__(self, address: str, value: float | None = None, expr: object = None):
        self.address = address
        self.value = value
        self.expr = expr


class NcBlock(Stmt):
    """An NC block: constant words, [expr] words, standalone [expr] words, a message, a sub-program call."""

    __slots__ = ("n", "skip", "words", "loose", "msg", "wait", "call", "ends")

    def __init__(
        self,
        line: int = 0,
        col: int = 0,
        cpl: int | None = None,
        n: int | None = None,
        skip: bool = False,
        words: list | None = None,
        loose: list | None = None,
        msg: str | None = None,
        wait: bool = False,
        call: tuple | None = None,
        ends: bool = False,
    ):
        Stmt.__init__(self, line, col, cpl)
        self.n = n
        self.skip = skip
        self.words = [] if words is None else words  # NcWord
        self.loose = [] if loose is None else loose  # standalone [expr]
        self.msg = msg
        self.wait = wait
        self.call = call  # (program name, [args], modal flag) for G/M/P calls
        self.ends = ends  # M2 / M30


class Program(Record):
    """One parsed program: flat statements plus where each CPL line number, N number and label starts."""

    __slots__ = ("path", "stmts", "lines", "nblocks", "labels", "din_only", "typ2", "has_cpl", "diagnostics")

    def __init__(self, path: str, stmts: list | None = None, lines: dict | None = None, nblocks: dict | None = None,
                 labels: dict | None = None, din_only: bool = False, typ2: bool = False, has_cpl: bool = False,
                 diagnostics: list | None = None):
        self.path = path
        self.stmts = [] if stmts is None else stmts
        self.lines = {} if lines is None else lines  # CPL line number -> [stmt index]
        self.nblocks = {} if nblocks is None else nblocks  # N number -> [stmt index]
        self.labels = {} if labels is None else labels  # label -> [stmt index]
        self.din_only = din_only  # "(DIN)" in the first line
        self.typ2 = typ2  # "(TYP2)" in the first line: an old CC 200/220 graphics program (manual §7 L4464-4468)
        self.has_cpl = has_cpl
        self.diagnostics = [] if diagnostics is None else diagnostics
