"""DIN 66025 blocks: the words of one NC block, and the reader for plain DIN text.

A :class:`Block` is what every front end hands to the kernel: G and M codes,
address words (``X``, ``F``, extended axis addresses such as ``Q1``), the
block number, a message. Front ends that compute word values at run time
(CPL ``X[expr]``, SINUMERIK ``X=R91``) build a Block per execution; constant
blocks are built once at compile time and reused.
"""

from __future__ import annotations

import math
import re
from operator import itemgetter
from typing import NamedTuple

from ..diagnostics import Diagnostic, Span
from ..lazy import lazy
from ..records import Record
from ..source import WORD_DECADES, stretches, too_many_decades, word_number
from ..source import lines as program_lines
from .canon import Src

np = lazy("numpy")


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


def acts(block: Block) -> bool:
    """Whether the block has anything for the kernel; else it only counts (a block number, a comment)."""
    return bool(block.g or block.m or block.words or block.msg is not None)


class PlainRow(NamedTuple):
    """The layout of a plain row: a plain block as a motion queue holds it -- at most a motion G code (G0-G3),
    no M code or message, words only for PLAIN_WORDS. Queues run stretches of rows column-wise
    (:func:`ncvm.nc.plainrun.plain_segments`).

    A queued row is a plain ``tuple`` in this field order, not an instance: CPL code queues one per executed
    block, and a tuple display costs a fifth of building a NamedTuple there. Read its fields with the
    getters below (``row_line(row)``), or ``PlainRow._make(row)`` where speed does not matter.
    """

    g: int  # the motion G code, -1 for none
    X: float  # NaN for a missing word, as every word
    Y: float
    Z: float
    I: float  # noqa: E741 (the address letter)
    J: float
    K: float
    F: float
    line: int  # the physical line of the block
    n: int | None  # its block number
    src: Src


_FIELD = {name: i for i, name in enumerate(PlainRow._fields)}
row_g, row_line, row_n, row_src = (itemgetter(_FIELD[name]) for name in ("g", "line", "n", "src"))
#: address -> the getter of its word in a row
ROW_WORD = {a: itemgetter(_FIELD[a]) for a in PlainRow._fields[1:8]}
_ROW_WORDS = itemgetter(*(_FIELD[a] for a in PlainRow._fields[1:8]))


def plain_row(values: tuple, file: str) -> tuple:
    """The row of a compiled plain block: ``values`` are its fields up to ``n``, the block is in ``file``."""
    return (*values, Src(file, row_line(values)))


def row_block(row: tuple) -> Block:
    """A plain row as the Block the kernel executes."""
    words = {a: v for a, v in zip(PLAIN_WORDS, _ROW_WORDS(row)) if v == v}
    g = row_g(row)
    return Block((g,) if g >= 0 else (), (), words, row_n(row), None, row_src(row))


def as_block(item):
    """A motion queue's item as a Block: a plain row turned into one, anything else as it is."""
    return row_block(item) if item.__class__ is tuple else item


def block_row(blk: Block) -> tuple | None:
    """A Block as a plain row, or None when it carries more than a plain block may."""
    g, words = blk.g, blk.words
    if blk.m or blk.msg is not None or len(g) > 1 or (g and g[0] not in (0, 1, 2, 3)) or not _PLAIN.issuperset(words):
        return None
    get = words.get
    return ((g[0] if g else -1), *(get(a, _NAN) for a in PLAIN_WORDS), blk.src.line, blk.n, blk.src)


#: one address word of plain DIN: a letter and a number (front ends with richer blocks read their own)
WORD = re.compile(r"\s*([A-Z])\s*([-+]?(?:\d+\.?\d*|\.\d+))")
#: a line body made of nothing but words: checked in one regex call before the words are read. Possessive:
#: ``\d+\.?\d*`` splits a run of digits in as many ways as it is long, and a bad character after a few long
#: numbers made the failing match try them all (a line of three 300-digit words and an '@' never ended)
CLEAN_BODY = re.compile(r"(?:\s*+[A-Z]\s*+[-+]?+(?:\d++(?:\.\d*+)?+|\.\d++))*+\s*+")


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
    if i < n and s[i] == "%":  # the tape mark stands alone (a comment beside it); never a block's start
        if s[i + 1:].strip():
            col = i + 1
            raise DinSyntaxError(col_map[col - 1] + 1 if col_map else col,
                                 "% is the tape mark and stands alone on its line: the rest of it would be lost")
        return None
    if not CLEAN_BODY.fullmatch(s, i):
        _raise_at_bad_character(s, i, col_map)
    g: list[float] = []
    m: list[int] = []
    words: dict[str, float] = {}
    nno = None
    for letter, num in WORD.findall(s, i):
        if len(num) > WORD_DECADES and word_number(num) is None:  # a shorter number has fewer digits
            col = next(mt.start(1) for mt in WORD.finditer(s, i) if mt.group(2) == num) + 1
            raise DinSyntaxError(col_map[col - 1] + 1 if col_map else col, too_many_decades(letter))
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


