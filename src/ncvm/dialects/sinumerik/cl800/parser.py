"""Recursive-descent parser for CL 800 programs and external lists (CL 800 manual §5, L972-4590).

Errors are collected (the parser resynchronises at the next ``;``); the caller
reports the first one, like the WS 800 A, or all of them for ``check --all``.
Leniencies for the manual's own examples (CL 800 manual §5, L972-4590): ``;`` before
ELSE/ENDIF/END optional, ``:=`` for ``=``, ``,`` or ``.`` in IF INT pairs,
``CHAN = n`` or ``CHAN(n)``, optional ``OF`` in CASE and ``:`` after CONST/POINTER.
"""

from __future__ import annotations

import re
from contextlib import contextmanager

from ....source import LETTERS, MAX_NESTING, NAME_CHARS, too_deep
from . import ast
from .errors import CompilerMessage
from .lexer import KEYWORDS, KEYWORDS_UPPER, Token, norm
from .tables import FUNCTIONS, NC_FUNCTIONS, PROCEDURES, RELOPS, SYS_READS, SYS_WRITES, TWO_WORD

TYPES = ("INTEGER", "REAL", "PATTERN", "BOOLEAN")
#: words that close a statement list; a missing ";" directly before them is accepted
CLOSERS = ("END", "ELSE", "ENDIF", "UNTIL", "OTHERWISE", "ENDCASE")
MAX_INT = 99_999_999
MAX_DEPTH = 9  # control constructs inside each other: one decimal digit of the block number (CL 800 manual L6427-6469), E058


