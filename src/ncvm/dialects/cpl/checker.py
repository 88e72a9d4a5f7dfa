"""The CPL checker: between linker and codegen, it resolves the type of every expression of a linked
program and reports the errors only types reveal (CPL manual §2.4.3, L650-737; §2.5, L738-770; chapters 4-5).

Types are I R D B S (INTEGER, REAL, DOUBLE, BOOLEAN, CHARACTER), N (NUL) or ? (known only at run time);
they are known from the suffixes. Every statement is checked on its own, in the order of the program (an
IF's condition, a FOR's limits, ...), so ``ncvm check`` lists the first error of every statement. The
result, :class:`Types`, is what codegen reads: it emits code for a program the checker passed.
"""

from __future__ import annotations

import inspect

from . import ast as A
from .builtins import FUNCTIONS
from .errors import diag
from .io.files import CplFiles
from .io.screen import Screen
from .system import SYSTEM_PROCS

NUMERIC = ("I", "R", "D")

#: statements that are plain calls of a CplIO part: name -> attribute of ``_io`` (chapters 6-8)
IO_PROCS = {
    **{n: "files" for n in ("OPENR", "OPENW", "CLOSE", "REWRITE", "SEEK")},
    **{n: "screen" for n in ("DSP", "PRN", "DLG", "ENDDLG", "CSF", "TFO", "COL", "RGB", "GMD", "GWD", "MWD", "LIN",
                              "CIR", "FIL", "CLG", "CLR", "CLS", "GPR", "BMP", "DLF")},
}


def io_arity(target: str, name: str) -> tuple[int, int]:
    """How many arguments the statement ``name`` of a CplIO part takes: its method's positional parameters
    (99 = any number), so that a wrong count is a compile error rather than a failed call at run time."""
    method = getattr({"files": CplFiles, "screen": Screen}[target], name)
    params = list(inspect.signature(method).parameters.values())[1:]  # without self
    positional = [p for p in params if p.kind == p.POSITIONAL_OR_KEYWORD]
    lo = sum(1 for p in positional if p.default is p.empty)
    hi = 99 if any(p.kind == p.VAR_POSITIONAL for p in params) else len(positional)
    return lo, hi


class CheckError(Exception):
    """A statement the control would refuse: the manual's error number (or CPL0xx) and what is wrong."""

    def __init__(self, code: str, detail: str):
        super().__init__(code, detail)
        self.code = code
        self.detail = detail


class Raw:
    """A value already computed by generated code (a WAIT result, a FOR counter, a value read back by INP,
    SFK, MMC): stored through the assignment rules with its known type."""

    def __init__(self, code: str, ty: str):
        self.code = code
        self.ty = ty


class Types:
    """The type of every expression of one program (by node identity), as the checker resolved them."""

    def __init__(self) -> None:
        self.of: dict[int, str] = {}

    def __getitem__(self, e) -> str:
        return e.ty if e.__class__ is Raw else self.of[id(e)]


def check(ln) -> tuple[Types, list]:
    """The types of a linked program and the diagnostics of its type errors (one per statement, in source
    order); an expression too deep to check is NESTING TOO DEEP (2153) unless an error came first."""
    c = Checker(ln)
    for i, s in enumerate(c.stmts):
        c.cur = s
        try:
            c.statement(i, s)
        except CheckError as e:
            c.errors.append((e, s))
        except RecursionError:
            if c.errors:
                break
            return c.types, [diag("2153", "expression or structure too deep to evaluate", ln.prog.path, s.line,
                                  s.col or None, s.cpl)]
    found = sorted(c.errors, key=lambda es: (es[1].line, es[1].col or 0))
    return c.types, [diag(e.code, e.detail, ln.prog.path, s.line, s.col or None, s.cpl) for e, s in found]


