"""Chapter 5: character fields, MID$ (read, write, views), LEN, INSTR, ASC, CHR$, STR$, VAL, TRIM$, +.

Two kinds of string holders (CPL manual §2.4.3, L711-728; §5, L3344-3834):

* a **character field** ``DIM A$(n)`` (:class:`CharacterField`): up to n characters and a current
  length (the assigned prefix); only it may receive a concatenation, STR$ or a MID$ write;
* a **string variable** (non-dimensioned ``B$``): the code generator keeps it as a plain Python
  value -- ``str``, None (NUL), or a :class:`StringView` when it was assigned ``MID$`` of a
  character field, which the manual says follows later changes of that field (L3378-3379).

Every function takes strings as ``str``, None (NUL) or any :class:`~.values.CplText`.
"""

from __future__ import annotations

from .errors import fail
from .format import format_items, standard_text
from .values import CplText, kind_of, text_of

MAX_FIELD = 1024  # characters in a character field, and the range of MID$/INSTR positions
MAX_CHAIN = 3  # operands of one chaining with "+" (L3773)
DIGITS = "0123456789"  # ASCII only: str.isdigit also takes the Latin-1 superscripts (CHR$(178) is "²")


class CharacterField(CplText):
    """``DIM NAME$(size)``: a field of ``size`` characters with a current length; NUL until assigned."""

    __slots__ = ("size", "_text")

    def __init__(self, size: int):
        if not isinstance(size, int) or isinstance(size, bool) or not 1 <= size <= MAX_FIELD:
            raise fail("INVALID_FIELD_LIMIT", f"DIM size {size!r} (1..{MAX_FIELD})")
        self.size = size
        self._text: str | None = None

    @property
    def text(self) -> str | None:
        return self._text

    def __len__(self) -> int:
        return len(self._text) if self._text is not None else 0

    def assign(self, value) -> None:
        """``A$ = expr``: the characters go to 1..len, surplus beyond the DIM size is dropped (L3713)."""
        text = text_of(value)
        self._text = None if text is None else text[: self.size]

    def write(self, start: int, count: int | None, value) -> None:
        """``MID$(A$,start[,count]) = value`` (manual §5.3, L3403-3430)."""
        _check_position(start)
        if count is not None:
            _check_position(count)
        current = self._text or ""
        if start > len(current) + 1:
            raise fail("CHARACTER_FIELD_NOT_ASSIGNED", f"MID$ at {start}, length is {len(current)}")
        text = text_of(value) or ""
        n = len(text) if count is None else min(count, len(text))
        n = max(0, min(n, self.size - start + 1))
        if n == 0 and self._text is None:
            return
        self._text = current[: start - 1] + text[:n] + current[start - 1 + n:]

    def __repr__(self) -> str:
        return f"CharacterField({self.size}, {self._text!r})"


class CharacterTable:
    """``DIM NAME$(rows, size)``: ``rows`` character fields of ``size`` characters, ``CD$(2) = "ABC"``."""

    __slots__ = ("rows",)

    def __init__(self, rows: int, size: int):
        if not isinstance(rows, int) or not 1 <= rows <= 65536:
            raise fail("INVALID_FIELD_LIMIT", f"DIM rows {rows!r}")
        # rows 0..n are accepted, as for numeric fields (CPL manual L932; L572; L702)
        self.rows = [CharacterField(size) for _ in range(rows + 1)]

    def row(self, index: int) -> CharacterField:
        if not isinstance(index, int) or not 0 <= index < len(self.rows):
            raise fail("INVALID_PARAMETER", f"row {index!r} of a character field with {len(self.rows) - 1} rows")
        return self.rows[index]


class StringView(CplText):
    """What a non-dimensioned variable holds after ``C$ = MID$(A$,s,n)``: re-read from A$ on every access."""

    __slots__ = ("source", "start", "count")

    def __init__(self, source: CharacterField, start: int, count: int | None):
        self.source, self.start, self.count = source, start, count

    @property
    def text(self) -> str | None:
        return _slice(self.source.text, self.start, self.count)

    def __repr__(self) -> str:
        return f"StringView({self.source!r}, {self.start}, {self.count})"


def _check_position(value) -> None:
    if not isinstance(value, int) or isinstance(value, bool) or not 1 <= value <= MAX_FIELD:
        raise fail("INVALID_PARAMETER", f"{value!r} is not in 1..{MAX_FIELD}")


def _slice(text: str | None, start: int, count: int | None) -> str | None:
    if text is None or start > len(text):
        return None  # the part asked for was never assigned (L3392)
    return text[start - 1:] if count is None else text[start - 1: start - 1 + count]


# -- the functions --------------------------------------------------------------------------

def mid(source, start: int, count: int | None = None) -> str | None:
    """``MID$(s,start[,count])`` read (L3371-3401): count clipped at the end, start beyond the end is NUL."""
    _check_position(start)
    if count is not None:
        _check_position(count)
    return _slice(text_of(source), start, count)


def mid_for_variable(source, start: int, count: int | None = None):
    """``B$ = MID$(A$,...)`` into a non-dimensioned variable: a live view when A$ is a character field."""
    _check_position(start)
    if count is not None:
        _check_position(count)
    if isinstance(source, CharacterField):
        return StringView(source, start, count)
    return _slice(text_of(source), start, count)


def length(s) -> int:
    """``LEN(s)``: the number of characters, 0 for "", -1 for NUL (L3431-3449)."""
    text = text_of(s)
    return -1 if text is None else len(text)


