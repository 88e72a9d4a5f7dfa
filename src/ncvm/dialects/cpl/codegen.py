"""CPL program -> Python source (one function per program), through runtime.codegen.PySource.

Programs without GOTO become structured Python (if/while); programs with GOTO become a basic-block
dispatch loop (``while True: if _pc == k: ...``) so a jump may leave any structure. Local variables
are Python locals; NUL is ``None``. The checker (checker.py) has resolved the type of every expression
and refused what the control refuses; from those types most conversions and the REAL (binary32)
comparison rule of CPL manual §2.4.3, L650-737 are decided here, not at run time. Codegen only emits.
"""

from __future__ import annotations

import marshal
import math

from ...nc.block import PLAIN_WORDS
from ...nc.profiles.blockrules import g_conflict
from ...nc.profiles.typ3osa import TYP3OSA
from ...runtime.codegen import PySource
from . import ast as A
from .builtins import FUNCTIONS
from .checker import (
    IO_PROCS,
    NUMERIC,
    Raw,
    Types,
    chain,
    const_step,
    increment_type,
    is_char_field,
    is_field_view,
    needs_field,
    step_type,
)
from .errors import diag
from .lexer import VarName
from .system import SYSTEM_PROCS
from .system.gfuncs import GEARS, TYP3_G
from .system.transforms import NO_TRAVEL_G
from .values import f32

#: the addresses of a plain NC block (a plain row, nc.block)
_PLAIN = frozenset(PLAIN_WORDS)
#: parameter Pn seen through its suffix (CPL manual §3.4, L1122-1179): the conversion applied to the passed value
PARAM_VIEW = {"%": "_pint", "": "_tor", "!": "_tod", "?": "_tob", "$": "_pstr"}
SUFFIX_TAG = {"%": "i", "": "r", "!": "d", "?": "b", "$": "s"}
AXIS_LETTERS = set("XYZABCUVW")
#: the structured statements: the index after one is past its end marker
STRUCTURES = (A.If, A.Case, A.For, A.While, A.Repeat)
LOOPS = (A.For, A.While, A.Repeat)


class UnitCode:
    """The generated code of one program: source text, line map, constants and reported variable names."""

    def __init__(self, path: str, src: PySource, consts: list, cpl_lines: dict, report: list, row_words: set):
        self.path = path
        self.src = src
        self.text = src.text()
        self.code = src.compile()
        self.consts = consts
        self.cpl_lines = cpl_lines  # physical line -> CPL line number
        self.report = report  # (python name, shown name)
        self.row_words = row_words  # the addresses its plain rows have (the motion queue builds these columns only)

    def __getstate__(self) -> dict:  # kept in a link table (linktables.py): the code object as marshal data
        state = dict(self.__dict__)
        state["code"] = marshal.dumps(self.code)
        return state

    def __setstate__(self, state: dict) -> None:
        state["code"] = marshal.loads(state["code"])
        self.__dict__.update(state)