class Checker:
    def __init__(self, ln):
        self.ln = ln
        self.stmts = ln.prog.stmts
        self.fields = ln.fields
        self.types = Types()
        self.errors: list[tuple[CheckError, A.Stmt]] = []
        self.cur: A.Stmt | None = None

    # -- expressions -------------------------------------------------------------------------
    def ty(self, e) -> str:
        """The type of expression ``e`` (resolved once, kept in ``types``)."""
        if e.__class__ is Raw:
            return e.ty
        known = self.types.of.get(id(e))
        if known is None:
            known = self.types.of[id(e)] = self._resolve(e)
        return known

    def _resolve(self, e) -> str:
        t = type(e)
        if t is A.Num:
            return e.type
        if t is A.Str:
            return "S"
        if t is A.BoolLit:
            return "B"
        if t is A.Nul:
            return "N"
        if t is A.Var:
            return self.read(e)
        if t is A.Unary:
            return self.unary(e)
        if t is A.Func:
            return self.func(e)
        if t is A.Bin:
            return self.binary(e)
        raise CheckError("CPL001", f"cannot compile {e!r}")

    def unary(self, e: A.Unary) -> str:
        ty = self.ty(e.operand)
        if e.op == "NOT":
            if ty in ("B", "I", "?"):
                return ty
            raise CheckError("CPL032", f"NOT of {_a(ty)} value")
        if ty not in NUMERIC + ("?",):
            raise CheckError("CPL032", f"sign of {_a(ty)} value")
        return ty

    def binary(self, e: A.Bin) -> str:
        op = e.op
        if op in ("=", "<>") and (isinstance(e.right, A.Nul) or isinstance(e.left, A.Nul)):
            self.ty(e.left if isinstance(e.right, A.Nul) else e.right)
            return "B"
        if op == "+" and self.is_string(e):
            parts = chain(e)
            if len(parts) > 3:
                raise CheckError("2153", f"string chaining of {len(parts)} operands (at most 3)")
            for p in parts:
                ty = self.ty(p)
                if ty not in ("S", "?"):
                    raise CheckError("CPL032", f"'+' joins strings, not {_a(ty)} value")
            return "S"
        lt, rt = self.ty(e.left), self.ty(e.right)
        if op in ("AND", "OR", "XOR"):
            return self.logic(op, lt, rt)
        if op in ("+", "-", "*", "/"):
            return self.arithmetic(op, lt, rt)
        if lt in NUMERIC and rt in NUMERIC:
            return "B"
        if lt == rt or "?" in (lt, rt):
            if lt == "B" and op not in ("=", "<>"):
                raise CheckError("CPL032", f"'{op}' on BOOLEAN values")
            return "B"
        raise CheckError("CPL032", f"comparison of {tname(lt)} with {tname(rt)}")

    @staticmethod
    def logic(op: str, lt: str, rt: str) -> str:
        if lt == rt and lt in ("B", "I"):
            return lt
        if "?" in (lt, rt) and {lt, rt} <= {"B", "I", "?"}:
            return lt if lt != "?" else rt
        raise CheckError("CPL032", f"{op} of {tname(lt)} and {tname(rt)}")

    @staticmethod
    def arithmetic(op: str, lt: str, rt: str) -> str:
        for ty in (lt, rt):
            if ty not in NUMERIC + ("?",):
                raise CheckError("CPL032", f"'{op}' of {_a(ty)} value")
        if op == "/":
            return "D" if "D" in (lt, rt) or "?" in (lt, rt) else "R"
        if lt == "I" and rt == "I":
            return "I"
        if "?" in (lt, rt):
            return "?"
        return "D" if "D" in (lt, rt) else "R"

    def is_string(self, e) -> bool:
        """Is ``e`` a string chain: a '+' with a CHARACTER operand somewhere?"""
        if isinstance(e, A.Bin) and e.op == "+":
            return self.is_string(e.left) or self.is_string(e.right)
        try:
            return self.ty(e) == "S"
        except CheckError:
            return False

    def func(self, e: A.Func) -> str:
        if e.name == "MMC":
            raise CheckError("CPL001", "MMC(...) stands as a statement or as r% = MMC(...)")
        b = FUNCTIONS.get(e.name)
        if b is None:
            raise CheckError("CPL037", f"{e.name} is not implemented (docs/cpl.md lists what is missing)")
        n = len(e.args)
        if not b.min_args <= n <= b.max_args:
            raise CheckError("CPL001", f"{e.name} takes {b.min_args}..{b.max_args} arguments, not {n}")
        types = []
        for k, a in enumerate(e.args):
            if a is None:
                types.append("N")
            elif k in b.refs and isinstance(a, A.Var) and not a.index:
                self.by_name(a)
                types.append("F")
            else:
                ty = self.ty(a)
                want = b.params[k:k + 1]
                if want == "S" and ty in NUMERIC + ("B",) or want in ("I", "N") and ty in ("S", "B"):
                    raise CheckError("CPL032", f"{e.name}: argument {k + 1} is {_a(ty)} value")
                types.append(ty)
        if b.out is not None and b.out < n and e.args[b.out] is not None:
            self.put(e.args[b.out], e.name)
        if b.result == "=":
            return types[0] if types[0] in NUMERIC else "?"
        if b.result == "RD":
            return "D" if types[0] in ("D", "?") else "R"
        return b.result

    def by_name(self, a: A.Var) -> None:
        """A field given by its bare name (GETERR, MCODS): a DIMensioned field or a simple numeric local."""
        v = a.var
        if v.cls == "G" or v.cls == "L" and (self.fields.get(v) is not None or v.type in NUMERIC):
            return
        raise CheckError("CPL035", f"{v.display}: a DIMensioned local or global field is needed here")

    @staticmethod
    def put(target, name: str) -> None:
        """The variable a function writes back: a numeric local or global variable."""
        if not isinstance(target, A.Var) or target.index or target.var.cls not in ("L", "G") \
                or target.var.type not in NUMERIC:
            raise CheckError("CPL001", f"{name}: a numeric local or global variable is needed here")

    # -- variables ---------------------------------------------------------------------------
    def read(self, e: A.Var) -> str:
        v = e.var
        n = len([self.index(i) for i in e.index]) if e.index else 0
        if v.cls == "L":
            dims = self.fields.get(v)
            if dims is None:
                if n:
                    raise CheckError("CPL035", f"{v.display} is used with an index but never DIMensioned")
            else:
                self.field_indices(v, dims, n)
            return v.type
        if v.cls == "G":
            if n:
                self.field_indices(v, n if v.type != "S" else n + 1, n)
            return v.type
        if v.cls == "P":
            if n:
                raise CheckError("CPL001", f"{v.display} is not a field")
            return "I"
        if v.cls == "R":
            if n != 1:
                raise CheckError("CPL001", "@_R needs one index (1..100)")
            return "D"
        if v.cls == "D":
            return v.type
        if v.cls == "A":
            if n:
                raise CheckError("CPL001", f"parameter {v.display} has no index")
            return v.type
        raise CheckError("CPL012", v.display)

    @staticmethod
    def field_indices(v, dims: int, n: int, what: str = "a string of the 2-dimensional field") -> None:
        """A field read or written with ``n`` indices: as many as it has dimensions (a character field: one
        less, its strings being the last dimension)."""
        if v.suffix == "$":
            if dims == 1:
                if n:
                    raise CheckError("CPL001", f"{v.display} is a 1-dimensional character field: no index")
            elif n != 1:
                raise CheckError("CPL001", f"{v.display}: one index selects {what}")
            return
        if n != dims:
            raise CheckError("CPL001", f"{v.display} needs {dims} ind{'ex' if dims == 1 else 'ices'}")

    def index(self, e) -> str:
        ty = self.ty(e)
        if not (isinstance(e, A.Num) and ty == "I") and ty not in ("I", "?"):
            raise CheckError("CPL031", f"index must be INTEGER, not {tname(ty)}")
        return ty

    # -- assignment ----------------------------------------------------------------------------
    @staticmethod
    def convert(target_type: str, e, ty: str) -> None:
        """May a value of type ``ty`` be stored into a variable of ``target_type``?"""
        if ty == "N":
            return
        name = {"I": "INTEGER", "R": "REAL", "D": "DOUBLE", "B": "BOOLEAN", "S": "CHARACTER"}.get(target_type)
        if name is None:
            raise CheckError("CPL001", "bad target")
        if target_type == "I" and isinstance(e, A.Num) and ty == "I" and not -2147483648 <= e.value <= 2147483647:
            raise CheckError("CPL027", f"{e.value} outside -2147483648..2147483647")
        refused = {"B": NUMERIC + ("S",), "S": NUMERIC + ("B",)}.get(target_type, ("B", "S"))
        if ty in refused:
            raise CheckError("CPL021", f"{tname(ty)} value assigned to {'an' if name[0] == 'I' else 'a'} {name} "
                                       "variable")

    def assign(self, s: A.Assign) -> None:
        tv = s.target
        v = tv.var
        if s.mid is not None:
            self.mid_write(s)
            return
        if v.cls == "A":
            raise CheckError("CPL036", f"{v.display} = ...")
        e = s.expr
        if v.suffix == "$" and v.cls == "L" and not is_char_field(tv, self.fields) and needs_field(e):
            raise CheckError("CPL025", f"{v.display} is not DIMensioned; '+' results go to character fields only")
        if is_field_view(s, self.fields):
            src = e.args[0]
            if src.index:
                self.index(src.index[0])
            self.ty(e.args[1])
            if len(e.args) > 2 and e.args[2] is not None:
                self.ty(e.args[2])
            return
        ty = self.mmc(e.args) if isinstance(e, A.Func) and e.name == "MMC" else self.ty(e)
        self.store_into(tv, e, ty)

    def store_into(self, tv: A.Var, e, ty: str) -> None:
        v = tv.var
        if v.cls == "L":
            dims = self.fields.get(v)
            if dims is None:
                if tv.index:
                    raise CheckError("CPL035", f"{v.display} is used with an index but never DIMensioned")
                self.convert(v.type, e, ty)
                return
            n = len([self.index(i) for i in tv.index]) if tv.index else 0
            self.field_indices(v, dims, n, "a string of the field")
            self.convert("S" if v.suffix == "$" else v.type, e, ty)
        elif v.cls == "G":
            if ty == "N" and not tv.index:
                return
            self.convert(v.type, e, ty)
            for i in tv.index or ():
                self.index(i)
        elif v.cls == "R":
            if not tv.index or len(tv.index) != 1:
                raise CheckError("CPL001", "@_R needs one index (1..100)")
            self.index(tv.index[0])
        elif v.cls == "D":
            for i in tv.index or ():
                self.index(i)
        elif v.cls != "P":
            raise CheckError("CPL012", v.display)

    def store(self, tv: A.Var, ty: str) -> None:
        """A value computed by generated code, of type ``ty``, stored into ``tv``."""
        self.assign(A.Assign(line=self.cur.line if self.cur else 0, target=tv, expr=Raw("", ty)))

    def mid_write(self, s: A.Assign) -> None:
        tv = s.target
        v = tv.var
        if v.suffix != "$":
            raise CheckError("CPL032", "MID$(...) = needs a character field")
        if v.cls == "L":
            if v not in self.fields:
                raise CheckError("CPL025", f"MID$({v.display},...)= : {v.display} is not DIMensioned")
            if tv.index:
                self.index(tv.index[0])
        elif v.cls == "G":
            if tv.index:
                self.index(tv.index[0])
        elif v.cls == "D":
            self.field_ref(tv)
        else:
            raise CheckError("CPL032", f"MID$(...) = : {v.display} is not a character field")
        self.ty(s.mid[0])
        if s.mid[1] is not None:
            self.ty(s.mid[1])
        if self.ty(s.expr) not in ("S", "?"):
            raise CheckError("CPL032", "MID$(...) = needs a string")

    def field_ref(self, tv: A.Var) -> None:
        """A character field passed as itself (not its text), for functions that write into it."""
        v = tv.var
        if v.cls == "D":
            for i in tv.index or ():
                self.index(i)
            return
        if v.cls not in ("L", "G"):
            raise CheckError("CPL032", f"{v.display} is not a character field")
        if tv.index:
            self.index(tv.index[0])

    # -- statements ----------------------------------------------------------------------------
    def statement(self, i: int, s) -> None:
        """One statement, as the GOTO form of codegen lowers it (a structure's markers one by one)."""
        t = type(s)
        if t in (A.If, A.While, A.Until):
            self.condition(s.cond)
        elif t is A.Case:
            ty = self.ty(s.expr)
            if ty not in ("I", "?"):
                raise CheckError("CPL032", f"CASE needs an INTEGER expression, not {tname(ty)}")
        elif t is A.For:
            self.for_header(s)
        elif t is A.Next:
            self.next(i, s)
        elif t in (A.Goto, A.Else, A.CaseLabel, A.Otherwise, A.WEnd, A.Repeat, A.EndIf, A.EndCase, A.LabelDef):
            pass
        else:
            self.simple(s)

    def condition(self, e) -> None:
        ty = self.ty(e)
        if ty not in ("B", "?"):
            raise CheckError("CPL032", f"condition must be BOOLEAN, not {tname(ty)}")

    def for_parts(self, s: A.For) -> tuple[str, str, int | float | None]:
        """(counter type, start type, constant step or None) of a FOR statement."""
        v = s.var
        if v.var.type not in NUMERIC or v.var.cls == "A":  # any numerical variable (§2.5.5 L924), not a parameter
            raise CheckError("CPL001", "FOR needs a numeric variable")
        start_ty = self.ty(s.start)
        if self.ty(s.end) not in NUMERIC + ("?",):
            raise CheckError("CPL032", "FOR end value must be a number")
        return v.var.type, start_ty, const_step(s.step)

    def for_header(self, s: A.For) -> None:
        _, start_ty, step = self.for_parts(s)
        self.store(s.var, start_ty)
        if step is None:
            self.ty(s.step)
        self.ty(s.var)

    def next(self, i: int, s: A.Next) -> None:
        """NEXT steps the counter; the FOR statement has reported an error of its own parts."""
        f = self.stmts[self.ln.pair[i]["for"]]
        try:
            ctype, _, step = self.for_parts(f)
        except CheckError:
            return
        if step is None:
            self.ty(f.step)
        self.ty(f.var)
        self.store(f.var, increment_type(ctype, step_type(step, self.types, f.step)))

    def simple(self, s) -> None:
        t = type(s)
        if t is A.Assign:
            self.assign(s)
        elif t is A.CallStmt:
            self.args(s.args)
        elif t is A.Wait:
            self.wait(s)
        elif t is A.Proc:
            self.proc(s)
        elif t is A.NcBlock:
            self.nc(s)
        elif t not in (A.LabelDef, A.Dim, A.Pdim):
            raise CheckError("CPL001", f"unexpected {t.__name__}")

    def args(self, args) -> None:
        for a in args:
            if a is not None:
                self.ty(a)

    def wait(self, s: A.Wait) -> None:
        if s.plain:
            return
        if s.state is not None and self.ty(s.state) not in ("B", "?"):
            raise CheckError("CPL032", "the <state> of a WAIT condition is a BOOLEAN expression (manual §4.1)")
        if s.result is not None and s.result.var.type != "I":
            raise CheckError("CPL032", "the <result var> of WAIT is an INTEGER variable (manual §4.1)")
        self.args(s.ic or ())
        self.args((s.state, s.duration))
        if s.result is not None:
            self.store(s.result, "I")

    def proc(self, s: A.Proc) -> None:
        """Statements of chapters 4-9: I/O statements, system procedures, functions called as statements."""
        name = s.name
        if name in ("LJUST", "NJUST"):
            return
        if name in ("PRN#", "INP#"):
            if not s.args or s.args[0] is None:
                raise CheckError("CPL001", f"{name} needs a file number")
            if name == "PRN#":
                self.args(s.args)
            else:
                self.inp_file(s)
        elif name in ("SFK", "INP"):
            self.read_back(s)
        elif name == "PRN" and len(s.args) == 4 and isinstance(s.args[3], A.Var):
            self.args(s.args)  # PRN(x, y, format, variable): the variable's name is shown
        elif name == "MMC":
            self.mmc(s.args)
        elif name == "ERASE" or name in IO_PROCS:
            lo, hi = io_arity("files" if name == "ERASE" else IO_PROCS[name], name)
            if not lo <= len(s.args) <= hi:
                most = f"..{hi}" if hi < 99 else " or more"
                raise CheckError("CPL001", f"{name} takes {lo}{most} arguments, not {len(s.args)}")
            self.args(s.args)
        elif name in FUNCTIONS and name not in SYSTEM_PROCS:  # SCSL(...), MCOPS(...) as a statement
            self.func(A.Func(name, s.args, 0))  # not kept in the types: a node of its own
        elif name in SYSTEM_PROCS:  # chapter 4: FXC(...)=v and friends, FXCR, FXDEL, FXINS
            _, lo, hi = SYSTEM_PROCS[name]
            if not lo <= len(s.args) <= hi:
                raise CheckError("CPL001", f"{name.rstrip('=')} takes {lo}..{hi} arguments, not {len(s.args)}")
            self.args(s.args)
        else:
            raise CheckError("CPL037", f"{name} is not implemented (docs/cpl.md lists what is missing)")

    def read_back(self, s: A.Proc) -> None:
        """SFK(var, texts...) and INP(var): the variable shown is given the value the operator enters."""
        if s.name == "SFK" and (not s.args or not isinstance(s.args[0], A.Var)):
            raise CheckError("CPL001", "SFK(var, texts...) needs a variable first")
        if s.name == "INP" and (len(s.args) != 1 or not isinstance(s.args[0], A.Var)):
            raise CheckError("CPL001", "INP(var) needs one variable")
        self.ty(s.args[0])
        self.args(s.args[1:])
        self.store(s.args[0], "?")

    def inp_file(self, s: A.Proc) -> None:
        if len(s.args) < 2:
            raise CheckError("CPL001", "INP# needs a file number and at least one variable: INP#(n,v1[,v2...])")
        stores = []
        for a in s.args[1:]:
            if isinstance(a, A.Var) and a.var.suffix == "$" and is_char_field(a, self.fields):
                self.field_ref(a)
            elif isinstance(a, A.Func) and a.name == "MID$" and isinstance(a.args[0], A.Var) \
                    and is_char_field(a.args[0], self.fields):
                self.args(a.args[2:3])
                self.field_ref(a.args[0])
                self.ty(a.args[1])
            elif isinstance(a, A.Var):
                stores.append(a)
            else:
                raise CheckError("CPL001", "INP# reads into variables")
        self.ty(s.args[0])
        for a in stores:
            self.store(a, "?")

    def mmc(self, args: list) -> str:
        """MMC(v1,...,v20): CPL variables only; the values the client sends back are stored into them."""
        if not args or any(not isinstance(a, A.Var) for a in args):
            raise CheckError("CPL001", "MMC takes CPL variables only")
        self.args(args)
        for a in args:
            self.store(a, "?")
        return "I"

    def nc(self, s: A.NcBlock) -> None:
        for w in s.words:
            if w.expr is not None:
                ty = self.ty(w.expr)
                if ty not in NUMERIC + ("?",):
                    raise CheckError("CPL032", f"[ ] value of address {w.address} is {tname(ty)}")
        self.args(s.loose)
        if s.call is not None:
            self.args(s.call[1])


