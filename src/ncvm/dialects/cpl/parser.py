"""Recursive-descent parser for CPL blocks and NC blocks (CPL manual §2, L302-1060), producing a flat statement list.

Expressions follow Pascal-like precedence levels (ncvm's reading; the manual gives no precedence table): unary NOT/-/+, then * / AND, then + - OR XOR, then
one relational operator. Parentheses nest at most 7 deep (RUNTIME ERROR 2153).
"""

from __future__ import annotations

import re

from ...source import ALNUM, DIGITS, LETTERS, NAME_CHARS, WORD_DECADES, is_digits, too_many_decades, word_number
from . import ast as A
from .errors import diag
from .lexer import LINE_MAX, LexError, Tok, VarName, classify, cpl_blocks, tokenize

#: keywords that close or split a structure; a statement may be followed directly by one of them
CLOSERS = {"ELSE", "ENDIF", "END", "NEXT", "UNTIL", "LABEL", "OTHERWISE", "ENDCASE"}
MAX_PARENS = 7
#: "Field size of the field variable of the types INTEGER and REAL: max. 65536" (manual §2.4.3 L702):
#: the elements of a numeric field, its two dimensions multiplied
MAX_FIELD_SIZE = 65536


class ParseError(Exception):
    def __init__(self, code: str, detail: str, line: int, col: int):
        self.code = code
        self.detail = detail
        self.line = line
        self.col = col


#: a part program's file name (manual §6.1.1 L3851): alphanumeric characters, "." and "_"; not "." or ".."
_PROGRAM_NAME = re.compile(r"(?!\.\.?$)[A-Za-z0-9_.]+")


COMPARISONS = ("=", "<>", "<", ">", "<=", ">=")


