"""NC words for axes the machine lacks: the CPL control's run-time error 1938 ("axis index programmed is not
configured", manual §4.2 L1337, GETERR L2577).

The addresses of a unit's NC blocks are literal, so the blocks that name a missing axis are found once per
unit and run (``ncvm check`` lists them); a unit with none of them runs its generated code untouched. Only
words made at run time (a standalone ``[A$]`` or AXP, manual §4.10) are looked at as they come.
"""

from __future__ import annotations

import re

from ...diagnostics import Diagnostic, Span, read_lines
from ...nc.axiswords import AXIS_LETTERS, is_dwell, is_missing_axis, names_axis
from ...nc.block import row_line
from ...nc.profiles.blockrules import dwell_time, g_conflict
from ...nc.profiles.check import g_column, refused_g_warnings
from ...nc.profiles.typ3osa import TYP3OSA, literal_fault
from ...nc.toolcheck import tool_change_warnings
from . import ast as A
from .errors import CplError, diag

CODE = "1938"
_COMMENT = re.compile(r"\([^)]*\)")


#: the one-letter addresses a function of the Typ3 osa profile reads besides the axes (P: dwell time and
#: circle turns, as the kernel reads them; L: a sub-program call the linker takes)
READ_LETTERS = frozenset(a.letter for a in TYP3OSA.addresses) | frozenset("GMNPL")


def refused_letter(address: str, axes) -> bool:
    """A one-letter address that is no axis letter and that no function of the profile reads (NC007)."""
    return len(address) == 1 and address not in AXIS_LETTERS and address not in READ_LETTERS and address not in axes


def missing_axis_blocks(prog: A.Program, axes, letters: bool = False) -> list[tuple[A.NcBlock, str]]:
    """The NC blocks of ``prog`` with a word for an axis not in ``axes`` (with ``letters``, also with an address
    no function reads), each with the first such address."""
    out = []
    for s in prog.stmts:
        if isinstance(s, A.NcBlock):
            address = next((w.address for w in s.words if (is_missing_axis(w.address, axes) and names_axis(
                w.address, is_dwell(g.value for g in s.words if g.address == "G"))) or (
                letters and refused_letter(w.address, axes))), None)
            if address is not None:
                out.append((s, address))
    return out


def axis_diagnostics(prog: A.Program, axes, lines: list[str] | None) -> list[Diagnostic]:
    """``ncvm check``: error 1938 at each word for a missing axis, with the word's column when it is found."""
    return [diag(CODE, detail(address, axes), prog.path, s.line, _column(lines, s, address), s.cpl)
            for s, address in missing_axis_blocks(prog, axes) if not refused_letter(address, axes)]


def refused_diagnostics(prog: A.Program, axes, lines: list[str] | None) -> list[Diagnostic]:
    """``ncvm check``: warnings for the G functions the Typ3 osa profile refuses (nc/profiles/check.py) and the
    addresses no function reads (NC007), where the run stops."""
    out = []
    for s, address in missing_axis_blocks(prog, axes, letters=True):
        if refused_letter(address, axes):
            d = Diagnostic(LETTER_CODE, f"{letter_detail(address)}: the run stops here",
                           Span(prog.path, s.line, _column(lines, s, address)), severity="warning")
            out.append(d)
    uses = []
    for s in prog.stmts:
        if isinstance(s, A.NcBlock):
            text = lines[s.line - 1] if lines and s.line <= len(lines) else ""
            uses.extend((w.value, s.line, g_column(text, w.value) or s.col or 1) for w in s.words
                        if w.address == "G" and w.value is not None)
    return out + refused_g_warnings(TYP3OSA, prog.path, uses)


