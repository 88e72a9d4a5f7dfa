"""Resolves every name and type of a parsed program before code generation (manual §5.3).

Errors carry the manual's numbers where it has them (3: used before its
declaration, 91: function result not used) and ncvm's SPnnn numbers otherwise.
The checker annotates the tree: ``ty`` on expressions, ``sym`` on names and calls.
"""

from __future__ import annotations

from . import ast as A
from .errors import SympasError
from .lexer import INT_MAX
from .symbols import (
    BIT_QUALIFIERS,
    BUILTINS,
    CASTS,
    EVENTS,
    INTLIKE,
    NUMERIC,
    QUALIFIER_ALIASES,
    QUALIFIERS,
    REAL,
    AxisSpec,
    Builtin,
    Const,
    Label,
    Routine,
    SysParam,
    Var,
    sysparam,
)


def assignable(dst: str, src: str) -> bool:
    """Assignment compatibility (L533-539) widened by rw_SymPas manual L533-539; L781; L783."""
    if dst == src:
        return True
    if dst == "double":
        return src in ("integer", "single", "boolean", "timer")
    if dst == "single":
        return src in ("integer", "boolean", "timer")
    if dst == "integer":
        return src in ("boolean", "timer")
    if dst == "timer":
        return src == "integer"
    return False


def literal_fits(dst: str, node) -> bool:
    """A literal constant may be narrowed where its value fits: 0.1 -> single, 5 -> timer (rw_SymPas manual L533-539; L781; L783)."""
    if isinstance(node, A.Unary) and node.op in ("+", "-"):
        node = node.operand
    if isinstance(node, A.Name) and isinstance(node.sym, Const):
        value, ty = node.sym.value, node.sym.ty
    elif isinstance(node, A.Num):
        value, ty = node.value, node.ty
    else:
        return False
    if dst == "single" and ty == "double":
        return True
    return dst == "timer" and ty == "integer" and value >= 0


class Scope:
    def __init__(self, parent: Scope | None, routine: Routine | None = None):
        self.names: dict = {}
        self.parent = parent
        self.routine = routine
        self.labels: dict[str, Label] = {}

    def lookup(self, name: str):
        s = self
        while s is not None:
            if name in s.names:
                return s.names[name]
            s = s.parent
        return None


