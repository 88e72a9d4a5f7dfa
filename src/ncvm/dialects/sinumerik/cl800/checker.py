"""Resolve every name of a CL 800 program before code generation (CL 800 manual §2, L395-734; §9, L6116-6310).

Named R parameters and R numbers are bound to their declarations (program,
GLOBAL and CENTRAL lists), CONST names are replaced by their values, labels and
GOTOs are matched, and the rules the WS 800 A enforces are checked with its
message numbers. Code generation then assumes a valid tree.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from pathlib import Path

from ....machine.files import find_in
from ....source import read_text
from . import ast
from .errors import CompilerMessage
from .lexer import Lexer, norm
from .parser import Parser
from .tables import FUNCTIONS, NC_FUNCTIONS, PROCEDURES, SYS_READS

#: declaration class -> allowed R numbers (manual §2.2, L395-495)
RANGES = {
    "PAR": (range(0, 50),), "LOCAL": (range(50, 100),), "POINTER": (range(50, 100),),
    "GLOBAL": (range(100, 200),), "CENTRAL": (range(900, 1000),),
}
#: documented windows of multi-register results (§5.3.8, L4109-4285): target, then operand windows
WINDOWS = {
    "PREP REF": ((192, 992), (197, 997)),
    "INT SEC": ((197, 997), (192, 992), (999, 999)),
    "PREP CYC": ((98, 998),),
}
LIST_EXTENSIONS = (".cl8", ".cl800", ".ext", ".lst8")
#: a file that begins (after comments) with EXTERNAL: a declaration list, whatever its errors
_EXTERNAL_FIRST = re.compile(r"\s*(?:\(\*.*?\*\)\s*)*EXTERNAL\b", re.S | re.I)
#: an undeclared name that is a bit pattern but for its digits (B00000002): E051, not E037
_DIGIT_PATTERN = re.compile(r"[Bb][0-9]{1,8}")


@dataclass
class Symbols:
    """What the checker learned: R number -> declaration, names -> declarations, push set."""

    by_r: dict = field(default_factory=dict)
    by_name: dict = field(default_factory=dict)
    locals: set = field(default_factory=set)  # LOCAL and POINTER registers (pushed)
    lists: list = field(default_factory=list)  # (kind, name, path, ExtList)


def parse_source(path: str, text: str, strict: bool = False):
    """Scan and parse one file; returns (unit or None, errors). ``strict`` drops the leniencies for
    the manual's own examples (dotted names, ``:=`` assignments, ``;`` missing before END/ELSE/...)."""
    lexer = Lexer(path, text, legacy_names=not strict)
    toks = lexer.tokens()
    parser = Parser(path, toks, text, strict)
    unit = parser.parse()
    return unit, lexer.errors + parser.errors