def word_column(text: str, letter: str) -> int | None:
    """The column of the first word with address ``letter`` in a DIN line (comments skipped), or None."""
    try:
        body, _msg, col_map = _strip_comments(text.rstrip("\r\n"))
    except DinSyntaxError:
        return None
    for mt in WORD.finditer(body.upper()):
        if mt.group(1) == letter:
            return col_map[mt.start(1)] + 1
    return None


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
    """Read a whole plain DIN program: (block, block-skip flag) per executable line, plus diagnostics."""
    segments, diags = read_din_segments(path, text)
    blocks: list[tuple[Block, bool]] = []
    for seg in segments:
        if isinstance(seg, PlainRun):
            blocks.extend((blk, False) for blk in seg.blocks())
        else:
            blocks.append(seg)
    return blocks, diags


class PlainRun(Record):
    """Consecutive plain blocks of one file (N, one motion G code, X Y Z I J K F words), held as columns.

    ``words`` maps each of :data:`PLAIN_WORDS` to a float column with NaN where
    a block has no such word; ``g`` is the motion G code or -1. The kernel
    executes a run column-wise (:mod:`ncvm.nc.plainrun`); :meth:`block` gives
    any one of them as the line parser reads it.

    A short run (fewer than :data:`RUN_COLUMNS_FROM` blocks, :func:`columnar`) is executed block by block and
    kept as what it was made of: the ``matches`` of its lines (their groups of ``_PLAIN_LINE``) when it was
    read from text, else its ``origin``; its columns are made only when asked for (issue 18: numpy's fixed
    cost per column operation made a drilling program's runs of four blocks 16 times slower than rs274, and
    Blocks held for a whole program kept the garbage collector busy: strings in tuples it leaves alone).
    """

    __slots__ = ("file", "_lines", "_g", "_words", "source", "origin", "source_first", "matches")

    def __init__(self, file: str, lines, g: np.ndarray | None, words: dict | None, source: list | None = None,
                 origin: list | None = None, source_first: int = 0, matches: list | None = None):
        self.file = file
        #: physical line of each block: an int column, a range (a short run read from text), or None (a
        #: short run made of its origin)
        self._lines = lines
        self._g = g  # int, motion G code 0..3 or -1 (None: not made yet)
        self._words = words  # address -> float column
        self.source = source  # the lines of the stretch it was read from, when it was read from text
        self.origin = origin  # the plain rows (or Blocks) the run was made of, when it was made of them
        self.source_first = source_first  # the program lines before source[0]
        self.matches = matches  # a short run read from text: the regex groups of its lines

    @property
    def lines(self) -> np.ndarray:
        if self._g is None:
            self._columns()
        return self._lines

    @property
    def g(self) -> np.ndarray:
        if self._g is None:
            self._columns()
        return self._g

    @property
    def words(self) -> dict:
        if self._g is None:
            self._columns()
        return self._words

    def _columns(self) -> None:
        """The columns of a short run, from what it was made of."""
        rows = [o if o.__class__ is tuple else block_row(o) for o in (self.origin or self.blocks())]
        n = len(rows)
        self._lines = np.fromiter(map(row_line, rows), np.int64, n)
        self._g = np.fromiter(map(row_g, rows), np.int64, n)
        self._words = {a: np.fromiter(map(get, rows), float, n) for a, get in ROW_WORD.items()}

    def __len__(self) -> int:
        return len(self.origin) if self._lines is None else len(self._lines)

    def line(self, i: int) -> int:
        """The physical line of block ``i``."""
        if self._lines is not None:
            return int(self._lines[i])
        o = self.origin[i]
        return row_line(o) if o.__class__ is tuple else o.src.line

    def block(self, i: int) -> Block:
        """Block ``i`` as the line parser reads it (or as it was built)."""
        if self.origin is not None:
            return as_block(self.origin[i])
        line = int(self._lines[i])
        if self.matches is not None:
            return next(_blocks(self.file, self.matches[i:i + 1], line))
        return parse_din_line(self.source[line - 1 - self.source_first], Src(self.file, line))

    def blocks(self):
        if self.origin is not None:
            return map(as_block, self.origin)
        if self.matches is not None:
            return _blocks(self.file, self.matches, self._lines[0])
        return (self.block(i) for i in range(len(self)))

    def head(self, n: int) -> "PlainRun":
        """The first ``n`` blocks as a run of their own."""
        origin = self.origin[:n] if self.origin is not None else None
        lines = self._lines[:n] if self._lines is not None else None
        if self._g is None:
            return PlainRun(self.file, lines, None, None, self.source, origin, self.source_first,
                            self.matches[:n] if self.matches is not None else None)
        return PlainRun(self.file, lines, self._g[:n], {a: col[:n] for a, col in self._words.items()}, self.source,
                        origin, self.source_first)


