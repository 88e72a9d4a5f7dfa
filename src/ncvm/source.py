"""Program text as the controls read it: 8-bit characters, ASCII letters and digits, bounded numbers.

Every front end reads its programs through :func:`read_text` and classifies characters with
the ASCII sets here, not with ``str.isalpha``/``isdigit``: those accept Latin-1 letters (é, ß)
and superscript digits (¹²³), which no control reads as part of a name or a number, and
``str.upper`` turns ß into two letters, which shifts every column after it.
"""

from __future__ import annotations

import os
import stat
import sys
from pathlib import Path

#: a UTF-8 byte-order mark as it reads in Latin-1; an editor may put it before the first line
BOM = "\xef\xbb\xbf"

# spelled out: the string module compiles string.Template's pattern when imported (issue 18)
_LOWER = "abcdefghijklmnopqrstuvwxyz"
DIGITS = frozenset("0123456789")
LETTERS = frozenset(_LOWER + _LOWER.upper())
ALNUM = DIGITS | LETTERS
#: a character that may continue a name in every dialect (letters, digits, underscore)
NAME_CHARS = ALNUM | {"_"}

_UPPER = str.maketrans(_LOWER, _LOWER.upper())

#: the most decades a number in an NC block may have before its decimal point (the 8 decades of the
#: SINUMERIK 800's R parameters and words, CL 800 manual L7061, L7077-7080; DIN word formats keep to it)
WORD_DECADES = 8


#: how deep ncvm reads nested statements and expressions where a manual sets no limit (NEST001,
#: docs/decisions.md): programs compile to Python, whose compiler nests at most 100 blocks and 200 brackets
MAX_NESTING = 64
#: loops inside loops where a manual sets no limit: Python nests at most 20 loops, and generated code may
#: wrap a body in two blocks of its own (a GOTO dispatch loop)
MAX_LOOP_NESTING = 16


def too_deep(what: str, limit: int) -> str:
    """The message of NEST001 for ``what`` (statements, loops, ...) nested beyond ``limit`` levels."""
    return f"{what} nested deeper than {limit} levels: ncvm's limit where the manual sets none"


def read_text(path: str | Path) -> str:
    """The text of a program file: every byte one Latin-1 character, a leading byte-order mark dropped.

    Raises OSError as reading a file does.
    """
    return without_bom(Path(path).read_text(encoding="latin-1"))


#: how much of a program file the dialect detector reads (a file without a known extension): its head only,
#: however large the file (docs/decisions.md, "Issue 18: a check in bounded memory")
HEAD_BYTES = 64 * 1024


def read_head(path: str | Path) -> str:
    """The first :data:`HEAD_BYTES` of a program file as :func:`read_text` reads it (line ends as LF).
    Raises OSError as reading a file does."""
    with open_program(path) as f:
        return without_bom(f.read(HEAD_BYTES))


def open_program(path: str | Path):
    """A program file opened for reading a stretch at a time (:func:`stretches`): Latin-1, every line end
    (LF, CR LF, a lone CR) read as LF, as :func:`lines` splits them. Raises OSError as opening a file does."""
    return open(path, encoding="latin-1", newline=None)


def stretches(file, chars: int, at=None):
    """The text of an open program file (:func:`open_program`) from its start, in stretches of about ``chars``
    characters that end at a line end (or at the end of the file), a leading byte-order mark dropped: a
    program of any size, never held whole. From ``at`` (where ``file.tell()`` stood after a stretch of an
    earlier reading) on, the stretches that reading went on with: each ends where it ended."""
    if at is not None:
        file.seek(at)
        read = piece = file.read(chars)
    else:
        if file.seekable():  # a pipe is read once, from where it stands
            file.seek(0)
        read = file.read(max(chars, len(BOM)))
        piece = without_bom(read)
    while read:
        piece += file.readline()
        if piece:
            yield piece
        read = piece = file.read(chars)


#: the program argument that stands for standard input (``ncvm run -d din -``), and the name the program
#: goes by in diagnostics, traces and results
STDIN_ARG, STDIN = "-", "<stdin>"
#: the text of the last program read from a pipe (stdin or a FIFO), by its name: a diagnostic shows its source
#: line from here, since the pipe cannot be read again (opening a FIFO again waits for a writer that is gone);
#: split into its lines when the first diagnostic asks (a run without one never splits it)
_piped: dict[str, str | list[str]] = {}


def program_name(path: str | Path) -> str:
    """The name a program goes by: :data:`STDIN` for :data:`STDIN_ARG`, else its path."""
    return STDIN if str(path) == STDIN_ARG else str(path)


def is_pipe(path: str | Path) -> bool:
    """Whether the program ``path`` names is read from a pipe: standard input (:data:`STDIN_ARG`) or a FIFO."""
    if str(path) == STDIN_ARG:
        return True
    try:
        return stat.S_ISFIFO(os.stat(path).st_mode)
    except (OSError, ValueError):  # no such file (said where it is read); ValueError: a NUL byte
        return False