class Checker:
    def __init__(self, path: str, prog: ast.Program, search: list[Path], control: str = "880"):
        self.path, self.prog, self.search = path, prog, search
        self.max_program = 999 if control in ("810", "820") else 9999  # L1069
        self.errors: list[CompilerMessage] = []
        self.sym = Symbols()
        self.placed: dict[str, int] = {}
        self.gotos: list[ast.Goto] = []

    def err(self, code: str, node, detail: str = "", file: str | None = None) -> None:
        self.errors.append(CompilerMessage(code, file or self.path, node.line, node.col, detail))

    # -- declarations --------------------------------------------------------
    def check(self) -> Symbols:
        prog = self.prog
        if prog.number != -1 and not 1 <= prog.number <= self.max_program:
            self.err("E027", prog, f"program number 1..{self.max_program}")
        for ref in prog.list_refs:
            self.load_list(*ref)
        for d in prog.decls:
            self.declare(d)
        # a name declared twice is reported where it is declared the second time
        for key, (_num, line, col, _raw) in prog.consts.items():
            if key in self.sym.by_name:
                self._double(self.sym.by_name[key], line, col)
        for key, (line, col, _raw) in prog.labels.items():
            if key in self.sym.by_name:
                self._double(self.sym.by_name[key], line, col)
            elif key in prog.consts:
                other = prog.consts[key]
                self.errors.append(CompilerMessage("E036", self.path, *max((line, col), (other[1], other[2]))))
        self.block(prog.body, top=True)
        for g in self.gotos:
            key = norm(g.target)
            if key not in prog.labels:
                self.err("S050", g, f"{g.target} is not a declared label")
            elif key not in self.placed:
                # known only when END. is reached: reported there, naming the GOTO's line
                end = ast.Node(prog.end_line or g.line, None)
                self.err("S075", end, f"{g.target}, GOTO in line {g.line}")
        return self.sym

    def declare(self, d: ast.Decl, file: str | None = None) -> None:
        if not any(d.r in rng for rng in RANGES[d.cls]):
            self.err("E054", d, f"{d.cls} declares R{RANGES[d.cls][0].start}..R{RANGES[d.cls][-1].stop - 1}",
                     file)
            return
        if d.r in self.sym.by_r:
            self.err("E042", d, f"R{d.r}", file)
            return
        self.sym.by_r[d.r] = d
        if d.cls in ("LOCAL", "POINTER"):
            self.sym.locals.add(d.r)
        if d.name:
            key = norm(d.name)
            if key in self.sym.by_name:
                self.err("E036", d, d.name, file)
            else:
                self.sym.by_name[key] = d

    def find_list(self, name: str) -> Path | None:
        """The list file ``name`` (or with an extension, in any case) inside one of the search folders,
        which confine it as the program path does: a name or link that leads out finds nothing."""
        return find_in(self.search, [name] + [name + e for e in LIST_EXTENSIONS])

    def load_list(self, kind: str, name: str, line: int, col: int) -> None:
        where = ast.Node(line, col)
        p = self.find_list(name)
        if p is None:
            self.err("E200", where, f'list "{name}"')
            return
        text = read_text(p)
        unit, errors = parse_source(str(p), text)
        if not isinstance(unit, ast.ExtList) and not _EXTERNAL_FIRST.match(text):
            self.errors.append(CompilerMessage("E014", str(p), 1, 1))  # a list starts with EXTERNAL (L1307)
            return
        if errors:
            self.errors.append(min(errors, key=lambda e: (e.line, e.col or 0)))
            return
        if not isinstance(unit, ast.ExtList):
            self.errors.append(CompilerMessage("E014", str(p), 1, 1))
            return
        term2 = (unit.ident or "").split("-")[1].strip() if unit.ident and "-" in unit.ident else None
        if term2 is not None and term2.upper() != name.upper():
            self.err("E034", where, f'list "{name}" is identified as "{term2}"')
            return
        for kind_seen, _name_seen, _p, lst in self.sym.lists:
            if kind_seen == kind == "CENTRAL" or (kind == "GLOBAL" == kind_seen and
                                                  (lst.channel == 0) == (unit.channel == 0)):
                self.err("E035", where, f"a second {kind} list")
                return
        wrong = [d for d in unit.decls if d.cls != kind]
        if wrong:
            self.errors.append(CompilerMessage("E016" if kind == "GLOBAL" else "E015", str(p), wrong[0].line, wrong[0].col))
            return
        list_errors = check_list(str(p), unit)
        if list_errors:
            self.errors.append(list_errors[0])
            return
        if kind == "GLOBAL" and unit.channel and unit.channel != self.prog.channel:
            self.err("E034", where, f"list for channel {unit.channel}, program for channel {self.prog.channel}")
            return
        self.sym.lists.append((kind, name, p, unit))
        for d in unit.decls:
            self.declare(d, str(p))

    # -- statements ----------------------------------------------------------
    def block(self, stmts: list, top: bool = False) -> None:
        for st in stmts:
            self.stmt(st, top)

    def stmt(self, st, top: bool) -> None:
        if st.label:
            key = norm(st.label)
            if key not in self.prog.labels:
                self.err("E037", st, st.label)
            elif key in self.placed:
                self.err("E100", st, st.label)
            elif not top:
                self.err("S050", st, f"{st.label} is not on the first nesting level")
            else:
                self.placed[key] = st.line
        if isinstance(st, ast.Assign):
            self.target(st.target)
            if isinstance(st.expr, ast.Call) and st.expr.name in NC_FUNCTIONS:
                self.nc_function(st.target, st.expr)
            else:
                st.expr = self.value(st.expr, whole=st.target)
        elif isinstance(st, ast.SysWrite):
            st.args = [self.value(a) for a in st.args]
            st.value = self.value(st.value)
        elif isinstance(st, ast.Proc):
            if st.name == "ESS" and not (self.prog.body and st is self.prog.body[0]):
                # the compiler would put @00f at the start of the object program, where ESS belongs
                self.err("E061", st, "ESS must be at the start of the statement part (L4338)")
            kinds = PROCEDURES.get(st.name, ("", "x"))[1] if st.name != "ESS" else ""
            new = []
            for kind, a in zip(kinds, st.args):
                if kind == "v":
                    if not isinstance(a, ast.Operand):
                        self.err("E061", a, "variable expected")
                    else:
                        self.target(a)
                    new.append(a)
                elif kind == "b":
                    self.bit(a, write=True)
                    new.append(a)
                else:
                    new.append(self.value(a))
            st.args = new
        elif isinstance(st, ast.Compound):
            self.block(st.body)  # a BEGIN ... END block is not the first nesting level (CL 800 manual §5, L972-4590)
        elif isinstance(st, ast.If):
            st.cond = self.condition(st.cond)
            self.block(st.then)
            self.block(st.orelse or [])
        elif isinstance(st, (ast.IfInt, ast.WhileInt)):
            st.byte, st.bit = self.value(st.byte), self.value(st.bit)
            if isinstance(st, ast.IfInt):
                self.block(st.then)
                self.block(st.orelse or [])
            else:
                self.block(st.body)
        elif isinstance(st, ast.Case):
            self.target(st.var, write=False)
            for i, (v, body, line) in enumerate(st.alts):
                st.alts[i] = (self.value(v), body, line)
                self.block(body)
            self.block(st.otherwise or [])
        elif isinstance(st, ast.While):
            st.cond = self.condition(st.cond)
            self.block(st.body)
        elif isinstance(st, ast.Repeat):
            self.block(st.body)
            st.cond = self.condition(st.cond)
        elif isinstance(st, ast.For):
            self.target(st.var)
            st.start, st.stop = self.value(st.start), self.value(st.stop)
            self.block(st.body)
        elif isinstance(st, ast.Goto):
            self.gotos.append(st)

    def condition(self, e):
        """A condition must be BOOLEAN: a comparison, a boolean variable, a bit or a boolean chain (L4730-4748)."""
        e = self.value(e)
        arithmetic = isinstance(e, (ast.Num, ast.Call)) or (
            isinstance(e, ast.Binary) and e.op in ("+", "-", "*", "/", "OR", "XOR", "AND", "NAND")) or (
            isinstance(e, ast.Unary) and e.op in ("-", "NOT"))
        if arithmetic or (isinstance(e, ast.Operand) and e.type in ("REAL", "INTEGER", "PATTERN")):
            self.err("E030", e)  # a REAL, INTEGER or PATTERN variable alone is no condition
        return e

    def nc_function(self, target: ast.Operand, call: ast.Call) -> None:
        code, kinds, _n = NC_FUNCTIONS[call.name]
        if target.pointer:
            self.err("E054", target, f"{call.name} needs a direct R parameter")
        windows = WINDOWS.get(call.name, ())
        for i, (kind, a) in enumerate(zip(kinds, call.args)):
            if kind == "v":
                if not isinstance(a, ast.Operand) or a.pointer:
                    self.err("E061", a, "R parameter expected")
                    continue
                self.target(a, write=False)
            else:
                call.args[i] = self.value(a)
        if windows and target.reg is not None:
            regs = [target] + [a for a in call.args if isinstance(a, ast.Operand)]
            for op, (low, high) in zip(regs, windows):
                if op.reg is not None and not (op.reg <= low or 900 <= op.reg <= high):
                    self.err("E061", op, f"{call.name}: R{op.reg} outside R0..R{low} / R900..R{high}")

    # -- operands and expressions ---------------------------------------------
    def resolve(self, op: ast.Operand) -> ast.Decl | None:
        if op.name is not None:
            key = norm(op.name)
            d = self.sym.by_name.get(key)
            if d is None:
                code = "E054" if key in self.prog.consts or key in self.prog.labels else "E037"
                if code == "E037" and _DIGIT_PATTERN.fullmatch(op.name):
                    code = "E051"  # B00000002: a bit pattern with a digit other than 0 and 1 (L7074-7075)
                self.err(code, op, op.name)
            return d
        d = self.sym.by_r.get(op.r)
        if d is None:
            self.err("E041", op, f"R{op.r}")
        return d

    def target(self, op: ast.Operand, write: bool = True) -> None:
        if op.name is not None and norm(op.name) in self.prog.consts and not op.pointer:
            self.err("E054", op, f"constant {op.name} cannot be changed" if write else op.name)
            return
        d = self.resolve(op)
        if d is None:
            return
        op.reg, op.type = d.r, d.type
        if op.pointer:
            if d.cls != "POINTER":
                self.err("E054", op, f"R{d.r} is not a POINTER")
            op.type = ""

    def _double(self, d: ast.Decl, line: int, col: int) -> None:
        """E036 for a CONST or LABEL name that a variable declaration (``d``) also declares: at the later
        of the two (a variable from a list file counts as declared first: the header names the lists)."""
        if d.file in ("", self.path) and (d.line, d.col) > (line, col):
            line, col = d.line, d.col
        self.errors.append(CompilerMessage("E036", self.path, line, col, d.name or ""))

    def bit(self, b: ast.Bit, write: bool = False) -> None:
        if isinstance(b.bit, str):
            num = self.prog.consts.get(norm(b.bit))
            b.bit = int(num[0].value) if num else 0
        if not 0 <= b.bit <= 7:
            self.err("E027", b, "bit 0..7")
        if b.var.pointer:
            self.err("E047", b)
            return
        self.target(b.var, write=False)
        if b.var.reg is not None and b.var.type != "PATTERN":
            self.err("E047", b, f"R{b.var.reg} is {b.var.type}, not PATTERN")

    def value(self, e, whole: ast.Operand | None = None):
        """Resolve an expression; CONST names become numbers. Returns the (possibly new) node."""
        if isinstance(e, ast.Operand):
            if e.name is not None and not e.pointer and norm(e.name) in self.prog.consts:
                num = self.prog.consts[norm(e.name)][0]
                return ast.Num(e.line, e.col, num.value, num.kind)
            self.target(e, write=False)
            return e
        if isinstance(e, ast.Bit):
            self.bit(e)
            return e
        if isinstance(e, ast.Unary):
            e.expr = self.value(e.expr)
            return e
        if isinstance(e, ast.Binary):
            e.left, e.right = self.value(e.left), self.value(e.right)
            return e
        if isinstance(e, ast.Call):
            if e.name in NC_FUNCTIONS:
                self.err("E054", e, f"{e.name} only as a whole assignment")
                return e
            regs = SYS_READS[e.name][2] if e.name in SYS_READS else 1
            if regs != 1 and (whole is None or whole.pointer):
                self.err("E054", e, f"{e.name} writes several registers: only as a whole assignment")
            assert e.name in FUNCTIONS or e.name in SYS_READS
            e.args = [self.value(a) for a in e.args]
            return e
        return e