class Parser:
    def __init__(self, path: str, tokens: list[Token], source: str, strict: bool = False):
        self.path, self.toks, self.pos, self.strict = path, tokens, 0, strict
        self.lines = source.replace("\r", "").split("\n")
        self.errors: list[CompilerMessage] = []
        self.consts: set[str] = set()
        self.statements = 0  # statements (BEGIN ... END too) the parser is inside: NEST001 beyond MAX_NESTING
        self.operands = 0  # nested operands (brackets, operators, arguments): NEST001 beyond MAX_NESTING

    # -- token helpers ---------------------------------------------------
    @property
    def tok(self) -> Token:
        return self.toks[self.pos]

    def peek(self, k: int = 1) -> Token:
        return self.toks[min(self.pos + k, len(self.toks) - 1)]

    def advance(self) -> Token:
        t = self.toks[self.pos]
        if t.kind != "EOF":
            self.pos += 1
        return t

    def fail(self, code: str, tok: Token | None = None, detail: str = "") -> CompilerMessage:
        t = tok or self.tok
        return CompilerMessage(code, self.path, t.line, t.col, detail, t.end_col if t.text else None)

    def is_sym(self, s: str) -> bool:
        return self.tok.kind == "SYM" and self.tok.text == s

    def accept_sym(self, s: str) -> bool:
        if self.is_sym(s):
            self.advance()
            return True
        return False

    def expect_sym(self, s: str, code: str) -> Token:
        if not self.is_sym(s):
            raise self.fail(code)
        return self.advance()

    def is_kw(self, *words: str) -> bool:
        return self.tok.is_kw(*words)

    def expect_kw(self, word: str, code: str) -> Token:
        if not self.is_kw(word):
            raise self.fail(code)
        return self.advance()

    def sync(self) -> None:
        """Skip to just after the next ';' (error recovery for check --all)."""
        while self.tok.kind != "EOF" and not self.is_sym(";"):
            self.advance()
        self.accept_sym(";")

    # -- numbers and names -------------------------------------------------
    def uint(self, header: bool = False) -> int:
        t = self.tok
        if t.kind == "INT":
            self.advance()
            return t.value
        if header:
            code = {"REAL": "E048", "NAME": "E039", "RPAR": "E043"}.get(t.kind, "E027")
            raise self.fail(code)
        raise self.fail("E027")

    def number(self) -> ast.Num:
        """A signed number constant (CONST values, header numbers checked elsewhere)."""
        neg = self.accept_sym("-")
        if not neg:
            self.accept_sym("+")
        t = self.tok
        if t.kind not in ("INT", "REAL", "PATTERN"):
            raise self.fail("E027")
        n = self.literal()
        if neg:
            n.value = -n.value
        return n

    def literal(self) -> ast.Num:
        t = self.advance()
        if t.kind == "INT":
            if len(t.text.lstrip("0")) > 8:
                raise self.fail("E050", t)
            return ast.Num(t.line, t.col, t.value, "INTEGER")
        if t.kind == "PATTERN":
            return ast.Num(t.line, t.col, t.value, "PATTERN")
        whole, frac = t.text.split(".")
        if len(whole.lstrip("0")) > 5:
            raise self.fail("E052", t)
        if t.value != 0 and abs(t.value) < 1e-8:
            raise self.fail("E049", t)
        return ast.Num(t.line, t.col, t.value, "REAL")

    def new_name(self) -> Token:
        """A name being declared: not a keyword in any letter case (E054), not starting with a digit (E040)."""
        t = self.tok
        if t.kind == "BADNAME":
            raise self.fail("E040")
        if t.kind != "NAME":
            raise self.fail("E061" if t.kind != "RPAR" else "E054", detail="name expected")
        if t.text.upper().rstrip(".") in KEYWORDS_UPPER:
            raise self.fail("E054")
        return self.advance()

    # -- units -------------------------------------------------------------
    def parse(self):
        if self.is_kw("EXTERNAL"):
            return self.ext_list()
        if not self.is_kw("PROGRAM"):
            self.errors.append(self.fail("E011"))
            return None
        return self.program()

    def guarded(self, fn, *args):
        try:
            return fn(*args)
        except CompilerMessage as e:
            self.errors.append(e)
            self.sync()
            return None

    def program(self) -> ast.Program:
        t = self.advance()
        prog = ast.Program(t.line, t.col, -1, 0)
        try:
            prog.number = self.uint(header=True)
            self.expect_sym(";", "E001")
        except CompilerMessage as e:
            self.errors.append(e)
            self.sync()
        self.guarded(self.channel, prog, False)
        while self.tok.kind != "EOF" and not self.is_kw("BEGIN"):
            before = self.pos
            self.guarded(self.program_item, prog)
            if self.pos == before:
                self.advance()
        if not self.is_kw("BEGIN"):
            self.errors.append(self.fail("E060", detail="BEGIN ... END. missing"))
            return prog
        prog.begin_line = self.advance().line
        prog.body = self.stmt_list(("END",), depth=0)
        if not self.is_kw("END"):
            self.errors.append(self.fail("E060" if self.tok.kind == "EOF" else "E001"))
            return prog
        end = self.advance()
        prog.end_line = end.line
        if not self.is_sym("."):
            # where the dot belongs, right after END (not at the next token, which may be the end of the file)
            self.errors.append(CompilerMessage("E010", self.path, end.line, end.col + len(end.text)))
        else:
            self.advance()
        if self.tok.kind != "EOF":
            self.errors.append(self.fail("E060", detail="text after END."))
        return prog

    def channel(self, unit, is_list: bool) -> None:
        if not self.is_kw("CHANNEL"):
            raise self.fail("E012")
        self.advance()
        if not (self.is_kw("NC") or (is_list and self.is_kw("COM"))):
            raise self.fail("E013")
        self.advance()
        unit.channel = self.uint(header=True)
        if unit.channel > 16:
            raise self.fail("E027", self.toks[self.pos - 1], "channel 0..16")
        self.expect_sym(";", "E001")

    def paren_text(self, code: str) -> str:
        """The raw text of ``ID ( ... )`` / ``PW ( ... )`` as it stands on its line."""
        open_tok = self.expect_sym("(", "E005")
        while self.tok.kind != "EOF" and not self.is_sym(")") and self.tok.line == open_tok.line:
            self.advance()
        if not self.is_sym(")"):
            raise self.fail("E006")
        close = self.advance()
        return self.lines[open_tok.line - 1][open_tok.col:close.col - 1].strip()

    def ident(self, unit) -> None:
        self.advance()
        text = self.paren_text("E032")
        if not _ident_ok(text, self.strict):
            raise self.fail("E032", self.toks[self.pos - 1])
        unit.ident = text
        self.expect_sym(";", "E001")

    def password(self, unit) -> None:
        self.advance()
        text = self.paren_text("E033")
        if not text or len(text) > 8 or text[0] not in LETTERS or not all(c in NAME_CHARS for c in text):
            raise self.fail("E033", self.toks[self.pos - 1])
        unit.password = text
        self.expect_sym(";", "E001")

    def program_item(self, prog: ast.Program) -> None:
        t = self.tok
        if t.is_kw("ESS"):
            self.advance()
            prog.ess = True
            self.expect_sym(";", "E001")
        elif t.is_kw("ID"):
            self.ident(prog)
        elif t.is_kw("PW"):
            self.password(prog)
        elif t.is_kw("GLOBAL", "CENTRAL"):
            self.advance()
            self.expect_sym(":", "E002")
            if self.tok.kind != "STRING":
                raise self.fail("E028")
            s = self.advance()
            name = s.value.strip()
            if not name:
                raise self.fail("E029", s)
            if len(name) > 8 or name[0] not in LETTERS:
                raise self.fail("E034", s)
            if self.is_sym(",") or (self.tok.kind == "STRING"):
                raise self.fail("E035")
            if prog.list_refs and prog.list_refs[-1][2] == t.line:
                raise self.fail("E035", t, "one list reference per line")
            prog.list_refs.append((t.text, name, s.line, s.col))
            self.expect_sym(";", "E001")
            if self.tok.kind == "STRING" and self.tok.line == s.line:
                raise self.fail("E035", detail="one list reference per line")
        elif t.is_kw("PAR", "LOCAL", "POINTER"):
            self.advance()
            if t.text == "POINTER":
                typ = "INTEGER"
                self.accept_sym(":")
            else:
                if not self.is_kw(*TYPES):
                    raise self.fail("E061", detail="data type expected")
                typ = self.advance().text
                self.expect_sym(":", "E002")
            self.rdecls(prog.decls, t.text, typ)
        elif t.is_kw("CONST"):
            self.advance()
            self.accept_sym(":")
            while True:
                n = self.new_name()
                self.expect_sym(":=", "E003")
                val = self.number()
                key = norm(n.text)
                if key in prog.consts:
                    raise self.fail("E036", n)
                prog.consts[key] = (val, n.line, n.col, n.text)
                self.consts.add(key)
                if not self.accept_sym(","):
                    break
            self.expect_sym(";", "E001")
        elif t.is_kw("LABEL"):
            self.advance()
            self.expect_sym(":", "E002")
            while True:
                n = self.new_name()
                key = norm(n.text)
                if len(n.text) > 8:
                    raise self.fail("E061", n, f"a label has at most 8 characters (L1297): {n.text}")
                if key in prog.labels:
                    raise self.fail("E036", n)
                prog.labels[key] = (n.line, n.col, n.text)
                if not self.accept_sym(","):
                    break
            self.expect_sym(";", "E001")
        elif t.is_kw("PROGRAM", "CHANNEL"):
            raise self.fail("E054")
        elif t.kind == "NAME" and t.text not in KEYWORDS:
            raise self.fail("E054", detail="declaration expected")
        else:
            raise self.fail("E061", detail="declaration expected")

    def rdecls(self, out: list, cls: str, typ: str) -> None:
        while True:
            t = self.tok
            if t.kind != "RPAR":
                raise self.fail("E054" if t.kind == "NAME" else "E061", detail="R parameter expected")
            self.advance()
            if self.is_sym(".") or (self.tok.kind == "REAL"):
                raise self.fail("E044", t)
            name = None
            if self.accept_sym(":="):
                name = self.new_name().text
            elif self.is_sym("=") or self.is_sym(":"):
                raise self.fail("E003")
            out.append(ast.Decl(t.line, t.col, cls, typ, t.value, name, self.path))
            if self.accept_sym(","):
                continue
            if self.tok.kind in ("RPAR",):
                raise self.fail("E009")
            break
        self.expect_sym(";", "E001")

    def ext_list(self) -> ast.ExtList:
        t = self.advance()
        lst = ast.ExtList(t.line, t.col, 0)
        try:
            lst.number = self.uint(header=True)
            if not 1 <= lst.number <= 9999:
                raise self.fail("E027", self.toks[self.pos - 1], "list number 1..9999")
            self.expect_sym(";", "E001")
        except CompilerMessage as e:
            self.errors.append(e)
            self.sync()
        while self.tok.kind != "EOF" and not self.is_kw("ENDEXTERN"):
            before = self.pos
            self.guarded(self.list_item, lst)
            if self.pos == before:
                self.advance()
        if not self.is_kw("ENDEXTERN"):
            self.errors.append(self.fail("S051"))
            return lst
        self.advance()
        self.accept_sym(";")
        if self.tok.kind != "EOF":
            self.errors.append(self.fail("E060", detail="text after ENDEXTERN"))
        return lst

    def list_item(self, lst: ast.ExtList) -> None:
        t = self.tok
        if t.is_kw("CHANNEL"):
            self.channel(lst, True)
        elif t.is_kw("ID"):
            self.ident(lst)
        elif t.is_kw("PW"):
            self.password(lst)
        elif t.is_kw("GLOBAL", "CENTRAL"):
            self.advance()
            if not self.is_kw(*TYPES):
                raise self.fail("E061", detail="data type expected")
            typ = self.advance().text
            self.expect_sym(":", "E002")
            self.rdecls(lst.decls, t.text, typ)
        else:
            raise self.fail("E016")

    # -- statements ----------------------------------------------------------
    def stmt_list(self, stops: tuple[str, ...], depth: int, case_alt: bool = False) -> list:
        out: list = []
        while True:
            t = self.tok
            if t.kind == "EOF" or t.is_kw(*stops) or t.is_kw(*CLOSERS) or (case_alt and self.is_sym("=")):
                return out
            if self.accept_sym(";"):
                continue
            try:
                st = self.statement(depth)
                if st is not None:
                    out.append(st)
                if self.accept_sym(";"):
                    continue
                if not self.strict and (self.tok.kind == "EOF" or self.tok.is_kw(*CLOSERS) or
                                        (case_alt and self.is_sym("="))):
                    continue
                # a closing bracket without its opener: "[" / "(" expected
                raise self.fail("E007" if self.is_sym("]") else "E005" if self.is_sym(")") else "E001")
            except CompilerMessage as e:
                self.errors.append(e)
                self.sync()

    def statement(self, depth: int):
        t = self.tok
        label = None
        if t.kind == "NAME" and t.text not in KEYWORDS and self.peek().kind == "SYM" and self.peek().text == ":":
            label = t.text
            self.advance()
            self.advance()
            t = self.tok
        if depth > MAX_DEPTH:
            raise self.fail("E058", t)
        if self.statements >= MAX_NESTING:
            raise self.fail("NEST001", t, too_deep("statements", MAX_NESTING))
        self.statements += 1
        try:
            st = self.bare_statement(depth)
        finally:
            self.statements -= 1
        if st is not None:
            st.label, st.depth = label, depth
        elif label is not None:
            raise self.fail("E061", t, "statement expected after the label")
        return st

    def two_word(self) -> str:
        """Read a (possibly two-word) keyword such as ``STOP DEC1`` and return the full name."""
        first = self.advance()
        seconds, code = TWO_WORD.get(first.text, (None, None))
        if seconds is None:
            return first.text
        if self.tok.kind == "NAME" and self.tok.text in seconds:
            return f"{first.text} {self.advance().text}"
        if first.text in ("INT", "DEC", "CLEAR"):
            return first.text
        raise self.fail(code)

    def bare_statement(self, depth: int):
        t = self.tok
        line, col = t.line, t.col
        if t.kind == "DIN":
            self.advance()
            return ast.Din(line, col, t.value)
        if t.kind == "RPAR" or self.is_sym("["):
            return self.assignment()
        if t.kind == "BADNAME":
            raise self.fail("E031")
        if t.kind != "NAME":
            raise self.fail("E061")
        w = t.text
        if w not in KEYWORDS:
            self.split_dotted()
            return self.assignment()
        if w == "LF":
            self.advance()
            return ast.Lf(line, col)
        if w == "ESS":
            self.advance()
            return ast.Proc(line, col, "ESS", [])
        if w == "BEGIN":
            self.advance()
            body = self.stmt_list(("END",), depth)
            self.expect_kw("END", "E060" if self.tok.kind == "EOF" else "E001")
            if self.is_sym("."):
                raise self.fail("E060", detail="END. inside the statement part")
            return ast.Compound(line, col, body)
        if w == "IF":
            return self.if_stmt(depth)
        if w == "WHILE":
            return self.while_stmt(depth)
        if w == "REPEAT":
            self.advance()
            body = self.stmt_list(("UNTIL",), depth + 1)
            until = self.expect_kw("UNTIL", "E024")
            cond = self.expr()
            return ast.Repeat(line, col, body, cond, until.line)
        if w == "FOR":
            return self.for_stmt(depth)
        if w == "CASE":
            return self.case_stmt(depth)
        if w == "GOTO":
            self.advance()
            if self.tok.kind != "NAME":
                raise self.fail("S050")
            return ast.Goto(line, col, self.advance().text)
        if w in SYS_WRITES and self.peek().kind == "SYM" and self.peek().text == "(":
            return self.sys_write()
        if w == "CHAN":
            self.advance()
            if self.accept_sym("="):
                return ast.Proc(line, col, "CHAN", [self.expr()])
            return ast.Proc(line, col, "CHAN", self.args(1))
        name = self.two_word()
        if name in PROCEDURES:
            kinds = PROCEDURES[name][1]
            if not kinds:
                return ast.Proc(line, col, name, [])
            if kinds == "b":
                self.expect_sym("(", "E005")
                target = self.primary()
                if not isinstance(target, ast.Bit):
                    raise self.fail("E010")
                self.expect_sym(")", "E006")
                return ast.Proc(line, col, name, [target])
            return ast.Proc(line, col, name, self.args(len(kinds)))
        raise self.fail("E054" if w in SYS_READS or w in FUNCTIONS else "E061", t)

    def split_dotted(self) -> None:
        """``deg_ref.THEN`` (legacy dotted names): split a keyword or bit constant off."""
        t = self.tok
        if "." not in t.text.rstrip("."):
            return
        parts = t.text.split(".")
        for k in range(len(parts) - 1, 0, -1):
            rest = ".".join(parts[k:])
            head = ".".join(parts[:k])
            if rest in KEYWORDS or (rest and norm(rest) in self.consts):
                col = t.col + len(head) + 1
                extra = [Token("NAME", rest, t.line, col, end_line=t.line)]
                if rest in KEYWORDS:
                    head += "."
                else:
                    extra.insert(0, Token("SYM", ".", t.line, col - 1, end_line=t.line))
                self.toks[self.pos:self.pos + 1] = [Token("NAME", head, t.line, t.col, end_line=t.line)] + extra
                return

    def args(self, n: int) -> list:
        with self.nested(self.tok):
            return self._args(n)

    def _args(self, n: int) -> list:
        self.expect_sym("(", "E005")
        out = []
        if n == 0:
            self.expect_sym(")", "E006")
            return out
        while True:
            out.append(self.expr())
            if len(out) == n:
                break
            if not self.accept_sym(","):
                raise self.fail("E009" if not self.is_sym(")") else "E061", detail=f"{n} arguments expected")
        if self.is_sym(","):
            raise self.fail("E006", detail=f"{n} arguments expected")
        self.expect_sym(")", "E006")
        return out

    def operand(self) -> ast.Operand:
        t = self.tok
        if self.accept_sym("["):
            inner = self.tok
            if inner.kind == "RPAR":
                self.advance()
                op = ast.Operand(t.line, t.col, None, inner.value, True)
            elif inner.kind == "NAME" and inner.text not in KEYWORDS:
                self.advance()
                op = ast.Operand(t.line, t.col, inner.text, None, True)
            else:
                raise self.fail("E061", detail="pointer expected")
            self.expect_sym("]", "E008")
            return op
        if t.kind == "RPAR":
            self.advance()
            return ast.Operand(t.line, t.col, None, t.value)
        if t.kind == "NAME" and t.text not in KEYWORDS:
            self.split_dotted()
            t = self.advance()
            return ast.Operand(t.line, t.col, t.text, None)
        if t.kind == "BADNAME":
            raise self.fail("E040")
        raise self.fail("E054" if t.kind == "NAME" else "E061", detail="variable expected")

    def assignment(self) -> ast.Stmt:
        target = self.operand()
        if self.is_sym("."):
            raise self.fail("E047")
        if not (self.accept_sym("=") or (not self.strict and self.accept_sym(":="))):
            raise self.fail("E004")
        return ast.Assign(target.line, target.col, target, self.rhs())

    def rhs(self):
        t = self.tok
        if t.kind == "NAME" and t.text in ("PREP", "INT", "MEAS"):
            name = self.two_word()
            if name not in NC_FUNCTIONS:
                raise self.fail("E021", t)
            code, kinds, _n = NC_FUNCTIONS[name]
            args = self.args(len(kinds)) if kinds else []
            return ast.Call(t.line, t.col, name, args)
        return self.expr()

    def sys_write(self) -> ast.SysWrite:
        t = self.advance()
        args = self.args(SYS_WRITES[t.text][1])
        self.expect_sym("=", "E004")
        return ast.SysWrite(t.line, t.col, t.text, args, self.expr())

    def if_stmt(self, depth: int):
        t = self.advance()
        if self.is_kw("INT"):
            self.advance()
            neg = bool(self.is_kw("NOT") and self.advance())
            a, b = self.int_pair()
            self.expect_kw("THEN", "E061")
            then, orelse = self.branches(depth)
            return ast.IfInt(t.line, t.col, neg, a, b, then, orelse)
        cond = self.expr()
        if not self.is_kw("THEN"):
            raise self.fail("E030" if isinstance(cond, ast.Num) else "E061", detail='"THEN" expected')
        self.advance()
        then, orelse = self.branches(depth)
        return ast.If(t.line, t.col, cond, then, orelse)

    def branches(self, depth: int):
        then = self.stmt_list(("ELSE", "ENDIF"), depth + 1)
        orelse = None
        if self.is_kw("ELSE"):
            self.advance()
            orelse = self.stmt_list(("ENDIF", "ELSE"), depth + 1)
        self.expect_kw("ENDIF", "E019")
        return then, orelse

    def int_pair(self):
        """``<Value1>.<Value2>`` or ``<Value1>,<Value2>`` of IF INT / WHILE INT (CL 800 manual L1717; L2060)."""
        t = self.tok
        if t.kind == "REAL":
            self.advance()
            a, b = t.text.split(".")
            return (ast.Num(t.line, t.col, int(a), "INTEGER"), ast.Num(t.line, t.col + len(a) + 1, int(b), "INTEGER"))
        a = self.operand() if t.kind in ("RPAR", "NAME") or self.is_sym("[") else self.int_value()
        if not (self.accept_sym(".") or self.accept_sym(",")):
            raise self.fail("E010")
        b = self.operand() if self.tok.kind in ("RPAR", "NAME") or self.is_sym("[") else self.int_value()
        return a, b

    def int_value(self) -> ast.Num:
        if self.tok.kind != "INT":
            raise self.fail("E027")
        return self.literal()

    def while_stmt(self, depth: int):
        t = self.advance()
        if self.is_kw("INT"):
            self.advance()
            neg = bool(self.is_kw("NOT") and self.advance())
            a, b = self.int_pair()
            self.expect_kw("DO", "E023")
            return ast.WhileInt(t.line, t.col, neg, a, b, [self.body(depth + 1)])
        cond = self.expr()
        self.expect_kw("DO", "E023")
        return ast.While(t.line, t.col, cond, [self.body(depth + 1)])

    def body(self, depth: int):
        st = self.statement(depth)
        if st is None:
            raise self.fail("E061", detail="statement expected")
        return st

    def for_stmt(self, depth: int):
        t = self.advance()
        var = self.operand()
        if not (self.accept_sym(":=") or (not self.strict and self.accept_sym("="))):
            raise self.fail("E003")
        start = self.expr()
        if not self.is_kw("TO", "DOWNTO"):
            raise self.fail("E061", detail='"TO" or "DOWNTO" expected')
        down = self.advance().text == "DOWNTO"
        stop = self.expr()
        self.expect_kw("DO", "E023")
        return ast.For(t.line, t.col, var, start, stop, down, [self.body(depth + 1)])

    def case_stmt(self, depth: int):
        t = self.advance()
        var = self.operand()
        if self.is_kw("OF"):
            self.advance()
        alts = []
        while self.is_sym("="):
            eq = self.advance()
            value = self.case_value()
            self.expect_sym(":", "E002")
            alts.append((value, self.stmt_list(("OTHERWISE", "ENDCASE"), depth + 1, case_alt=True), eq.line))
        if not alts:
            raise self.fail("E004")
        otherwise = None
        if self.is_kw("OTHERWISE"):
            self.advance()
            self.accept_sym(":")
            otherwise = self.stmt_list(("ENDCASE",), depth + 1)
        end = self.expect_kw("ENDCASE", "E017")
        return ast.Case(t.line, t.col, var, alts, otherwise, end_line=end.line)

    def case_value(self):
        t = self.tok
        if t.kind in ("RPAR", "NAME") or self.is_sym("["):
            if t.kind == "NAME" and t.text in KEYWORDS:
                raise self.fail("E054")
            return self.operand()
        return self.number()

    # -- expressions (manual §11.4, L7361-7386) ----------------------------
    LEVELS = (("ANDB", "NANDB", "ORB", "XORB"), tuple(RELOPS), ("OR", "XOR"), ("AND", "NAND"), ("+", "-"),
              ("*", "/"))

    def expr(self, level: int = 0):
        if level == len(self.LEVELS):
            return self.unary()
        ops = self.LEVELS[level]
        left = self.expr(level + 1)
        chained = 0
        try:
            while True:
                t = self.tok
                if t.kind == "NAME" and "." in t.text.rstrip("."):
                    self.split_dotted()
                    t = self.tok
                if (t.kind == "SYM" or t.kind == "NAME") and t.text in ops:
                    self.advance()
                    self.nest(t)  # each operator of a chain is one more level of the tree
                    chained += 1
                    right = self.expr(level + 1)
                    left = ast.Binary(t.line, t.col, t.text, left, right)
                else:
                    return left
        finally:
            self.operands -= chained

    def nest(self, t: Token) -> None:
        """One more level of the expression being read; beyond MAX_NESTING it is NEST001 at ``t``."""
        if self.operands >= MAX_NESTING:
            raise self.fail("NEST001", t, too_deep("brackets, operators and calls", MAX_NESTING))
        self.operands += 1

    @contextmanager
    def nested(self, t: Token):
        """Read an operand inside ``t`` (a bracket, a sign, a function's arguments) one level deeper."""
        self.nest(t)
        try:
            yield
        finally:
            self.operands -= 1

    def unary(self):
        t = self.tok
        if self.is_sym("-") or self.is_sym("+"):
            self.advance()
            with self.nested(t):
                inner = self.unary()
            if t.text == "+":
                return inner
            if isinstance(inner, ast.Num):
                inner.value = -inner.value
                return inner
            return ast.Unary(t.line, t.col, "-", inner)
        if self.is_kw("NOT", "NOTB"):
            self.advance()
            with self.nested(t):
                return ast.Unary(t.line, t.col, t.text, self.unary())
        return self.primary()

    def primary(self):
        t = self.tok
        if t.kind in ("INT", "REAL", "PATTERN"):
            return self.literal()
        if self.accept_sym("("):
            with self.nested(t):
                e = self.expr()
            self.expect_sym(")", "E006")
            return e
        if t.kind == "NAME" and t.text in KEYWORDS:
            if t.text in ("ARC", "INV", "PREP", "MEAS") or (t.text == "INT" and self.peek().is_kw("SEC")):
                name = self.two_word()
            else:
                name = self.advance().text
            if name in FUNCTIONS:
                return ast.Call(t.line, t.col, name, self.args(FUNCTIONS[name][1]))
            if name in SYS_READS:
                n = SYS_READS[name][1]
                if name == "PPCH" and not self.is_sym("("):
                    return ast.Call(t.line, t.col, name, [])
                return ast.Call(t.line, t.col, name, self.args(n))
            if name in NC_FUNCTIONS:
                kinds = NC_FUNCTIONS[name][1]
                return ast.Call(t.line, t.col, name, self.args(len(kinds)) if kinds else [])
            raise self.fail("E054", t)
        if t.kind in ("RPAR", "NAME") or self.is_sym("["):
            op = self.operand()
            if self.is_sym(".") and not op.pointer:
                self.advance()
                b = self.tok
                if b.kind == "INT":
                    self.advance()
                    return ast.Bit(op.line, op.col, op, b.value)
                if b.kind == "NAME" and norm(b.text) in self.consts:
                    self.advance()
                    return ast.Bit(op.line, op.col, op, b.text)
                raise self.fail("E027")
            return op
        if t.kind == "BADNAME":
            raise self.fail("E031")
        if t.kind == "EOF":
            raise self.fail("E060")
        raise self.fail("E061", detail="operand expected")


def _ident_ok(text: str, strict: bool) -> bool:
    """ID designation (L1116-1145): at most 40 characters; terms 1-4 fixed, separated by hyphens: the
    consecutive number (1 character), the file designation (8), the date (DD.MM.YY), the programmer (3).
    The manual's own examples leave out the date and initials (``0-BEISP2-...``) or give longer file
    designations (``0-HOLE PATTERN-...``): unless ``strict``, the number and a file designation suffice."""
    terms = [t.strip() for t in text.split("-")]
    if len(text) > 40 or len(terms) < 2 or len(terms[0]) != 1 or not terms[1]:
        return False
    if not strict:
        return True
    return (len(terms) >= 4 and len(terms[1]) <= 8 and re.fullmatch(r"\d\d\.\d\d\.\d\d", terms[2]) is not None
            and len(terms[3]) == 3)