class Gen:
    def __init__(self, ln, types: Types, hook: bool = False):
        self.ln = ln
        self.prog = ln.prog
        self.stmts = ln.prog.stmts
        self.path = ln.prog.path
        self.src = PySource(self.path)
        self.types = types
        self.hook = hook
        self.locals: dict[VarName, str] = {}
        self.consts: list = []
        self.tmp = 0
        self.fields = ln.fields
        self.cur = None
        self.flat = ln.uses_goto  # the GOTO form: a dispatch loop over basic blocks
        self.max_param = 0
        self.row_words: set[str] = set()
        self.pc: dict = {}  # GOTO form: statement index (or ("t", FOR index)) -> basic block number
        #: statements counted into _n ahead of time but not yet executed, while a stretch is emitted
        self._ahead = 0
        #: generated body line index -> that number, for the lines where it is not 0 (see generate)
        self.ahead_at: dict[int, int] = {}

    # -- names -----------------------------------------------------------------
    def local(self, v: VarName) -> str:
        name = self.locals.get(v)
        if name is None:
            name = f"v_{v.name}_{SUFFIX_TAG[v.suffix]}"
            self.locals[v] = name
        return name

    def const(self, value) -> str:
        self.consts.append(value)
        return f"_K[{len(self.consts) - 1}]"

    def temp(self, base: str) -> str:
        self.tmp += 1
        return f"_{base}{self.tmp}"

    def emit(self, text: str, line: int | None = None) -> None:
        self.src.emit(text, line, self.col(line))

    def block(self, header: str, line: int | None):
        return self.src.block(header, line, self.col(line))

    def col(self, line: int | None) -> int | None:
        """The column of the statement being generated, for a run-time error in the Python lines of ``line``."""
        cur = self.cur
        return (cur.col or 1) if cur is not None and cur.line == line else None

    # -- expressions -------------------------------------------------------------
    def ex(self, e) -> tuple[str, str]:
        """(python expression, type) with type in I R D B S, N (NUL) or ? (known only at run time)."""
        t = type(e)
        if t is Raw:
            return e.code, e.ty
        ty = self.types[e]
        if t is A.Num:
            return repr(e.value), ty
        if t is A.Str:
            return repr(e.value), ty
        if t is A.BoolLit:
            return ("True" if e.value else "False"), ty
        if t is A.Nul:
            return "None", ty
        if t is A.Var:
            return self.read(e), ty
        if t is A.Unary:
            return self.unary(e), ty
        if t is A.Func:
            return self.func(e), ty
        return self.binary(e), ty

    def unary(self, e: A.Unary) -> str:
        code, ty = self.ex(e.operand)
        if e.op == "NOT":
            if ty == "B":
                return f"(not _cond({code}))" if _maybe_nul(e.operand) else f"(not {code})"
            return f"(~{code})" if ty == "I" else f"_lnot({code})"
        return f"(-{code})" if e.op == "-" else code

    def binary(self, e: A.Bin) -> str:
        op = e.op
        if op in ("=", "<>") and (isinstance(e.right, A.Nul) or isinstance(e.left, A.Nul)):
            code = self.ex(e.left if isinstance(e.right, A.Nul) else e.right)[0]
            return f"({code} is None)" if op == "=" else f"({code} is not None)"
        if op == "+" and self.types[e] == "S":  # a string chain
            return "(" + " + ".join(self.ex(p)[0] for p in chain(e)) + ")"
        lc, lt = self.ex(e.left)
        rc, rt = self.ex(e.right)
        if op in ("AND", "OR", "XOR"):
            if lt == rt and lt in ("B", "I") and not (lt == "B" and (_maybe_nul(e.left) or _maybe_nul(e.right))):
                return f"({lc} {LOGIC[op]} {rc})"
            return f"_logic({op!r}, {lc}, {rc})"
        if op in ("+", "-", "*", "/"):
            if op == "/" or lt != rt:  # an INTEGER result leaving INTEGER arithmetic: 32 bits (manual L655)
                lc, rc = _int32(e.left, lc, lt), _int32(e.right, rc, rt)
                lc, rc = _float_constant(e.left, lc, e.right), _float_constant(e.right, rc, e.left)
            return f"({lc} {op} {rc})"
        pyop = RELATION[op]
        if pyop in ("==", "!="):  # Python's == takes None silently; NUL is an error unless compared to NUL
            lc, rc = _not_nul(e.left, lc, lt), _not_nul(e.right, rc, rt)
        if lt in NUMERIC and rt in NUMERIC:
            lc, rc = _int32(e.left, lc, lt), _int32(e.right, rc, rt)
            if "D" not in (lt, rt) and "R" in (lt, rt):
                lc, rc = self._single(e.left, lc, lt), self._single(e.right, rc, rt)
        return f"({lc} {pyop} {rc})"

    def _single(self, e, code: str, ty: str) -> str:
        """An operand of a REAL comparison rounded to binary32 (CPL manual §2.4.3, L650-737), unless it already is."""
        if isinstance(e, A.Num):
            return repr(f32(e.value))
        if ty == "I":
            return code
        if isinstance(e, A.Var) and ty == "R" and e.var.cls != "A":
            return code  # REAL variables hold binary32 values already
        return f"_f32({code})"

    def func(self, e: A.Func) -> str:
        b = FUNCTIONS[e.name]
        codes, types = [], []
        out = b.out
        backs: list = []  # (variable, python expression) to store after the call
        for k, a in enumerate(e.args):
            if a is None:
                codes.append("None")
                types.append("N")
                continue
            if k in b.refs and isinstance(a, A.Var) and not a.index:
                codes.append(self.by_name(a, backs))  # a field given by its bare name (GETERR, MCODS)
                types.append("F")
                continue
            c, ty = self.ex(a)
            if k == out:
                c = f"(0 if {c} is None else {c})"  # present, even when not yet assigned
            codes.append(c)
            types.append(ty)
        if len(codes) == 1 and types[0] in NUMERIC and e.name in INLINE:
            if e.name == "INT" and magnitude(e.args[0]) < 2147483648.0:
                return f"int({codes[0]})"  # finite and within the INTEGER range: nothing to test
            return INLINE[e.name].format(codes[0])
        fn = f"_F_{e.name.replace('$', '_S')}"
        if e.name == "STR$" and types[-1] == "D":
            codes[-1] = f"_Dbl({codes[-1]})"  # the standard format depends on the value's type
        args = ", ".join((["_rt"] if b.rt else []) + (["_io"] if b.io else []) + codes)
        if out is not None and (out >= len(e.args) or e.args[out] is None):
            return f"{fn}({args})[0]"  # the variable is not given: only the result
        if out is not None or backs:
            t = self.temp("r")
            if out is not None:  # the function returns (result, new value of argument ``out``)
                backs.insert(0, (e.args[out], f"{t}[1]"))
                call = f"({t} := {fn}({args}))"
            else:
                call = f"({t} := ({fn}({args}),))"
            puts = [self.put(target, value) for target, value in backs]
            return f"({call}, {', '.join(puts)}, {t}[0])[-1]"
        return f"{fn}({args})"

    def by_name(self, a: A.Var, backs: list) -> str:
        """(field, type) for a field given by name; a simple numeric local variable travels in a box
        [None, value] as a one-element field and is stored back after the call."""
        v = a.var
        if v.cls == "L" and self.fields.get(v) is not None:
            return f"({self.local(v)}, {v.type!r})"
        if v.cls == "G":
            return f"(_gfield({v.display!r}), {v.type!r})"
        box = self.temp("b")
        backs.append((a, f"{box}[1]"))
        return f"(({box} := [None, {self.local(v)}]), {v.type!r})"

    def put(self, target: A.Var, value: str) -> str:
        """An assignment inside an expression (walrus for locals) of a numeric local or global variable."""
        ty = target.var.type
        conv = f"_toi({value})" if ty == "I" else (f"_f32({value})" if ty == "R" else f"_tod({value})")
        if target.var.cls == "L":
            return f"({self.local(target.var)} := {conv})"
        return f"_G.__setitem__({target.var.display!r}, {conv})"

    # -- variables ----------------------------------------------------------------
    def read(self, e: A.Var) -> str:
        v = e.var
        idx = [self.index(i) for i in e.index] if e.index else []
        if v.cls == "L":
            name = self.local(v)
            if self.fields.get(v) is None:
                return f"_sv({name})" if v.type == "S" else name
            return self._field_read(name, v, idx)
        if v.cls == "G":
            key = repr(v.display)
            if not idx:
                return f"_sv(_G.get({key}))" if v.type == "S" else f"_G.get({key})"
            return self._field_read(f"_gfield({key})", v, idx)
        if v.cls == "P":
            return f"_PM.get_n({v.name})"
        if v.cls == "R":
            return f"_PM.get_r({idx[0]})"
        if v.cls == "D":
            return f"_PM.get_d({v.name!r}, {v.suffix!r}, ({', '.join(idx)}{',' if idx else ''}))"
        k = int(v.name)  # a parameter Pn
        self.max_param = max(self.max_param, k)
        return f"{PARAM_VIEW[v.suffix]}(P[{k - 1}])"

    @staticmethod
    def _field_read(base: str, v: VarName, idx: list[str]) -> str:
        if v.suffix == "$":
            return f"{base}.row({idx[0]}).text" if idx else f"_sv({base})"
        return base + "".join(f"[{i}]" for i in idx)

    def index(self, e) -> str:
        code, ty = self.ex(e)
        if isinstance(e, A.Num) and ty == "I":
            return code
        return f"_ix({code})"

    # -- assignment --------------------------------------------------------------
    def convert(self, target_type: str, e, code: str, ty: str) -> str:
        """Python expression storing value ``code`` (type ``ty``) into a variable of ``target_type``."""
        if ty == "N":
            return "None"
        if target_type == "I":
            if ty == "I":
                if isinstance(e, (A.Num, A.Var)):
                    return code
                return f"_toi({code})"  # a function result too: ABS(-2147483648), BCD(99999999) leave the range
            if ty in ("R", "D"):
                return "_bad_assign('REAL value assigned to an INTEGER variable (use INT or ROUND)')"
            return f"_toi({code})"
        if target_type == "R":
            if isinstance(e, A.Var):  # a variable or parameter copied as it is: NUL stays NUL
                return code if ty == "R" else f"_tor({code})"
            if isinstance(e, A.Num):
                return repr(f32(e.value))
            return f"_f32({_int32(e, code, ty)})" if ty != "?" else f"_tor({code})"
        if target_type == "D":
            if isinstance(e, A.Num):
                return repr(float(e.value))
            if ty == "I":
                return f"_tod({code})" if isinstance(e, A.Var) else f"float({_int32(e, code, ty)})"
            # a computed DOUBLE can overflow to infinity, which _tod refuses (range +/-1e308)
            return code if ty in ("R", "D") and isinstance(e, A.Var) else f"_tod({code})"
        if target_type == "B":
            return code if ty == "B" and not _maybe_nul(e) else f"_tob({code})"
        return code  # CHARACTER

    def assign(self, s: A.Assign) -> None:
        tv = s.target
        v = tv.var
        if s.mid is not None:
            self.mid_write(s)
            return
        e = s.expr
        if is_field_view(s, self.fields):
            self.field_view(s)
            return
        if isinstance(e, A.Func) and e.name == "MMC":
            code, ty = self.mmc(e.args, s.line), "I"
        else:
            code, ty = self.ex(e)
        if v.cls == "L":
            self.assign_local(s, code, ty)
        elif v.cls == "G":
            self.assign_global(s, code, ty)
        elif v.cls == "P":
            self.emit(f"_PM.set_n({v.name}, {code})", s.line)
        elif v.cls == "R":
            self.emit(f"_PM.set_r({self.index(tv.index[0])}, {code})", s.line)
        else:  # a definable permanent
            idx = [self.index(i) for i in tv.index] if tv.index else []
            self.emit(f"_PM.set_d({v.name!r}, {v.suffix!r}, ({', '.join(idx)}{',' if idx else ''}), {code})", s.line)

    def field_view(self, s: A.Assign) -> None:
        """``A$ = MID$(F$, ...)``: a live view into the field, or into one string of a 2-dimensional field
        (manual L3373-3401)."""
        e = s.expr
        src = self.local(e.args[0].var)
        if e.args[0].index:
            src = f"{src}.row({self.index(e.args[0].index[0])})"
        start = self.ex(e.args[1])[0]
        count = self.ex(e.args[2])[0] if len(e.args) > 2 and e.args[2] is not None else "None"
        self.emit(f"{self.local(s.target.var)} = _view({src}, {start}, {count})", s.line)

    def assign_local(self, s: A.Assign, code: str, ty: str) -> None:
        tv, e, line = s.target, s.expr, s.line
        v = tv.var
        name = self.local(v)
        dims = self.fields.get(v)
        if dims is None:
            if v.type == "I" and ty == "I" and isinstance(e, (A.Bin, A.Unary)):
                # INTEGER arithmetic: check the 32-bit range inline (cheaper than a call)
                self.emit(f"{name} = {code}", line)
                self.emit(f"if not -2147483648 <= {name} <= 2147483647: {name} = _toi({name})", line)
            elif v.type == "R" and ty in NUMERIC and not isinstance(e, (A.Var, A.Num)):
                self.real_store(name, e, _int32(e, code, ty), line)
            elif v.type == "D" and ty in ("R", "D") and not isinstance(e, (A.Var, A.Num)):
                # computed DOUBLE: x - x is 0.0 unless x is infinity or NaN (the result left the range)
                self.emit(f"{name} = {code}", line)
                self.emit(f"if {name} - {name}: {name} = _tod({name})", line)
            else:
                self.emit(f"{name} = {self.convert(v.type, e, code, ty)}", line)
            return
        idx = [self.index(i) for i in tv.index] if tv.index else []
        if v.suffix == "$":
            row = f"{name}.row({idx[0]})" if dims != 1 else name
            self.emit(f"_setf({row}, {self.convert('S', e, code, ty)})", line)
            return
        self.emit(f"{name}{''.join(f'[{i}]' for i in idx)} = {self.convert(v.type, e, code, ty)}", line)

    def real_store(self, name: str, e, code: str, line: int) -> None:
        """A computed value stored into a REAL local, rounded to binary32 inline (CPL manual §2.4.3, L650-737), no call: set
        and read back the C float of a ``memoryview`` of format ``f`` (``_m32``), which rounds as ``values.f32``
        does (a C cast, as ``ctypes.c_float``, and cheaper to set and read). What it refuses (NUL, a string)
        goes to ``_f32``, which raises the error it always raised. A value beyond +/-3.4e38 comes back infinite
        (so does infinity, NaN as NaN): unless :func:`magnitude` proves the expression within the REAL range,
        the result is tested and ``_f32`` names the error. The variable keeps its old value when the store
        fails."""
        self.emit(f"_r32 = {code}", line)
        self.emit("try: _m32[0] = _r32", line)
        self.emit("except Exception: _m32[0] = _f32(_r32)", line)
        if magnitude(e) < REAL_PROVEN:
            self.emit(f"{name} = _m32[0]", line)
            return
        self.emit("_t32 = _m32[0]", line)
        self.emit("if _t32 - _t32: _t32 = _f32(_r32)", line)
        self.emit(f"{name} = _t32", line)

    def assign_global(self, s: A.Assign, code: str, ty: str) -> None:
        tv, e, line = s.target, s.expr, s.line
        v = tv.var
        key = repr(v.display)
        if ty == "N" and not tv.index:
            self.emit(f"_G.pop({key}, None)", line)
            return
        value = self.convert(v.type, e, code, ty)
        if not tv.index:
            if v.suffix == "$":
                self.emit(f"_gset_s({key}, {value}, {needs_field(e)})", line)
            else:
                self.emit(f"_G[{key}] = {value}", line)
            return
        idx = [self.index(i) for i in tv.index]
        if v.suffix == "$":
            self.emit(f"_setf(_gfield({key}).row({idx[0]}), {value})", line)
        else:
            self.emit(f"_gfield({key}){''.join(f'[{i}]' for i in idx)} = {value}", line)

    def mid_write(self, s: A.Assign) -> None:
        tv = s.target
        v = tv.var
        if v.cls == "L":
            base = self.local(v)
            if tv.index:
                base += f".row({self.index(tv.index[0])})"
        elif v.cls == "G":
            base = f"_G.get({v.display!r})"
            if tv.index:
                base = f"_gfield({v.display!r}).row({self.index(tv.index[0])})"
        else:
            base = self.field_ref(tv)
        start = self.ex(s.mid[0])[0]
        count = self.ex(s.mid[1])[0] if s.mid[1] is not None else "None"
        code = self.ex(s.expr)[0]
        self.emit(f"_midw({base}, {start}, {count}, {code})", s.line)

    def store(self, tv: A.Var, value_code: str, value_type: str, line: int) -> None:
        """Assign an already computed value (WAIT result, FOR counter)."""
        self.assign(A.Assign(line=line, target=tv, expr=Raw(value_code, value_type)))

    # -- statements -----------------------------------------------------------------
    def simple(self, i: int, s) -> None:
        self.cur = s
        t = type(s)
        line = s.line
        if self.hook:
            self.emit(f"_hook({line}, locals())", line)
        if t is A.Assign:
            self.assign(s)
        elif t is A.CallStmt:
            args = ", ".join(self.arg(a) for a in s.args)
            self.emit("_st.steps += _n; _n = 0", line)
            self.emit(f"_call({s.name!r}, ({args}{',' if s.args else ''}), {s.din}, {line})", line)
            self.emit("_lim = _st.limit - _st.steps", line)
        elif t is A.Dim:
            self.dim(s)
        elif t is A.Pdim:
            self.emit(f"P = _pdim(P, {s.var.name}, {s.size})", line)
        elif t is A.Wait:
            self.wait(s)
        elif t is A.Proc:
            self.proc(s)
        elif t is A.NcBlock:
            self.nc(s)

    def dim(self, s: A.Dim) -> None:
        for var, sizes in s.items:
            kind = "S" if var.suffix == "$" else var.type
            if var.cls == "L":
                name = self.local(var)
                self.emit(f"{name} = _dim({name}, {tuple(sizes)!r}, {kind!r})", s.line)
            else:
                key = repr(var.display)
                self.emit(f"_G[{key}] = _dim(_G.get({key}), {tuple(sizes)!r}, {kind!r})", s.line)

    def arg(self, e) -> str:
        if e is None:
            return "None"
        code, ty = self.ex(e)
        return code

    def wait(self, s: A.Wait) -> None:
        line = s.line
        if s.plain:
            self.emit("_drain()", line)
            return
        ic = "None"
        if s.ic is not None:
            ic = "(" + ", ".join(self.arg(a) for a in s.ic) + ("," if s.ic else "") + ")"
        state = self.arg(s.state) if s.state is not None else "True"
        dur = self.arg(s.duration) if s.duration is not None else "None"
        r = self.temp("w")
        self.emit(f"{r} = _wait({ic}, {s.neg}, {state}, {dur})", line)
        if s.result is not None:
            self.store(s.result, r, "I", line)

    def proc(self, s: A.Proc) -> None:
        """Statements of chapters 4-9: calls into the run's CplIO (``_io``, see docs/cpl-io.md), system
        procedures, functions called as statements."""
        line = s.line
        name = s.name
        if name in ("LJUST", "NJUST"):
            self.emit(f"_io.mode.{name}()", line)
        elif name == "PRN#":
            items = ", ".join(self.out_arg(a) if k else self.set_arg(a) for k, a in enumerate(s.args))
            self.emit(f"_io.files.PRN({items}, semicolon={s.no_end})", line)
        elif name == "INP#":
            self.inp_file(s)
        elif name == "SFK":
            self.sfk(s)
        elif name == "INP":
            tv = s.args[0]
            cur, ty = self.ex(tv)
            r = self.temp("i")
            self.emit(f"{r} = _io.screen.INP({tv.var.display!r}, {cur}, {ty!r})", line)
            self.store(tv, r, "?", line)
        elif name == "PRN" and len(s.args) == 4 and isinstance(s.args[3], A.Var):
            args = ", ".join(self.out_arg(a) for a in s.args)
            self.emit(f"_io.screen.PRN({args}, name={s.args[3].var.display!r})", line)
        elif name == "MMC":
            self.emit(self.mmc(s.args, line), line)
        elif name == "ERASE" or name in IO_PROCS:
            target = "files" if name == "ERASE" else IO_PROCS[name]
            self.emit(f"_io.{target}.{name}({self.args(s, TEXT_FROM.get(name, 99))})", line)
        elif name not in SYSTEM_PROCS:  # SCSL(...), MCOPS(...) as a statement
            self.emit(self.func(A.Func(name, s.args, 0)), line)
        else:  # chapter 4: FXC(...)=v and friends, FXCR, FXDEL, FXINS
            args = [self.ex(a)[0] if a is not None else "None" for a in s.args]
            if name.endswith("="):
                args[-1] = f"value={args[-1]}"
            self.emit(f"_rt.sys_procs[{name!r}](_rt, {', '.join(args)})", line)

    def args(self, s: A.Proc, text_from: int = 99) -> str:
        """The arguments of an I/O statement; those before position ``text_from`` (positions, sizes, names,
        colours) must not be NUL: an unassigned variable there is VARIABLE NOT ASSIGNED, not "omitted"."""
        return ", ".join(self.out_arg(a) if a is None or k >= text_from else self.set_arg(a)
                         for k, a in enumerate(s.args))

    def set_arg(self, e) -> str:
        """An argument that sets something (a file number, a position, a colour): NUL is an error."""
        code, ty = self.ex(e)
        code = _not_nul(e, code, ty)
        return f"_Dbl({code})" if ty == "D" else code

    def out_arg(self, e) -> str:
        """An argument of an output statement: DOUBLE values are marked, as their standard format differs."""
        if e is None:
            return "None"
        code, ty = self.ex(e)
        return f"_Dbl({code})" if ty == "D" else code

    def inp_file(self, s: A.Proc) -> None:
        """INP#(n, targets...): character fields are filled in place, plain variables get the values read."""
        line = s.line
        targets, stores = [], []
        for k, a in enumerate(s.args[1:]):
            if isinstance(a, A.Var) and a.var.suffix == "$" and is_char_field(a, self.fields):
                targets.append(self.field_ref(a))
            elif isinstance(a, A.Func):  # MID$ of a character field
                count = self.arg(a.args[2]) if len(a.args) > 2 else "None"
                targets.append(f"_SView({self.field_ref(a.args[0])}, {self.arg(a.args[1])}, {count})")
            else:
                targets.append(repr(a.var.type if a.var.suffix != "$" else "S"))
                stores.append((k, a))
        r = self.temp("r")
        self.emit(f"{r} = _io.files.INP({self.set_arg(s.args[0])}, {', '.join(targets)}, semicolon={s.no_end})",
                  line)
        for k, a in stores:
            self.store(a, f"{r}[{k}]", "?", line)

    def field_ref(self, tv: A.Var) -> str:
        """The character field object itself (not its text), for functions that write into it."""
        v = tv.var
        if v.cls == "D":  # a definable permanent: the field (or its row) writes through to the store
            idx = [self.index(i) for i in tv.index or ()]
            return f"_PM.char_field({v.name!r}, ({', '.join(idx)}{',' if idx else ''}))"
        base = self.local(v) if v.cls == "L" else f"_gfield({v.display!r})"
        if tv.index:
            base += f".row({self.index(tv.index[0])})"
        return base

    def sfk(self, s: A.Proc) -> None:
        tv = s.args[0]
        cur, ty = self.ex(tv)
        texts = "".join(f", {self.arg(a)}" for a in s.args[1:])
        r = self.temp("k")
        self.emit(f"{r} = _io.screen.SFK({cur}{texts}, want_text={ty == 'S'})", s.line)
        self.store(tv, r, "?", s.line)

    def mmc(self, args: list, line: int) -> str:
        """MMC(v1,...,v20): names and values go to the client; the values it sends back are stored."""
        names = tuple(a.var.display for a in args)
        values = ", ".join(self.ex(a)[0] for a in args)
        r = self.temp("m")
        self.emit(f"{r} = _io.mmc.MMC({names!r}, ({values},))", line)
        for k, a in enumerate(args):
            self.store(a, f"{r}[1][{k}]", "?", line)
        return f"{r}[0]"

    # -- NC blocks ----------------------------------------------------------------------
    def nc(self, s: A.NcBlock) -> None:
        """An NC block: its words into the motion queue, then the WAIT, the sub-program call, the program end."""
        line = s.line
        src = self.const(("src", line))  # every block has its constant, queued or not
        words = NcWords(s, self.word)
        if s.skip:
            self.emit(f"_rt.block_skip_read({src})", line)
            self.emit("if not _rt.block_skip:", line)
            self.src._indent += 1
        if words.queued:
            self.nc_queue(s, words, src)
            if 80 in words.g_const:
                self.emit("_modal[0] = None", line)
            elif words.has_motion and self.ln.modal_calls and not (s.call is not None and s.call[2]):
                # a block that selects a drilling cycle runs the new one only (its call follows)
                self.emit("if _modal[0] is not None: _st.steps += _n; _n = 0; _modal_call("
                          f"{line}); _lim = _st.limit - _st.steps", line)
        if s.wait:
            self.emit("_drain()", line)
        if s.call is not None:
            self.nc_call(s)
        if s.ends:
            self.emit("raise _EP", line)
        if s.skip:
            self.src._indent -= 1

    def word(self, w: A.NcWord) -> str:
        """The Python expression of an [expr] word's value."""
        code, ty = self.ex(w.expr)
        e = w.expr
        if isinstance(e, A.Var) and e.var.cls == "A" and e.var.suffix == "" and not e.index:
            return f"_wtor(P[{int(e.var.name) - 1}])"  # REAL view of a parameter, checked as a word
        if isinstance(e, (A.Var, A.Func)) or ty == "?":
            return f"_word({code})"
        return code

    def nc_queue(self, s: A.NcBlock, w: NcWords, src: str) -> None:
        """Queue the block: a plain row, a constant block, or one built at run time."""
        line = s.line
        typ3 = (w.g_dyn or w.m_dyn or s.loose or TYP3_G.intersection(w.g_const) or GEARS.intersection(w.m_const)
                or g_conflict(TYP3OSA, w.g_const))  # its preparation refuses it (system/gfuncs.py)
        enqueue = "_q3" if typ3 else "_q"
        if w.plain:
            self.plain_row(s, src, w.g_const, dict(w.words_const), dict(w.words_dyn), w.dynamic)
        elif not w.dynamic:
            blk = self.const(("block", tuple(w.g_const), tuple(w.m_const), dict(w.words_const), s.n, s.msg, line))
            if s.ends and w.m_sub != w.m_const:
                blk_sub = self.const(("block", tuple(w.g_const), tuple(w.m_sub), dict(w.words_const), s.n, s.msg,
                                      line))
                self.emit(f"{enqueue}({blk} if _main else {blk_sub})", line)
            else:
                self.emit(f"{enqueue}({blk})", line)
        else:
            self.nc_dynamic(s, w, enqueue, src)

    def nc_dynamic(self, s: A.NcBlock, w: NcWords, enqueue: str, src: str) -> None:
        """A block with [expr] words: its G, M and word values are computed when the block is prepared."""
        line = s.line
        g = "(" + ", ".join([repr(x) for x in w.g_const] + w.g_dyn) + ("," if (w.g_const or w.g_dyn) else "") + ")"
        m = _m_tuple(w.m_const, w.m_dyn)
        if s.ends and w.m_sub != w.m_const:
            m = f"({m} if _main else {_m_tuple(w.m_sub, w.m_dyn)})"
        items = [f"{k!r}: {v!r}" for k, v in w.words_const.items()] + [f"{k!r}: {c}" for k, c in w.words_dyn]
        words = "{" + ", ".join(items) + "}"
        if s.loose:
            loose = "(" + ", ".join(self.arg(x) for x in s.loose) + ",)"
            self.emit(f"{enqueue}(_loose({g}, {m}, {words}, {loose}, {s.n!r}, {s.msg!r}, {src}))", line)
        else:
            self.emit(f"{enqueue}(_Block({g}, {m}, {words}, {s.n!r}, {s.msg!r}, {src}))", line)

    def nc_call(self, s: A.NcBlock) -> None:
        """The sub-program call of an NC block (L, or a drilling cycle's G81-G86 made modal)."""
        line = s.line
        name, args, modal = s.call
        argc = ", ".join(self.arg(a) for a in args)
        self.emit("_st.steps += _n; _n = 0", line)
        if modal:  # a new selection replaces the old one, whose repetitions must not run inside this call
            self.emit("_modal[0] = None", line)
        self.emit(f"_call({name!r}, ({argc}{',' if args else ''}), False, {line})", line)
        self.emit("_lim = _st.limit - _st.steps", line)
        if modal:
            self.emit(f"_modal[0] = ({name!r}, ({argc}{',' if args else ''}))", line)

    def plain_row(self, s: A.NcBlock, src: str, g: list, const: dict, dyn: dict, dynamic: bool) -> None:
        """A plain block goes into the queue as a plain row (nc.block): a tuple, no Block and no dict."""
        motion = g[0] if g else -1
        self.row_words.update(const, dyn)
        if not dynamic:
            values = tuple(const.get(a, math.nan) for a in PLAIN_WORDS)
            self.emit(f"_qr({self.const(('plain row', (motion, *values, s.line, s.n)))})", s.line)
            return
        cells = [dyn[a] if a in dyn else repr(const[a]) if a in const else "_NaN" for a in PLAIN_WORDS]
        self.emit(f"_qr(({motion!r}, {', '.join(cells)}, {s.line}, {s.n!r}, {src}))", s.line)

    # -- structured code (programs without GOTO) ----------------------------------------
    def count(self, a: int, b: int) -> int:
        """Statements executed on one straight pass through [a, b) (nested bodies not counted)."""
        n, i = 0, a
        pair = self.ln.pair
        while i < b:
            s = self.stmts[i]
            if not isinstance(s, A.LabelDef):
                n += 1
            i = pair[i]["end"] + 1 if type(s) in STRUCTURES else i + 1
        return n

    def structured(self, a: int, b: int, extra: int = 0) -> None:
        """The stretch [a, b) (a loop's body with ``extra`` = 1 for its END, NEXT or UNTIL), in the groups
        of :meth:`groups`."""
        for ga, gb, k_extra in self.groups(a, b, extra):
            self.group(ga, gb, k_extra)

    def groups(self, a: int, b: int, extra: int) -> list[tuple[int, int, int]]:
        """The groups of [a, b), each counted at its head: a structure that repeats (a loop, or one holding
        a loop or a call) is a group of its own, and a call ends its group, so nothing is counted ahead of
        a loop's passes or a called program and the step limit stops them exactly; ``extra`` (the loop's
        END) goes with the last group."""
        pair = self.ln.pair
        out, start, i = [], a, a
        while i < b:
            s = self.stmts[i]
            t = type(s)
            nxt = self._next_index(i, t, pair)
            if t in STRUCTURES and self.repeats(i, nxt):
                if start < i:
                    out.append((start, i, 0))
                out.append((i, nxt, 0))
                start = nxt
            elif self.calls(s):
                out.append((start, nxt, 0))
                start = nxt
            i = nxt
        if start < b or extra:
            out.append((start, b, extra))
        return out

    def repeats(self, i: int, nxt: int) -> bool:
        """Whether the structure at ``i`` (ending before ``nxt``) is a loop or holds a loop or a call."""
        return type(self.stmts[i]) in LOOPS or any(type(s) in LOOPS or self.calls(s) for s in self.stmts[i + 1:nxt])

    def calls(self, s) -> bool:
        """Whether a statement calls a program: CALL, an NC block's L or drilling cycle call. (A selected
        cycle that runs after a traversing block is left inside its group: counted ahead, it stops early.)"""
        return type(s) is A.CallStmt or (type(s) is A.NcBlock and s.call is not None)

    def group(self, a: int, b: int, extra: int) -> None:
        """A group counted at its head and tested there: a group that would pass the step limit is not
        begun (the count, with the statements of enclosing groups counted ahead taken back on the way out,
        stays the statements that ran; RUN001 names the group's first statement)."""
        k = self.count(a, b) + extra
        if k:
            self.emit(f"_n += {k}")
            self.emit(f"if _n > _lim: _n -= {k}; _runaway({self.first_line(a, b)})")
        i = a
        pair = self.ln.pair
        outer, remaining = self._ahead, k
        while i < b:
            s = self.stmts[i]
            self.cur = s
            t = type(s)
            if t is not A.LabelDef:
                remaining -= 1
            self._ahead = ahead = outer + remaining
            first = len(self.src.lines)
            self._structured_one(i, s, t, pair)
            if ahead:  # lines of nested stretches already carry their own (larger) figure
                for j in range(first, len(self.src.lines)):
                    self.ahead_at.setdefault(j, ahead)
            i = self._next_index(i, t, pair)
        self._ahead = outer

    def first_line(self, a: int, b: int) -> int:
        """The line of the first statement a stretch runs: its first that is not a label, else the END,
        NEXT or UNTIL that closes it."""
        for s in self.stmts[a:b]:
            if not isinstance(s, A.LabelDef):
                return s.line
        return self.stmts[b].line

    @staticmethod
    def _next_index(i: int, t, pair) -> int:
        return pair[i]["end"] + 1 if t in STRUCTURES else i + 1

    def _structured_one(self, i: int, s, t, pair) -> None:
        """One statement of a stretch (a whole structure for IF, CASE and the loops)."""
        if t is A.If:
            info = pair[i]
            cond = self.condition(s.cond)
            with self.block(f"if {cond}:", s.line):
                self.structured(i + 1, info["else"] if info["else"] is not None else info["end"])
            if info["else"] is not None:
                with self.block("else:", self.stmts[info["else"]].line):
                    self.structured(info["else"] + 1, info["end"])
        elif t is A.Case:
            info = pair[i]
            sel, select = self.case_selector(s)
            self.emit(select, s.line)
            arms = info["arms"]
            bounds = arms + ([info["otherwise"]] if info["otherwise"] is not None else []) + [info["end"]]
            kw = "if"
            for j, arm in enumerate(arms):
                vals = self.stmts[arm].values
                test = f"{sel} == {vals[0]}" if len(vals) == 1 else f"{sel} in {tuple(vals)!r}"
                with self.block(f"{kw} {test}:", self.stmts[arm].line):
                    self.structured(arm + 1, bounds[j + 1])
                kw = "elif"
            if info["otherwise"] is not None:
                ow = info["otherwise"]
                with self.block("else:" if arms else "if True:", self.stmts[ow].line):
                    self.structured(ow + 1, info["end"])
        elif t is A.For:
            end = pair[i]["end"]
            self.for_loop(i, s, end)
        elif t is A.While:
            end = pair[i]["end"]
            cond = self.condition(s.cond)
            with self.block(f"while {cond}:", s.line):
                self.structured(i + 1, end, extra=1)
        elif t is A.Repeat:
            end = pair[i]["end"]
            with self.block("while True:", s.line):
                self.structured(i + 1, end, extra=1)
                self.emit(f"if {self.condition(self.stmts[end].cond)}: break", self.stmts[end].line)
        elif t not in (A.Else, A.EndIf, A.CaseLabel, A.Otherwise, A.EndCase, A.Next, A.WEnd, A.Until):
            self.simple(i, s)

    def case_selector(self, s) -> tuple[str, str]:
        """The temporary that holds a CASE value, and the Python statement that sets it."""
        sel = self.temp("c")
        return sel, f"{sel} = _caseval({self.ex(s.expr)[0]})"

    def condition(self, e) -> str:
        code, ty = self.ex(e)
        return code if ty == "B" and not _maybe_nul(e) else f"_cond({code})"

    def for_parts(self, s: A.For):
        """The counter, its type, the start (code, type), the end's code and the constant step (or None)."""
        v = s.var
        start = self.ex(s.start)
        end_code = self.ex(s.end)[0]
        return v, v.var.type, start, end_code, const_step(s.step)

    def for_loop(self, i: int, s: A.For, end: int) -> None:
        v, ctype, start, end_code, step = self.for_parts(s)
        fe = self.temp("fe")
        fs = self.temp("fs")
        self.store(v, start[0], start[1], s.line)
        self.emit(f"{fe} = {end_code}", s.line)
        counter = self.read(v)
        if step is not None:
            test = f"{counter} <= {fe}" if step >= 0 else f"{counter} >= {fe}"
            step_code = repr(step)
        else:
            step_code = self.ex(s.step)[0]
            self.emit(f"{fs} = {step_code}", s.line)
            test = f"({counter} <= {fe} if {fs} >= 0 else {counter} >= {fe})"
        nxt = self.stmts[end]
        with self.block(f"while {test}:", s.line):
            self.structured(i + 1, end, extra=1)
            if step is not None:
                inc_code = f"({counter} + {step_code})"
            else:
                self.emit(f"{fs} = {step_code}", nxt.line)
                inc_code = f"({counter} + {fs})"
            inc_ty = increment_type(ctype, step_type(step, self.types, s.step))
            if ctype == "I" and inc_ty == "I" and v.var.cls == "L" and not v.index:
                self.emit(f"{counter} = {inc_code}", nxt.line)
            else:
                self.store(v, inc_code, inc_ty, nxt.line)
        if ctype == "I" and inc_ty == "I" and v.var.cls == "L" and not v.index:  # exit value past INTEGER, once
            self.cur = nxt
            self.emit(f"if not -2147483648 <= {counter} <= 2147483647: {counter} = _toi({counter})", nxt.line)

    # -- dispatch code (programs with GOTO) ---------------------------------------------------
    def dispatch(self) -> None:
        stmts = self.stmts
        n = len(stmts)
        leaders = self.leaders()
        order = sorted((x for x in leaders if isinstance(x, int)))
        pc: dict = {}
        for x in order:
            pc[x] = len(pc)
        for x in leaders:
            if not isinstance(x, int):
                pc[x] = len(pc)
        self.pc = pc
        self.emit("_pc = 0")
        with self.src.block("while True:"):
            self._open(0)
            for i, s in enumerate(stmts):
                if i in pc and i != 0:
                    self._close(pc[i])
                    self._open(pc[i])
                self.lower(i, s)
            if n in pc and n != 0:
                self._close(pc[n])
                self._open(pc[n])
            self.emit("break")
            self.src._indent -= 1

    def leaders(self) -> set:
        """The statements that begin a basic block (jump targets, the statements after a structure's parts),
        and ("t", i) for the test of the FOR loop at i."""
        pair = self.ln.pair
        leaders: set = {0}
        for i, s in enumerate(self.stmts):
            t = type(s)
            if t is A.Goto:
                leaders.add(self.ln.jumps[i])
            elif t is A.If:
                info = pair[i]
                leaders.add(info["else"] + 1 if info["else"] is not None else info["end"] + 1)
                leaders.add(info["end"] + 1)
            elif t is A.Case:
                info = pair[i]
                for arm in info["arms"]:
                    leaders.add(arm + 1)
                if info["otherwise"] is not None:
                    leaders.add(info["otherwise"] + 1)
                leaders.add(info["end"] + 1)
            elif t is A.For:
                leaders.add(pair[i]["end"] + 1)
                leaders.add(("t", i))
            elif t is A.While:
                leaders.add(i)
                leaders.add(pair[i]["end"] + 1)
            elif t is A.Repeat:
                leaders.add(i + 1)
        return leaders

    def _open(self, k: int) -> None:
        self.emit(f"if _pc == {k}:")
        self.src._indent += 1

    def _close(self, nxt: int) -> None:
        self.emit(f"_pc = {nxt}")
        self.src._indent -= 1

    def count_one(self, line: int) -> None:
        """Count one statement of the GOTO form and test the step limit before it runs."""
        self.emit("_n += 1", line)
        self.emit(f"if _n > _lim: _n -= 1; _runaway({line})", line)

    def emit_jump(self, key, line: int) -> None:
        """A jump counts one step (tested like a statement), then goes to the basic block ``key``."""
        self.count_one(line)
        self.emit(f"_pc = {self.pc[key]}", line)
        self.emit("continue", line)

    def lower(self, i: int, s) -> None:
        """One statement in the GOTO form."""
        self.cur = s
        t = type(s)
        pair = self.ln.pair
        line = s.line
        if t is A.Goto:
            self.emit_jump(self.ln.jumps[i], line)
        elif t is A.If:
            info = pair[i]
            target = info["else"] + 1 if info["else"] is not None else info["end"] + 1
            self.count_one(line)
            with self.block(f"if not {self.condition(s.cond)}:", line):
                self.emit_jump(target, line)
        elif t is A.Else:
            self.emit_jump(pair[i]["end"] + 1, line)
        elif t is A.Case:
            info = pair[i]
            sel, select = self.case_selector(s)
            self.count_one(line)
            self.emit(select, line)
            for arm in info["arms"]:
                vals = self.stmts[arm].values
                with self.block(f"if {sel} in {tuple(vals)!r}:", line):
                    self.emit_jump(arm + 1, line)
            other = info["otherwise"] + 1 if info["otherwise"] is not None else info["end"] + 1
            self.emit_jump(other, line)
        elif t in (A.CaseLabel, A.Otherwise):
            self.emit_jump(pair[i]["end"] + 1, line)
        elif t is A.For:
            self.lower_for(i, s)
        elif t is A.Next:
            self.lower_next(i, s)
        elif t is A.While:
            self.count_one(line)
            with self.block(f"if not {self.condition(s.cond)}:", line):
                self.emit_jump(pair[i]["end"] + 1, line)
        elif t is A.WEnd:
            self.emit_jump(pair[i]["while"], line)
        elif t is A.Repeat:
            pass
        elif t is A.Until:
            self.count_one(line)
            with self.block(f"if not {self.condition(s.cond)}:", line):
                self.emit_jump(pair[i]["repeat"] + 1, line)
        elif t in (A.EndIf, A.EndCase, A.LabelDef):
            pass
        else:
            self.count_one(line)
            self.simple(i, s)

    def lower_for(self, i: int, s: A.For) -> None:
        """FOR in the GOTO form: the start and the limits, then the test, a basic block of its own."""
        pair = self.ln.pair
        line = s.line
        v, ctype, start, end_code, step = self.for_parts(s)
        fe, fs = f"_fe{i}", f"_fs{i}"
        self.store(v, start[0], start[1], line)
        self.emit(f"{fe} = {end_code}", line)
        if step is not None:
            self.emit(f"{fs} = {step!r}", line)
        else:
            self.emit(f"{fs} = {self.ex(s.step)[0]}", line)
        self._close(self.pc[("t", i)])
        self._open(self.pc[("t", i)])
        counter = self.read(v)
        self.count_one(line)
        with self.block(f"if not ({counter} <= {fe} if {fs} >= 0 else {counter} >= {fe}):", line):
            self.emit_jump(pair[i]["end"] + 1, line)

    def lower_next(self, i: int, s: A.Next) -> None:
        """NEXT in the GOTO form: the step (a computed STEP again) and the jump back to the test."""
        pair = self.ln.pair
        line = s.line
        j = pair[i]["for"]
        f = self.stmts[j]
        v, ctype, start, end_code, step = self.for_parts(f)
        fs = f"_fs{j}"
        if step is None:
            self.emit(f"{fs} = {self.ex(f.step)[0]}", line)
        counter = self.read(v)
        inc_ty = increment_type(ctype, step_type(step, self.types, f.step))
        self.store(v, f"({counter} + {fs})", inc_ty, line)
        self.emit_jump(("t", j), line)

    # -- the unit ------------------------------------------------------------------------
    def generate(self) -> UnitCode:
        body = PySource(self.path)
        outer = self.src
        self.src = body
        body._indent = 3
        try:
            if self.flat:
                self.dispatch()
            else:
                self.structured(0, len(self.stmts))
        finally:
            self.src = outer
        src = self.src
        src.emit("def make(_H, _K):")
        src._indent = 1
        for name in HELPER_NAMES:
            src.emit(f"{name} = _H[{name!r}]")
        ahead_line = len(src.lines)
        src.emit("_AHEAD = {}")  # filled in below, once the body's place is known
        src.emit("def unit(P, _main):")
        src._indent = 2
        for name in sorted(set(self.locals.values())):
            src.emit(f"{name} = None")
        if self.max_param:
            src.emit(f"if len(P) < {self.max_param}: P = P + (None,) * ({self.max_param} - len(P))")
        src.emit("_n = 0")
        src.emit("_lim = _st.limit - _st.steps")
        src.emit("try:")
        first = len(src.lines) + 1  # Python line number of the body's first line
        src.append(body)
        if not body.lines:
            src.emit("    pass")
        # a fault leaves out of the steps the statements counted ahead of it (_AHEAD, by Python line)
        src.lines[ahead_line] = src.lines[ahead_line].replace(
            "{}", repr({first + j: k for j, k in sorted(self.ahead_at.items())}))
        report = sorted(((py, v.display) for v, py in self.locals.items()), key=lambda x: x[1])
        items = ", ".join(f"{shown!r}: {py}" for py, shown in report)
        src.emit("except _EP:")
        src.emit("    pass")
        src.emit("except BaseException as _e:")
        src.emit("    _n -= _AHEAD.get(_e.__traceback__.tb_lineno, 0)")
        src.emit(f"    if _main: _rt.fault_locals = {{{items}}}  # what the main program held when it faulted")
        src.emit("    raise")
        src.emit("finally:")
        src.emit("    _st.steps += _n")
        src.emit(f"return {{{items}}} if _main else None  # the variables are reported for the main program")
        src._indent = 1
        src.emit("return unit")
        cpl_lines = {s.line: s.cpl for s in self.stmts if s.cpl is not None}
        return UnitCode(self.path, src, self.consts, cpl_lines, report, self.row_words)