def block_rule_diagnostics(prog: A.Program, axes, lines: list[str] | None) -> list[Diagnostic]:
    """``ncvm check``: the blocks whose words the run refuses together (nc/profiles/blockrules.py): two functions
    of one G group (CPL040, as their preparation refuses them: system/gfuncs.py) and a dwell block with a move
    (NC009, the kernel's dwell row). Computed words count with the value 0."""
    out = []
    for s in prog.stmts:
        if not isinstance(s, A.NcBlock):
            continue
        g = [w.value for w in s.words if w.address == "G" and w.value is not None]
        if not g and not any(w.address == "H" for w in s.words):
            continue
        text = lines[s.line - 1] if lines and s.line <= len(lines) else ""
        both = g_conflict(TYP3OSA, g)
        words = {w.address: (w.value if w.value is not None else 0.0) for w in s.words if w.address not in "GM"}
        found = ("CPL040", both[0], "G", both[1]) if both else dwell_time(TYP3OSA, g, words, axes) if g else None
        if found is None:
            literal = {w.address: w.value for w in s.words if w.address not in "GM"}
            found = literal_fault(g, literal, axes, not s.loose)
        if found is not None:
            column = g_column(text, found[3]) if found[2] == "G" else _word_column(text, found[2])
            out.append(_block_diagnostic(found, prog.path, s, column or s.col or 1))
    return out


def _block_diagnostic(found: tuple, path: str, s: A.NcBlock, column: int) -> Diagnostic:
    """A refused block's diagnostic: "not supported by ncvm" (NC004) is a warning of its own category, as
    nc/profiles/check.py gives it; the control's errors are errors."""
    if found[0] == "NC004":
        return Diagnostic("NC004", f"{found[1]}: the run stops here", Span(path, s.line, column), severity="warning")
    return diag(found[0], found[1], path, s.line, column, s.cpl)


def tool_diagnostics(prog: A.Program, tools, lines: list[str] | None) -> list[Diagnostic]:
    """``ncvm check``: NC008 where a literal T word selects a tool the machine file lacks and M6 changes to
    it (nc/toolcheck.py, the kernel's rule; a warning: TC may write table K4, the machine's tools, first)."""
    blocks = []
    for s in prog.stmts:
        if isinstance(s, A.NcBlock):
            t = next((w.value for w in s.words if w.address == "T"), None)
            m6 = any(w.address == "M" and w.value == 6 for w in s.words)
            blocks.append((s.line, _column(lines, s, "T"), t, m6))
    return tool_change_warnings(prog.path, blocks, tools)


def refused_blocks(prog: A.Program, axes) -> dict[int, tuple[str, int]]:
    """For a run: line -> (address, column of its word) of the blocks refused with 1938, where the check
    shows them."""
    found = missing_axis_blocks(prog, axes, letters=True)
    if not found:
        return {}
    lines = read_lines(prog.path)  # only for a unit that has such a block
    return {s.line: (address, _column(lines, s, address)) for s, address in found}


def _column(lines: list[str] | None, s: A.NcBlock, address: str) -> int:
    text = lines[s.line - 1] if lines and s.line <= len(lines) else ""
    return _word_column(text, address) or s.col or 1


def _word_column(text: str, address: str) -> int | None:
    blanked = _COMMENT.sub(lambda m: " " * len(m.group()), text.upper())  # (MSG, ...) and remarks
    m = re.search(rf"(?<![A-Z0-9_$%!?.]){re.escape(address)}(?=\s*[-+=\[.\d])", blanked)
    return m.start() + 1 if m else None


def refusing(rt, enqueue, refused: dict):
    """``enqueue`` for a unit whose blocks on the lines of ``refused`` (:func:`refused_blocks`) name a missing
    axis: such a block is refused with 1938 once the blocks queued before it have run, as if it had been
    executed."""
    def checked(item):
        hit = refused.get(row_line(item) if item.__class__ is tuple else item.src.line)
        if hit is not None:
            refuse(rt, *hit)
        enqueue(item)

    return checked


def check_words(rt, g, words) -> None:
    """Words made at run time (standalone ``[A$]``, AXP): refused as the block is prepared."""
    for address in words:
        if (is_missing_axis(address, rt.kernel.axis_of) and names_axis(address, is_dwell(g))) or refused_letter(
                address, rt.kernel.axis_of):
            refuse(rt, address)


def refuse(rt, address: str, column: int | None = None):
    rt.drain()
    if refused_letter(address, rt.kernel.axis_of):
        raise CplError(LETTER_CODE, letter_detail(address), column)
    raise CplError(CODE, detail(address, rt.kernel.axis_names), column)


LETTER_CODE = "NC007"


def letter_detail(address: str) -> str:
    return f"address {address} is not supported by ncvm (no function of the typ3osa profile reads it)"


def detail(address: str, axes) -> str:
    return f"address {address} (the machine's axes: {' '.join(axes) or 'none'})"