class BlockParser:
    """Parses the statements of one CPL block into the program's flat list."""

    def __init__(self, toks: list[Tok], line: int, cpl: int | None):
        self.toks = toks
        self.i = 0
        self.line = line
        self.cpl = cpl
        self.depth = 0

    # -- token helpers ----------------------------------------------------
    def peek(self, k: int = 0) -> Tok | None:
        j = self.i + k
        return self.toks[j] if j < len(self.toks) else None

    def at(self, kind: str, val=None) -> bool:
        t = self.peek()
        return t is not None and t.kind == kind and (val is None or t.val == val)

    def at_kw(self, *names) -> bool:
        t = self.peek()
        return t is not None and t.kind == "kw" and t.val in names

    def next(self) -> Tok:
        t = self.peek()
        if t is None:
            self.error("CPL001", "unexpected end of block")
        self.i += 1
        return t

    def expect(self, kind: str, val=None, what: str = "") -> Tok:
        t = self.peek()
        if t is None or t.kind != kind or (val is not None and t.val != val):
            self.error("CPL001", f"{what or repr(val)} expected")
        self.i += 1
        return t

    def error(self, code: str, detail: str, tok: Tok | None = None):
        t = tok or self.peek() or (self.toks[-1] if self.toks else None)
        raise ParseError(code, detail, t.line if t else self.line, t.col if t else 1)

    def stmt(self, cls, tok: Tok | None = None, **kw):
        t = tok or self.peek() or (self.toks[-1] if self.toks else None)
        return cls(line=t.line if t else self.line, col=t.col if t else 1, cpl=self.cpl, **kw)

    # -- statements --------------------------------------------------------
    def parse(self, out: list, prog: A.Program) -> None:
        first = True
        while self.peek() is not None:
            if self.at("op", ":"):
                self.i += 1
                first = True
                continue
            if self.at("label"):
                t = self.next()
                prog.labels.setdefault(t.val, []).append(len(out))
                out.append(self.stmt(A.LabelDef, t, name=t.val))
                continue
            if not first and not self.at_kw(*CLOSERS):
                self.error("CPL001", "':' expected between statements")
            chain = self.statement(out)
            # after THEN, ELSE, DO, REPEAT, OTHERWISE, LABEL c: a statement may follow directly
            first = chain

    def statement(self, out: list) -> bool:
        """Parse one statement; True when another statement may follow without ':'."""
        t = self.peek()
        if t.kind == "var":
            self.assignment(out)
            return False
        if t.kind != "kw":
            if t.kind == "num" and t.line != self.line and (self.i == 0 or self.toks[self.i - 1].line != t.line):
                self.error("CPL001", "the block before ends with ':', so this line continues it and has no line "
                                     "number (manual §2.1.2 L375-380)")
            self.error("CPL001", "statement expected")
        kw = t.val
        if kw == "IF":
            self.next()
            cond = self.expr()
            self.expect("kw", "THEN", "THEN")
            out.append(self.stmt(A.If, t, cond=cond))
            return True
        if kw == "ELSE":
            self.next()
            out.append(self.stmt(A.Else, t))
            return True
        if kw == "ENDIF":
            self.next()
            out.append(self.stmt(A.EndIf, t))
            return False
        if kw == "CASE":
            self.next()
            e = self.expr()
            self.expect("kw", "OF", "OF")
            out.append(self.stmt(A.Case, t, expr=e))
            return False
        if kw == "LABEL":
            self.next()
            vals = [self.case_const()]
            while self.at("op", ","):
                self.next()
                vals.append(self.case_const())
            out.append(self.stmt(A.CaseLabel, t, values=vals))
            return True
        if kw == "OTHERWISE":
            self.next()
            out.append(self.stmt(A.Otherwise, t))
            return True
        if kw == "ENDCASE":
            self.next()
            out.append(self.stmt(A.EndCase, t))
            return False
        if kw == "FOR":
            self.next()
            v = self.var_ref()
            self.expect("op", "=", "'='")
            start = self.expr()
            step = None
            if self.at_kw("STEP"):
                self.next()
                step = self.expr()
            self.expect("kw", "TO", "TO")
            end = self.expr()
            out.append(self.stmt(A.For, t, var=v, start=start, step=step, end=end))
            return True
        if kw == "NEXT":
            self.next()
            v = self.var_ref() if self.at("var") else None
            out.append(self.stmt(A.Next, t, var=v))
            return False
        if kw == "WHILE":
            self.next()
            cond = self.expr()
            if self.at_kw("DO"):
                self.next()
            out.append(self.stmt(A.While, t, cond=cond))
            return True
        if kw == "END":
            self.next()
            out.append(self.stmt(A.WEnd, t))
            return False
        if kw == "REPEAT":
            self.next()
            out.append(self.stmt(A.Repeat, t))
            return True
        if kw == "UNTIL":
            self.next()
            out.append(self.stmt(A.Until, t, cond=self.expr()))
            return False
        if kw == "GOTO":
            self.next()
            tt = self.next()
            if tt.kind == "num" and isinstance(tt.val, int):
                out.append(self.stmt(A.Goto, t, kind="line", target=tt.val))
            elif tt.kind == "label":
                out.append(self.stmt(A.Goto, t, kind="label", target=tt.val))
            elif tt.kind == "var" and tt.val.cls == "L" and not tt.val.suffix and tt.text[:1] == "N" \
                    and is_digits(tt.text[1:]) and len(tt.text) <= WORD_DECADES + 1:
                out.append(self.stmt(A.Goto, t, kind="n", target=int(tt.text[1:])))
            else:
                self.error("CPL001", "GOTO needs a line number, N<number> or .label", tt)
            return False
        if kw == "CALL":
            self.next()
            name = self.expect("name", None, "program name")
            if not _PROGRAM_NAME.fullmatch(name.val):  # a name along the program path, never a path of the host
                self.error("CPL001", f"program name {name.val!r}: letters, digits, '.' and '_' only "
                                     "(manual §6.1.1 L3851)", name)
            if len(name.val) > 28:  # the link table's file name adds two characters to the 30 a name may have
                self.error("CPL001", f"program name {name.val!r}: at most 28 characters (manual §6.1.1 L3851)",
                           name)
            args = []
            if self.at("op", "["):
                self.next()
                args = self.arg_list("]")
                self.expect("op", "]", "']'")
            din = False
            if self.at("var") and self.peek().text == "DIN":
                self.next()
                din = True
            out.append(self.stmt(A.CallStmt, t, name=name.val, args=args, din=din))
            return False
        if kw == "DIM":
            self.next()
            items = [self.dim_item()]
            while self.at("op", ","):
                self.next()
                items.append(self.dim_item())
            out.append(self.stmt(A.Dim, t, items=items))
            return False
        if kw == "PDIM":
            self.next()
            v = self.next()
            if v.kind != "var" or v.val.cls != "A":
                self.error("CPL001", "PDIM needs a parameter name (P1$ ...)", v)
            if v.val.suffix != "$":  # PDIM gives a string constant passed as a parameter its size (§3.4 L1149)
                self.error("CPL001", f"PDIM dimensions a string parameter: P{v.val.name}$, not {v.val.display}", v)
            self.expect("op", "(", "'('")
            size = self.expect("num", None, "field size")
            if size.val.__class__ is not int or not 1 <= size.val <= 1024:
                self.error("CPL022", f"PDIM size {size.val}: an INTEGER constant 1..1024", size)
            self.expect("op", ")", "')'")
            out.append(self.stmt(A.Pdim, t, var=v.val, size=size.val))
            return False
        if kw == "WAIT":
            self.next()
            out.append(self.wait(t))
            return False
        if kw == "MID$":
            self.next()
            self.expect("op", "(", "'('")
            target = self.var_ref()
            self.expect("op", ",", "','")
            start = self.expr()
            count = None
            if self.at("op", ","):
                self.next()
                count = self.expr()
            self.expect("op", ")", "')'")
            self.expect("op", "=", "'='")
            out.append(self.stmt(A.Assign, t, target=target, expr=self.expr(), mid=(start, count)))
            return False
        if kw in ("LJUST", "NJUST", "CLG", "CLR", "CLS", "CSF", "DLF"):
            self.next()
            out.append(self.stmt(A.Proc, t, name=kw))
            return False
        if kw in SETTABLE and self.peek(1) is not None and self.peek(1).kind == "op" and self.peek(1).val == "(":
            self.next()  # FXC(...)=v, TC(...)=v, TDA(...)=v, IC(...)=b, PLC(...)=v (manual chapter 4)
            self.next()
            args = self.arg_list(")")
            self.expect("op", ")", "')'")
            self.expect("op", "=", "'='")
            out.append(self.stmt(A.Proc, t, name=kw + "=", args=args + [self.expr()]))
            return False
        if kw in PROCS:
            self.next()
            args: list = []
            no_end = False
            if self.at("op", "("):
                self.next()
                args = self.arg_list(")")
                if self.at("op", ";"):
                    self.next()
                    no_end = True
                self.expect("op", ")", "')'")
            out.append(self.stmt(A.Proc, t, name=kw, args=args, no_end=no_end))
            return False
        self.error("CPL001", f"'{kw}' cannot start a statement")
        return False

    def assignment(self, out: list) -> None:
        t = self.peek()
        target = self.var_ref()
        if not self.at("op", "="):
            if target.index is None and (self.peek() is None or self.at("op", ":")):
                self.error("2167", f"'{t.text}' is a variable name; a value assignment is expected", t)
            self.error("2167", "'=' expected", self.peek())
        self.next()
        out.append(self.stmt(A.Assign, t, target=target, expr=self.expr()))

    def case_const(self) -> int:
        neg = False
        if self.at("op", "-") or self.at("op", "+"):
            neg = self.next().val == "-"
        t = self.expect("num", None, "INTEGER constant")
        if not isinstance(t.val, int):
            self.error("CPL001", "LABEL needs INTEGER constants", t)
        return -t.val if neg else t.val

    def dim_item(self):
        v = self.next()
        if v.kind != "var" or v.val.cls not in ("L", "G"):
            self.error("CPL001", "DIM needs a local or global variable name"
                       + (" (definable permanent fields are declared in wmhperm.dat/anwperm.dat)"
                          if v.kind == "var" and v.val.cls == "D" else ""), v)
        self.expect("op", "(", "'('")
        sizes = [self.expect("num", None, "INTEGER constant")]
        if self.at("op", ","):
            self.next()
            sizes.append(self.expect("num", None, "INTEGER constant"))
        self.expect("op", ")", "')'")
        for s in sizes:
            if not isinstance(s.val, int):
                self.error("CPL022", "field sizes are INTEGER constants", s)
        limit = 1024 if v.val.suffix == "$" else MAX_FIELD_SIZE
        for s in sizes:
            if not 1 <= s.val <= limit:
                self.error("CPL022", f"size {s.val} outside 1..{limit}", s)
        if v.val.suffix != "$" and len(sizes) == 2 and sizes[0].val * sizes[1].val > MAX_FIELD_SIZE:
            self.error("CPL022", f"field size {sizes[0].val} x {sizes[1].val} = {sizes[0].val * sizes[1].val}: "
                                 f"a field holds at most {MAX_FIELD_SIZE} elements", sizes[0])
        return (v.val, [s.val for s in sizes])

    def wait(self, t: Tok) -> A.Wait:
        w = self.stmt(A.Wait, t)
        if not self.at("op", "("):
            return w
        w.plain = False
        self.next()
        if not self.at("op", ","):
            if self.at_kw("NOT"):
                self.next()
                w.neg = True
            paren = False
            if self.at("op", "("):
                self.next()
                paren = True
            self.expect("kw", "IC", "IC(...)")
            self.expect("op", "(", "'('")
            w.ic = self.arg_list(")")
            self.expect("op", ")", "')'")
            if paren:
                self.expect("op", ")", "')'")
            if self.at("op", "="):
                self.next()
                w.state = self.expr()
        if self.at("op", ","):
            self.next()
            if not self.at("op", ",") and not self.at("op", ")"):
                w.duration = self.expr()
            if self.at("op", ","):
                self.next()
                w.result = self.var_ref()
        self.expect("op", ")", "')'")
        if w.result is not None and w.ic is None and w.duration is None:
            self.error("CPL001", "WAIT result variable needs a condition or a duration", t)
        return w

    # -- expressions -------------------------------------------------------
    def arg_list(self, close: str) -> list:
        args: list = []
        if self.at("op", close) or self.at("op", ";"):
            return args
        while True:
            if self.at("op", ",") or self.at("op", close) or self.at("op", ";"):
                args.append(None)
            else:
                args.append(self.expr())
            if self.at("op", ","):
                self.next()
                continue
            return args

    def var_ref(self) -> A.Var:
        t = self.next()
        if t.kind != "var":
            self.error("CPL001", "variable expected", t)
        index = None
        if self.at("op", "("):
            self.next()
            index = [self.expr()]
            if self.at("op", ","):
                self.next()
                index.append(self.expr())
            self.expect("op", ")", "')'")
        return A.Var(t.val, index, t.col)

    def expr(self):
        left = self.simple()
        t = self.peek()
        if t is not None and t.kind == "op" and t.val in COMPARISONS:
            self.next()
            right = self.simple()
            left = A.Bin(t.val, left, right)
            again = self.peek()
            if again is not None and again.kind == "op" and again.val in COMPARISONS:
                # AND/OR/XOR bind tighter than a comparison (Pascal levels, §2.5.1): A%>1 AND B%<2 reads as
                # A% > (1 AND B%) < 2 (L851, L872; the manual parenthesises every compound condition, L4648)
                self.error("CPL001", "a second comparison: comparisons joined by AND, OR or XOR need "
                                     "parentheses, e.g. (A%>1) AND (B%<2)", again)
        return left

    def simple(self):
        left = self.term()
        while True:
            t = self.peek()
            if t is not None and ((t.kind == "op" and t.val in "+-" and len(t.val) == 1)
                                  or (t.kind == "kw" and t.val in ("OR", "XOR"))):
                self.next()
                left = A.Bin(t.val, left, self.term())
            else:
                return left

    def term(self):
        left = self.factor()
        while True:
            t = self.peek()
            if t is not None and ((t.kind == "op" and t.val in ("*", "/")) or (t.kind == "kw" and t.val == "AND")):
                self.next()
                left = A.Bin(t.val, left, self.factor())
            else:
                return left

    def factor(self):
        t = self.next()
        if t.kind == "op" and t.val in ("-", "+"):
            return A.Unary(t.val, self.factor())
        if t.kind == "kw" and t.val == "NOT":
            return A.Unary("NOT", self.factor())
        if t.kind == "num":
            return A.Num(t.val, "I" if isinstance(t.val, int) else "R")
        if t.kind == "str":
            return A.Str(t.val)
        if t.kind == "op" and t.val == "(":
            self.depth += 1
            if self.depth > MAX_PARENS:
                self.error("2153", f"parentheses nested deeper than {MAX_PARENS}", t)
            e = self.expr()
            self.expect("op", ")", "')'")
            self.depth -= 1
            return e
        if t.kind == "var":
            self.i -= 1
            return self.var_ref()
        if t.kind == "kw":
            if t.val in ("TRUE", "FALSE"):
                return A.BoolLit(t.val == "TRUE")
            if t.val == "NUL":
                return A.Nul()
            if t.val in FUNCS:
                args: list = []
                if self.at("op", "("):
                    self.next()
                    self.depth += 1
                    args = self.arg_list(")")
                    self.expect("op", ")", "')'")
                    self.depth -= 1
                return A.Func(t.val, args, t.col)
        self.error("CPL001", f"unexpected '{t.val}' in an expression", t)


