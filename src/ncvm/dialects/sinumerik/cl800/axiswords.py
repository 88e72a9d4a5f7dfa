"""``ncvm check`` of CL 800: the DIN words of ``(: ... :)`` blocks for axes the machine lacks (NC011), and the
G functions the SINUMERIK 810-880 profile refuses (warnings, nc/profiles/check.py).

The compiled object runs on the SINUMERIK 800 front end, which refuses such a word where it stands; the
check reads the same words with the SINUMERIK block reader, so both judge them alike.
"""

from __future__ import annotations

from dataclasses import fields

from ....diagnostics import Diagnostic, Span, read_lines
from ....nc.profiles.check import refused_g_warnings
from ....nc.profiles.sinumerik8xx import SINUMERIK8XX
from ..codegen import _word_diagnostic as word_diagnostic
from ..codegen import dwell_diagnostics, dwells, g_word, missing_axis
from ..errors import ReadError
from ..reader import Word, read_block
from . import ast


def axis_diagnostics(path: str, prog, axes, radius: str = "B") -> list[Diagnostic]:
    if not isinstance(prog, ast.Program):
        return []
    lines = read_lines(path) or []
    out = []
    uses = []
    blocks = []  # (line, column offset, words) for the dwell rule
    for st in _din_blocks(prog.body):
        source = lines[st.line - 1] if st.line <= len(lines) else ""
        base = source.find(st.text, max(st.col - 1, 0))
        try:
            words = [it for it in read_block(st.text, st.line).items if isinstance(it, Word)]
        except ReadError as e:  # the object program's reader refuses the block when it runs: so does check
            out.append(Diagnostic(e.code, e.message, Span(path, st.line, base + e.col if base >= 0 else st.col)))
            continue
        dwell = dwells(words)
        blocks.append((st.line, base if base >= 0 else st.col - 1, words))
        uses.extend((w.value, st.line, base + w.col if base >= 0 else st.col) for w in words if g_word(w))
        for w in words:
            if (w.value is not None or w.rref is not None) and missing_axis(w.address, axes, dwell, radius):
                column = base + w.col if base >= 0 else st.col
                out.append(word_diagnostic(path, st.line, column, w.address, axes))
    return out + dwell_diagnostics(path, blocks, axes) + refused_g_warnings(SINUMERIK8XX, path, uses)


def _din_blocks(node):
    """The ``(: ... :)`` statements anywhere in a statement list (bodies, branches, CASE alternatives)."""
    if isinstance(node, ast.Din):
        yield node
    elif isinstance(node, (list, tuple)):
        for item in node:
            yield from _din_blocks(item)
    elif isinstance(node, ast.Stmt):
        for f in fields(node):
            yield from _din_blocks(getattr(node, f.name))
