"""CL 800 -> @ code (manual §10).

The object program is text: ``%SPF<n>``, then one NC block per line. Control
structures become @1gx jumps to 4-digit block numbers ``N = 1000*T + 100*L + s``
(T = construct type, L = nesting depth, s = counter per (T, L)). Expressions are
split into single-precedence R arithmetic words and @6xx/@3xx instructions,
using undeclared R50..R99 from R99 down as temporaries. Locals and temporaries
are pushed in the first block and popped in the last, before ``M17``.
"""

from __future__ import annotations

import re
import zlib
from dataclasses import dataclass, field

from . import ast
from .checker import Symbols
from .errors import CompilerMessage
from .lexer import norm
from .tables import FUNCTIONS, LOGIC, NC_FUNCTIONS, PROCEDURES, RELOPS, SYS_READS, SYS_WRITES

MAX_BLOCK = 120  # characters per NC block (L1008, S064)
TEMP_RANGE = range(99, 49, -1)
#: construct -> type digit of its block numbers (subgroup of its @1gx code; 7 for GOTO labels)
TYPE_DIGIT = {"CASE": 1, "IF": 2, "WHILE": 3, "REPEAT": 4, "FOR": 5, "DOWNTO": 6, "LABEL": 7, "IFINT": 8,
              "WHILEINT": 9}


@dataclass
class Block:
    number: int | None
    items: list = field(default_factory=list)  # (text, source line)
    line: int = 0

    def text(self) -> str:
        words = ([f"N{self.number}"] if self.number is not None else []) + [t for t, _ in self.items]
        return " ".join(words)

    @property
    def source_line(self) -> int:
        return self.items[0][1] if self.items else self.line


#: the note (a "(Text)" block, L6401) that ends the last line of every file ncvm writes (object program and
#: listing), after M17 (so the header, ESS's @00f in the first block and every block's line stay where they
#: are). The line is ``(CRC32 <8 hex digits>) (COMPILED BY NCVM)``: the CRC-32 of the text above it, so that a
#: later ``compile`` replaces a file only as ncvm wrote it, never one written or edited by hand since
MARK = "(COMPILED BY NCVM)"
_MARK_LINE = re.compile(r"\(CRC32 ([0-9A-F]{8})\) " + re.escape(MARK))


def _crc(text: str) -> str:
    return f"{zlib.crc32(text.replace(chr(13) + chr(10), chr(10)).encode('latin-1', 'replace')):08X}"


def marked(text: str) -> str:
    """File text with the mark line (the checksum of ``text`` and the :data:`MARK` note) as its last line."""
    return f"{text}(CRC32 {_crc(text)}) {MARK}\n"


def written_by_ncvm(text: str) -> bool:
    """Whether a file ends with the mark line and is, above it, what ncvm wrote (its checksum holds)."""
    body, _, last = text.rstrip().rpartition("\n")
    found = _MARK_LINE.fullmatch(last.strip())
    return bool(found) and found.group(1) == _crc(body + "\n")


@dataclass
class ObjectProgram:
    number: int
    header_line: int
    blocks: list

    def text(self) -> str:
        return "\n".join([f"%SPF{self.number}"] + [b.text() for b in self.blocks]) + "\n"

    def file_text(self) -> str:
        """The object program as ``compile`` writes it: with the :data:`MARK` note after the last block."""
        return marked(self.text())

    def xref(self) -> str:
        """The cross-reference listing (L355-365): every statement's object code under the number of its
        source line; a statement that starts an NC block begins at column 7, one that continues the block
        is indented by two more."""
        lines = [f"{self.header_line:5d} %SPF{self.number}"]
        for b in self.blocks:
            groups: list[tuple[int, list[str]]] = []
            for text, src in b.items:
                if groups and groups[-1][0] == src:
                    groups[-1][1].append(text)
                else:
                    groups.append((src, [text]))
            if b.number is not None:
                if groups:
                    groups[0][1].insert(0, f"N{b.number}")
                else:
                    groups.append((b.line, [f"N{b.number}"]))
            lines += [f"{src:5d} {'  ' * (k > 0)}{' '.join(words)}" for k, (src, words) in enumerate(groups)]
        return "\n".join(lines) + "\n"

    def executed_line(self, line: int) -> int:
        """The source line of the last statement of the block at object ``line``: the block runs when it
        is complete, so its motion, M0 and limits are reported there, not at an assignment before."""
        if line <= 1 or line - 2 >= len(self.blocks):
            return self.header_line
        blk = self.blocks[line - 2]
        return blk.items[-1][1] if blk.items else blk.line

    def source_line(self, line: int, column: int | None = None) -> int:
        """The source line of the statement that produced the object text at ``line`` (1: the ``%SPF``
        header), ``column``: the statement whose words stand there (None: the block's first)."""
        if line <= 1 or line - 2 >= len(self.blocks):
            return self.header_line
        blk = self.blocks[line - 2]
        if column is None:
            return blk.source_line
        at = len(f"N{blk.number} ") + 1 if blk.number is not None else 1
        found = blk.source_line
        for text, src in blk.items:
            if column < at:
                break
            found = src
            at += len(text) + 1
        return found