class NcWords:
    """The words of an NC block sorted for emitting: constant and computed G, M and address words."""

    def __init__(self, s: A.NcBlock, word):
        self.g_const: list = []
        self.m_const: list = []
        self.g_dyn: list[str] = []
        self.m_dyn: list[str] = []
        self.words_const: dict = {}
        self.words_dyn: list[tuple[str, str]] = []
        for w in s.words:
            if w.expr is None:
                if w.address == "G":
                    v = w.value
                    self.g_const.append(int(v) if v == int(v) else v)
                elif w.address == "M":
                    self.m_const.append(int(w.value))
                else:
                    self.words_const[w.address] = w.value
            else:
                code = word(w)
                if w.address == "G":
                    self.g_dyn.append(f"_nocall('G', {code})")
                elif w.address == "M":
                    self.m_dyn.append(f"_nocall('M', {code})")
                else:
                    self.words_dyn.append((w.address, code))
        #: the M functions of the block in a sub-program (M2/M30 end the sub-program, not the run)
        self.m_sub = [m for m in self.m_const if m not in (2, 30)]
        moves = any(k[0] in AXIS_LETTERS for k in self.words_const) or any(a[0] in AXIS_LETTERS for a, _ in self.words_dyn)
        self.has_motion = moves and not NO_TRAVEL_G.intersection(self.g_const)  # G60 X5, G92 X0, G4 X1: no travel
        self.queued = bool(self.g_const or self.m_const or self.words_const or self.g_dyn or self.m_dyn
                           or self.words_dyn or s.loose or s.msg is not None)
        self.dynamic = bool(self.g_dyn or self.m_dyn or self.words_dyn or s.loose)
        # a plain block (a motion G code at most, words of PLAIN_WORDS): the queue runs it column-wise
        self.plain = (not self.m_const and not self.m_dyn and not self.g_dyn and not s.loose and s.msg is None
                      and len(self.g_const) <= 1 and set(self.g_const) <= {0, 1, 2, 3}
                      and set(self.words_const) <= _PLAIN and all(a in _PLAIN for a, _ in self.words_dyn))