#: a run of fewer plain blocks than this is kept as Blocks and executed block by block through the kernel
#: (:func:`columnar`); the columns' fixed cost (a few dozen numpy calls a run, ~0.1 ms) is paid back from
#: about this many blocks on (measured: docs/performance.md, thirteenth pass)
RUN_COLUMNS_FROM = 32


def columnar(blocks: int) -> bool:
    """Whether a run of ``blocks`` plain blocks is held and executed as columns (read at each call, so a
    test can set :data:`RUN_COLUMNS_FROM`)."""
    return blocks >= RUN_COLUMNS_FROM


#: the addresses of a plain block besides N and its motion G code, in the order CAM output writes them
PLAIN_WORDS = "XYZIJKF"
_PLAIN = frozenset(PLAIN_WORDS)
#: a number; possessive quantifiers (nothing a number gives back could start the next word) keep the scan fast
#: (at most WORD_DECADES digits before the point: a longer number goes the general way and gets its error there)
_NUM = r"([-+]?+(?:\d{1,8}+(?:\.\d*+)?+|\.\d++))"
#: a plain line with at least one G code or word (groups: N, G, then PLAIN_WORDS; an N of at most WORD_DECADES
#: digits, as any word), or any other line with its
#: line break (last group: never empty, so blank lines and lines of nothing but N go the general way too);
#: multi-line (re.M). Compiled into re's cache at first use (about 1.5 ms): a short program is read line by line
_PLAIN_LINE = (r"^[ \t]*+(?:N(\d{1,8}+)[ \t]*+)?(?=[GXYZIJKF])(?:G0?([0-3])(?![\d.])[ \t]*+)?"
               + "".join(rf"(?:{a}{_NUM}[ \t]*+)?" for a in PLAIN_WORDS) + r"$|^(.*\n?)")
#: motion G code as the reader finds it -> its number (-1: the block has none)
_MOTION = {"": -1, "0": 0, "1": 1, "2": 2, "3": 3}
_NAN = math.nan
#: characters of a program read in one regex pass (about 8,000 lines of CAM output)
CHUNK_CHARS = 1 << 18
#: a check or a run reads programs (and a file's last stretch) of fewer lines line by line: columns would cost
#: more than they save (numpy's import alone is ~0.1 s, issue 18)
COLUMNS_FROM = 200


def read_din_segments(path: str, text: str, as_columns: bool = True) -> tuple[list, list[Diagnostic]]:
    """The program as segments in line order: :class:`PlainRun` stretches and (block, skip) pairs, plus diagnostics
    (all the stretches of :func:`read_din_chunks` at once)."""
    segments: list = []
    diags: list[Diagnostic] = []
    for more, found in read_din_chunks(path, text, as_columns):
        segments += more
        diags += found
    return segments, diags


def read_din_chunks(path: str, text: str, as_columns: bool = True):
    """The program a stretch of about :data:`CHUNK_CHARS` characters at a time: (segments, diagnostics) per
    stretch, in line order, line numbers counted from the program's start (:func:`din_stretches`). Without
    ``as_columns`` (and in a text with lone CR line ends) every line goes the general way, in one stretch.
    """
    flat = text.replace("\r\n", "\n")
    if not as_columns or "\r" in flat:  # lone CR line ends: read line by line
        segments: list = []
        diags: list[Diagnostic] = []
        for lineno, line in enumerate(program_lines(text), 1):
            _read_general(segments, diags, path, lineno, line)
        yield segments, diags
        return
    for stretch in din_stretches(path, text_stretches(flat)):
        yield stretch.segments, stretch.diags


def text_stretches(flat: str):
    """A program text with LF line ends in stretches of about :data:`CHUNK_CHARS` characters, each ending at a
    line end (as :func:`ncvm.source.stretches` reads a file)."""
    pos = 0
    while pos < len(flat):
        end = flat.find("\n", pos + CHUNK_CHARS) + 1 or len(flat)
        yield flat[pos:end]
        pos = end


def file_stretches(file, at=None):
    """An open program file (:func:`ncvm.source.open_program`) in stretches of about :data:`CHUNK_CHARS`
    characters, each ending at a line end: from its start, or from ``at`` (a position ``file.tell()`` gave
    after a stretch) on."""
    return stretches(file, CHUNK_CHARS, at)


class DinStretch(NamedTuple):
    """A stretch of a program as read: its segments and diagnostics, its ``lines`` (the source lines of its
    blocks, for the columns of later diagnostics), the program lines before it (``first``) and its size in
    characters."""

    segments: list
    diags: list
    lines: list
    first: int
    chars: int

    def line(self, lineno: int) -> str:
        """Program line ``lineno`` (1-based, counted from the program's start), which lies in this stretch."""
        return self.lines[lineno - 1 - self.first]


