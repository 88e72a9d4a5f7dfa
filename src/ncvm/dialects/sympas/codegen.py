"""Turns a checked rw_SymPas program into Python source (one generator function per routine).

Every routine and the main block become generator functions, so a CNC task can
be suspended at a wait and resumed by the scheduler (cooperative tasks, no
threads). Calls are ``yield from``; statements count into a local ``_n`` that is
handed to the task (``tk.flush``) before anything that needs the simulated time,
and checked at loop back-edges against the task's budget, where the scheduler
may switch tasks and event handlers are polled. Each group counted at once is
tested against the step limit at its head, before any of it runs (``count``).
"""

from __future__ import annotations

import math

from ...runtime.codegen import PySource
from . import ast as A
from .symbols import AxisSpec, Builtin, Const, Routine, SysParam, Var

INT_WRAP = "(_t if -2147483648 <= (_t := {}) <= 2147483647 else _ovf(_t))"
#: math functions generated inline (a wrapper's call costs more than the function): the function where its
#: argument is valid, NaN (the manual's "no valid return value") elsewhere. SIN and COS fail on +-inf only,
#: where x - x is NaN (0.0 for every finite x)
_INLINE = {
    "SQRT": "(_msqrt(_t) if (_t := {}) >= 0 else _NAN)",
    "SIN": "(_msin(_t) if (_t := {}) - _t == 0.0 else _NAN)",
    "COS": "(_mcos(_t) if (_t := {}) - _t == 0.0 else _NAN)",
}
#: their unchecked forms, for an assignment that catches the ValueError (CodeGen.assign_value)
_UNCHECKED = {"SIN": "_msin({})", "COS": "_mcos({})"}