def _m_tuple(m_const: list, m_dyn: list[str]) -> str:
    """The Python tuple of a block's M functions: the constant ones, then the computed ones."""
    items = [repr(x) for x in m_const] + [f"_mval({c})" for c in m_dyn]
    return "(" + ", ".join(items) + ("," if items else "") + ")"


#: CPL's logical and relational operators as Python's
LOGIC = {"AND": "&", "OR": "|", "XOR": "^"}
RELATION = {"=": "==", "<>": "!=", "<": "<", ">": ">", "<=": "<=", ">=": ">="}


def _not_nul(e, code: str, ty: str) -> str:
    """An operand of = or <> that may be NUL (a variable, a function result) must not be: VARIABLE NOT
    ASSIGNED (CPL manual §2.5, L758-769). ``+ 0`` raises the TypeError for a NUL number without a call."""
    if not _maybe_nul(e):
        return code
    return f"({code} + 0)" if ty in NUMERIC else f"_nn({code})"


def _int32(e, code: str, ty: str) -> str:
    """An INTEGER sum, difference, product or negation used outside INTEGER arithmetic (compared, stored into
    a REAL, mixed with one) must fit 32 bits (manual L655): INVALID INTEGER VALUE otherwise.
    INTEGER stores check on their own, so ``I% = I% + 1`` pays nothing. Constants alone are exempt: they take
    the precision of their context (``D2! = -123456789012345``, manual L484-490)."""
    if ty == "I" and (isinstance(e, A.Bin) or isinstance(e, A.Unary) and e.op == "-") and _reads(e):
        return f"_toi({code})"
    return code