def instr(find, s, start: int = 1) -> int:
    """``INSTR(find,s[,start])``: 1-based position of ``find`` in ``s`` at or after ``start``, else 0."""
    _check_position(start)
    needle, hay = text_of(find), text_of(s)
    if not needle or hay is None:
        return 0
    return hay.find(needle, start - 1) + 1


def asc(s) -> int:
    """``ASC(s)``: code of the first character; -1 for "" or NUL (L3480-3500)."""
    text = text_of(s)
    return ord(text[0]) if text else -1


def chr_(code: int) -> str:
    """``CHR$(n)``: the character with code 0..255."""
    if not isinstance(code, int) or isinstance(code, bool) or not 0 <= code <= 255:
        raise fail("INVALID_PARAMETER", f"CHR$({code!r}) needs 0..255")
    return chr(code)


def str_(*args) -> str:
    """``STR$([format,]value)``: the number as text, by a template or the standard format (L3514-3539).

    A value that does not fit its template prints ``*`` (as PRN# does). The result may go only to a
    character field: the code generator calls :func:`string_variable_value` with ``computed=True``.
    """
    if len(args) == 2:
        fmt, value = args
        if kind_of(value) not in "IRD":
            raise fail("INVALID_PARAMETER", "STR$ needs a numeric value")
        return format_items([fmt, value]).text
    (value,) = args
    if kind_of(value) not in "IRD":
        raise fail("INVALID_PARAMETER", "STR$ needs a numeric value")
    return standard_text(value, kind_of(value))


def scan_number(text: str, pos: int = 0) -> tuple[int | float, int] | None:
    """Read a number at ``pos`` as VAL and INP# do; returns (value, end) or None when there is none.

    Leading blanks and zeros are skipped, one sign may come first (blanks may follow it), then
    digits and at most one ``.``; the first other character ends the number. With a point the
    value is a float (REAL), otherwise an int.
    """
    i, n = pos, len(text)
    while i < n and text[i] == " ":
        i += 1
    sign = 1
    if i < n and text[i] in "+-":
        sign = -1 if text[i] == "-" else 1
        i += 1
        while i < n and text[i] == " ":
            i += 1
    digits, point = "", False
    while i < n and (text[i] in DIGITS or (text[i] == "." and not point)):
        point = point or text[i] == "."
        digits += text[i]
        i += 1
    if not any(c in DIGITS for c in digits):
        return None
    value: int | float = sign * float(digits) if point else sign * int(digits)
    return value, i


INT_MIN, INT_MAX = -(2**31), 2**31 - 1


def val(s) -> int | float | None:
    """``VAL(s)`` (L3541-3569): an int, a float when the text has a point, None (NUL) if no number."""
    text = text_of(s)
    if text is None:
        return None
    found = scan_number(text)
    if found is None:
        return None
    value = found[0]
    if isinstance(value, int) and not INT_MIN <= value <= INT_MAX:
        raise fail("INVALID_INTEGER_VALUE", text.strip())
    return value


def val_integer(s) -> int | None:
    """``I% = VAL(s)``: a text with a decimal point gives INVALID ASSIGNMENT (L3545)."""
    value = val(s)
    if isinstance(value, float):
        raise fail("INVALID_ASSIGNMENT", f"VAL gives the REAL {value!r}")
    return value


def trim(s, side: str | None = None) -> str | None:
    """``TRIM$(s[,"L"|"R"])``: drop leading (L), trailing (R) or both blanks (L3571-3594)."""
    text = text_of(s)
    mode = None if side is None else text_of(side)
    if mode not in (None, "L", "R"):
        raise fail("INVALID_PARAMETER", f'TRIM$ option {mode!r} (only "L" or "R")')
    if text is None:
        return None
    if mode == "L":
        return text.lstrip(" ")
    if mode == "R":
        return text.rstrip(" ")
    return text.strip(" ")


def concat(*parts) -> str:
    """``a + b [+ c]``: chaining of at most 3 string expressions (RUNTIME ERROR 2153 beyond, L3773)."""
    if len(parts) > MAX_CHAIN:
        raise fail("NESTING_TOO_DEEP", f"{len(parts)} strings chained, at most {MAX_CHAIN}")
    return "".join(text_of(p) or "" for p in parts)


def string_variable_value(value, *, computed: bool = False):
    """What a non-dimensioned ``B$ = value`` stores.

    ``computed``: the right side is a concatenation, a STR$ or a MID$/TRIM$ of a concatenation,
    which only a character field may receive (L3609-3614, L3789-3793). A :class:`StringView` is kept
    as the live view; another holder is copied to a plain string.
    """
    if computed:
        raise fail("INADMISSIBLE_ASSIGNMENT")
    if isinstance(value, StringView) or value is None or isinstance(value, str):
        return value
    return text_of(value)


def mid_write(target, start: int, count: int | None, value) -> None:
    """``MID$(target,start[,count]) = value``: only a character field may be written (L3609)."""
    if not isinstance(target, CharacterField):
        raise fail("INADMISSIBLE_ASSIGNMENT", "MID$ writes need a DIMensioned character field")
    target.write(start, count, value)


def compare(a, b) -> int:
    """-1, 0 or 1: string order by ASCII code, character by character (L3749-3770); NUL sorts first."""
    x, y = text_of(a), text_of(b)
    if x == y:
        return 0
    if x is None:
        return -1
    if y is None:
        return 1
    return -1 if x < y else 1