def din_stretches(path: str, pieces, columns_from: int = 0, first: int = 0):
    """:class:`DinStretch` after stretch of a program given as ``pieces`` of text with LF line ends, each
    ending at a line end (:func:`text_stretches`, or :func:`ncvm.source.stretches` over a file), the first
    piece after the program's line ``first`` (a piece is read alone: no state crosses from one to the next
    but the line count, so a program read again from a later piece on reads as it did).

    Per-line work dominates reading a large program, so one regex pass over a
    stretch sorts its lines: plain lines become columns of a
    :class:`PlainRun`; the others (comments, block skip, ``%``, other words,
    errors) go through :func:`parse_din_line` one by one.
    A stretch at a time, the strings the pass finds never take more memory than one stretch's worth, and a
    run can execute a program of millions of lines without holding all of it (issue 18: a 500,000-line
    file took 282 MB read in one pass). A stretch of fewer than ``columns_from`` lines (a check of a small
    program) is read line by line: columns would cost more than they save (:data:`COLUMNS_FROM`).
    """
    for chunk in pieces:  # first: the lines before the stretch
        lines = chunk.split("\n")
        if chunk.endswith("\n"):
            lines.pop()
        if len(lines) < columns_from:
            segments, diags = [], []
            for k, line in enumerate(lines, first + 1):
                _read_general(segments, diags, path, k, line)
            yield DinStretch(segments, diags, lines, first, len(chunk))
            first += len(lines)
            del segments, diags, lines  # not held here while the next stretch is read (the caller may let go)
            continue
        found = re.findall(_PLAIN_LINE, chunk if chunk.isupper() else chunk.upper(), re.M)[:len(lines)]
        columns = list(zip(*found))
        segments, diags = [], []
        start = 0
        for k in [k for k, rest in enumerate(columns[-1], 1) if rest]:
            if k - 1 > start:
                _add_run(segments, path, lines, found, columns, start, k - 1, first)
            start = k
            _read_general(segments, diags, path, first + k, lines[k - 1])
        if len(lines) > start:
            _add_run(segments, path, lines, found, columns, start, len(lines), first)
        yield DinStretch(segments, diags, lines, first, len(chunk))
        first += len(lines)
        del segments, diags, lines, found, columns  # as above


def _read_general(segments, diags, path: str, lineno: int, line: str) -> None:
    skip = line.lstrip().startswith("/")
    if skip:
        line = line.replace("/", " ", 1)
    try:
        blk = parse_din_line(line, Src(path, lineno))
    except DinSyntaxError as e:
        diags.append(Diagnostic("NC001", e.message, Span(path, lineno, e.column)))
        return
    if blk is not None:
        segments.append((blk, skip))


def _add_run(segments, path: str, lines: list, found: list, columns, lo: int, hi: int, first: int) -> None:
    """Rows lo..hi-1 of a stretch's regex matches ``found`` (as ``columns``) and ``lines`` (program lines
    first+lo+1..first+hi), all plain, as a PlainRun: of columns, or of Blocks when it is short
    (:func:`columnar`)."""
    if not columnar(hi - lo):
        segments.append(PlainRun(path, range(first + lo + 1, first + hi + 1), None, None, lines, None, first,
                                 found[lo:hi]))
        return
    words = {a: _floats(col[lo:hi]) for a, col in zip(PLAIN_WORDS, columns[2:])}
    g = np.array(list(map(_MOTION.__getitem__, columns[1][lo:hi])), dtype=np.int64)
    segments.append(PlainRun(path, np.arange(first + lo + 1, first + hi + 1), g, words, source=lines,
                             source_first=first))


def _blocks(path: str, found: list, line: int):
    """The regex matches ``found`` of plain lines from program line ``line`` on as the Blocks
    :func:`parse_din_line` makes of them (the words in the order the lines write them, PLAIN_WORDS)."""
    for k, (n, g, x, y, z, i, j, kk, f, _rest) in enumerate(found, line):
        words = {}  # unrolled: a comprehension's call costs a third of a block
        if x:
            words["X"] = float(x)
        if y:
            words["Y"] = float(y)
        if z:
            words["Z"] = float(z)
        if i:
            words["I"] = float(i)
        if j:
            words["J"] = float(j)
        if kk:
            words["K"] = float(kk)
        if f:
            words["F"] = float(f)
        yield Block((_MOTION[g],) if g else (), (), words, int(n) if n else None, None, Src(path, k))


def _floats(cells: tuple) -> np.ndarray:
    """A word column: the numbers as written, NaN where a block has no such word."""
    if not any(cells):
        return np.full(len(cells), _NAN)
    return np.array([float(v) if v else _NAN for v in cells])
