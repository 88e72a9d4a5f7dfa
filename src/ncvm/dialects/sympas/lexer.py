"""rw_SymPas tokens (manual §5.2): comments, directives, includes, literals, operators.

Keywords and type names are case-insensitive, user identifiers are case-sensitive
and significant to 32 characters (rw_SymPas manual L298; L1281; L1420; §5.2.3.2, L264-302). ``{! file}`` includes are
expanded here, nested up to 15 levels (§6.7.1); ``{$TASK n}`` and
``{$FULLSYSTEM}`` become directive tokens for the parser.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

from ...source import DIGITS, LETTERS, NAME_CHARS, int_literal, read_text
from .errors import SympasError

KEYWORDS = frozenset("""and begin boolean const do double downto else end for forward function goto if integer
label mod module not or procedure repeat shl shr single then timer to until var while xor program""".split())

MAX_INCLUDE_DEPTH = 15
SIGNIFICANT = 32
INT_MIN, INT_MAX = -2147483648, 2147483647
#: beyond the Integer range: a longer decimal constant keeps this value (and is clamped)
INT_CEILING = 1 << 40


@dataclass(slots=True)
class Token:
    kind: str  # "id" "kw" "int" "real" "str" "op" "dir" "eof"
    value: object
    file: str
    line: int
    col: int
    text: str = ""


class Lexer:
    """Turns one source file (and the files it includes) into a token list."""

    def __init__(self, finder=None, warn=None):
        self.finder = finder  # name -> Path | None
        self.warn = warn or (lambda code, msg, tok: None)

    def tokens(self, path: str, text: str, depth: int = 0) -> list[Token]:
        out: list[Token] = []
        i, line, col0 = 0, 1, 0
        n = len(text)
        while i < n:
            c = text[i]
            col = i - col0 + 1
            if c == "\n":
                line += 1
                i += 1
                col0 = i
                continue
            if c in " \t\r\f\x1a":
                i += 1
                continue
            if c == "/" and text.startswith("//", i):
                j = text.find("\n", i)
                i = n if j < 0 else j
                continue
            if c == "{":
                j = text.find("}", i + 1)
                if j < 0:
                    raise SympasError("SP001", "comment not closed: '}' missing", path, line, col)
                body = text[i + 1:j]
                if body.startswith("$"):
                    out.append(self._directive(body[1:], path, line, col))
                elif body.startswith("!"):
                    out.extend(self._include(body[1:].strip(), path, line, col, depth))
                nl = body.count("\n")
                if nl:
                    line += nl
                    col0 = i + 1 + body.rfind("\n") + 1
                i = j + 1
                continue
            if c in LETTERS or c == "_":
                j = i + 1
                while j < n and text[j] in NAME_CHARS:
                    j += 1
                word = text[i:j]
                low = word.lower()
                if low in KEYWORDS:
                    out.append(Token("kw", low, path, line, col, word))
                else:
                    out.append(Token("id", word[:SIGNIFICANT], path, line, col, word))
                i = j
                continue
            if c in DIGITS or (c == "." and i + 1 < n and text[i + 1] in DIGITS
                               and not (out and out[-1].kind in ("id", "kw"))):
                i = self._number(text, i, path, line, col, out)
                continue
            if c == "$":
                j = i + 1
                while j < n and text[j] in "0123456789abcdefABCDEF":
                    j += 1
                if j == i + 1:
                    raise SympasError("SP001", "hexadecimal constant needs digits after '$'", path, line, col)
                digits = text[i + 1:j].lstrip("0") or "0"
                if len(digits) > 8:
                    self.warn("W006", "hexadecimal constant too long: clamped to $7FFFFFFF",
                              Token("int", 0, path, line, col))
                    v = INT_MAX
                else:
                    v = int(digits, 16)
                    if v > INT_MAX:
                        v -= 1 << 32
                out.append(Token("int", v, path, line, col, text[i:j]))
                i = j
                continue
            if c == "'":
                j = i + 1
                buf = []
                while True:
                    if j >= n or text[j] == "\n":
                        raise SympasError("SP001", "string constant not closed on its line", path, line, col)
                    if text[j] == "'":
                        if j + 1 < n and text[j + 1] == "'":
                            buf.append("'")
                            j += 2
                            continue
                        break
                    buf.append(text[j])
                    j += 1
                out.append(Token("str", "".join(buf), path, line, col, text[i:j + 1]))
                i = j + 1
                continue
            two = text[i:i + 2]
            if two in (":=", "<>", "<=", ">="):
                out.append(Token("op", two, path, line, col, two))
                i += 2
                continue
            if c in "+-*/=<>(),;:.[]":
                out.append(Token("op", c, path, line, col, c))
                i += 1
                continue
            raise SympasError("SP001", f"character {c!r} is not allowed here", path, line, col)
        if depth == 0:
            if out:
                last = out[-1]
                out.append(Token("eof", None, last.file, last.line, last.col + len(last.text or str(last.value))))
            else:
                out.append(Token("eof", None, path, line, i - col0 + 1))
        return out

    def _number(self, text, i, path, line, col, out) -> int:
        n = len(text)
        j = i
        while j < n and text[j] in DIGITS:
            j += 1
        is_real = False
        if j < n and text[j] == "." and not text.startswith("..", j):
            # "1." is a fraction; "A1.dp" never reaches here because identifiers start with a letter
            is_real = True
            j += 1
            while j < n and text[j] in DIGITS:
                j += 1
        if j < n and text[j] in "eE":
            k = j + 1
            if k < n and text[k] in "+-":
                k += 1
            if k < n and text[k] in DIGITS:
                is_real = True
                j = k
                while j < n and text[j] in DIGITS:
                    j += 1
        lit = text[i:j]
        if is_real:
            value = float(lit)
            if value == math.inf:
                raise SympasError("SP010", f"real constant {lit} is beyond the double range", path, line, col)
            out.append(Token("real", value, path, line, col, lit))
        else:
            # clamped by the parser (sign folding), as the manual clamps a constant beyond the range (L398)
            out.append(Token("int", int_literal(lit, INT_CEILING), path, line, col, lit))
        return j

    def _directive(self, body: str, path, line, col) -> Token:
        parts = body.split()
        name = parts[0].upper() if parts else ""
        if name == "TASK":
            if len(parts) != 2:
                raise SympasError("SP001", "{$TASK n} needs a task number 0..3 or a constant name", path, line, col)
            return Token("dir", ("TASK", parts[1]), path, line, col)
        if name == "FULLSYSTEM":
            return Token("dir", ("FULLSYSTEM", None), path, line, col)
        raise SympasError("SP008", f"unknown compiler directive '{{${parts[0] if parts else ''}}}'", path, line, col)

    def _include(self, name: str, path, line, col, depth) -> list[Token]:
        if depth + 1 > MAX_INCLUDE_DEPTH:
            raise SympasError("SP007", f"includes nested deeper than {MAX_INCLUDE_DEPTH} levels", path, line, col)
        found = None
        if name:
            here = Path(path).parent / name
            found = here if here.is_file() else (self.finder(name) if self.finder else None)
        if found is None:
            raise SympasError("SP007", f"include file '{name}' not found", path, line, col)
        text = read_text(found)
        return self.tokens(str(found), text, depth + 1)