def fmt_number(v) -> str:
    """A constant as the NC reads it: no '+', no trailing zeros or '.' (ncvm's reading; the CL 800 manual is silent)."""
    if isinstance(v, int) or float(v).is_integer():
        return str(int(v))
    s = f"{v:.8f}".rstrip("0").rstrip(".")
    return "0" if s in ("-0", "") else s


class Compiler:
    def __init__(self, path: str, prog: ast.Program, sym: Symbols, push: list[int] | None = None):
        self.path, self.prog, self.sym = path, prog, sym
        self.blocks: list[Block] = []
        self.cur: Block | None = None
        self.line = prog.begin_line
        self.counters: dict[tuple[int, int], int] = {}
        self.in_use: list[int] = []
        self.reserved: list[int] = []
        self.temps_used: set[int] = set()
        self.push = push
        self.label_numbers = {key: 7000 + i + 1 for i, key in enumerate(prog.labels)}
        self.label_lines: dict[str, int] = {}
        self.stmt_index = 0
        self.label_index: dict[str, int] = {}

    # -- blocks --------------------------------------------------------------
    def err(self, code: str, line: int, detail: str = "") -> CompilerMessage:
        return CompilerMessage(code, self.path, line, None, detail)

    def emit(self, text: str, line: int | None = None) -> None:
        line = self.line if line is None else line
        if len(text) > MAX_BLOCK:
            raise self.err("S064", line, text[:20] + "...")
        if self.cur is None:
            self.cur = Block(None, line=line)
            self.blocks.append(self.cur)
        elif len(self.cur.text()) + 1 + len(text) > MAX_BLOCK:
            self.cur = Block(None, line=line)
            self.blocks.append(self.cur)
        self.cur.items.append((text, line))

    def end_block(self) -> None:
        self.cur = None

    def numbered(self, n: int, line: int | None = None) -> None:
        self.cur = Block(n, line=self.line if line is None else line)
        self.blocks.append(self.cur)

    def allocate(self, kind: str, depth: int, line: int) -> int:
        t = TYPE_DIGIT[kind]
        s = self.counters.get((t, depth), 0) + 1
        if s > 99:
            raise self.err("S120", line)
        self.counters[(t, depth)] = s
        return 1000 * t + 100 * depth + s

    # -- temporaries -----------------------------------------------------------
    def temp(self, cause: str = "S125") -> str:
        for r in TEMP_RANGE:
            if r not in self.sym.by_r and r not in self.in_use and r not in self.reserved:
                self.in_use.append(r)
                self.temps_used.add(r)
                return f"R{r}"
        raise self.err(cause, self.line)

    # -- operands ----------------------------------------------------------------
    @staticmethod
    def leaf(e) -> str | None:
        if isinstance(e, ast.Num):
            return "K" + fmt_number(e.value)
        if isinstance(e, ast.Operand):
            return f"{'P' if e.pointer else 'R'}{e.reg}"
        return None

    def value(self, e, cause: str = "S125") -> str:
        """A <Value> operand: K, R or P; anything else goes through a temporary."""
        lf = self.leaf(e)
        if lf is not None:
            return lf
        t = self.temp(self.cause_of(e, cause))
        self.into(t, e)
        return t

    def var(self, e, cause: str = "S125") -> str:
        """A <Var> operand: R or P; constants are loaded into a temporary."""
        if isinstance(e, ast.Operand):
            return self.leaf(e)
        t = self.temp(self.cause_of(e, cause))
        self.into(t, e)
        return t

    @staticmethod
    def cause_of(e, default: str) -> str:
        if isinstance(e, ast.Call):
            return "S127"
        return default

    def rterm(self, e, cause: str) -> str:
        """An operand of an R arithmetic word: a number or R<n> (pointers go through a temporary)."""
        if isinstance(e, ast.Num) and e.value >= 0:
            return fmt_number(e.value)
        if isinstance(e, ast.Operand) and not e.pointer:
            return f"R{e.reg}"
        t = self.temp(self.cause_of(e, cause))
        self.into(t, e)
        return t

    # -- expressions -------------------------------------------------------------
    def into(self, target: str, e) -> None:
        """Emit code that leaves the value of ``e`` in ``target`` (R<n> or P<n>)."""
        lf = self.leaf(e)
        if lf is not None:
            self.emit(f"@201 {target} {lf}")
            return
        if isinstance(e, ast.Binary) and e.op in ("+", "-", "*", "/") or isinstance(e, ast.Unary) and e.op == "-":
            if target.startswith("P"):
                t = self.temp()
                self.into(t, e)
                self.emit(f"@201 {target} {t}")
                return
            self.emit(f"{target}={self.chain(e)}")
            return
        if isinstance(e, ast.Call):
            if e.name in FUNCTIONS:
                args = [self.value(a, "S127") for a in e.args]
                self.emit(" ".join([f"@{FUNCTIONS[e.name][0]}", target] + args))
            else:
                args = [self.value(a, "S127") for a in e.args]
                self.emit(" ".join([f"@{SYS_READS[e.name][0]}", target] + args))
            return
        if isinstance(e, ast.Bit):
            self.emit(f"@203 {target} {self.leaf(e.var)} K{e.bit}")
            return
        if isinstance(e, ast.Unary):
            code = "654" if e.op == "NOT" else "659"
            self.emit(f"@{code} {target} {self.value(e.expr)}")
            return
        if isinstance(e, ast.Binary) and e.op in LOGIC:
            a = self.var(e.left)
            b = self.value(e.right)
            self.emit(f"@{LOGIC[e.op]} {target} {a} {b}")
            return
        if isinstance(e, ast.Binary) and e.op in RELOPS:
            a = self.var(e.left)
            b = self.value(e.right)
            self.emit(f"@67{RELOPS[e.op]} {target} {a} {b}")
            return
        raise self.err("E061", getattr(e, "line", self.line), "expression cannot be compiled")

    def chain(self, e) -> str:
        """One R arithmetic word's right-hand side: a chain of one precedence level (ncvm's reading; the CL 800 manual is silent)."""
        level = ("*", "/") if isinstance(e, ast.Binary) and e.op in ("*", "/") else ("+", "-")
        elems: list = []
        node = e
        while isinstance(node, ast.Binary) and node.op in level:
            elems.append((node.op, node.right))
            node = node.left
        elems.append(("", node))
        elems.reverse()
        cause = "S126" if level == ("+", "-") else "S125"
        out = []
        for i, (op, el) in enumerate(elems):
            if i == 0 and isinstance(el, ast.Unary) and el.op == "-":
                out.append("-" + self.rterm(el.expr, cause))
            elif i == 0 and isinstance(el, ast.Num) and el.value < 0:
                out.append(fmt_number(el.value))
            else:
                out.append(op + self.rterm(el, cause))
        return "".join(out)

    # -- conditions ----------------------------------------------------------------
    def condition(self, group: int, cond, target: int, backward: bool = False) -> None:
        k = f"K-{target}" if backward else f"K{target}"
        if isinstance(cond, ast.Binary) and cond.op in RELOPS:
            a = self.var(cond.left)
            b = self.value(cond.right)
            self.emit(f"@1{group}{RELOPS[cond.op]} {a} {b} {k}")
        elif isinstance(cond, ast.Operand):
            self.emit(f"@1{group}1 {self.leaf(cond)} K1 {k}")
        else:
            t = self.temp()
            self.into(t, cond)
            self.emit(f"@1{group}1 {t} K1 {k}")

    def free(self, mark: int) -> None:
        del self.in_use[mark:]

    # -- statements -------------------------------------------------------------------
    def compile(self) -> ObjectProgram:
        prog = self.prog
        self.number_statements(prog.body)
        self.line = prog.begin_line
        ess = prog.ess or any(isinstance(s, ast.Proc) and s.name == "ESS" for s in prog.body)
        if ess:
            self.emit("@00f")
        push = self.push or []
        for chunk in push_chunks(push):
            self.emit(push_code(True, chunk), prog.begin_line)
        first = self.cur
        for i, st in enumerate(prog.body):
            self.stmt_index = i
            self.statement(st)
        self.line = prog.end_line
        if first is not None and self.cur is first and push:
            self.end_block()  # the push and the pop of a program never share a block
        for chunk in reversed(push_chunks(push)):  # the stack gives back the last push first
            self.emit(push_code(False, chunk), prog.end_line)
        self.emit("M17", prog.end_line)
        return ObjectProgram(prog.number, prog.line, self.blocks)

    def number_statements(self, body: list) -> None:
        """Source order index of top-level statements, to tell forward from backward GOTOs."""
        for i, st in enumerate(body):
            if st.label:
                self.label_index[norm(st.label)] = i

    def statements(self, body: list) -> None:
        for st in body:
            self.statement(st)

    def statement(self, st) -> None:
        self.line = st.line
        mark = len(self.in_use)
        if st.label:
            key = norm(st.label)
            self.numbered(self.label_numbers[key], st.line)
        if isinstance(st, ast.Assign):
            self.assign(st)
        elif isinstance(st, ast.SysWrite):
            args = [self.value(a) for a in st.args]
            val = self.value(st.value)
            self.emit(" ".join([f"@{SYS_WRITES[st.name][0]}"] + args + [val]))
        elif isinstance(st, ast.Proc):
            self.procedure(st)
        elif isinstance(st, ast.Din):
            if st.text:
                self.emit(st.text)
        elif isinstance(st, ast.Lf):
            self.end_block()
        elif isinstance(st, ast.Compound):
            self.statements(st.body)
        elif isinstance(st, ast.If):
            self.if_stmt(st)
        elif isinstance(st, ast.IfInt):
            self.if_int(st)
        elif isinstance(st, ast.While):
            self.while_loop("WHILE", st, mark, lambda cont: self.condition(3, st.cond, cont))
        elif isinstance(st, ast.WhileInt):
            code = "198" if st.negated else "197"
            self.while_loop("WHILEINT", st, mark, lambda cont: self.emit(
                f"@{code} {self.value(st.byte)} {self.value(st.bit)} K{cont}"))
        elif isinstance(st, ast.Repeat):
            start = self.allocate("REPEAT", st.depth, st.line)
            cont = self.allocate("REPEAT", st.depth, st.line)
            self.numbered(start)
            self.statements(st.body)
            self.line = st.until_line
            mark = len(self.in_use)
            self.condition(4, st.cond, start, backward=True)
            self.free(mark)
            self.numbered(cont, st.until_line)
        elif isinstance(st, ast.For):
            self.for_stmt(st)
        elif isinstance(st, ast.Case):
            self.case_stmt(st)
        elif isinstance(st, ast.Goto):
            key = norm(st.target)
            n = self.label_numbers[key]
            backward = self.label_index.get(key, 1 << 30) <= self.stmt_index
            self.emit(f"@100 K-{n}" if backward else f"@100 K{n}")
        self.free(mark)

    def assign(self, st: ast.Assign) -> None:
        target = self.leaf(st.target)
        e = st.expr
        if isinstance(e, ast.Call) and e.name in NC_FUNCTIONS:
            code, kinds, _n = NC_FUNCTIONS[e.name]
            args = [self.leaf(a) if k == "v" else self.value(a) for k, a in zip(kinds, e.args)]
            self.emit(" ".join([f"@{code}", target] + args))
            return
        self.into(target, e)

    def procedure(self, st: ast.Proc) -> None:
        if st.name == "ESS":
            return
        code, kinds = PROCEDURES[st.name]
        ops = []
        for k, a in zip(kinds, st.args):
            if k == "v":
                ops.append(self.leaf(a))
            elif k == "b":
                ops += [self.leaf(a.var), f"K{a.bit}"]
            else:
                ops.append(self.value(a))
        self.emit(" ".join([f"@{code}"] + ops))

    def while_loop(self, kind: str, st, mark: int, exit_test) -> None:
        """WHILE and WHILE INT: the start block, ``exit_test(cont)`` jumping past the loop, the body, the jump
        back, the block after the loop."""
        start = self.allocate(kind, st.depth, st.line)
        cont = self.allocate(kind, st.depth, st.line)
        self.numbered(start)
        exit_test(cont)
        self.free(mark)
        self.statements(st.body)
        self.emit(f"@100 K-{start}", st.line)
        self.numbered(cont, st.line)

    def if_stmt(self, st: ast.If) -> None:
        other = self.allocate("IF", st.depth, st.line) if st.orelse is not None else None
        cont = self.allocate("IF", st.depth, st.line)
        mark = len(self.in_use)
        self.condition(2, st.cond, other or cont)
        self.free(mark)
        self.branches(st, other, cont)

    def if_int(self, st: ast.IfInt) -> None:
        other = self.allocate("IFINT", st.depth, st.line) if st.orelse is not None else None
        cont = self.allocate("IFINT", st.depth, st.line)
        mark = len(self.in_use)
        code = "188" if st.negated else "187"
        self.emit(f"@{code} {self.value(st.byte)} {self.value(st.bit)} K{other or cont}")
        self.free(mark)
        self.branches(st, other, cont)

    def branches(self, st, other: int | None, cont: int) -> None:
        self.statements(st.then)
        if other is not None:
            self.emit(f"@100 K{cont}", st.line)
            self.numbered(other, st.line)
            self.statements(st.orelse)
        self.numbered(cont, st.line)

    def for_stmt(self, st: ast.For) -> None:
        kind = "DOWNTO" if st.down else "FOR"
        start = self.allocate(kind, st.depth, st.line)
        cont = self.allocate(kind, st.depth, st.line)
        v = self.leaf(st.var)
        mark = len(self.in_use)
        self.into(v, st.start)
        self.free(mark)
        stop = self.leaf(st.stop)
        reserved = None
        if stop is None:
            stop = self.temp()
            self.into(stop, st.stop)
            reserved = int(stop[1:])
            self.free(mark)
            self.reserved.append(reserved)
        self.numbered(start)
        self.emit(f"@{'161' if st.down else '151'} {v} {stop} K{cont}")
        self.statements(st.body)
        self.emit(f"@{'621' if st.down else '620'} {v}", st.line)
        self.emit(f"@100 K-{start}", st.line)
        if reserved is not None:
            self.reserved.remove(reserved)
        self.numbered(cont, st.line)

    def case_stmt(self, st: ast.Case) -> None:
        alts = [self.allocate("CASE", st.depth, st.line) for _ in st.alts]
        other = self.allocate("CASE", st.depth, st.line) if st.otherwise is not None else None
        cont = self.allocate("CASE", st.depth, st.line)
        v = self.leaf(st.var)
        pairs = [f"{self.leaf(val)} K{n}" for (val, _b, _l), n in zip(st.alts, alts)]
        item = f"@111 {v}"
        for p in pairs:
            if len(item) + 1 + len(p) > MAX_BLOCK:
                self.emit(item)
                item = f"@111 {v}"
            item += " " + p
        self.emit(item)
        self.emit(f"@100 K{other or cont}")
        for (_val, body, line), n in zip(st.alts, alts):
            self.numbered(n, line)
            self.statements(body)
            self.emit(f"@100 K{cont}", line)
        if other is not None:
            self.numbered(other, st.line)
            self.statements(st.otherwise)
        self.numbered(cont, st.end_line or st.line)


