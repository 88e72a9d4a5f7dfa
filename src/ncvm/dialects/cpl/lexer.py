"""CPL lines and tokens: which physical line is a CPL block, an NC block or a continuation (CPL manual §2.1.1-2.1.2, L345-406),
and the tokens of a CPL block (CPL manual §2.4, L429-737).

A line whose first non-blank character is a digit is a CPL block (the digits are its line number); a line
after a CPL block that ended in ``:`` outside a REM continues that block; every other line is an NC block.
Keywords and names are case-insensitive; a keyword with a type suffix (``STEP%``, ``END%``) is a variable.
"""

from __future__ import annotations

from dataclasses import dataclass

from ...records import Record
from ...source import DIGITS, LETTERS, NAME_CHARS, int_literal, lines, upper

#: reserved words (manual §2.4.1, L435-455, its OCR-damaged table cleaned up), plus TO, SCSL and the unused ones
KEYWORDS = frozenset("""
ABS ACOS AND APOS ASC ASIN ATAN AXO AXP BCD BIN BMP CALL CASE CHR$ CIR CLG CLOCK CLOSE CLR CLS COF COL COM COS
CPOS CPROBE CSF DATE DIM DLF DLG DO DPC DSP ELSE END ENDCASE ENDDLG ENDIF EOF ERASE FALSE FIL FILEACCESS FILEDATE
FILEPOS FILESIZE FIX FIXB FIXE FOR FXC FXCR FXDEL FXINS GETERR GMD GOTO GPR GWD IC IF INKEY INP INP# INSTR INT
LABEL LEN LIN LJUST MCA MCODS MCOPS MIC MID$ MMC MPOS MWD NCF NEXT NJUST NOT NUL OF OPENR OPENW OR OTHERWISE PDIM
PLC PPOS PRN PRN# PROBE REM REPEAT REWRITE RGB ROUND SCL SCS SCSL SD SDR SEEK SFK SIN SPOS SQRT STEP STR$ TAN TC
TD TDA TDR TFO THEN TIME TRIM$ TRUE TXT$ UNTIL VAL WAIT WHILE WPOS XOR TO
""".split())

SUFFIXES = "%!?$"
TYPE_OF_SUFFIX = {"%": "I", "": "R", "!": "D", "?": "B", "$": "S"}
OPS2 = ("<>", "<=", ">=")
OPS1 = "+-*/=<>(),[];:"


#: the largest DOUBLE (64 bit, manual §2.4.3): a number constant beyond it cannot be held
DOUBLE_MAX = 1.7976931348623157e308
#: a CPL line number is an INTEGER: 1 to 2147483647 (CPL manual §2.1.2, L373-406)
LINE_MAX = 2147483647
#: the highest sub-program parameter ncvm reads (the manual sets none; docs/decisions.md)
MAX_PARAM = 999
#: above DOUBLE_MAX: a longer integer constant keeps this value and gets the range error
CEILING = 10 ** 309


class LexError(Exception):
    def __init__(self, line: int, column: int, message: str):
        self.line = line
        self.column = column
        self.message = message


class Tok(Record):
    __slots__ = ("kind", "val", "line", "col", "text")

    def __init__(self, kind: str, val: object, line: int, col: int, text: str = ""):
        self.kind = kind  # num str kw var label op name
        self.val = val
        self.line = line
        self.col = col
        self.text = text


@dataclass(frozen=True, slots=True)
class VarName:
    """A variable as the program names it: class, significant name, type suffix."""

    cls: str  # L local, G global #, P numbered permanent @n, R @_R field, D definable @NAME, A parameter Pn
    name: str  # significant name without suffix (for P/A the number as text)
    suffix: str = ""

    @property
    def type(self) -> str:
        if self.cls == "P":
            return "I"
        if self.cls == "R":
            return "D"
        return TYPE_OF_SUFFIX[self.suffix]

    @property
    def display(self) -> str:
        if self.cls == "G":
            return f"#{self.name}{self.suffix}"
        if self.cls == "P":
            return f"@{self.name}"
        if self.cls == "R":
            return "@_R"
        if self.cls == "D":
            return f"@{self.name}{self.suffix}"
        if self.cls == "A":
            return f"P{self.name}{self.suffix}"
        return f"{self.name}{self.suffix}"


class Line(Record):
    """One physical line of the program, classified."""

    __slots__ = ("kind", "number", "text", "offset", "lineno")

    def __init__(self, kind: str, number: int | None, text: str, offset: int, lineno: int):
        self.kind = kind  # "cpl", "cont" (continuation of a CPL block), "nc", "blank"
        self.number = number  # CPL line number
        self.text = text  # the text after the line number (CPL) or the whole line (NC)
        self.offset = offset  # column offset of ``text`` in the physical line (0-based)
        self.lineno = lineno  # physical line, 1-based