# -- rules codegen shares -----------------------------------------------------------------------
def chain(e) -> list:
    """The operands of a '+' chain, left to right."""
    if isinstance(e, A.Bin) and e.op == "+":
        return chain(e.left) + chain(e.right)
    return [e]


def is_char_field(tv: A.Var, fields: dict) -> bool:
    v = tv.var
    if v.suffix != "$":
        return False
    if v.cls == "L":
        return v in fields
    return v.cls in ("G", "D")  # decided at run time


def needs_field(e) -> bool:
    """Results that only a character field may receive: '+' chains, STR$, MID$/TRIM$ of a chain."""
    if isinstance(e, A.Bin) and e.op == "+":
        return True
    if isinstance(e, A.Func) and e.name == "STR$":
        return True
    return isinstance(e, A.Func) and e.name in ("MID$", "TRIM$") and bool(e.args) and isinstance(e.args[0], A.Bin)


def is_field_view(s: A.Assign, fields: dict) -> bool:
    """``A$ = MID$(F$, ...)`` of a local character field: a live view into the field, or into one string of a
    2-dimensional field (manual L3373-3401)."""
    tv, e = s.target, s.expr
    v = tv.var
    return v.suffix == "$" and v.cls == "L" and not is_char_field(tv, fields) and isinstance(e, A.Func) \
        and e.name == "MID$" and len(e.args) >= 2 and isinstance(e.args[0], A.Var) \
        and is_char_field(e.args[0], fields) and e.args[0].var.cls == "L" \
        and len(e.args[0].index or ()) == fields[e.args[0].var] - 1


def const_step(step) -> int | float | None:
    """The step of a FOR statement when it is a constant (1 without STEP), else None."""
    if step is None:
        return 1
    if isinstance(step, A.Num):
        return step.value
    if isinstance(step, A.Unary) and step.op == "-" and isinstance(step.operand, A.Num):
        return -step.operand.value
    return None


def step_type(const: int | float | None, types: Types, step) -> str:
    return "I" if isinstance(const, int) else ("R" if const is not None else types[step])


def increment_type(ctype: str, step_ty: str) -> str:
    """The type of counter + step."""
    return "I" if ctype == "I" and step_ty == "I" else ("D" if "D" in (ctype, step_ty) else "R")


def tname(ty: str) -> str:
    return {"I": "INTEGER", "R": "REAL", "D": "DOUBLE", "B": "BOOLEAN", "S": "CHARACTER", "N": "NUL",
            "?": "unknown"}.get(ty, ty)


def _a(ty: str) -> str:
    name = tname(ty)
    return ("an " if name[0] in "AEIOU" else "a ") + name