def _float_constant(e, code: str, other) -> str:
    """An integer constant beside an operand that is a float whenever it is a number, written as a float:
    ``abs(v_S_r) + 1.0`` is CPython's float-only arithmetic (about 10 ns an operation less than ``+ 1``), with
    the same result (the constant converts exactly, |n| <= 2**53) and the same TypeError for NUL."""
    if type(e) is A.Num and type(e.value) is int and abs(e.value) <= 1 << 53 and _float_or_nul(other):
        return repr(float(e.value))
    return code


def _float_or_nul(e) -> bool:
    """Is the expression a Python float or NUL at run time: a REAL local (its stores round through a C float
    or convert to one), a float constant, or SIN, COS, ATAN, SQRT, ABS of one (ABS keeps the type)?"""
    t = type(e)
    if t is A.Var:
        return e.var.cls == "L" and e.var.type == "R" and not e.index
    if t is A.Num:
        return type(e.value) is float
    if t is A.Func and len(e.args) == 1 and e.args[0] is not None:
        return e.name in ("SIN", "COS", "ATAN", "SQRT") or e.name == "ABS" and _float_or_nul(e.args[0])
    return False


def _reads(e) -> bool:
    """Does the expression read a variable or call a function (is it more than constants)?"""
    if isinstance(e, A.Bin):
        return _reads(e.left) or _reads(e.right)
    if isinstance(e, A.Unary):
        return _reads(e.operand)
    return not isinstance(e, (A.Num, A.Str, A.BoolLit, A.Nul))