class CplBlock(Record):
    """One CPL block: its line number and tokens over one or more physical lines (continuations)."""

    __slots__ = ("number", "lineno", "tokens", "lines", "has_colon", "error")

    def __init__(self, number: int, lineno: int, tokens: list[Tok] | None = None, lines: list[int] | None = None,
                 has_colon: bool = False, error: LexError | None = None):
        self.number = number
        self.lineno = lineno
        self.tokens = [] if tokens is None else tokens
        self.lines = [] if lines is None else lines
        self.has_colon = has_colon
        self.error = error  # the first lexical error in one of its lines (the block is not parsed)


#: the control's end-of-file marker: every file it keeps ends with ETX LF after the last record (manual §6.1.2
#: L3867), so does a program CPL wrote itself with PRN# (L4003, L4057)
ETX = "\x03"


def classify(text: str) -> list[Line]:
    """The lines of a program up to the end-of-file marker: a line starting with ETX ends the usable data
    (L3867); what follows it is not part of the program."""
    out: list[Line] = []
    cont = False
    for i, raw in enumerate(lines(text), 1):
        line = raw.rstrip("\r\n")
        if line.startswith(ETX):
            break
        stripped = line.strip()
        if not stripped:
            out.append(Line("blank", None, "", 0, i))
            cont = False if not cont else cont
            continue
        if cont:
            out.append(Line("cont", None, line, 0, i))
            cont = _ends_with_colon(line)
            continue
        lead = len(line) - len(line.lstrip())
        if stripped[0] in DIGITS:
            j = lead
            while j < len(line) and line[j] in DIGITS:
                j += 1
            out.append(Line("cpl", int_literal(line[lead:j], LINE_MAX + 1), line[j:], j, i))
            cont = _ends_with_colon(line[j:])
        else:
            out.append(Line("nc", None, line, 0, i))
            cont = False
    return out


def _ends_with_colon(text: str) -> bool:
    """True when the text ends in ':' outside strings and without a REM on the line."""
    in_str = False
    last = ""
    up = upper(text)
    i = 0
    while i < len(text):
        c = text[i]
        if c == '"':
            in_str = not in_str
        elif not in_str:
            if up.startswith("REM", i) and (i == 0 or not (up[i - 1] in NAME_CHARS or up[i - 1] in "#@")) \
                    and not (i + 3 < len(up) and (up[i + 3] in NAME_CHARS or up[i + 3] in SUFFIXES)):
                return False
            if not c.isspace():
                last = c
        i += 1
    return last == ":"