class CodeGen:
    def __init__(self, filename: str, checker, unit: A.Program, stepping: bool = False):
        self.src = PySource(filename)
        self.stepping = stepping  # a check point after every line, so STEPCNCT stops after one line
        self.next_at = None  # (file, line) of the statement that follows the one being generated
        self.chk = checker
        self.unit = unit
        self.locs: list[tuple[str, int]] = [("", 0)]
        self._loc_ids: dict[tuple[str, int], int] = {}
        self.tmp = 0
        self.const_axes = not checker.axis_an_written
        self.shared_writes: set[str] = set()  # the card's registers (CI, CD, ...) the program assigns
        self.unchecked = False  # SIN and COS unchecked: the statement catches their ValueError (assign_value)

    # -- helpers ---------------------------------------------------------------------
    def loc(self, node) -> int:
        key = (node.file, node.line)
        i = self._loc_ids.get(key)
        if i is None:
            i = self._loc_ids[key] = len(self.locs)
            self.locs.append(key)
        return i

    def emit(self, text: str, node=None) -> None:
        self.src.emit(text, self.loc(node) if node is not None else None)

    def new_tmp(self, stem: str) -> str:
        self.tmp += 1
        return f"_{stem}{self.tmp}"

    # -- units -------------------------------------------------------------------------
    def generate(self) -> PySource:
        chk = self.chk
        for r in chk.routines:
            self.routine(r)
        self.main()
        return self.src

    def global_names(self, main: bool = False) -> list[str]:
        """Globals the unit's functions share; in the main block only those a routine also uses."""
        return [v.py for v in self.chk.globals if v.in_routine or not main]

    def routine(self, r: Routine) -> None:
        d = r.node
        args = ", ".join(v.py for v in r.param_vars)
        with self.src.block(f"def {r.py}(tk{', ' if args else ''}{args}):", self.loc(d)):
            gl = self.global_names()
            if gl:
                self.emit("global " + ", ".join(gl))
            for v in r.param_vars:
                if v.ty == "single":
                    self.emit(f"{v.py} = _f32({v.py})")
                elif v.ty == "double":
                    self.emit(f"{v.py} = float({v.py})")
            for v in r.locals[len(r.param_vars):]:
                self.emit(f"{v.py} = {zero(v.ty)}")
            if r.result:
                self.emit(f"l__result = {zero(r.result)}")
            self.emit("_n = 0; _card = tk.card")
            self.emit("tk.depth += 1")
            self.emit("if tk.depth > tk.max_depth: _fault(8, 'stack overflow: calls nested deeper than ' "
                      "+ str(tk.max_depth))")
            self.block_body(d.body)
            self.emit("tk.depth -= 1")
            self.emit("tk.flush(_n)")
            self.emit("return l__result" if r.result else "return None")
            self.emit("yield")  # makes it a generator even without waits

    def main(self) -> None:
        body = self.unit.body
        with self.src.block("def _main(tk):", self.loc(body)):
            gl = self.global_names(main=True)
            if gl:
                self.emit("global " + ", ".join(gl))
            for v in self.chk.globals:
                self.emit(f"{v.py} = {zero(v.ty)}")
            self.emit("_n = 0; _card = tk.card")
            self.block_body(body)
            self.emit("tk.flush(_n)")
            self.emit("tk.main_locals = locals()")
            self.emit("return None")
            self.emit("yield")

    # -- statements ----------------------------------------------------------------------
    def block_body(self, comp: A.Compound) -> None:
        if not getattr(comp, "has_goto", False):
            self.stmts(comp.body)
            return
        # goto inside a block: the statement sequence becomes segments of a dispatch loop
        segments: list[list] = [[]]
        self.labels = {}
        for s in comp.body:
            if s.label is not None:
                segments.append([])
                self.labels[s.label] = len(segments) - 1
            segments[-1].append(s)
        self.emit("_pc = 0")
        with self.src.block("while True:"):
            with self.src.block("try:"):
                for i, seg in enumerate(segments):
                    with self.src.block(f"if _pc <= {i}:"):
                        self.stmts(seg)
                self.emit("break")
            with self.src.block("except _Goto:"):
                self.emit("pass")

    def plain_run(self, body: list, i: int) -> int:
        """The end of the run of plain assignments from ``body[i]`` (counted as one group)."""
        j = i
        # events are polled after every statement (L1548), so only programs without them merge
        while not self.stepping and not self.chk.events_used and j < len(body) \
                and isinstance(body[j], A.Assign) and body[j].label is None and not needs_time(body[j].value):
            j += 1
        return j

    def stmts(self, body: list, ahead: bool = False) -> None:
        """``ahead``: the run of plain assignments the sequence starts with is tested against the step
        limit before it (a loop's ``lead``)."""
        outer = self.next_at  # what follows the last statement of this sequence
        i = 0
        while i < len(body):
            j = self.plain_run(body, i)
            if ahead and i == 0 and j > 0:
                self.emit(f"_n += {j}", body[0])
                for s in body[:j]:
                    self.assign_value(s)
                i = j
            elif j - i > 1:
                # a run of plain assignments: count them once
                self.count(j - i, body[i])
                for s in body[i:j]:
                    self.assign_value(s)
                self.event_point(body[j - 1])
                i = j
            else:
                nxt = body[i + 1] if i + 1 < len(body) else None
                self.next_at = (nxt.file, nxt.line) if nxt is not None else outer
                self.stmt(body[i])
                i += 1

    def stmt(self, s) -> None:
        if isinstance(s, A.Assign):
            self.count(1, s)
            self.flush_if_needed(s.value, s)
            self.assign_value(s)
            self.event_point(s)
        elif isinstance(s, A.CallStmt):
            self.count(1, s)
            self.call_stmt(s.call, s)
            self.event_point(s)
        elif isinstance(s, A.Goto):
            self.emit("_n += 1", s)
            target = self.labels[s.target]
            self.emit(f"_pc = {target}")
            self.back_edge(s, s)
            self.emit("raise _GOTO" if s.in_loop else "continue")
        elif isinstance(s, A.Compound):
            self.stmts(s.body)
        elif isinstance(s, A.If):
            self.count(1, s)
            self.flush_if_needed(s.cond, s)
            with self.src.block(f"if {self.expr(s.cond)}:", self.loc(s)):
                self.stmt(s.then)
            if s.other is not None:
                with self.src.block("else:"):
                    self.stmt(s.other)
        elif isinstance(s, A.While):
            self.count(1, s)
            self.flush_if_needed(s.cond, s)
            cond = self.expr(s.cond)
            body = s.body.body if isinstance(s.body, A.Compound) else [s.body]
            lead = self.lead(body, s.cond)
            if lead:
                self.emit(f"if _n + {lead} >= tk.budget and {cond}: tk.fits(_n + {lead}, {lead}, "
                          f"{self.loc(body[0])})", s)
            with self.src.block(f"while {cond}:", self.loc(s)):
                self.next_at = (s.file, s.line)  # after the body the loop head's line comes next
                self.stmts(body, bool(lead))
                self.emit("_n += 1", s)
                self.back_edge(s, s, lead, body, cond)  # the head's test again
                self.flush_if_needed(s.cond, s)
        elif isinstance(s, A.Repeat):
            lead = self.lead(s.body, s.cond)
            if lead:
                self.emit(f"if _n + {lead} >= tk.budget: tk.fits(_n + {lead}, {lead}, {self.loc(s.body[0])})", s)
            with self.src.block("while True:", self.loc(s)):
                self.stmts(s.body, bool(lead))
                self.emit("_n += 1", s)
                cond = self.expr(s.cond)
                # before the UNTIL test, as WHILE's before its head's
                self.back_edge(s, s.cond, lead, s.body, f"not {cond}")
                self.flush_if_needed(s.cond, s)
                self.emit(f"if {cond}: break", s)
        elif isinstance(s, A.For):
            self.for_stmt(s)
        elif isinstance(s, A.Empty):
            pass

    def event_point(self, node) -> None:
        """Programs that enable events poll them after every simple statement (§6.4, L1548); a task that
        may be single-stepped (STEPCNCT) needs a check point there too."""
        if self.chk.events_used or (self.stepping and self.next_at != (node.file, node.line)):
            self.back_edge(node)

    def count(self, k: int, node) -> None:
        """Count a group of ``k`` statements that starts at ``node``, and stop at its head if they do not fit
        under the step limit. The budget never exceeds the room left under the limit by more than one
        (``Task.set_budget``), so the limit costs a group one compare: only a group that finds the budget spent
        asks the task whether it fits."""
        self.emit(f"_n += {k}", node)
        self.emit(f"if _n >= tk.budget: tk.fits(_n, {k}, {self.loc(node)})", node)

    def lead(self, body: list, cond) -> int:
        """The statements of the run of plain assignments a loop's body starts with, where the loop's
        test cannot change the card (no clock, axis, common buffer or routine): the loop's back-edge then
        tests them against the step limit ahead, with the test itself, and they need no test of their own
        (one compare a pass, as before the limit was tested at every group)."""
        return 0 if needs_time(cond) else self.plain_run(body, 0)

    def back_edge(self, node, counted=None, lead: int = 0, body=None, again: str = "") -> None:
        """A check point; ``counted``: the one statement just counted (a loop's test, a GOTO), which the
        check point tests against the step limit before it runs, as ``count`` does; ``lead``: the
        statements that run next when the loop goes on (``again``) are tested with it. Entering the check
        point early changes nothing else: it lets other tasks run only once the task's time is due."""
        self.emit(f"if _n + {lead} >= tk.budget:" if lead else "if _n >= tk.budget:", node)
        if counted is None:
            self.emit("    yield from tk.checkin(_n)")
        else:
            self.emit(f"    yield from tk.checkin(_n, {self.loc(counted)})")
        self.emit("    _n = 0")
        if lead:
            self.emit(f"    if {lead} >= tk.budget and {again}: tk.fits({lead}, {lead}, {self.loc(body[0])})")

    def flush_if_needed(self, e, node) -> None:
        if needs_time(e):
            self.emit("tk.flush(_n); _n = 0", node)

    def for_stmt(self, s: A.For) -> None:
        self.count(1, s)
        self.flush_if_needed(s.start, s)
        self.flush_if_needed(s.stop, s)
        start, stop = self.new_tmp("f"), self.new_tmp("e")
        self.emit(f"{start} = {self.int_value(s.start)}; {stop} = {self.int_value(s.stop)}", s)
        step = -1 if s.down else 1
        var = self.new_tmp("v")
        self.assign(s.var, start, "integer", s)
        with self.src.block(f"for {var} in range({start}, {stop} {'-' if s.down else '+'} 1, {step}):", self.loc(s)):
            self.assign(s.var, var, "integer", s)
            self.next_at = (s.file, s.line)
            self.stmt(s.body)
            self.emit("_n += 1", s)
            self.back_edge(s, s)

    def int_value(self, e) -> str:
        code = self.expr(e)
        return f"_t2i({code})" if e.ty == "timer" else code

    def assign_value(self, s: A.Assign) -> None:
        """``target := value``. Into a variable, SIN and COS run unchecked inside ``try``: they raise
        ValueError on +-inf only, and then the value is worked out again with the checked forms (NaN). A value
        with a routine call (its side effects would repeat) or no SIN or COS is checked inline."""
        code = self.expr(s.value)
        target = s.target
        if not (isinstance(target, A.Name) and not isinstance(target.sym, SysParam)) or "yield" in code \
                or not ("_msin(" in code or "_mcos(" in code):
            self.assign(target, code, s.value.ty, s)
            return
        self.unchecked = True
        try:
            fast = self.expr(s.value)
        finally:
            self.unchecked = False
        with self.src.block("try:", self.loc(s)):
            self.assign(target, fast, s.value.ty, s)
        with self.src.block("except ValueError:", self.loc(s)):
            self.assign(target, code, s.value.ty, s)

    def assign(self, target, code: str, src_ty: str, node) -> None:
        if isinstance(target, A.Name):
            sym = target.sym
            if isinstance(sym, SysParam):
                self.shared_writes.add(sym.name)
                self.emit(f"tk.set_sys({sym.name!r}, {convert(code, src_ty, sym.ty)})", node)
                return
            self.emit(f"{sym.py} = {convert(code, src_ty, sym.ty)}", node)
            return
        q = target
        ax = self.axis_ref(q.axis)
        if q.bit is not None:
            self.emit(f"_set_bit(tk.card, {ax}, {q.qual!r}, {q.bitno}, {code})", node)
        elif q.qual == "an":
            sym = q.axis.sym
            value = convert(code, src_ty, "integer")
            if isinstance(sym, AxisSpec):
                self.emit(f"tk.axmap[{sym.number}] = {value}", node)
            else:
                self.emit(f"{sym.py} = {value}", node)
        else:
            self.emit(f"_set_qual(tk.card, tk, {ax}, {q.qual!r}, {convert(code, src_ty, q.ty)})", node)

    def axis_ref(self, name: A.Name) -> str:
        sym = name.sym
        if isinstance(sym, AxisSpec):
            return str(sym.number) if self.const_axes else f"tk.axmap[{sym.number}]"
        return sym.py

    # -- calls --------------------------------------------------------------------------------
    def call_stmt(self, c: A.Call, node) -> None:
        self.emit("tk.flush(_n); _n = 0", node)
        if isinstance(c.sym, Routine):
            self.emit(f"yield from {self.routine_call(c)}", node)
            return
        b: Builtin = c.sym
        name = c.name
        loc = self.loc(node)
        if b.form == "X":
            args = ", ".join(self.arg(a, p) for a, p in zip(c.args, b.params))
            if name == "WT":
                self.emit(f"_g = tk.wt({args}, {loc})", node)
                self.emit("if _g is not None: yield from _g", node)
            else:
                self.emit(f"tk.{name.lower()}({args})", node)
        elif b.form == "N":
            self.emit(f"yield from tk.{name.lower()}()", node)
        elif b.form == "K":
            arg = self.expr(c.args[0])
            self.emit(f"yield from tk.{name.lower()}({arg})", node)
        elif b.form == "E":
            ev = c.args[0]
            self.emit(f"tk.{name.lower()}({ev.name!r}, {ev.sym.py})", node)
        elif b.form == "V":
            parts = ", ".join(self.write_item(a) for a in c.args)
            self.emit(f"if tk.write(({parts}{',' if len(c.args) == 1 else ''}), {name == 'WRITELN'}):", node)
            self.emit("    yield from tk.stopped()", node)
        elif b.form == "S":
            axes = ", ".join(self.axis_ref(a) for a in c.axes)
            self.emit(f"_g = _C_{name.lower()}(_card, tk, ({axes},), {loc})", node)
            self.emit("if _g is not None: yield from _g", node)
        else:
            for p in c.params:
                self.shared_writes.add(p.name)
                self.emit(f"tk.set_sys({p.name!r}, {convert(self.expr(p.value), p.value.ty, 'double')})", node)
            items = ", ".join(f"({self.axis_ref(a)}, {convert(self.expr(a.value), a.value.ty, 'double')})"
                              for a in c.axes)
            flags = {p.name for p in c.params}
            target = "DTCA1" in flags or "DTCA2" in flags or "DTCA3" in flags
            base = name.lower()
            call = f"_C_{base}(_card, tk, _it, {loc}{', True' if target else ''})"
            if base in ("mlaw", "mlrw") and self.const_axes and all(isinstance(a.sym, AxisSpec) for a in c.axes):
                # the common waiting line: one call when nothing else can happen meanwhile
                self.emit(f"_it = _axis_values(({items},))", node)
                self.emit(f"if not _fast_line(_card, tk, _it, {loc}, {base == 'mlrw'}):", node)
                self.emit(f"    _g = {call}", node)
                self.emit("    if _g is not None: yield from _g", node)
            else:
                self.emit(f"_it = _axis_values(({items},))", node)
                self.emit(f"_g = {call}", node)
                self.emit("if _g is not None: yield from _g", node)

    def write_item(self, a) -> str:
        if isinstance(a, A.Str):
            return repr(a.value)
        code = self.expr(a)
        if a.ty == "boolean":
            return f"('TRUE' if {code} else 'FALSE')"
        if a.ty == "single":
            return f"_fmt({code}, 7)"
        if a.ty == "double":
            return f"_fmt({code}, _DIGITS)"
        return f"str({code})"

    def arg(self, a, ty: str) -> str:
        return convert(self.expr(a), a.ty, ty)

    def routine_call(self, c: A.Call) -> str:
        r: Routine = c.sym
        args = ", ".join(self.arg(a, p.ty) for a, p in zip(c.args, r.params))
        return f"{r.py}(tk{', ' if args else ''}{args})"

    # -- expressions ------------------------------------------------------------------------------
    def expr(self, e) -> str:
        if isinstance(e, A.Num):
            return _literal(e.value)
        if isinstance(e, A.Name):
            sym = e.sym
            if isinstance(sym, Const):
                return _literal(sym.value)
            if isinstance(sym, Var):
                return sym.py
            if isinstance(sym, SysParam):
                if sym.name == "CLOCK":
                    return "tk.clock(_n)"
                return f"tk.get_sys({sym.name!r})"
            if isinstance(sym, Routine):
                return f"(yield from {sym.py}(tk))"
            raise AssertionError(sym)
        if isinstance(e, A.Qual):
            ax = self.axis_ref(e.axis)
            if e.bit is not None:
                return f"_get_bit(tk.card, tk, {ax}, {e.qual!r}, {e.bitno})"
            if e.qual == "an":
                return ax
            return f"_get_qual(tk.card, tk, {ax}, {e.qual!r})"
        if isinstance(e, A.Call):
            return self.call_expr(e)
        if isinstance(e, A.Unary):
            x = self.expr(e.operand)
            t = e.operand.ty
            if e.op == "not":
                if t == "boolean":
                    return f"(not {x})"
                if t == "timer":
                    return f"(~{x} & 0xFFFFFFFF)"
                return f"(~{x})"
            if e.op == "+":
                return x
            if t == "integer":
                return INT_WRAP.format(f"-{x}")
            if t == "timer":
                return f"(-{x} & 0xFFFFFFFF)"
            return f"(-{x})"
        if isinstance(e, A.Bin):
            return self.binary(e)
        raise AssertionError(e)

    def call_expr(self, c: A.Call) -> str:
        if isinstance(c.sym, Routine):
            return f"(yield from {self.routine_call(c)})"
        if c.sym == "cast":
            a = c.args[0]
            x = self.expr(a)
            return cast(x, a.ty, c.ty)
        b: Builtin = c.sym
        args = ", ".join(self.arg(a, p) for a, p in zip(c.args, b.params))
        if c.name.startswith("RDCB"):
            return f"tk.{c.name.lower()}({args})"
        if self.unchecked and c.name in _UNCHECKED:
            return _UNCHECKED[c.name].format(args)
        if c.name in _INLINE:
            return _INLINE[c.name].format(args)
        if c.name == "ABS":
            return f"abs({args})" if c.args[0].ty == "double" else f"float(abs({args}))"
        return f"_F_{c.name}({args})"

    def binary(self, e: A.Bin) -> str:
        op = e.op
        lt, rt = e.left.ty, e.right.ty
        a, b = self.expr(e.left), self.expr(e.right)
        ty = e.ty
        if op in ("=", "<>", "<", ">", "<=", ">="):
            if "timer" in (lt, rt) and op not in ("=", "<>"):
                return f"({_TCMP[op].format(a, b)})"
            if "timer" in (lt, rt) and lt != rt:
                a, b = (f"({a} & 0xFFFFFFFF)", f"({b} & 0xFFFFFFFF)")
            pyop = {"=": "==", "<>": "!="}.get(op, op)
            return f"({a} {pyop} {b})"
        if op in ("and", "or", "xor"):
            pyop = {"and": "&", "or": "|", "xor": "^"}[op]
            if ty == "timer":
                return f"(({a} {pyop} {b}) & 0xFFFFFFFF)"
            return f"({a} {pyop} {b})"
        if ty == "timer":
            if op == "shl":
                return f"(({a} << ({b} & 31)) & 0xFFFFFFFF)"
            if op == "shr":
                return f"({a} >> ({b} & 31))"
            pyop = {"+": "+", "-": "-", "*": "*"}.get(op)
            if pyop:
                return f"(({a} {pyop} {b}) & 0xFFFFFFFF)"
            return f"(_idiv({a}, {b}) & 0xFFFFFFFF)"
        if ty == "integer":
            if "timer" in (lt, rt):
                a, b = (f"_t2i({a})" if lt == "timer" else a), (f"_t2i({b})" if rt == "timer" else b)
            const_b = isinstance(e.right, A.Num) and e.right.value > 0
            if op == "/":
                return f"_idiv({a}, {b})"
            if op == "mod":
                if const_b:
                    return f"({a} % {b} if (_t := {a}) >= 0 else -(-_t % {b}))" if isinstance(
                        e.left, A.Name) else f"_imod({a}, {b})"
                return f"_imod({a}, {b})"
            if op == "shl":
                return INT_WRAP.format(f"{a} << ({b} & 31)")
            if op == "shr":
                return f"({a} >> ({b} & 31))"
            return INT_WRAP.format(f"{a} {op} {b}")
        # real arithmetic runs in binary64 (rw_SymPas manual L556)
        if op == "/":
            if isinstance(e.right, A.Num) and e.right.value != 0:
                return f"({a} / {b})"
            return f"_rdiv({a}, {b})"
        return f"({a} {op} {b})"


