"""LinuxCNC's own extensions of G-code in a `din` program, named once instead of line by line.

rs274ngc reads more than DIN 66025 / ISO 6983: numbered and named parameters (``#1``, ``#<depth>``),
O-word sub-programs, loops and conditions (``o100 sub``, ``o<x> if [...]``), and expressions in
brackets (``X[#1 + 2]``, ``sin[30]``). ncvm's `din` runs plain blocks only, so each such line is a syntax
error (NC001); a program written for LinuxCNC had hundreds of them. The reader's NC001 diagnostics of
those lines become one NC013 that says what the program is.
"""

from __future__ import annotations

import re

from ...diagnostics import Diagnostic, Span

# The patterns are compiled (into re's cache) when a program first has a syntax error, not at every start-up.
_COMMENTS = r"\([^)]*\)|;.*"
#: (what, how it shows in a line without its comments)
FEATURES = (
    ("named parameters (#<name>)", r"#\s*<"),
    ("# parameters", r"#\s*[\d\[]"),
    ("O-words (sub-programs, loops, conditions)", r"(?i)^\s*(?:/\s*)?(?:N\d+\s*)?O\s*(?:<|\d+\s*[A-Z])"),
    ("expressions in brackets", r"\["),
)


def fold_extensions(diags: list[Diagnostic], line_at) -> list[Diagnostic]:
    """``diags`` with the NC001 of every line that uses a LinuxCNC extension replaced by one NC013 (at the
    first such line); the other diagnostics as they are. ``line_at(n)``: source line ``n`` of an NC001 (or
    None)."""
    extensions = Extensions()
    kept = [d for d in diags if not extensions.take(d, line_at)]
    folded = extensions.folded()
    if folded is None:
        return diags
    return sorted([folded, *kept], key=lambda d: (d.span.line, d.span.column or 0) if d.span else (0, 0))


class Extensions:
    """The LinuxCNC extensions of a program, found in its NC001 diagnostics one at a time (a check reads a
    DIN file a stretch at a time): :meth:`take` each, :meth:`folded` at the end."""

    def __init__(self):
        self.used: dict[str, None] = {}
        self.first: Diagnostic | None = None
        self.count = 0

    def take(self, d: Diagnostic, line_at) -> bool:
        """True when ``d`` is the NC001 of a line that uses an extension (it goes into the NC013)."""
        line = line_at(d.span.line) if d.code == "NC001" and d.span else None
        body = re.sub(_COMMENTS, "", line) if line is not None else None
        found = [what for what, pattern in FEATURES if body is not None and re.search(pattern, body)]
        if not found:
            return False
        self.used.update(dict.fromkeys(found))
        self.count += 1
        self.first = self.first or d
        return True

    def folded(self) -> Diagnostic | None:
        """The one NC013 for every line taken (None: no line used an extension)."""
        if self.first is None:
            return None
        what = ", ".join(self.used)
        lines_text = "1 line" if self.count == 1 else f"{self.count} lines"
        first = self.first.span
        return Diagnostic("NC013", f"this is a LinuxCNC program, not DIN 66025: it uses LinuxCNC's extensions of "
                                   f"G-code ({what}; {lines_text}, the first here), which ncvm does not run (README: "
                                   f"which .ngc files run)", Span(first.file, first.line, first.column))