def _maybe_nul(e) -> bool:
    """Can the BOOLEAN expression be NUL (a variable read) rather than a computed TRUE/FALSE?"""
    return isinstance(e, (A.Var, A.Func))


#: the bound of |value| a variable of each type holds: INTEGER 32 bits, REAL binary32 (FLT_MAX), BOOLEAN
_HOLDS = {"I": 2147483648.0, "R": 3.4028234663852886e38, "B": 1.0}
#: a bound below which a computed value is a finite REAL: under FLT_MAX (3.4028e38) by far more than the
#: rounding of the bound's own arithmetic and of the expression's
REAL_PROVEN = 3.4e38
#: bounds of the built-ins written inline, from the bound of their argument
_FUNC_BOUND = {"ABS": lambda b: b, "SIN": lambda b: 1.0, "COS": lambda b: 1.0, "SQRT": math.sqrt,
               "INT": lambda b: 2147483648.0}


def magnitude(e) -> float:
    """An upper bound of |value of e| (infinity when none is known): constants, INTEGER and REAL variables
    (their stores keep them in range), sums, products, quotients by a constant and a few built-ins. A finite
    bound below the DOUBLE range proves the computed value is neither infinite nor NaN."""
    if isinstance(e, A.Num):
        return math.inf if abs(e.value) > 1e300 else abs(float(e.value))  # an integer beyond any float: unbounded
    if isinstance(e, A.Var):
        return _HOLDS.get(e.var.type, math.inf) if e.var.cls in ("L", "G") else math.inf
    if isinstance(e, A.Unary) and e.op in ("-", "+"):
        return magnitude(e.operand)
    if isinstance(e, A.Bin):
        if e.op in ("+", "-"):
            return magnitude(e.left) + magnitude(e.right)
        if e.op == "*":
            return magnitude(e.left) * magnitude(e.right)
        if e.op == "/" and isinstance(e.right, A.Num) and e.right.value:
            return magnitude(e.left) / abs(float(e.right.value))
    if isinstance(e, A.Func) and e.name in _FUNC_BOUND and len(e.args) == 1 and e.args[0] is not None:
        return _FUNC_BOUND[e.name](magnitude(e.args[0]))
    return math.inf