#: keywords usable as functions in expressions (the implemented ones are in builtins.FUNCTIONS)
FUNCS = frozenset("""
ABS ACOS APOS ASC ASIN ATAN AXO AXP BCD BIN CHR$ CLOCK COF COS CPOS CPROBE DATE DPC EOF ERASE FILEACCESS FILEDATE
FILEPOS FILESIZE FXC GETERR IC INKEY INSTR INT LEN MCA MCODS MCOPS MID$ MMC MPOS NCF PLC PPOS PROBE ROUND SCL SCS
SCSL SD SDR SIN SPOS SQRT STR$ TAN TC TDA TIME TRIM$ VAL WPOS
""".split())

#: functions of chapter 4 that can also be assigned to: FXC(...)=v (stored as the procedure "FXC=")
SETTABLE = frozenset(("FXC", "TC", "TDA", "IC", "PLC"))

#: keywords usable as procedure statements
PROCS = frozenset("""
OPENR OPENW CLOSE REWRITE SEEK PRN# INP# ERASE DSP PRN INP SFK TFO COL RGB GMD GWD MWD LIN CIR FIL GPR BMP FXCR
FXDEL FXINS SCSL MCODS MCOPS MMC GETERR DLG ENDDLG
""".split())


# -- NC blocks --------------------------------------------------------------
def parse_nc(text: str, lineno: int, calls: dict) -> A.NcBlock:
    """Read one NC block: words with constant or [expr] values, standalone [expr], (MSG, ...), WAIT, calls."""
    blk = A.NcBlock(line=lineno, col=1)
    s = text
    n = len(s)
    i = 0
    while i < n and s[i] in " \t":
        i += 1
    if i < n and s[i] == "/":
        blk.skip = True
        i += 1
    while i < n:
        c = s[i]
        if c in " \t":
            i += 1
            continue
        if c == "(":
            j = s.find(")", i)
            if j < 0:
                raise ParseError("CPL001", "comment not closed with ')'", lineno, i + 1)
            inner = s[i + 1:j].strip()
            if inner.upper().startswith("MSG,"):
                blk.msg = inner[4:].strip()
            i = j + 1
            continue
        if c == ";" or c == "%":
            break
        if c == ":":
            rest = s[i + 1:].strip().upper()
            if rest.startswith("REM") or not rest:
                break
            raise ParseError("CPL001", "only ': REM ...' may follow an NC block", lineno, i + 1)
        if c == "[":
            j = _close_bracket(s, i, lineno)
            blk.loose.append(_nc_expr(s[i + 1:j], lineno, i + 1))
            i = j + 1
            continue
        up = c.upper()
        if c not in LETTERS:
            raise ParseError("CPL001", f"cannot read '{s[i:i + 10].strip()}' in the NC block", lineno, i + 1)
        if s[i:i + 4].upper() == "WAIT" and not (i + 4 < n and s[i + 4] in ALNUM):
            if s[i + 4:i + 5] == "(":
                raise ParseError("CPL001", "WAIT with parameters can be programmed only in a CPL block "
                                           "(manual §4.1 L1203)", lineno, i + 1)
            blk.wait = True
            i += 4
            continue
        col = i + 1
        j = i + 1
        addr = up
        # extended address: letters/digits followed by '=' (X2=, U_CH1=)
        k = j
        while k < n and s[k] in NAME_CHARS:
            k += 1
        if k < n and s[k] == "=" and k > j:
            addr = s[i:k].upper()
            j = k
        while j < n and s[j] in " \t":
            j += 1
        if j < n and s[j] == "=":
            j += 1
            while j < n and s[j] in " \t":
                j += 1
        if addr == "P" and j < n and s[j] in LETTERS:
            k = j
            while k < n and (s[k] in NAME_CHARS or s[k] == "."):
                k += 1
            name = s[j:k]
            args, i = _call_args(s, k, lineno)
            blk.call = (name, args, False)
            continue
        if j < n and s[j] == "[":
            if addr == "N":  # the block number is known when linking: GOTO N.. must find it (§2.1.1 L357)
                raise ParseError("CPL001", "the N address takes no [ ]: word contents with the exception of "
                                           "N-addresses may be written with variables (manual §2.1.1 L357)",
                                 lineno, col)
            k = _close_bracket(s, j, lineno)
            e = _nc_expr(s[j + 1:k], lineno, j + 1)
            if addr not in ("G", "M") and any(w.address == addr for w in blk.words):
                raise ParseError("CPL001", f"address {addr} twice in one block", lineno, col)
            blk.words.append(A.NcWord(addr, None, e))
            i = k + 1
            continue
        k = j
        if k < n and s[k] in "+-":
            k += 1
        while k < n and (s[k] in DIGITS or s[k] == "."):
            k += 1
        num = s[j:k]
        if not num or num in "+-." or num.count(".") > 1:
            raise ParseError("CPL001", f"address {addr} needs a number or [expression]", lineno, col)
        value = word_number(num)
        if value is None:
            raise ParseError("CPL001", too_many_decades(addr), lineno, col)
        i = k
        if addr == "N" and blk.n is None and not blk.words:
            blk.n = int(value)
            continue
        key = f"{addr}{int(value) if value == int(value) else value}"
        if addr in ("G", "M", "P") and key in calls:
            prog, modal = calls[key]
            args, i = _call_args(s, i, lineno)
            blk.call = (prog, args, modal)
            continue
        if addr == "M" and value in (2, 30):
            blk.ends = True
        if addr not in ("G", "M") and any(w.address == addr for w in blk.words):
            raise ParseError("CPL001", f"address {addr} twice in one block", lineno, col)
        blk.words.append(A.NcWord(addr, value, None))
    return blk


