"""CL 800 scanner (manual §3, §11.2).

Comments ``(* *)`` and DIN code ``(: :)`` are taken out first, so their text is
never tokenised. Keywords are upper case only; names compare case-insensitively
on their first 8 characters. ``R 61`` is an R parameter, ``B0101`` a bit pattern.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from ....source import DIGITS, LETTERS, int_literal
from .errors import CompilerMessage

#: every CL 800 word (CL 800 manual §3, L742-776; §11.2, L7022-7122) plus the system memory and function names of §4
KEYWORDS = frozenset("""
PROGRAM CHANNEL NC COM ESS ID PW EXTERNAL ENDEXTERN GLOBAL CENTRAL PAR LOCAL POINTER CONST LABEL
INTEGER REAL PATTERN BOOLEAN BEGIN END LF REPEAT UNTIL WHILE DO INT NOT FOR TO DOWNTO IF THEN ELSE
ENDIF CASE OF OTHERWISE ENDCASE GOTO CLEAR XCHG MIB INC DEC TRUNC ABS SQRT SQRTS SIN COS TAN ARC
ANGLE LN INV OR XOR AND NAND ORB XORB ANDB NANDB NOTB BIT SET POS MSYS PREP REF SEC CYC STOP DEC1
MEAS M REL INTA WRT PIC RECALL PORT OUTP ZOA DATA PARA ETX INP CHAN PPCH WITH
MDN MDNBY MDNBI MDZ MDZBY MDZBI MDP MDPBY MDPBI MDD MDDBY MDDBI SEN SENBY SENBI SEZ SEZBY SEZBI
TOS TOAD ZOFA ZOPR ZOE ZOD ZOPS ZOS ZOADW ZOPRDW ZOFADW ZOFPRDW PRSS PRVC PCDA PCDS PRAP PRAD
PANG PRIP ACPW ACPM ACP ACSP ACSS ACAS ACD ACG SOB PLCI PLCQ PLCF PLCW PLCIB PLCQB PLCPB PLCFB
PLCDBL PLCDBR PLCIW PLCQW PLCPW PLCFW PLCT PLCC PLCDF PLCDB PLCDG ALNP ALNPZ ALNZ RSDA RSDS RSDD
AGS SATC
""".split())

KEYWORDS_UPPER = frozenset(k.upper() for k in KEYWORDS)

#: two-word keywords written as one word: "Blank or other separator expected" (E031)
JOINED = frozenset("""
ARCSIN INVLN PREPREF PREPCYC INTSEC STOPDEC STOPDEC1 MEASM POSMSYS CLEARBIT SETBIT CLEARMIB WRTPIC
RECALLPIC OUTPZOA OUTPDATA OUTPPARA OUTPETX IFINT WHILEINT
""".split())


@dataclass(slots=True)
class Token:
    kind: str  # NAME RPAR INT REAL PATTERN STRING DIN SYM BADNAME EOF
    text: str
    line: int
    col: int
    value: object = None
    end_line: int = 0

    def is_kw(self, *words: str) -> bool:
        return self.kind == "NAME" and self.text in words

    @property
    def end_col(self) -> int:
        return self.col + len(self.text)


_SYMBOLS = (":=", "<>", ">=", "<=", ";", ",", ":", "=", "(", ")", "[", "]", ".", "+", "-", "*", "/", "<", ">")
_NAME = re.compile(r"[A-Za-z][A-Za-z0-9_]*")
_NAME_REST = re.compile(r"[A-Za-z0-9_]*")
_RPAR = re.compile(r"R[ \t]*([0-9]+)(?![A-Za-z0-9_])")
_PATTERN = re.compile(r"B([01]+)(?![A-Za-z0-9_])")
_NUMBER = re.compile(r"[0-9]+(?:\.[0-9]+)?")
#: above every CL 800 number (8 decades): a longer literal keeps this value and gets its range error
CEILING = 10 ** 9


def norm(name: str) -> str:
    """The significant part of a name: case-insensitive, first 8 characters, trailing dots dropped."""
    return name.upper().rstrip(".")[:8]


class Lexer:
    """Turns a source text into tokens; problems become :class:`CompilerMessage` s in ``errors``."""

    def __init__(self, path: str, text: str, legacy_names: bool = True):
        self.path, self.text, self.legacy = path, text.replace("\r", ""), legacy_names
        self.errors: list[CompilerMessage] = []

    def err(self, code: str, line: int, col: int | None, detail: str = "") -> None:
        self.errors.append(CompilerMessage(code, self.path, line, col, detail))

    def tokens(self) -> list[Token]:
        # no line length limit: E208 (one screen line) is a message of the editor, not of the compiler
        # (L6218-6230), and the manual's own listings 7.3 and 7.4 have lines of 85-89 characters
        text, out = self.text, []
        i, line, bol = 0, 1, 0
        size = len(text)
        while i < size:
            c = text[i]
            col = i - bol + 1
            if c == "\n":
                i, line, bol = i + 1, line + 1, i + 1
                continue
            if c in " \t\f\x1a":
                i += 1
                continue
            two = text[i:i + 2]
            if two == "(*":
                end = text.find("*)", i + 2)
                if end < 0:
                    self.err("E060", line, col, "comment (* is not closed")
                    break
                if "\n" in text[i:end]:
                    self.err("W001", line, col)
                for k in range(i, end):
                    if text[k] == "\n":
                        line, bol = line + 1, k + 1
                i = end + 2
                continue
            if two == "(:":
                end = text.find(":)", i + 2)
                split = re.compile(r":[ \t]*\n[ \t]*\)").search(text, i + 2)
                if split and (end < 0 or split.start() < end):
                    self.err("E057", line, col)
                    end = split.start()
                    stop = split.end()
                elif end < 0:
                    self.err("E060", line, col, "DIN code (: is not closed")
                    break
                else:
                    stop = end + 2
                raw = text[i + 2:end]
                if "\n" in raw:
                    self.err("W002", line, col)
                din = re.sub(r"\s*\n\s*", " ", raw).strip()
                out.append(Token("DIN", din, line, col, din))
                for k in range(i, stop):
                    if text[k] == "\n":
                        line, bol = line + 1, k + 1
                out[-1].end_line = line
                i = stop
                continue
            if two == "*)":
                self.err("E055", line, col)
                i += 2
                continue
            if two == ":)":
                self.err("E056", line, col)
                i += 2
                continue
            if c == '"':
                end = text.find('"', i + 1)
                nl = text.find("\n", i + 1)
                if end < 0 or (0 <= nl < end):
                    self.err("E061", line, col, "string not closed")
                    i = nl if nl >= 0 else size
                    continue
                s = text[i + 1:end]
                if "%" in s:
                    self.err("E045", line, col)
                elif len(s) > 120:
                    self.err("E046", line, col)
                out.append(Token("STRING", text[i:end + 1], line, col, s))
                i = end + 1
                continue
            m = _RPAR.match(text, i)
            if m:
                out.append(Token("RPAR", m.group(0), line, col, int_literal(m.group(1), CEILING)))
                i = m.end()
                continue
            m = _PATTERN.match(text, i)
            if m:
                if len(m.group(1)) > 8:
                    self.err("E051", line, col)
                out.append(Token("PATTERN", m.group(0), line, col, int_literal(m.group(1), CEILING)))
                i = m.end()
                continue
            if c in LETTERS:
                i = self._name(i, line, col, out)
                continue
            if c in DIGITS:
                m = _NUMBER.match(text, i)
                j = m.end()
                if j < size and (text[j] in LETTERS or text[j] == "_"):
                    k = _NAME_REST.match(text, j)  # a digit, then letters or '_': no name starts so
                    out.append(Token("BADNAME", text[i:k.end()], line, col))
                    i = k.end()
                    continue
                num = m.group(0)
                if "." in num:
                    out.append(Token("REAL", num, line, col, float(num)))
                else:
                    out.append(Token("INT", num, line, col, int_literal(num, CEILING)))
                i = j
                continue
            for s in _SYMBOLS:
                if text.startswith(s, i):
                    out.append(Token("SYM", s, line, col))
                    i += len(s)
                    break
            else:
                self.err("E053", line, col, repr(c))
                i += 1
        out.append(Token("EOF", "", line, i - bol + 1))
        for t in out:
            if not t.end_line:
                t.end_line = t.line
        return out

    def _name(self, i: int, line: int, col: int, out: list[Token]) -> int:
        text = self.text
        m = _NAME.match(text, i)
        j = m.end()
        # legacy (manual examples): '.' inside a name when no digit follows it
        while self.legacy and j < len(text) and text[j] == "." and text[i:j] not in KEYWORDS:
            nxt = text[j + 1] if j + 1 < len(text) else "\n"
            if nxt in LETTERS or nxt == "_":
                j = _NAME_REST.match(text, j + 1).end()
            elif nxt not in DIGITS and nxt != ".":
                j += 1
                break
            else:
                break
        word = text[i:j]
        if word in JOINED:
            self.err("E031", line, col, f"{word} is two words")
        if len(word) > 25:
            self.err("E038", line, col)
        out.append(Token("NAME", word, line, col))
        return j