def push_code(push: bool, regs: list[int]) -> str:
    """@041/@043 Ra Rb for one contiguous range of 2 or more, else @040/@042 Kn R... (CL 800 manual L6386-6413; L461-463; L1222-1226)."""
    regs = sorted(regs)
    if len(regs) > 1 and regs[-1] - regs[0] == len(regs) - 1:
        return f"@{'041' if push else '043'} R{regs[0]} R{regs[-1]}"
    return f"@{'040' if push else '042'} K{len(regs)} " + " ".join(f"R{r}" for r in regs)


def push_chunks(regs: list[int]) -> list[list[int]]:
    """The push set as one instruction, or split into several when one would not fit a block.

    Many locals and temporaries that are no single range would make an @040 longer than an NC
    block (S064) although the program is valid; successive pushes save the same registers.
    """
    regs = sorted(regs)
    if not regs or len(push_code(True, regs)) <= MAX_BLOCK:
        return [regs] if regs else []
    runs: list[list[int]] = []
    for r in regs:
        if runs and r == runs[-1][-1] + 1:
            runs[-1].append(r)
        else:
            runs.append([r])
    chunks = [run for run in runs if len(run) > 1]  # each range one @041
    singles: list[list[int]] = []
    for [r] in (run for run in runs if len(run) == 1):  # the others listed in @040s that fit a block
        if singles and len(push_code(True, [*singles[-1], r])) <= MAX_BLOCK:
            singles[-1].append(r)
        else:
            singles.append([r])
    return sorted(chunks + singles)


def compile_program(path: str, prog: ast.Program, sym: Symbols) -> ObjectProgram:
    """Two passes: the first finds the temporaries, the second emits with the full push set."""
    probe = Compiler(path, prog, sym, push=sorted(sym.locals))
    probe.compile()
    push = sorted(sym.locals | probe.temps_used)
    return Compiler(path, prog, sym, push=push).compile()