_TCMP = {
    ">": "0 < (({} - {}) & 0xFFFFFFFF) < 0x80000000",
    "<": "0 < (({1} - {0}) & 0xFFFFFFFF) < 0x80000000",
    ">=": "(({} - {}) & 0xFFFFFFFF) < 0x80000000",
    "<=": "(({1} - {0}) & 0xFFFFFFFF) < 0x80000000",
}


def zero(ty: str) -> str:
    return {"boolean": "False", "single": "0.0", "double": "0.0"}.get(ty, "0")


def convert(code: str, src: str, dst: str) -> str:
    """The value of ``code`` (type ``src``) stored into a ``dst`` location."""
    if src == dst:
        return code
    if dst == "double":
        return f"float({code})"
    if dst == "single":
        return f"_f32({code})"
    if dst == "integer":
        return f"_t2i({code})" if src == "timer" else f"int({code})"
    if dst == "timer":
        return f"({code} & 0xFFFFFFFF)"
    return code


def cast(code: str, src: str, dst: str) -> str:
    """Explicit conversion BOOLEAN(x), INTEGER(x), SINGLE(x), DOUBLE(x) (§5.3.3.2)."""
    if dst == "boolean":
        return f"({code} != 0)" if src != "boolean" else code
    if dst == "integer":
        if src in ("single", "double"):
            return f"(int(_t) if -2147483648.0 < (_t := {code}) < 2147483648.0 else _toint(_t))"
        if src == "timer":
            return f"_t2i({code})"
        return f"int({code})"
    if dst == "single":
        return f"_f32({code})"
    return f"float({code})"


def needs_time(e) -> bool:
    """Does evaluating ``e`` read the clock, an axis, or call a routine (so the task's time must be current)?"""
    if isinstance(e, A.Name):
        return isinstance(e.sym, Routine) or isinstance(e.sym, SysParam) and e.sym.name == "CLOCK"
    if isinstance(e, A.Qual):
        return e.qual != "an"
    if isinstance(e, A.Call):
        return e.sym != "cast" and not (isinstance(e.sym, Builtin) and not e.name.startswith("RDCB")) or any(
            needs_time(a) for a in e.args)
    if isinstance(e, A.Unary):
        return needs_time(e.operand)
    if isinstance(e, A.Bin):
        return needs_time(e.left) or needs_time(e.right)
    return False


def _literal(value) -> str:
    """Python text of a constant; a folded constant may have overflowed to inf (or nan)."""
    if isinstance(value, float) and not math.isfinite(value):
        return f"float({str(value)!r})"
    return repr(value)