def tokenize(text: str, lineno: int, offset: int) -> list[Tok]:
    """Tokens of one physical line's CPL text; REM ends the line (colons in it are text)."""
    toks: list[Tok] = []
    up = upper(text)
    n = len(text)
    i = 0
    while i < n:
        c = up[i]
        col = offset + i + 1
        if c in " \t":
            i += 1
            continue
        if c == '"':
            j = text.find('"', i + 1)
            if j < 0:
                raise LexError(lineno, col, "string not closed with '\"'")
            toks.append(Tok("str", text[i + 1:j], lineno, col))
            i = j + 1
            continue
        if c in DIGITS or (c == "." and i + 1 < n and up[i + 1] in DIGITS):
            j = i
            while j < n and up[j] in DIGITS:
                j += 1
            is_real = False
            if j < n and up[j] == ".":
                is_real = True
                j += 1
                while j < n and up[j] in DIGITS:
                    j += 1
            lit = up[i:j]
            value = float(lit) if is_real else int_literal(lit, CEILING)
            if value > DOUBLE_MAX:
                raise LexError(lineno, col, f"number constant {lit[:20]}{'...' if len(lit) > 20 else ''} outside "
                                            "the DOUBLE range (1.7976931348623157E308)")
            toks.append(Tok("num", value, lineno, col, lit))
            i = j
            continue
        if c == ".":
            j = i + 1
            while j < n and up[j] == " ":
                j += 1
            if j < n and up[j] in LETTERS:
                k = j
                while k < n and up[k] in NAME_CHARS:
                    k += 1
                toks.append(Tok("label", up[j:k], lineno, col))
                i = k
                continue
            raise LexError(lineno, col, "'.' must start a label (.NAME) or a number")
        if c == "#":
            j = i + 1
            if j < n and up[j] in LETTERS:
                k, word, suffix = _word(up, j)
                toks.append(Tok("var", VarName("G", ("#" + word)[:8][1:], suffix), lineno, col, up[i:k]))
                i = k
                continue
            raise LexError(lineno, col, "'#' must start a global variable name")
        if c == "@":
            j = i + 1
            if j < n and up[j] in DIGITS:
                k = j
                while k < n and up[k] in DIGITS:
                    k += 1
                num = int_literal(up[j:k], 101)
                while k < n and up[k] in NAME_CHARS:
                    k += 1
                if k < n and up[k] == "%":
                    k += 1
                elif k < n and up[k] in "!?$":
                    raise LexError(lineno, k + offset + 1, f"@{num} is an INTEGER permanent variable: only '%' may "
                                                           "follow it (manual §2.4.3 L540-542)")
                if not 1 <= num <= 100:
                    raise LexError(lineno, col, f"permanent variable @{num}: only @1 to @100 exist")
                toks.append(Tok("var", VarName("P", str(num), ""), lineno, col, up[i:k]))
                i = k
                continue
            if up.startswith("_R", j) and not (j + 2 < n and up[j + 2] in NAME_CHARS):
                toks.append(Tok("var", VarName("R", "_R", ""), lineno, col, "@_R"))
                i = j + 2
                continue
            if j < n and up[j] in LETTERS:
                k, word, suffix = _word(up, j)
                toks.append(Tok("var", VarName("D", word[:16], suffix), lineno, col, up[i:k]))
                i = k
                continue
            if up.startswith(("_RES_DOUBLE", "_RES_DWORD"), j):
                raise LexError(lineno, col, "@_RES_DOUBLE and @_RES_DWORD are reserved for internal applications "
                                            "(manual §2.4.3 L544)")
            raise LexError(lineno, col, "'@' must start a permanent variable name")
        if c in LETTERS:
            k, word, suffix = _word(up, i)
            if word == "REM" and not suffix:
                break  # the rest of the physical line is a remark
            if suffix in ("$", "#") and word + suffix in KEYWORDS:
                toks.append(Tok("kw", word + suffix, lineno, col))
            elif suffix == "#":
                raise LexError(lineno, col, f"'{word}#' is not a keyword")
            elif not suffix and word in KEYWORDS:
                toks.append(Tok("kw", word, lineno, col))
                if word == "CALL":
                    i = _call_name(text, up, k, lineno, offset, toks)
                    continue
            elif word[0] == "P" and len(word) > 1 and word[1] in DIGITS:
                m = 1
                while m < len(word) and word[m] in DIGITS:
                    m += 1
                number = int_literal(word[1:m], MAX_PARAM + 1)
                if number > MAX_PARAM:
                    raise LexError(lineno, col, f"parameter {word[:m][:12]}: ncvm reads P1 to P{MAX_PARAM} (a call "
                                                f"passes no more)")
                toks.append(Tok("var", VarName("A", str(number), suffix), lineno, col, up[i:k]))
            else:
                toks.append(Tok("var", VarName("L", word[:8], suffix), lineno, col, up[i:k]))
            i = k
            continue
        two = up[i:i + 2]
        if two in OPS2:
            toks.append(Tok("op", two, lineno, col))
            i += 2
            continue
        if c in OPS1:
            toks.append(Tok("op", c, lineno, col))
            i += 1
            continue
        raise LexError(lineno, col, f"unexpected character '{text[i]}'")
    return toks


def _word(up: str, i: int) -> tuple[int, str, str]:
    k = i
    n = len(up)
    while k < n and up[k] in NAME_CHARS:
        k += 1
    word = up[i:k]
    suffix = ""
    if k < n and up[k] in SUFFIXES:
        suffix = up[k]
        k += 1
    elif k < n and up[k] == "#" and word in ("INP", "PRN"):
        suffix = "#"
        k += 1
    return k, word, suffix


def _call_name(text: str, up: str, i: int, lineno: int, offset: int, toks: list[Tok]) -> int:
    """After CALL: the program name as written (file names are case-sensitive), up to blank, '[' or ':'."""
    n = len(text)
    while i < n and text[i] in " \t":
        i += 1
    j = i
    while j < n and text[j] not in " \t[:":
        j += 1
    if j > i:
        toks.append(Tok("name", text[i:j], lineno, offset + i + 1))
    return j


def cpl_blocks(lines: list[Line]) -> list[tuple[str, object]]:
    """The program as a sequence of ("cpl", CplBlock) and ("nc", Line) items (blank lines dropped)."""
    out: list[tuple[str, object]] = []
    current: CplBlock | None = None
    for ln in lines:
        if ln.kind == "cpl":
            current = CplBlock(ln.number, ln.lineno)
            out.append(("cpl", current))
        elif ln.kind == "nc":
            current = None
            out.append(("nc", ln))
            continue
        elif ln.kind != "cont" or current is None:
            continue
        current.lines.append(ln.lineno)
        if current.error is None:
            try:
                current.tokens.extend(tokenize(ln.text, ln.lineno, ln.offset))
            except LexError as e:  # reported with the block's line number; the other blocks are still checked
                current.error = e
    for kind, item in out:
        if kind == "cpl":
            item.has_colon = any(t.kind == "op" and t.val == ":" for t in item.tokens)
    return out