def _call_args(s: str, i: int, lineno: int) -> tuple[list, int]:
    n = len(s)
    while i < n and s[i] in " \t":
        i += 1
    if i < n and s[i] == "[":
        j = _close_bracket(s, i, lineno)
        bp = BlockParser(tokenize(s[i + 1:j], lineno, i + 1), lineno, None)
        args = bp.arg_list("]") if bp.peek() is not None else []
        if bp.peek() is not None:
            bp.error("CPL001", "',' expected between parameters")
        return args, j + 1
    return [], i


def _close_bracket(s: str, i: int, lineno: int) -> int:
    depth = 0
    in_str = False
    for j in range(i, len(s)):
        c = s[j]
        if c == '"':
            in_str = not in_str
        elif not in_str:
            if c == "[":
                depth += 1
            elif c == "]":
                depth -= 1
                if depth == 0:
                    return j
    raise ParseError("CPL001", "'[' not closed with ']'", lineno, i + 1)


def _nc_expr(text: str, lineno: int, offset: int):
    bp = BlockParser(tokenize(text, lineno, offset), lineno, None)
    if bp.peek() is None:
        raise ParseError("CPL001", "empty [ ]", lineno, offset)
    e = bp.expr()
    if bp.peek() is not None:
        bp.error("CPL001", "unexpected text in [ ]")
    return e