def read_piped(path: str | Path) -> str:
    """The whole text of a program from a pipe (standard input for :data:`STDIN_ARG`, else a FIFO), as
    :func:`read_text` reads a file, kept for the source lines of its diagnostics (:func:`lines_at`, under
    :func:`program_name`) until the next program is read. Raises OSError as reading a file does."""
    if str(path) == STDIN_ARG:
        if sys.stdin is None:
            raise OSError(9, "standard input is closed")
        if sys.stdin.isatty():  # a forgotten "< part.ngc": the run would wait for typing, saying nothing
            raise OSError(25, "standard input is a terminal; pipe the program in (ncvm run -d din - < part.ngc) "
                              "or give its file")
        data = sys.stdin.buffer.read()
    else:
        with _open_fifo(path) as pipe:
            data = pipe.read()
    text = without_bom(data.decode("latin-1"))
    _piped.clear()  # one pipe at a time: the last one's lines stay
    _piped[program_name(path)] = text
    return text


def _open_fifo(path: str | Path):
    """A FIFO opened for reading. Opening waits until a writer opens it: a wait of more than a second is said on
    stderr, else a run with nothing writing its FIFO would hang without a word."""
    import threading

    said = threading.Timer(WAIT_SAID_AFTER_S, lambda: print(
        f"ncvm: {path}: waiting for a program to be written into this FIFO (Ctrl-C stops)", file=sys.stderr,
        flush=True))
    said.daemon = True
    said.start()
    try:
        return open(path, "rb")
    finally:
        said.cancel()


#: how long opening a FIFO waits for its writer before it says so
WAIT_SAID_AFTER_S = 1.0


def forget_piped() -> None:
    """Drop the kept text of a pipe: a program is read from a file now, whatever its name."""
    _piped.clear()


def lines_at(path: str | Path, wanted) -> dict[int, str]:
    """The lines numbered ``wanted`` (1-based) of a program file, read up to the last of them and no further
    (a diagnostic shows its source line without reading a file of millions of lines whole); of a program read
    from a pipe, from its kept text (:func:`read_piped`); none of another pipe or a device, which would wait
    or be consumed. Raises OSError."""
    last = max(wanted, default=0)
    found: dict[int, str] = {}
    if last < 1:
        return found
    piped = _piped.get(str(path))
    if piped is not None:
        if isinstance(piped, str):
            piped = _piped[str(path)] = lines(piped)
        return {n: piped[n - 1] for n in wanted if 0 < n <= len(piped)}
    if not stat.S_ISREG(os.stat(path).st_mode):
        return found
    with open_program(path) as file:
        for n, line in enumerate(file, 1):
            if n in wanted:
                found[n] = without_bom(line) if n == 1 else line
                found[n] = found[n][:-1] if found[n].endswith("\n") else found[n]
            if n >= last:
                break
    return found


def lines(text: str) -> list[str]:
    """The lines of a program text, ended by LF, CR LF or a lone CR, as the controls end their blocks.

    Unlike ``str.splitlines`` a form feed (the page break of a printed listing), a vertical tab, the
    separators 1C-1E and NEL (85, a Latin-1 letter's neighbour) stay characters of their line: splitting
    there broke comments in two and shifted every line number after them.
    """
    if "\r" in text:
        text = text.replace("\r\n", "\n").replace("\r", "\n")
    out = text.split("\n")
    if out[-1] == "":
        out.pop()
    return out


def without_bom(text: str) -> str:
    return text[len(BOM):] if text.startswith(BOM) else text


def upper(text: str) -> str:
    """``text`` with a-z in capitals and every other character kept: one character for one (unlike str.upper)."""
    return text.translate(_UPPER)


def is_digits(text: str) -> bool:
    """True for a non-empty string of ASCII digits 0-9."""
    return bool(text) and all(c in DIGITS for c in text)


def int_literal(digits: str, ceiling: int) -> int:
    """The value of a string of ASCII digits, or ``ceiling`` when it is larger.

    A front end passes a ceiling beyond its range, so that its range check refuses the literal
    at its position; Python itself refuses to convert more than 4300 digits (ValueError).
    """
    significant = digits.lstrip("0")
    if len(significant) > len(str(ceiling)):
        return ceiling
    return min(int(significant or "0"), ceiling)


def decades(number: str) -> int:
    """Digits before the decimal point of a decimal number (``-0012.5``: 2), leading zeros not counted."""
    return len(number.lstrip("+-").partition(".")[0].lstrip("0"))


def word_number(text: str) -> float | None:
    """The value of the number of an NC word (``-12.5``, ``+3``, ``.5``); None when it has more than
    :data:`WORD_DECADES` digits before its decimal point, which no block format holds."""
    return None if decades(text) > WORD_DECADES else float(text)


def too_many_decades(address: str) -> str:
    """The message for a word whose number :func:`word_number` refuses."""
    return f"{address}: more than {WORD_DECADES} digits before the decimal point (an NC word has at most {WORD_DECADES})"
