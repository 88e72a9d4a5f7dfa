"""DIN 66025 blocks: the words of one NC block, and the reader for plain DIN text.

A :class:`Block` is what every front end hands to the kernel: G and M codes,
address words (``X``, ``F``, extended axis addresses such as ``Q1``), the
block number, a message. Front ends that compute word values at run time
(CPL ``X[expr]``, SINUMERIK ``X=R91``) build a Block per execution; constant
blocks are built once at compile time and reused.
"""

from __future__ import annotations

import re

from ..diagnostics import Diagnostic, Span
from .canon import Src


class Block:
    """One NC block, ready for the kernel."""

    __slots__ = ("g", "m", "words", "n", "msg", "src")

    def __init__(self, g=(), m=(), words=None, n=None, msg=None, src: Src | None = None):
        self.g = g  # tuple of G numbers (floats allowed: 54.1)
        self.m = m  # tuple of M numbers
        self.words = words if words is not None else {}  # address -> float
        self.n = n
        self.msg = msg
        self.src = src

    def __repr__(self) -> str:
        return f"Block(g={self.g}, m={self.m}, words={self.words}, n={self.n})"


#: one address word of plain DIN: a letter and a number (front ends with richer blocks read their own)
WORD = re.compile(r"\s*([A-Z])\s*([-+]?(?:\d+\.?\d*|\.\d+))")
#: a line body made of nothing but words: checked in one regex call before the words are read
CLEAN_BODY = re.compile(r"(?:\s*[A-Z]\s*[-+]?(?:\d+\.?\d*|\.\d+))*\s*")


class DinSyntaxError(Exception):
    def __init__(self, column: int, message: str):
        self.column = column
        self.message = message


def parse_din_line(text: str, src: Src) -> Block | None:
    """Read one line of plain DIN 66025 / ISO 6983; None for a line with nothing to do.

    Returns a :class:`Block` (with ``msg`` set for ``(MSG, ...)`` comments), or
    raises :class:`DinSyntaxError` with the column of the first bad character.
    """
    line = text.rstrip("\r\n")
    msg = None
    if "(" in line or ";" in line:
        body, msg, col_map = _strip_comments(line)
    else:
        body, col_map = line, None
    s = body.upper()
    i, n = 0, len(s)
    while i < n and s[i] in " \t":
        i += 1
    if i < n and s[i] == "%":
        return None
    if not CLEAN_BODY.fullmatch(s, i):
        _raise_at_bad_character(s, i, col_map)
    g: list[float] = []
    m: list[int] = []
    words: dict[str, float] = {}
    nno = None
    for letter, num in WORD.findall(s, i):
        if letter == "G":
            v = float(num)
            g.append(int(v) if v == int(v) else v)
        elif letter == "M":
            m.append(int(float(num)))
        elif letter == "N":
            nno = int(float(num))
        elif letter in words:
            col = [mt.start(1) for mt in WORD.finditer(s, i) if mt.group(1) == letter][1] + 1
            raise DinSyntaxError(col_map[col - 1] + 1 if col_map else col, f"address {letter} twice in one block")
        else:
            words[letter] = float(num)
    if not g and not m and not words and msg is None:
        return None
    return Block(tuple(g), tuple(m), words, nno, msg, src)


def _raise_at_bad_character(s: str, pos: int, col_map) -> None:
    """The line is not all words: find the first thing that is not one and report its column."""
    while (mt := WORD.match(s, pos)) is not None:
        pos = mt.end()
    rest = s[pos:]
    col = pos + len(rest) - len(rest.lstrip()) + 1
    raise DinSyntaxError(col_map[col - 1] + 1 if col_map else col, f"cannot read '{rest.strip()[:20]}'")


def _strip_comments(line: str):
    """Remove (comments) and ;comments; keep a map from new column to original column."""
    out, cols = [], []
    msg = None
    i, n = 0, len(line)
    while i < n:
        c = line[i]
        if c == "(":
            j = line.find(")", i)
            if j < 0:
                raise DinSyntaxError(i + 1, "comment not closed with ')'")
            inner = line[i + 1:j].strip()
            if inner.upper().startswith("MSG,"):
                msg = inner[4:].strip()
            i = j + 1
            continue
        if c == ";":
            break
        out.append(c)
        cols.append(i)
        i += 1
    return "".join(out), msg, cols


def read_din_program(path: str, text: str) -> tuple[list[tuple[Block, bool]], list[Diagnostic]]:
    """Read a whole plain DIN program: (block, block-skip flag) per executable line, plus diagnostics.

    Per-line regex calls dominate reading a large program, so the whole text is
    cut into words by one regex pass (:func:`_plain_lines`); only the few lines
    that are more than bare words (comments, block skip, ``%``, an address
    twice, errors) go through :func:`parse_din_line`. Both give the same blocks.
    """
    lines = text.splitlines()
    plain = _plain_lines(text, path)
    blocks: list[tuple[Block, bool]] = []
    diags: list[Diagnostic] = []
    for lineno, line in enumerate(lines, 1):
        blk = plain.get(lineno, _GENERAL) if plain is not None else _GENERAL
        if blk is not _GENERAL:
            if blk is not None:
                blocks.append((blk, False))
            continue
        stripped = line.lstrip()
        skip = stripped.startswith("/")
        if skip:
            line = line.replace("/", " ", 1)
        try:
            blk = parse_din_line(line, Src(path, lineno))
        except DinSyntaxError as e:
            diags.append(Diagnostic("NC001", e.message, Span(path, lineno, e.column)))
            continue
        if blk is not None:
            blocks.append((blk, skip))
    return blocks, diags


#: marks a line that the general line parser must read
_GENERAL = object()
#: a word, a line end, or any other visible character (which sends its line to the general parser)
_TOKEN = re.compile(r"([A-Z])[ \t]*([-+]?(?:\d+\.?\d*|\.\d+))|(\n)|[^ \t]")
#: line breaks of str.splitlines other than \n: texts with these are read line by line
_ODD_BREAKS = re.compile("[\r\x0b\x0c\x1c\x1d\x1e\x85\u2028\u2029]")


def _plain_lines(text: str, path: str) -> dict | None:
    """Block (or None for an empty line) per line number of every line that is nothing but words.

    Lines missing from the result need :func:`parse_din_line`. None when the
    text has line breaks other than LF / CRLF (then every line goes there).
    """
    text = text.replace("\r\n", "\n")
    if _ODD_BREAKS.search(text):
        return None
    out: dict[int, Block | None] = {}
    lineno = 1
    g: list = []
    m: list = []
    words: dict[str, float] = {}
    nno = None
    general = False
    for letter, num, newline in _TOKEN.findall(text.upper()):
        if letter:
            if letter == "G":
                v = float(num)
                g.append(int(v) if v == int(v) else v)
            elif letter == "M":
                m.append(int(float(num)))
            elif letter == "N":
                nno = int(float(num))
            elif letter in words:
                general = True  # an address twice: the general parser reports it
            else:
                words[letter] = float(num)
            continue
        if not newline:
            general = True
            continue
        if not general:
            out[lineno] = Block(tuple(g), tuple(m), words, nno, None, Src(path, lineno)) if g or m or words else None
        lineno += 1
        g, m, words, nno, general = [], [], {}, None, False
    if not general:
        out[lineno] = Block(tuple(g), tuple(m), words, nno, None, Src(path, lineno)) if g or m or words else None
    return out
