"""Recursive-descent parser for rw_SymPas (rw_SymPas manual §5.3, L468-1259).

A file holds one program, or several, each after its own ``{$TASK n}``
(ncvm's way to load more than one CNC task from one file). Statements and
declarations follow Pascal; the lenient points ncvm accepts for the manual's examples (``;`` before
``else``, stray ``;`` between declarations, ``:=`` in constant declarations)
are accepted with a warning.
"""

from __future__ import annotations

from ...source import MAX_LOOP_NESTING, MAX_NESTING, int_literal, is_digits, too_deep
from . import ast as A
from .errors import SympasError
from .lexer import INT_CEILING, INT_MAX, INT_MIN, Token

SCALAR_TYPES = ("boolean", "integer", "single", "double", "timer")
CASTS = ("boolean", "integer", "single", "double")
REL_OPS = ("=", "<>", "<", ">", "<=", ">=")
ADD_OPS = ("+", "-", "or", "xor")
MUL_OPS = ("*", "/", "mod", "shl", "shr", "and")


class Parser:
    def __init__(self, tokens: list[Token], warn=None):
        self.toks = tokens
        self.i = 0
        self.forwards: set[str] = set()  # routines declared forward so far (a stray second forward, L1191)
        self.warn = warn or (lambda code, msg, tok: None)
        # nesting where the manual sets no limit ("nahezu beliebiger Tiefe", L1004): NEST001 beyond ncvm's
        self.statements = 0  # statements the parser is inside
        self.loops = 0  # loops the parser is inside
        self.operands = 0  # nested operands (brackets, unary operators, arguments) the parser is inside
        self.height = 0  # height of the expression tree just parsed

    # -- token helpers -----------------------------------------------------
    @property
    def tok(self) -> Token:
        return self.toks[self.i]

    def peek(self, k: int = 1) -> Token:
        return self.toks[min(self.i + k, len(self.toks) - 1)]

    def at(self, kind: str, value=None) -> bool:
        t = self.tok
        return t.kind == kind and (value is None or t.value == value)

    def at_op(self, *ops) -> bool:
        return self.tok.kind == "op" and self.tok.value in ops

    def at_kw(self, *kws) -> bool:
        return self.tok.kind == "kw" and self.tok.value in kws

    def advance(self) -> Token:
        t = self.tok
        if t.kind != "eof":
            self.i += 1
        return t

    def error(self, message: str, tok: Token | None = None, code: str = "SP001"):
        t = tok or self.tok
        raise SympasError(code, message, t.file, t.line, t.col)

    def expect_op(self, op: str) -> Token:
        if not self.at_op(op):
            self.error(f"'{op}' expected, found {self.describe()}")
        return self.advance()

    def expect_kw(self, kw: str) -> Token:
        if not self.at_kw(kw):
            self.error(f"'{kw}' expected, found {self.describe()}")
        return self.advance()

    def expect_id(self) -> Token:
        if self.tok.kind != "id":
            self.error(f"identifier expected, found {self.describe()}")
        return self.advance()

    def describe(self) -> str:
        t = self.tok
        if t.kind == "eof":
            return "end of file"
        if t.kind == "str":
            return "a string"
        return f"'{t.text or t.value}'"

    # -- program -------------------------------------------------------------
    def programs(self) -> list[A.Program]:
        units = []
        while not self.at("eof"):
            units.append(self.program())
        if not units:
            self.error("empty program: 'begin ... end.' expected")
        return units

    def program(self) -> A.Program:
        t = self.tok
        self.forwards.clear()
        prog = A.Program(t.file, t.line, t.col)
        self.directives(prog)
        if self.at_kw("program"):
            self.advance()
            prog.name = str(self.expect_id().value)
            self.expect_op(";")
        while True:
            self.directives(prog)
            if self.at_op(";"):
                self.advance()
                continue
            if self.at_kw("label", "const", "var"):
                prog.decls.extend(self.decl_part(global_level=True))
            elif self.at_kw("procedure", "function"):
                prog.decls.append(self.routine())
            elif self.at_kw("module"):
                self.error("'module' is reserved but not supported by rw_SymPas", code="SP008")
            elif self.at_kw("begin"):
                break
            else:
                self.error(f"declaration or 'begin' expected, found {self.describe()}")
        prog.body = self.compound()
        self.expect_op(".")
        return prog

    def directives(self, prog: A.Program) -> None:
        while self.at("dir"):
            t = self.advance()
            name, arg = t.value
            if name == "TASK":
                prog.task = int_literal(arg, INT_CEILING) if is_digits(arg) else arg
                prog.task_tok = t
            else:
                prog.fullsystem = True

    def decl_part(self, global_level: bool) -> list:
        t = self.advance()
        out = []
        if t.value == "label":
            names = [self.expect_id()]
            while self.at_op(","):
                self.advance()
                names.append(self.expect_id())
            self.expect_op(";")
            out.append(A.LabelDecl(t.file, t.line, t.col, [(n.value, n) for n in names]))
        elif t.value == "const":
            while self.at("id"):
                out.append(self.const_decl())
            if not out:
                self.error("constant declaration expected after 'const'")
        else:
            while self.at("id"):
                out.append(self.var_decl())
            if not out:
                self.error("variable declaration expected after 'var'")
        return out

    def const_decl(self) -> A.ConstDecl:
        name = self.advance()
        if self.at_op(":="):
            self.warn("W009", "':=' in a constant declaration accepted as '=' (manual example L741)", self.tok)
            self.advance()
        else:
            self.expect_op("=")
        sign = 1
        if self.at_op("+", "-"):
            sign = -1 if self.advance().value == "-" else 1
        v = self.tok
        if v.kind == "int":
            self.advance()
            value = A.Num(v.file, v.line, v.col, max(INT_MIN, min(INT_MAX, sign * v.value)), "integer")
            if not INT_MIN <= sign * v.value <= INT_MAX:
                self.warn("W006", "integer constant out of range: clamped", v)
            sign = 1
        elif v.kind == "real":
            self.advance()
            value = A.Num(v.file, v.line, v.col, sign * v.value, "double")
            sign = 1
        elif v.kind == "id":
            self.advance()
            value = A.Name(v.file, v.line, v.col, v.value)
        else:
            self.error(f"constant value expected, found {self.describe()} (constant expressions are not "
                       "possible, L427)")
        if not self.at_op(";"):
            self.error("';' expected after the constant (constant expressions are not possible, L427)")
        self.advance()
        return A.ConstDecl(name.file, name.line, name.col, name.value, value, sign)

    def var_decl(self) -> A.VarDecl:
        first = self.tok
        names = [self.expect_id()]
        while self.at_op(","):
            self.advance()
            names.append(self.expect_id())
        self.expect_op(":")
        t = self.tok
        if t.kind == "kw" and t.value in SCALAR_TYPES:
            ty = t.value
        elif t.kind == "id" and t.value.upper() == "AXIS":
            ty = "axis"
        else:
            self.error(f"type expected (boolean, integer, single, double, timer, AXIS), found {self.describe()}")
        self.advance()
        self.expect_op(";")
        return A.VarDecl(first.file, first.line, first.col, [(n.value, n) for n in names], ty)

    def routine(self) -> A.Routine:
        t = self.advance()
        name = self.expect_id()
        r = A.Routine(t.file, t.line, t.col, name.value)
        r.name_tok = name
        if self.at_op("("):
            self.advance()
            while True:
                group = [self.expect_id()]
                while self.at_op(","):
                    self.advance()
                    group.append(self.expect_id())
                self.expect_op(":")
                ty = self.tok
                if not (ty.kind == "kw" and ty.value in SCALAR_TYPES):
                    if ty.kind == "kw" and ty.value == "var" or ty.kind == "id" and ty.value.upper() == "AXIS":
                        self.error("parameters are value parameters of a scalar type only (L1052)", code="SP008")
                    self.error(f"parameter type expected, found {self.describe()}")
                self.advance()
                r.params.extend(A.Param(g.file, g.line, g.col, g.value, ty.value) for g in group)
                if self.at_op(";"):
                    self.advance()
                    continue
                break
            self.expect_op(")")
        if t.value == "function":
            self.expect_op(":")
            ty = self.tok
            if not (ty.kind == "kw" and ty.value in SCALAR_TYPES):
                self.error(f"result type expected, found {self.describe()}")
            self.advance()
            r.result = ty.value
        self.expect_op(";")
        if self.at_kw("forward"):
            fw = self.tok
            self.advance()
            self.expect_op(";")
            key = r.name.lower()
            if key in self.forwards and self.at_kw("begin"):  # the definition, with a stray 'forward'
                self.error(f"'forward' in the definition of {r.name}: it repeats the heading without 'forward' "
                           "(L1185-1191)", fw)
            self.forwards.add(key)
            r.forward = True
            return r
        while True:
            if self.at_kw("label", "const", "var"):
                r.decls.extend(self.decl_part(global_level=False))
            elif self.at_kw("procedure", "function"):
                self.error("routines are declared at program level only (L1056)", code="SP008")
            elif self.at_op(";"):
                self.advance()
            else:
                break
        r.body = self.compound()
        self.expect_op(";")
        return r

    # -- statements ------------------------------------------------------------
    def compound(self) -> A.Compound:
        t = self.expect_kw("begin")
        body = self.stmt_seq(("end",))
        self.expect_kw("end")
        return A.Compound(t.file, t.line, t.col, body)

    def stmt_seq(self, enders: tuple) -> list:
        body = [self.statement()]
        while True:
            if self.at_op(";"):
                self.advance()
                body.append(self.statement())
            elif self.at_kw(*enders) or self.at("eof"):
                return [s for s in body if not (isinstance(s, A.Empty) and s.label is None)]
            else:
                self.error(f"';' expected, found {self.describe()}")

    def statement(self):
        t = self.tok
        label = None
        if t.kind == "id" and self.peek().kind == "op" and self.peek().value == ":":
            label = t.value
            self.advance()
            self.advance()
            t = self.tok
        self.statements += 1
        if self.statements > MAX_NESTING:
            self.error(too_deep("statements", MAX_NESTING), t, "NEST001")
        s = self.unlabelled(t)
        self.statements -= 1
        s.label = label
        return s

    def loop_body(self, t: Token, parse):
        """``parse()`` of a loop's body, counted against the loop nesting ncvm compiles."""
        self.loops += 1
        if self.loops > MAX_LOOP_NESTING:
            self.error(too_deep("loops", MAX_LOOP_NESTING), t, "NEST001")
        body = parse()
        self.loops -= 1
        return body

    def unlabelled(self, t: Token):
        if t.kind == "kw":
            k = t.value
            if k == "begin":
                return self.compound()
            if k == "if":
                self.advance()
                cond = self.expression()
                self.expect_kw("then")
                then = self.statement()
                other = None
                if self.at_op(";") and self.peek().kind == "kw" and self.peek().value == "else":
                    self.warn("W017", "';' before 'else' accepted (manual example L980)", self.tok)
                    self.advance()
                if self.at_kw("else"):
                    self.advance()
                    other = self.statement()
                return A.If(t.file, t.line, t.col, cond, then, other)
            if k == "while":
                self.advance()
                cond = self.expression()
                self.expect_kw("do")
                return A.While(t.file, t.line, t.col, cond, self.loop_body(t, self.statement))
            if k == "repeat":
                self.advance()
                body = self.loop_body(t, lambda: self.stmt_seq(("until",)))
                self.expect_kw("until")
                return A.Repeat(t.file, t.line, t.col, body, self.expression())
            if k == "for":
                self.advance()
                var = self.designator()
                self.expect_op(":=")
                start = self.expression()
                if not self.at_kw("to", "downto"):
                    self.error(f"'to' or 'downto' expected, found {self.describe()}")
                down = self.advance().value == "downto"
                stop = self.expression()
                self.expect_kw("do")
                return A.For(t.file, t.line, t.col, var, start, stop, down, self.loop_body(t, self.statement))
            if k == "goto":
                self.advance()
                return A.Goto(t.file, t.line, t.col, str(self.expect_id().value))
            if k in ("end", "until", "else"):
                return A.Empty(t.file, t.line, t.col)
            self.error(f"statement expected, found {self.describe()}")
        if t.kind == "op" and t.value == ";":
            return A.Empty(t.file, t.line, t.col)
        if t.kind != "id":
            self.error(f"statement expected, found {self.describe()}")
        nxt = self.peek()
        if nxt.kind == "op" and nxt.value in (":=", "."):
            target = self.designator()
            if self.at_op("="):
                self.error("':=' expected for an assignment, found '='")
            self.expect_op(":=")
            return A.Assign(t.file, t.line, t.col, target, self.expression())
        call = self.call_rest(self.advance())
        return A.CallStmt(t.file, t.line, t.col, call)

    def designator(self):
        t = self.expect_id()
        if not self.at_op("."):
            return A.Name(t.file, t.line, t.col, t.value)
        self.advance()
        q = self.tok
        if q.kind not in ("id", "kw"):
            self.error(f"qualifier expected after '.', found {self.describe()}")
        self.advance()
        node = A.Qual(t.file, t.line, t.col, A.Name(t.file, t.line, t.col, t.value), str(q.value if q.kind == "id"
                                                                                             else q.text))
        if self.at_op(".") and self.peek().kind in ("int", "id"):
            self.advance()
            b = self.advance()
            node.bit = b.value if b.kind == "int" else A.Name(b.file, b.line, b.col, b.value)
        return node

    def call_rest(self, name: Token) -> A.Call:
        call = A.Call(name.file, name.line, name.col, str(name.value))
        if self.at_op("("):
            self.advance()
            call.parens = True
            height = 0
            if not self.at_op(")"):
                call.args.append(self.call_arg())
                height = self.height
                while self.at_op(","):
                    self.advance()
                    call.args.append(self.call_arg())
                    height = max(height, self.height)
            self.expect_op(")")
            self.height = height + 1
        return call

    def call_arg(self):
        t = self.tok
        if t.kind == "id" and self.peek().kind == "op" and self.peek().value == ":=":
            self.advance()
            self.advance()
            return A.Named(t.file, t.line, t.col, t.value, self.expression())
        return self.expression()

    # -- expressions -------------------------------------------------------------
    def expression(self):
        return self.chain(self.simple, lambda: self.at_op(*REL_OPS))

    def simple(self):
        return self.chain(self.term, lambda: self.at_op("+", "-") or self.at_kw("or", "xor"))

    def term(self):
        return self.chain(self.factor, lambda: self.at_op("*", "/") or self.at_kw("mod", "shl", "shr", "and"))

    def chain(self, operand, at_operator):
        """``operand {operator operand}``, left-associative; each operator is one level of the tree."""
        left = operand()
        height = self.height
        while at_operator():
            op = self.advance()
            left = A.Bin(op.file, op.line, op.col, op.value, left, operand())
            height = max(height, self.height) + 1
            if height > MAX_NESTING:
                self.error(too_deep("brackets, operators and calls", MAX_NESTING), op, "NEST001")
        self.height = height
        return left

    def factor(self):
        """An operand; ``self.height`` is the height of its tree (0 for a constant or a name)."""
        t = self.tok
        self.operands += 1
        if self.operands > MAX_NESTING:
            self.error(too_deep("brackets, operators and calls", MAX_NESTING), t, "NEST001")
        self.height = 0
        node = self.operand(t)
        self.operands -= 1
        return node

    def operand(self, t: Token):
        if t.kind == "op" and t.value in ("+", "-") or t.kind == "kw" and t.value == "not":
            self.advance()
            operand = self.factor()
            self.height += 1
            if t.value == "-" and isinstance(operand, A.Num) and operand.ty == "integer" and operand.value == -INT_MIN:
                operand.value = INT_MIN
                return operand
            return A.Unary(t.file, t.line, t.col, t.value, operand)
        if t.kind == "int":
            self.advance()
            v = t.value
            if v > INT_MAX + 1:
                self.warn("W006", "integer constant out of range: clamped to 2147483647", t)
            return A.Num(t.file, t.line, t.col, v if v <= INT_MAX + 1 else INT_MAX, "integer")
        if t.kind == "real":
            self.advance()
            return A.Num(t.file, t.line, t.col, t.value, "double")
        if t.kind == "str":
            self.advance()
            return A.Str(t.file, t.line, t.col, t.value)
        if t.kind == "op" and t.value == "(":
            self.advance()
            e = self.expression()
            self.expect_op(")")
            self.height += 1
            return e
        if t.kind == "kw" and t.value in CASTS:
            self.advance()
            if not self.at_op("("):
                self.error(f"'(' expected after type name {t.text}")
            self.advance()
            e = self.expression()
            self.expect_op(")")
            self.height += 1
            return A.Call(t.file, t.line, t.col, t.value.upper(), [e], True)
        if t.kind == "id":
            nxt = self.peek()
            if nxt.kind == "op" and nxt.value == ".":
                return self.designator()
            if nxt.kind == "op" and nxt.value == "(":
                return self.call_rest(self.advance())
            self.advance()
            return A.Name(t.file, t.line, t.col, t.value)
        self.error(f"expression expected, found {self.describe()}")
