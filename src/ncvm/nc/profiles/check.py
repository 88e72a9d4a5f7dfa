"""``ncvm check`` sees what the run will refuse (issue 14 §5): each G function of a program that the
control's profile refuses, or that the profile does not have, is a *warning* with the code the run stops
with (NC004, NC005 for a refused cutter radius compensation) and the words "not supported by ncvm" -- a
category of its own beside the control's errors, so a check without them means the run will not stop on
an unsupported function. The first block of each is named, with the number of blocks that use it.
"""

from __future__ import annotations

import re

from ...diagnostics import Diagnostic, Span
from . import DIALECT, Profile

_COMMENTS = re.compile(r"\([^)]*\)|;.*")


def refused_g_warnings(profile: Profile, path: str, uses, dialect_runs: bool = True) -> list[Diagnostic]:
    """``uses``: (G number, line, column or None) of every constant G word of a program, in program order.
    ``dialect_runs``: the profile's own dialect runs the rows it takes out of the block (a ``din`` program
    read with another control's profile has no such front end: those rows are refused too)."""
    grouped: dict = {}
    for g, line, column in uses:
        count_g_use(grouped, g, line, column)
    return grouped_g_warnings(profile, path, grouped, dialect_runs)


def count_g_use(grouped: dict, g, line: int, column: int | None) -> None:
    """One use of G ``g`` into ``grouped``: G number -> [first line, its column, blocks that use it]."""
    grouped.setdefault(g, [line, column, 0])[2] += 1


def grouped_g_warnings(profile: Profile, path: str, grouped: dict, dialect_runs: bool = True) -> list[Diagnostic]:
    """:func:`refused_g_warnings` of the uses :func:`count_g_use` gathered (a program read a stretch at a time)."""
    by_g = profile.by_g
    out = []
    for g, (line, column, count) in grouped.items():
        row = by_g.get(g)
        if not (row is None or row.code or (not dialect_runs and row.status == DIALECT)):
            continue
        what = f"G{g:g} ({row.meaning})" if row else f"G{g:g} (not a G function of the {profile.name} profile)"
        more = f"; {count} blocks use it" if count > 1 else ""
        out.append(Diagnostic(row.code if row and row.code else "NC004", f"{what} is not supported by ncvm: the run stops here{more}",
                              Span(path, line, column), severity="warning"))
    return out


def g_column(text: str, g) -> int | None:
    """The column of the word G<g> in a source line (comments left out), None when it is not written there."""
    body = _COMMENTS.sub(lambda m: " " * len(m.group()), text.upper())
    if g != int(g):
        return None
    m = re.search(rf"(?<![A-Z0-9_$%!?.])G\s*0*{int(g)}(?![\d.])", body)
    return m.start() + 1 if m else None
