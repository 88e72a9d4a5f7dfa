"""The editor dialog's view of the selected NC block (manual §7.2, L4503-4532).

A CPL dialog started from the editor gets the NC block selected there. ``INP#(0,P1,...)`` reads the
block's *call parameters*, the ``[a,b,...]`` list of its sub-program call (manual §3.4: parameters
"written in square brackets and separated by commas"); ``PRN#(0,...)`` overwrites the whole block.

Which bracket is the call's list: the first ``[...]`` that is not the value of an address word.
An address word's value follows its address letter directly (``X[XVALUE]``, ``F[FEED*2+1000]``,
manual L359-369; blanks may come between) or an extended address with ``=`` (``X2=[A]``); every other bracket belongs to
the call: after a program name (``P SP["TEST"]``, ``BOLTCIRC[80,6]``), after a calling G, M or P
address (``G81 [2,5]``, ``P999 [2.75,X%,0]``) or after the manual's ``Q900[...]``. A block without
such a list (a plain NC block, which the editor hands to ``cpldlg05.dlg``) has no call parameters.
"""

from __future__ import annotations

import re

_ADDRESS_VALUE = re.compile(r"(?:^|[^A-Za-z0-9_])[A-Za-z]$|=$")


def _close(text: str, start: int) -> int:
    """Index of the ``]`` that closes the ``[`` at ``start`` (nested brackets, strings), or -1."""
    depth, quoted = 0, False
    for i in range(start, len(text)):
        c = text[i]
        if c == '"':
            quoted = not quoted
        elif not quoted and c == "[":
            depth += 1
        elif not quoted and c == "]":
            depth -= 1
            if depth == 0:
                return i
    return -1


def _split(inside: str) -> list[str]:
    """The parameters of a call list: commas inside ( ), [ ] or strings do not separate."""
    params, depth, quoted, start = [], 0, False, 0
    for i, c in enumerate(inside):
        if c == '"':
            quoted = not quoted
        elif quoted:
            continue
        elif c in "([":
            depth += 1
        elif c in ")]":
            depth -= 1
        elif c == "," and depth == 0:
            params.append(inside[start:i].strip())
            start = i + 1
    params.append(inside[start:].strip())
    return params


def call_parameters(block: str) -> list[str]:
    """The texts of the call parameters of an NC block, in order ([] for a block without a call list)."""
    i = 0
    while i < len(block):
        c = block[i]
        if c == "(":  # a remark: (MSG, ...) or any other
            end = block.find(")", i)
            if end < 0:
                return []
            i = end + 1
            continue
        if c in ";%":  # the rest is a comment
            return []
        if c == "[":
            end = _close(block, i)
            if end < 0:
                return []
            if not _ADDRESS_VALUE.search(block[:i].rstrip()):
                inside = block[i + 1:end]
                return _split(inside) if inside.strip() else []
            i = end + 1
            continue
        i += 1
    return []
