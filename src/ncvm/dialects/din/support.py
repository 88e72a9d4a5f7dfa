"""What the `din` profile runs, and the warnings of ``ncvm check`` for what it refuses.

A run stops at a G function the kernel does not implement (NC004; NC005 for cutter radius compensation)
and at an address no function of the profile reads (NC007). ``ncvm check`` reports each such function
and address as a *warning* with the code the run stops with, and the words "not supported by ncvm", so
a check without warnings means the run will not stop on an unsupported function; errors stay the
program's own (the syntax, the axes of the machine). ``tests/dialects/din/test_support.py`` holds this
table against the kernel: every G number the table lacks faults there, every one it has does not.
"""

from __future__ import annotations

import re

from ...diagnostics import Diagnostic, Span
from ...nc.axiswords import AXIS_LETTERS
from ...nc.block import WORD, PlainRun
from ...nc.profiles import Profile
from ...nc.profiles.blockrules import block_refusal
from ...nc.profiles.check import count_g_use, g_column, grouped_g_warnings
from ...nc.profiles.iso import ISO

#: the G functions the profile runs (its rows, nc/profiles/iso.py)
G_FUNCTIONS = frozenset(g for g, row in ISO.by_g.items() if not row.code)
#: the addresses its functions read besides the axes (O: a program number, as ISO controls read it; it does
#: nothing); every other letter is refused (NC007), an axis letter the machine lacks is NC011 (nc/axiswords.py)
ADDRESSES = frozenset("DFGHIJKLMNOPQRST")
_COMMENTS = re.compile(r"\([^)]*\)|;.*")


def refused_address(blk, axes) -> str | None:
    """The first address of ``blk`` the profile refuses (an axis letter the machine lacks is NC011's)."""
    return next((a for a in blk.words if _refused_letter(a, axes)), None)


def _refused_letter(address: str, axes) -> bool:
    return address not in ADDRESSES and address not in axes and address not in AXIS_LETTERS


def _refused_g(g, words) -> bool:
    """A G function the iso profile does not run, or G10 other than L2 P1..P6."""
    return g not in G_FUNCTIONS or (g == 10 and (words.get("L") != 2 or words.get("P") not in (1, 2, 3, 4, 5, 6)))


def block_error(path: str, blk, line_text: str, found: tuple) -> Diagnostic:
    """The control's refusal of ``blk`` (``found``: what :func:`~ncvm.nc.profiles.blockrules.block_refusal`
    returned) as an error at the word it names."""
    code, message, letter, value = found
    return Diagnostic(code, message, Span(path, blk.src.line, _column(line_text, letter, value)))


def block_errors(path: str, segments: list, line_at, axes, profile: Profile) -> list[Diagnostic]:
    """``ncvm check``: the blocks that break a block rule of the control (two functions of one modal group,
    rs274's rules: nc/profiles/blockrules.py); plain runs keep every rule (one motion code, no M, no D).
    ``line_at(n)``: source line ``n``."""
    out = []
    for seg in segments:
        if not isinstance(seg, PlainRun):
            blk = seg[0]
            found = block_refusal(profile, blk.g, blk.m, blk.words, axes)
            if found is not None:
                out.append(block_error(path, blk, line_at(blk.src.line), found))
    return out


def address_refusal(path: str, blk, line_text: str, address: str) -> Diagnostic:
    return Diagnostic("NC007", f"address {address} is not supported by ncvm (no function of the din profile "
                               "reads it)", Span(path, blk.src.line, _column(line_text, address, None)))


class Unsupported:
    """Warnings for the G functions and addresses of a program the run would refuse: the first block of
    each, with the number of blocks that use it, gathered a stretch of the program at a time (:meth:`add`).
    With another profile than iso ([din] profile) its G table judges the G functions (nc/profiles/check.py);
    the rows its dialect runs are refused here."""

    def __init__(self, path: str, axes, profile: Profile = ISO):
        self.path = path
        self.axes = axes
        self.profile = profile
        self.found: dict = {}  # (kind, what) -> [first block, count, its source line]
        self.g_uses: dict = {}  # another profile's G functions: nc/profiles/check.py count_g_use

    def add(self, segments: list, line_at) -> None:
        """The next ``segments`` of the program; ``line_at(n)``: source line ``n``."""
        for seg in segments:
            if isinstance(seg, PlainRun):
                continue  # G0-G3 and X Y Z I J K F only
            blk = seg[0]
            for g in blk.g:
                if self.profile is not ISO:
                    count_g_use(self.g_uses, g, blk.src.line, g_column(line_at(blk.src.line), g))
                elif _refused_g(g, blk.words):
                    self._count(("G", g), blk, line_at)
            for a in blk.words:
                if _refused_letter(a, self.axes):
                    self._count(("A", a), blk, line_at)

    def _count(self, key, blk, line_at) -> None:
        if key not in self.found:
            self.found[key] = [blk, 0, line_at(blk.src.line)]
        self.found[key][1] += 1

    def warnings(self) -> list[Diagnostic]:
        out = []
        for (kind, what), (blk, count, text) in self.found.items():
            more = f"; {count} blocks use it" if count > 1 else ""
            if kind == "G":
                row = ISO.refused(what)
                name = f"G{what:g} ({row.meaning})" if row else f"G{what:g}"
                d = Diagnostic("NC004", f"{name} is not supported by ncvm: the run stops here{more}",
                               Span(self.path, blk.src.line, _column(text, "G", what)), severity="warning")
                if what == 10:
                    d.message = f"G10 other than G10 L2 P1..P6 is not supported by ncvm: the run stops here{more}"
            else:
                d = address_refusal(self.path, blk, text, what)
                d.severity, d.message = "warning", d.message + f": the run stops here{more}"
            out.append(d)
        if self.g_uses:
            out += grouped_g_warnings(self.profile, self.path, self.g_uses, dialect_runs=False)
        return out


def tool_blocks(segments: list, line_at) -> list:
    """The blocks of ``segments`` as :class:`~ncvm.nc.toolcheck.ToolChanges` takes them (NC008 where a T word
    selects a tool the machine lacks and M6 changes to it: the kernel's rule)."""
    blocks = []
    for seg in segments:
        if isinstance(seg, PlainRun):
            continue  # no T, no M
        blk = seg[0]
        t = blk.words.get("T")
        blocks.append((blk.src.line, _column(line_at(blk.src.line), "T", t) if t is not None else None, t,
                       6 in blk.m))
    return blocks


def _column(text: str, letter: str, value) -> int | None:
    """The column of the word ``letter`` (with ``value``, when given) in a line, comments left out."""
    body = _COMMENTS.sub(lambda m: " " * len(m.group()), text.upper())
    for mt in WORD.finditer(body):
        if mt.group(1) == letter and (value is None or float(mt.group(2)) == value):
            return mt.start(1) + 1
    return None