def parse_program(path: str, text: str, calls: dict | None = None) -> A.Program:
    """Parse a whole program; syntax errors are collected in ``Program.diagnostics``."""
    calls = calls or {}
    prog = A.Program(path)
    lines = classify(text)
    first = next((ln for ln in lines if ln.kind != "blank"), None)
    if first is not None and first.kind == "nc" and "(DIN)" in first.text.upper().replace(" ", ""):
        prog.din_only = True
    if first is not None and first.kind == "nc" and "(TYP2)" in first.text.upper().replace(" ", ""):
        prog.typ2 = True
    for kind, item in cpl_blocks(lines):
        if kind == "cpl":
            prog.has_cpl = True
            if item.number > LINE_MAX:
                prog.diagnostics.append(diag("CPL001", f"line number beyond {LINE_MAX}", path, item.lineno, 1))
                continue
            if item.error is not None:
                e = item.error
                prog.diagnostics.append(diag("CPL001", e.message, path, e.line, e.column, item.number))
                continue
            prog.lines.setdefault(item.number, []).append(len(prog.stmts))
            bp = BlockParser(item.tokens, item.lineno, item.number)
            start = len(prog.stmts)
            try:
                bp.parse(prog.stmts, prog)
            except ParseError as e:
                del prog.stmts[start:]
                prog.diagnostics.append(diag(e.code, e.detail, path, e.line, e.col, item.number))
                continue
            except RecursionError:  # the control's evaluation stack has a limit too (§2.5.1 L782-791)
                del prog.stmts[start:]
                prog.diagnostics.append(diag("2153", "expression nested too deeply", path, item.lineno,
                                             item.tokens[0].col if item.tokens else 1, item.number))
                continue
            block = prog.stmts[start:]
            for code, kind in (("CPL009", A.Wait), ("CPL014", A.CallStmt)):
                alone = next((s for s in block if isinstance(s, kind)), None)
                # WAIT: no ':' in its block (§4.1 L1201); CALL: a block of its own (§3 L1068, §3.3 L1087), so not
                # inside a one-line IF either (a label before it or a remark after it is no instruction)
                if alone is not None and (item.has_colon if kind is A.Wait else
                                          sum(not isinstance(s, A.LabelDef) for s in block) > 1):
                    prog.diagnostics.append(diag(code, "put the other statements in their own blocks", path,
                                                 alone.line, alone.col or None, item.number))
        else:
            try:
                blk = parse_nc(item.text, item.lineno, calls)
            except ParseError as e:
                prog.diagnostics.append(diag(e.code, e.detail, path, e.line, e.col))
                continue
            except LexError as e:  # inside an [expr] word
                prog.diagnostics.append(diag("CPL001", e.message, path, e.line, e.column))
                continue
            except RecursionError:
                prog.diagnostics.append(diag("2153", "expression nested too deeply", path, item.lineno, 1))
                continue
            if blk.n is not None:
                prog.nblocks.setdefault(blk.n, []).append(len(prog.stmts))
            if blk.words or blk.loose or blk.msg is not None or blk.wait or blk.call or blk.n is not None:
                prog.stmts.append(blk)
    return prog


__all__ = ["parse_program", "parse_nc", "ParseError", "VarName"]