def check_list(path: str, lst: ast.ExtList) -> list[CompilerMessage]:
    """A list on its own: R ranges per class and channel, no R number or name twice (CL 800 manual §5.2.2, L1305-1395; §6.2, L4660-4695)."""
    errors, by_r, by_name = [], set(), set()
    for d in lst.decls:
        if d.cls == "GLOBAL" and lst.channel is None:
            errors.append(CompilerMessage("E012", path, d.line, d.col, "GLOBAL lists need CHANNEL NC"))
        elif not any(d.r in rng for rng in RANGES[d.cls]) or d.cls == "GLOBAL" and (lst.channel == 0) != (d.r >= 150):
            errors.append(CompilerMessage("E054", path, d.line, d.col,
                                     "R100..R149 per channel, R150..R199 in a CHANNEL NC 0 list, R900..R999 central"))
        elif d.r in by_r:
            errors.append(CompilerMessage("E042", path, d.line, d.col, f"R{d.r}"))
        elif d.name and norm(d.name) in by_name:
            errors.append(CompilerMessage("E036", path, d.line, d.col, d.name))
        by_r.add(d.r)
        if d.name:
            by_name.add(norm(d.name))
    return errors


def check_program(path: str, text: str, search: list[Path], strict: bool = False, control: str = "880"):
    """Parse and check; returns (Program or None, Symbols or None, errors sorted by position)."""
    unit, errors = parse_source(path, text, strict)
    sym = None
    if isinstance(unit, ast.Program):
        checker = Checker(path, unit, search, control)
        sym = checker.check()
        errors += checker.errors
    elif isinstance(unit, ast.ExtList):
        errors += check_list(path, unit)
    here = [e for e in errors if e.file == path]
    other = [e for e in errors if e.file != path]
    here.sort(key=lambda e: (e.line, e.col or 0))
    return unit, sym, other + here if other else here