class Checker:
    def __init__(self, axis_names: list[str], warn=None):
        self.warn = warn or (lambda code, msg, node: None)
        self.predef = Scope(None)
        for i, n in enumerate(axis_names):
            self.predef.names[n] = AxisSpec(n, i)
        self.axis_count = len(axis_names)
        self.events_used = False
        self.steps_tasks = False  # STEPCNCT appears: every task must stop after each line (L2125)
        self.axis_an_written = False
        self.uses_clock = False

    def err(self, code: str, msg: str, node):
        raise SympasError(code, msg, node.file, node.line, node.col)

    def undeclared(self, node):
        """Error 3: `node` names nothing declared before it."""
        self.err("3", f"'{node.name}' is not declared (or used before its declaration)", node)

    def declared(self, node, scope=None):
        """The symbol `node` names in `scope` (the current one by default); error 3 where there is none."""
        sym = (self.scope if scope is None else scope).lookup(node.name)
        if sym is None:
            self.undeclared(node)
        return sym

    # -- program -----------------------------------------------------------------
    def program(self, prog: A.Program) -> None:
        g = Scope(self.predef)
        self.globals: list[Var] = []
        self.routines: list[Routine] = []
        self.scope = g
        if isinstance(prog.task, str):
            c = g.lookup(prog.task)
            # {$TASK Task1} may name a constant declared before it
            prog.task_name = prog.task
        for d in prog.decls:
            self.decl(d, g, top=True)
        if isinstance(prog.task, str):
            c = g.lookup(prog.task)
            if not isinstance(c, Const) or c.ty != "integer" or not 0 <= c.value <= 3:
                self.err("SP010", f"{{$TASK {prog.task}}}: task must be 0..3 or an integer constant of that range",
                         getattr(prog, "task_tok", prog))
            prog.task = c.value
        elif prog.task is not None and not 0 <= prog.task <= 3:
            self.err("SP010", "{$TASK n}: the task number must be 0..3", getattr(prog, "task_tok", prog))
        for r in self.routines:
            if not r.defined:
                self.err("SP009", f"{'function' if r.result else 'procedure'} '{r.name}' is declared forward "
                                  "but never defined", r.forward_node)
        self.body(prog.body, g)

    def declare(self, scope: Scope, name: str, sym, node) -> None:
        if name in scope.names:
            self.err("SP002", f"'{name}' is declared twice in this block", node)
        if scope.lookup(name) is not None and not isinstance(scope.lookup(name), AxisSpec):
            pass  # hiding an outer name is allowed (L658)
        scope.names[name] = sym

    def decl(self, d, scope: Scope, top: bool) -> None:
        if isinstance(d, A.ConstDecl):
            v = d.value
            if isinstance(v, A.Num):
                val, ty = v.value, v.ty
            else:
                if v.name.upper() in ("TRUE", "FALSE"):
                    val, ty = v.name.upper() == "TRUE", "boolean"
                else:
                    c = self.declared(v, scope)
                    if not isinstance(c, Const):
                        self.err("SP001", f"'{v.name}' is not a constant (constant expressions are not possible)", v)
                    val, ty = c.value, c.ty
                if d.sign == -1:
                    if ty == "boolean":
                        self.err("SP003", "a sign cannot stand before a boolean constant", v)
                    val = -val
            self.declare(scope, d.name, Const(d.name, ty, val), d)
        elif isinstance(d, A.VarDecl):
            if d.ty == "axis" and not top:
                self.err("SP008", "AXIS variables may be declared in the main program only (L728)", d)
            for name, tok in d.names:
                py = ("g_" if top else "l_") + name
                v = Var(name, d.ty, py, top)
                self.declare(scope, name, v, tok)
                if top:
                    self.globals.append(v)
                else:
                    scope.routine.locals.append(v)
        elif isinstance(d, A.LabelDecl):
            for name, tok in d.names:
                lab = Label(name, decl=tok)
                self.declare(scope, name, lab, tok)
                scope.labels[name] = lab
        elif isinstance(d, A.Routine):
            self.routine(d, scope)

    def routine(self, d: A.Routine, g: Scope) -> None:
        prev = g.names.get(d.name)
        if isinstance(prev, Routine) and not prev.defined and not d.forward:
            r = prev
            if [(p.name, p.ty) for p in d.params] != [(p.name, p.ty) for p in r.params] or d.result != r.result:
                if d.params or d.result:
                    self.err("SP009", f"the header of '{d.name}' differs from its forward declaration", d)
        else:
            r = Routine(d.name, list(d.params), d.result, "r_" + d.name, is_event=d.name in EVENTS)
            self.declare(g, d.name, r, d)
            self.routines.append(r)
            if r.is_event and (d.params or d.result):
                self.err("SP005", f"event procedure '{d.name}' must be a procedure without parameters", d)
        if d.forward:
            r.forward_node = d
            return
        r.node = d
        r.defined = True
        s = Scope(g, routine=r)
        r.locals = []
        r.scope = s
        for p in r.params:
            v = Var(p.name, p.ty, "l_" + p.name, False)
            self.declare(s, p.name, v, p)
            r.locals.append(v)
        r.param_vars = list(r.locals)
        if r.result:
            r.result_var = Var(r.name, r.result, "l__result", False)
        for x in d.decls:
            self.decl(x, s, top=False)
        self.body(d.body, s)

    # -- statements ---------------------------------------------------------------
    def body(self, comp: A.Compound, scope: Scope) -> None:
        prev = self.scope
        self.scope = scope
        self.loop_depth = 0
        self.gotos: list = []
        # labels are defined in the block's top-level statement sequence
        for i, s in enumerate(comp.body):
            if s.label is not None:
                lab = scope.labels.get(s.label)
                if lab is None:
                    self.err("3" if scope.lookup(s.label) is None else "SP004",
                             f"label '{s.label}' is not declared in this block", s)
                if lab.defined:
                    self.err("SP004", f"label '{s.label}' is defined more than once (L594)", s)
                lab.defined = True
                lab.index = i
        self.stmt_list(comp.body, top=True)
        for g in self.gotos:
            lab = scope.labels.get(g.target)
            if lab is None:
                self.err("3" if scope.lookup(g.target) is None else "SP004",
                         f"label '{g.target}' is not declared in this block", g)
            if not lab.defined:
                self.err("SP004", f"goto '{g.target}': the label is not defined in the statement part of this "
                                  "block (jumps into structured statements are not allowed)", g)
        comp.has_goto = bool(self.gotos)
        self.scope = prev

    def stmt_list(self, body: list, top: bool = False) -> None:
        for s in body:
            if s.label is not None and not top:
                self.err("SP004", f"label '{s.label}' must stand in the block's own statement sequence "
                                  "(no jumps into structured statements)", s)
            self.stmt(s)

    def stmt(self, s) -> None:
        if isinstance(s, A.Assign):
            self.assign(s)
        elif isinstance(s, A.CallStmt):
            self.call(s.call, statement=True)
        elif isinstance(s, A.Goto):
            s.in_loop = self.loop_depth > 0
            self.gotos.append(s)
        elif isinstance(s, A.Compound):
            self.stmt_list(s.body)
        elif isinstance(s, A.If):
            self.cond(s.cond)
            self.stmt(s.then)
            if s.other is not None:
                self.stmt(s.other)
        elif isinstance(s, A.While):
            self.cond(s.cond)
            self.loop(s.body)
        elif isinstance(s, A.Repeat):
            self.loop_depth += 1
            self.stmt_list(s.body)
            self.loop_depth -= 1
            self.cond(s.cond)
        elif isinstance(s, A.For):
            v = s.var
            if isinstance(v, A.Name):
                sym = self.declared(v)
                if not isinstance(sym, Var) or sym.ty != "integer":
                    self.err("SP003", f"the control variable '{v.name}' must be an integer variable", v)
                v.sym, v.ty = sym, "integer"
            else:
                self.lvalue(v)
                if v.qual != "an":
                    self.err("SP003", "the control variable must be an integer variable or AXISvar.an", v)
            for e in (s.start, s.stop):
                t = self.expr(e)
                if t not in INTLIKE:
                    self.err("SP003", "start and end value of a for loop must be integer", e)
            self.loop(s.body)
        elif isinstance(s, A.Empty):
            pass

    def loop(self, body) -> None:
        self.loop_depth += 1
        self.stmt(body)
        self.loop_depth -= 1

    def cond(self, e) -> None:
        if self.expr(e) != "boolean":
            self.err("SP003", "the condition must be boolean", e)

    def assign(self, s: A.Assign) -> None:
        dst = self.lvalue(s.target)
        src = self.expr(s.value)
        if not assignable(dst, src):
            if not literal_fits(dst, s.value):
                self.err("SP003", f"incompatible types: {src} cannot be assigned to {dst}", s.value)

    def lvalue(self, t) -> str:
        if isinstance(t, A.Name):
            sym = self.scope.lookup(t.name)
            if sym is None:
                sp = sysparam(t.name)
                if sp is not None:
                    sym = sp
            if sym is None:
                self.undeclared(t)
            if isinstance(sym, Routine) and sym.result:
                r = self.scope.routine
                if r is None or r is not sym:
                    self.err("SP006", f"the function name '{t.name}' can be assigned only inside its own body "
                                      "(L1138)", t)
                sym = sym.result_var
            if isinstance(sym, SysParam):
                if not sym.writable:
                    self.err("SP006", f"system parameter '{t.name}' is read only", t)
            elif not isinstance(sym, Var):
                self.err("SP006", f"'{t.name}' cannot be assigned", t)
            elif sym.ty == "axis":
                self.err("SP003", f"an AXIS variable is set through its number: {t.name}.an := ...", t)
            self.touch(sym)
            t.sym, t.ty = sym, sym.ty
            return sym.ty
        return self.qual(t, write=True)

    def qual(self, q: A.Qual, write: bool = False) -> str:
        ax = q.axis
        sym = self.declared(ax)
        if not (isinstance(sym, AxisSpec) or isinstance(sym, Var) and sym.ty == "axis"):
            self.err("SP003", f"'{ax.name}' is not an axis specifier or AXIS variable", ax)
        ax.sym = sym
        self.touch(sym)
        name = QUALIFIER_ALIASES.get(q.qual, q.qual)
        if q.qual in QUALIFIER_ALIASES and q.qual == "jtvf":
            self.warn("W031", "qualifier 'jtvf' read as 'jtv' (L1464)", q)
        q.qual = name
        if q.bit is not None:
            if name not in BIT_QUALIFIERS:
                self.err("SP001", f"'{name}' is not a structured qualifier (digib, digob, ifsb, axstb)", q)
            if write and not BIT_QUALIFIERS[name][1]:
                self.err("SP006", f"'{name}' bits are read only; only digob bits can be written", q)
            b = q.bit
            if isinstance(b, A.Name):
                c = self.declared(b)
                if not isinstance(c, Const) or c.ty != "integer":
                    self.err("SP003", f"bit number '{b.name}' must be an integer constant", b)
                b = c.value
            if not 1 <= b <= 32:
                self.err("SP010", f"bit number {b} out of range 1..32 (bits count from 1, L1528)", q)
            q.bitno = b
            q.ty = "boolean"
            return "boolean"
        if name not in QUALIFIERS:
            self.err("SP001", f"unknown axis qualifier '{q.qual}' (qualifiers are case-sensitive)", q)
        ty, w = QUALIFIERS[name]
        if write and not w:
            self.err("SP006", f"qualifier '{name}' is read only", q)
        if write and name == "an" and isinstance(sym, AxisSpec):
            self.axis_an_written = True
        q.ty = ty
        return ty

    # -- calls ---------------------------------------------------------------------
    def call(self, c: A.Call, statement: bool) -> str | None:
        sym = self.scope.lookup(c.name)
        if isinstance(sym, Routine):
            c.sym = sym
            if sym.is_event and not statement:
                pass
            if len(c.args) != len(sym.params):
                self.err("SP005", f"'{c.name}' takes {len(sym.params)} argument(s), {len(c.args)} given", c)
            for a, p in zip(c.args, sym.params):
                if isinstance(a, A.Named):
                    self.err("SP005", f"'{c.name}': named arguments are for commands only", a)
                t = self.expr(a)
                if not assignable(p.ty, t) and not literal_fits(p.ty, a):
                    self.err("SP003", f"argument '{p.name}': {t} cannot be passed as {p.ty}", a)
            if statement and sym.result:
                self.err("91", f"the value of function '{c.name}' is not used (L1138)", c)
            if not statement and not sym.result:
                self.err("SP003", f"procedure '{c.name}' has no value", c)
            c.ty = sym.result or ""
            return sym.result
        if sym is not None:
            self.err("SP001", f"'{c.name}' is not a procedure or function", c)
        up = c.name.upper()
        if up in CASTS:
            if len(c.args) != 1:
                self.err("SP005", f"{up}(...) takes one argument", c)
            t = self.expr(c.args[0])
            if t == "string" or t == "axis":
                self.err("SP003", f"{up}() cannot convert {t}", c.args[0])
            if up != "BOOLEAN" and t == "boolean" and up in ("SINGLE", "DOUBLE"):
                pass
            c.sym = "cast"
            c.ty = up.lower()
            if statement:
                self.err("91", f"the value of {up}() is not used", c)
            return c.ty
        b = BUILTINS.get(up)
        if b is None:
            self.undeclared(c)
        c.sym = b
        c.name = up
        if b.form == "F":
            if statement:
                self.err("91", f"the value of function {up} is not used (L1138)", c)
            self.plain_args(c, b)
            c.ty = b.result
            return b.result
        if not statement:
            self.err("SP003", f"{up} is a command and has no value", c)
        getattr(self, "form_" + {"SP+": "SPP"}.get(b.form, b.form))(c, b)
        return None

    def plain_args(self, c: A.Call, b: Builtin) -> None:
        if len(c.args) != len(b.params):
            self.err("SP005", f"{c.name} takes {len(b.params)} argument(s), {len(c.args)} given", c)
        for a, pty in zip(c.args, b.params):
            if isinstance(a, A.Named):
                self.err("SP005", f"{c.name}: ':=' items are not allowed here", a)
            t = self.expr(a)
            if not assignable(pty, t) and not literal_fits(pty, a):
                self.err("SP003", f"{c.name}: {t} argument where {pty} is expected", a)

    form_X = plain_args

    def form_N(self, c, b) -> None:
        if c.args or c.parens:
            self.err("SP005", f"{c.name} takes no arguments", c)

    def form_K(self, c, b) -> None:
        if c.name == "STEPCNCT":
            self.steps_tasks = True
        if len(c.args) != 1:
            self.err("SP005", f"{c.name} takes one integer constant", c)
        a = c.args[0]
        t = self.expr(a)
        if t != "integer":
            self.err("SP003", f"{c.name}: integer constant expected", a)
        lo, hi = b.axes
        val = None
        if isinstance(a, A.Num):
            val = a.value
        elif isinstance(a, A.Name) and isinstance(a.sym, Const):
            val = a.sym.value
        if val is not None and not lo <= val <= hi:
            self.err("SP010", f"{c.name}: {val} is outside {lo}..{hi}", a)
        c.const = val

    def form_E(self, c, b) -> None:
        if len(c.args) != 1 or not isinstance(c.args[0], A.Name):
            self.err("SP005", f"{c.name} takes the name of an event procedure", c)
        a = c.args[0]
        sym = self.scope.lookup(a.name)
        if a.name not in EVENTS:
            self.err("SP005", f"{c.name}: '{a.name}' is not an event procedure ({', '.join(EVENTS)})", a)
        if not isinstance(sym, Routine):
            self.err("3", f"event procedure '{a.name}' is not declared", a)
        a.sym = sym
        self.events_used = True

    def form_V(self, c, b) -> None:
        for a in c.args:
            if isinstance(a, A.Named):
                self.err("SP005", f"{c.name}: ':=' items are not allowed here", a)
            t = self.expr(a)
            if t == "axis":
                self.err("SP003", f"{c.name}: an AXIS cannot be written", a)

    def touch(self, sym) -> None:
        """Remember globals a routine uses: the others can be fast locals of the main block."""
        if isinstance(sym, Var) and sym.is_global and self.scope.routine is not None:
            sym.in_routine = True

    def axis_item(self, a, c) -> None:
        node = a if isinstance(a, A.Name) else a
        sym = self.declared(node)
        if not (isinstance(sym, AxisSpec) or isinstance(sym, Var) and sym.ty == "axis"):
            self.err("SP005", f"{c.name}: '{node.name}' is not an axis specifier or AXIS variable", node)
        return sym

    def form_S(self, c, b) -> None:
        lo, hi = b.axes
        if not c.args:
            self.err("SP005", f"{c.name} needs a list of axes", c)
        seen = set()
        for a in c.args:
            if not isinstance(a, A.Name):
                self.err("SP005", f"{c.name} takes axis specifiers only (no ':=' values)", a)
            a.sym = self.axis_item(a, c)
            self.touch(a.sym)
            if a.name in seen:
                self.err("SP005", f"{c.name}: axis '{a.name}' is named twice", a)
            seen.add(a.name)
        if not lo <= len(c.args) <= hi:
            noun = "axis" if lo == hi == 1 else "axes"
            self.err("SP005", f"{c.name} takes {lo if lo == hi else f'{lo}..{hi}'} {noun}, {len(c.args)} given", c)
        c.axes = list(c.args)

    def form_SP(self, c, b) -> None:
        self.form_SPP(c, b)

    def form_SPP(self, c, b) -> None:
        axes, params, seen = [], [], set()
        for a in c.args:
            if isinstance(a, A.Bin) and a.op == "=" and isinstance(a.left, A.Name) and a.left.name in b.extra:
                self.warn("W035", f"'{a.left.name} = ...' read as '{a.left.name} := ...' (L1880, L2091)", a)
                a = A.Named(a.file, a.line, a.col, a.left.name, a.right, True)
            if not isinstance(a, A.Named):
                if isinstance(a, A.Name):
                    self.err("SP005", f"{c.name} needs 'axis := value' items; '{a.name}' has no value (L453)", a)
                self.err("SP005", f"{c.name} needs 'axis := value' items", a)
            if a.name in b.extra:
                t = self.expr(a.value)
                if not assignable(sysparam(a.name).ty, t):
                    self.err("SP003", f"{a.name}: {t} cannot be assigned", a.value)
                params.append(a)
                continue
            sym = self.scope.lookup(a.name)
            if sym is None and sysparam(a.name) is not None:
                self.err("SP005", f"{c.name} does not take system parameter {a.name}", a)
            a.sym = self.axis_item(a, c)
            self.touch(a.sym)
            if a.name in seen:
                self.err("SP005", f"{c.name}: axis '{a.name}' is named twice", a)
            seen.add(a.name)
            t = self.expr(a.value)
            if t not in NUMERIC:
                self.err("SP003", f"{c.name}: the value for {a.name} must be numeric", a.value)
            axes.append(a)
        lo, hi = b.axes
        if not lo <= len(axes) <= hi:
            want = str(lo) if lo == hi else f"at least {lo}"
            self.err("SP005", f"{c.name} takes {want} axis item(s), {len(axes)} given", c)
        c.axes, c.params = axes, params

    # -- expressions ------------------------------------------------------------------
    def expr(self, e) -> str:
        t = self._expr(e)
        e.ty = t
        return t

    def _expr(self, e) -> str:
        if isinstance(e, A.Num):
            if e.ty == "integer" and e.value > INT_MAX:
                self.warn("W006", "integer constant out of range: clamped to 2147483647", e)
                e.value = INT_MAX
            return e.ty
        if isinstance(e, A.Str):
            return "string"
        if isinstance(e, A.Name):
            return self.name(e)
        if isinstance(e, A.Qual):
            return self.qual(e)
        if isinstance(e, A.Call):
            t = self.call(e, statement=False)
            return t
        if isinstance(e, A.Unary):
            t = self.expr(e.operand)
            if e.op == "not":
                if t in ("boolean", "integer", "timer"):
                    return t
                self.err("SP003", f"'not' needs a boolean or integer operand, not {t}", e)
            if t in NUMERIC:
                return t
            self.err("SP003", f"unary '{e.op}' needs a numeric operand, not {t}", e)
        if isinstance(e, A.Bin):
            lt, rt = self.expr(e.left), self.expr(e.right)
            return self.binary(e, lt, rt)
        self.err("SP001", "expression expected", e)

    def name(self, e: A.Name) -> str:
        sym = self.scope.lookup(e.name)
        if sym is None:
            up = e.name.upper()
            if up in ("TRUE", "FALSE"):
                e.sym = Const(up, "boolean", up == "TRUE")
                return "boolean"
            sp = sysparam(e.name)
            if sp is not None:
                e.sym = sp
                if e.name == "CLOCK":
                    self.uses_clock = True
                return sp.ty
            b = BUILTINS.get(up)
            if b is not None and b.form == "F":
                self.err("SP005", f"{up} needs its argument list", e)
            self.undeclared(e)
        e.sym = sym
        if isinstance(sym, (Var, Const)):
            self.touch(sym)
            return sym.ty
        if isinstance(sym, Routine):
            r = self.scope.routine
            if sym.result and r is sym:
                e.sym = sym.result_var
                return sym.result
            if sym.result:
                if sym.params:
                    self.err("SP005", f"'{e.name}' takes {len(sym.params)} argument(s)", e)
                return sym.result
            self.err("SP003", f"procedure '{e.name}' has no value", e)
        if isinstance(sym, AxisSpec):
            self.err("SP003", f"axis '{e.name}' has no value here; use a qualifier such as {e.name}.rp", e)
        if isinstance(sym, Label):
            self.err("SP003", f"label '{e.name}' has no value", e)
        self.err("SP003", f"'{e.name}' has no value", e)

    def binary(self, e: A.Bin, lt: str, rt: str) -> str:
        op = e.op
        if "string" in (lt, rt) or "axis" in (lt, rt):
            self.err("SP003", f"'{op}' cannot be applied to {lt} and {rt}", e)
        if op in ("=", "<>", "<", ">", "<=", ">="):
            if lt == "boolean" and rt == "boolean" or lt in NUMERIC and rt in NUMERIC:
                return "boolean"
            self.err("SP003", f"cannot compare {lt} with {rt}", e)
        if op in ("and", "or", "xor"):
            if lt == rt == "boolean":
                return "boolean"
            if lt in INTLIKE and rt in INTLIKE:
                return "timer" if "timer" in (lt, rt) else "integer"
            self.err("SP003", f"'{op}' needs two boolean or two integer operands, not {lt} and {rt}", e)
        if lt not in NUMERIC or rt not in NUMERIC:
            self.err("SP003", f"'{op}' needs numeric operands, not {lt} and {rt}", e)
        if op in ("mod", "shl", "shr"):
            if lt in INTLIKE and rt in INTLIKE:
                return "timer" if lt == "timer" and op != "mod" else "integer"
            self.err("SP003", f"'{op}' needs integer operands, not {lt} and {rt}", e)
        if lt in INTLIKE and rt in INTLIKE:
            if op in ("+", "-") and "timer" in (lt, rt):
                return "timer"
            return "integer"
        if "double" in (lt, rt) or "timer" in (lt, rt):
            return "double"
        return "single" if "single" in (lt, rt) and all(t in ("single", "integer") for t in (lt, rt)) else "double"


__all__ = ["Checker", "assignable", "REAL"]
