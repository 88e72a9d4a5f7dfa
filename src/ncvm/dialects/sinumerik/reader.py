"""Reading SINUMERIK 800 part programs: blocks of DIN words, R parameter words and @ code.

The canonical object text (ncvm's reading; the CL 800 manual is silent) is one NC block per line:
``[/][N<nnnn>] item {item}``, where an item is an @ instruction with its
operands (``@201 R13 P37``), an R arithmetic word (``R10=R50+R51``), a DIN
word (``G01``, ``X-1.5``, ``X=R91``, ``F=-R25``, ``Q1=25``, ``L=R20``) or a
note in parentheses. A leading ``%SPF<n>`` / ``%MPF<n>`` line names the
program. The reader only reads; it resolves nothing (that is codegen's job).
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from ...diagnostics import Diagnostic, Span
from ...nc.profiles.blockrules import g_conflict
from ...nc.profiles.sinumerik8xx import SINUMERIK8XX
from ...source import (
    ALNUM,
    LETTERS,
    WORD_DECADES,
    decades,
    int_literal,
    is_digits,
    lines,
    too_many_decades,
    word_number,
)
from .atcodes import AT_CODES
from .errors import ReadError


@dataclass(slots=True)
class Operand:
    """An @ code operand: K constant, R parameter, or P pointer (R parameter holding an R number)."""

    kind: str  # "K", "R" or "P"
    value: float  # the constant, or the R number


@dataclass(slots=True)
class AtInstr:
    code: str  # three lower-case hex digits, e.g. "201"
    operands: list[Operand]
    col: int


@dataclass(slots=True)
class Arith:
    """``R<target>=t0 op1 t1 op2 t2 ...`` evaluated left to right (ncvm's reading; the CL 800 manual is silent)."""

    target: int
    terms: list[tuple[str, Operand]]  # first op is "" or "-"
    col: int


@dataclass(slots=True)
class Word:
    """A DIN word. ``value`` is a number, or ``rref`` = (sign, R number) for ``X=R91``."""

    address: str
    value: float | None
    rref: tuple[float, int] | None
    col: int


@dataclass(slots=True)
class Note:
    text: str
    col: int


@dataclass(slots=True)
class NcBlock:
    line: int
    n: int | None
    skip: bool
    items: list = field(default_factory=list)


@dataclass(slots=True)
class PartProgram:
    path: str
    kind: str  # "MPF", "SPF" or "" (no header)
    number: int | None
    blocks: list[NcBlock]


_DIGITS = "0123456789"
_NUMCH = "0123456789."
_HEX = "0123456789abcdefABCDEF"


def read_program(path: str, text: str) -> tuple[PartProgram, list[Diagnostic]]:
    """All blocks of a part program, plus a diagnostic per block that cannot be read."""
    blocks: list[NcBlock] = []
    diags: list[Diagnostic] = []
    kind, number = "", None
    for lineno, raw in enumerate(lines(text), 1):
        line = raw.rstrip("\r\n\x1a")
        stripped = line.strip()
        if not stripped:
            continue
        if stripped.startswith("%"):
            head = stripped[1:].replace(" ", "").upper()
            if head[:3] in ("SPF", "MPF") and is_digits(head[3:]) and decades(head[3:]) <= WORD_DECADES:
                if not blocks and kind == "":
                    kind, number = head[:3], int(head[3:])
                    continue
            elif head == "":
                continue
            diags.append(Diagnostic("SIN001", f"cannot read program header '{stripped[:30]}' (expected %MPF<n> or "
                                              f"%SPF<n> on the first line)", Span(path, lineno, 1)))
            continue
        try:
            blocks.append(read_block(line, lineno))
        except ReadError as e:
            diags.append(Diagnostic(e.code, e.message, Span(path, lineno, e.col)))
    return PartProgram(path, kind, number, blocks), diags


#: a block of plain words only (``N10 G1 X-2.5 Y3 F1500``), the bulk of CAM output: read by regex (numbers
#: of at most WORD_DECADES digits before the point: a longer one is read the general way and refused there)
_PLAIN = re.compile(r"^[ \t]*(?:[Nn]([0-9]{1,8}+))?((?:[ \t]*[A-QS-Za-qs-z][+-]?(?:[0-9]{1,8}+(?:\.[0-9]*+)?+|\.[0-9]+))*)"
                    r"[ \t]*$")
_PLAIN_WORD = re.compile(r"([A-Za-z])([+-]?(?:[0-9]+\.?[0-9]*|\.[0-9]+))")


def read_block(line: str, lineno: int) -> NcBlock:
    m = _PLAIN.match(line)
    if m is not None:
        blk = NcBlock(lineno, int(m.group(1)) if m.group(1) else None, False)
        blk.items = [Word(w.group(1).upper(), float(w.group(2)), None, w.start() + 1)
                     for w in _PLAIN_WORD.finditer(line, m.start(2))]
        _refuse_repeated(blk.items)
        return blk
    s = line
    n = len(s)
    i = 0
    while i < n and s[i] in " \t":
        i += 1
    skip = False
    if i < n and s[i] == "/":
        skip = True
        i += 1
    blk = NcBlock(lineno, None, skip)
    items = blk.items
    first = True
    run_end = 0
    while True:
        while i < n and s[i] in " \t":
            i += 1
        if i >= n:
            break
        c = s[i]
        col = i + 1
        if c == "(":
            j = s.find(")", i)
            if j < 0:
                raise ReadError(col, "note not closed with ')'")
            items.append(Note(s[i + 1:j].strip(), col))
            i = j + 1
        elif c == ";":
            break  # rest of the line is a remark
        elif c == "@":
            i = _read_at(s, i, items)
        elif c in LETTERS:
            letter = c.upper()
            j = i + 1
            if letter == "N" and first and j < n and s[j] in _DIGITS:
                k = j
                while k < n and s[k] in _DIGITS:
                    k += 1
                if decades(s[j:k]) > WORD_DECADES:
                    raise ReadError(col, too_many_decades("N"))
                blk.n = int(s[j:k])
                i = k
            elif letter == "R" and j < n and s[j] in _DIGITS:
                i = _read_arith(s, i, items)
            else:
                if i >= run_end:  # the end of this run of letters and digits, found once per run
                    run_end = i + 1
                    while run_end < n and s[run_end] in ALNUM:
                        run_end += 1
                i = _read_word(s, i, items, run_end)
        else:
            raise ReadError(col, f"cannot read '{s[i:i + 20].strip()}'")
        first = False
    bare = [w for w in items if isinstance(w, Word) and w.value is None and w.rref is None]
    if bare and not any(isinstance(w, Word) and w.address == "G" and w.value == 16 for w in items):
        raise ReadError(bare[0].col, f"address {bare[0].address.rstrip('-')} without a value")
    _refuse_repeated(items)
    return blk


#: the addresses a block may hold more than once: G words (each of its own group), M words, and H words
#: (each goes to the PLC, in the block's order)
REPEATABLE = frozenset("GMH")


def _refuse_repeated(items: list) -> None:
    """SIN001 at the second word of an address the block holds twice (``G1 X10 X20``): the control keeps
    one value per address, so the second would silently replace the first (docs/decisions.md); and at the
    second of two G functions of one G group (``G90 G91``: nc/profiles/blockrules.py)."""
    seen = set()
    for it in items:
        if it.__class__ is Word and it.address not in REPEATABLE:
            if it.address in seen:
                raise ReadError(it.col, f"address {it.address.rstrip('-')} twice in one block")
            seen.add(it.address)
    g_words = [it for it in items if it.__class__ is Word and it.address == "G" and it.value is not None]
    both = g_conflict(SINUMERIK8XX, [w.value for w in g_words]) if len(g_words) > 1 else None
    if both is not None:  # CL 800 §11.5 L7392-7410: one function of each internal G group is active
        raise ReadError(next(w.col for w in reversed(g_words) if w.value == both[1]), both[0])


def _number(s: str, i: int, address: str) -> tuple[float, int]:
    """A signed decimal number starting at ``i``, the value of ``address`` (for the message)."""
    n = len(s)
    j = i
    if j < n and s[j] in "+-":
        j += 1
    k = j
    while k < n and s[k] in _NUMCH:
        k += 1
    text = s[j:k]
    if not text or text == "." or text.count(".") > 1:
        raise ReadError(i + 1, f"number expected at '{s[i:i + 12].strip()}'")
    v = word_number(text)
    if v is None:
        raise ReadError(i + 1, too_many_decades(address))
    return (-v if s[i] == "-" else v), k


def _read_at(s: str, i: int, items: list) -> int:
    col = i + 1
    code = s[i + 1:i + 4].lower()
    if len(code) < 3 or any(ch not in _HEX for ch in code):
        raise ReadError(col, f"'{s[i:i + 4]}' is not an @ code (three hexadecimal digits)", "SIN002")
    spec = AT_CODES.get(code)
    if spec is None:
        raise ReadError(col, f"@{code} is not an @ code of the SINUMERIK 800", "SIN002")
    i += 4
    ops: list[Operand] = []
    n = len(s)
    want = spec.count
    while True:
        j = i
        while j < n and s[j] in " \t":
            j += 1
        if j >= n or s[j].upper() not in "KRP":
            break
        if want is not None and len(ops) >= want:
            break
        if code == "111" and s[j].upper() == "R" and len(ops) % 2 == 1 and _is_arith(s, j):
            break
        kind = s[j].upper()
        if kind == "K":
            v, k = _number(s, j + 1, f"@{code} K")
        else:
            k = j + 1
            while k < n and s[k] in _DIGITS:
                k += 1
            if k == j + 1:
                raise ReadError(j + 1, f"@{code}: R number expected after {kind}", "SIN003")
            if k < n and s[k] == "=":  # an R arithmetic word follows, not an operand
                break
            v = float(_r_number(s, j, k))
        ops.append(Operand(kind, v))
        i = k
        if want is None and code in ("040", "042") and len(ops) == 1:
            want = 1 + int(v)
    spec.check(ops, col)
    items.append(AtInstr(code, ops, col))
    return i


def _r_number(s: str, j: int, k: int) -> int:
    """The number of the R parameter written as R (or P) at ``j`` with digits up to ``k``: R0 to R999."""
    number = int_literal(s[j + 1:k], 1000)
    if number > 999:
        raise ReadError(j + 1, f"{s[j:min(k, j + 13)]}{'...' if k > j + 13 else ''}: the R parameters are R0 to R999")
    return number


def _is_arith(s: str, j: int) -> bool:
    k = j + 1
    while k < len(s) and s[k] in _DIGITS:
        k += 1
    return k < len(s) and s[k] == "="


def _read_arith(s: str, i: int, items: list) -> int:
    col = i + 1
    n = len(s)
    k = i + 1
    while k < n and s[k] in _DIGITS:
        k += 1
    target = _r_number(s, i, k)
    while k < n and s[k] in " \t":
        k += 1
    if k >= n or s[k] != "=":
        raise ReadError(col, f"R{target}: '=' expected (R parameter word R{target}=...)")
    k += 1
    terms: list[tuple[str, Operand]] = []
    op = ""
    while True:
        while k < n and s[k] in " \t":
            k += 1
        if not terms and k < n and s[k] in "+-":
            op = "-" if s[k] == "-" else ""
            k += 1
        if k < n and s[k] in "Rr" and k + 1 < n and s[k + 1] in _DIGITS:
            m = k + 1
            while m < n and s[m] in _DIGITS:
                m += 1
            terms.append((op, Operand("R", float(_r_number(s, k, m)))))
            k = m
        elif k < n and s[k] in _NUMCH:
            v, k = _number(s, k, f"R{target}=")
            terms.append((op, Operand("K", v)))
        else:
            raise ReadError(k + 1, f"R{target}=: R parameter or number expected")
        m = k
        while m < n and s[m] in " \t":
            m += 1
        if m < n and s[m] in "+-*/":
            # an operator continues the chain; a signed number after a blank is the next word only
            # when what follows cannot be an operand (never the case here)
            op = s[m]
            k = m + 1
            continue
        break
    items.append(Arith(target, terms, col))
    return k


def _read_word(s: str, i: int, items: list, m: int) -> int:
    """The word at ``s[i]``; ``m`` is the end of the run of letters and digits it starts in (scanned
    once by the caller: scanning it per letter made a line of 80,000 letters take minutes)."""
    col = i + 1
    n = len(s)
    letter = s[i].upper()
    k = i + 1
    # extended address: letters/digits followed by '=' (Q1=25); plain: one letter and a number
    address = letter
    if k < m < n and s[m] == "=":
        address = (letter + s[k:m]).upper()
        k = m
    if k < n and s[k] == "=":
        k += 1
        sign = 1.0
        if k < n and s[k] in "+-":
            sign = -1.0 if s[k] == "-" else 1.0
            k += 1
        if k < n and s[k] in "Rr" and k + 1 < n and s[k + 1] in _DIGITS:
            m = k + 1
            while m < n and s[m] in _DIGITS:
                m += 1
            items.append(Word(address, None, (sign, _r_number(s, k, m)), col))
            return m
        v, k = _number(s, k, address)
        items.append(Word(address, sign * v, None, col))
        return k
    if k < n and (s[k] in _NUMCH or (s[k] in "+-" and k + 1 < n and s[k + 1] in _NUMCH)):
        v, k = _number(s, k, address)
        items.append(Word(address, v, None, col))
        return k
    # an address letter alone: only the G16 axis list uses it (G16 X Y Z-)
    if k < n and s[k] == "-":
        k += 1
        address += "-"  # G16 Z-: length compensation in the minus direction
    items.append(Word(address, None, None, col))
    return k