#: output statements whose arguments from this position on are printed (NUL prints nothing)
TEXT_FROM = {"DSP": 2, "PRN": 2}


#: built-ins with a numeric argument known at compile time, written inline (no call, no type check)
INLINE = {
    "ABS": "abs({0})",
    # INT: truncation with the 32-bit range check inline; infinity, NaN or a result out of range go to the
    # checked built-in, which names the error
    # (a value strictly between -2147483649 and 2147483648 truncates into the range; NaN compares false)
    "INT": "(int(_a) if -2147483649.0 < (_a := ({0})) < 2147483648.0 else _F_INT(_a))",
    "SIN": "_msin({0} * 0.017453292519943295)",
    "COS": "_mcos({0} * 0.017453292519943295)",
    "ATAN": "(_matan({0}) * 57.29577951308232)",
    "SQRT": "_msqrt({0})",  # a negative argument raises ValueError: RUNTIME ERROR CPL029
}

HELPER_NAMES = (
    "_rt", "_st", "_G", "_PM", "_EP", "_qr", "_NaN", "_f32", "_toi", "_tor", "_wtor", "_tod", "_tob", "_tos", "_bad_assign", "_cond",
    "_logic", "_lnot", "_ix", "_sv", "_view", "_setf", "_midw", "_dim", "_pdim", "_pstr", "_gfield", "_gset_s", "_pint",
    "_call", "_q", "_q3", "_drain", "_wait", "_Block", "_loose", "_word", "_mval", "_modal", "_modal_call",
    "_runaway", "_hook", "_caseval", "_nocall", "_msin", "_mcos", "_matan", "_msqrt",
    "_io", "_Dbl", "_SView", "_nn", "_m32",
) + tuple(f"_F_{name.replace('$', '_S')}" for name in FUNCTIONS)


def generate(ln, types: Types, hook: bool = False) -> tuple[UnitCode | None, list]:
    """Generate the unit for a linked program the checker passed (``types`` are its results).

    Structures nested deeper than Python's blocks allow are generated in the flat (GOTO) form instead; an
    expression too deep for Python is the manual's NESTING TOO DEEP (2153, §2.5.1 L782: the depth a control
    allows depends on the memory the expression needs)."""
    for flat in ((True,) if ln.uses_goto else (False, True)):
        g = Gen(ln, types, hook)
        g.flat = flat
        try:
            return g.generate(), []
        except (RecursionError, SyntaxError, MemoryError) as e:
            line = g.src.source_line(e.lineno) if isinstance(e, SyntaxError) and e.lineno else 0
            s = next((x for x in g.stmts if x.line == line), None) or g.cur
    return None, [diag("2153", "expression or structure too deep to evaluate", ln.prog.path, s.line if s else 1,
                       (s.col or None) if s else None, s.cpl if s else None)]
