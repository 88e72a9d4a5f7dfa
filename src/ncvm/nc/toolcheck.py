"""A tool change to a tool the machine file does not have: the kernel's NC008 at M6, and ``ncvm check``'s
warning at the literal T word that selects it (issue 14 §5: a clean check means the run will not stop on
what the machine lacks). One rule for both: :func:`missing_tool`.

The check follows the blocks in the order they are written (a jump may change which T an M6 takes) and
warns, not errs: a program may write its tool table before the change (CPL's TC into table K4), or a run
may start from a kept state that has the tool.
"""

from __future__ import annotations

from ..diagnostics import Diagnostic, Span


def missing_tool(number, tools) -> str | None:
    """Why an M6 cannot load tool ``number`` (None: it can; T0 empties the spindle)."""
    if number and number not in tools:
        return f"tool {number:g} is not in the tool table"
    return None


def tool_change_warnings(path: str, blocks, tools) -> list[Diagnostic]:
    """``blocks``: (line, column of the T word, literal T value or None, the block has a literal M6) in
    program order. NC008 at each T word whose tool an M6 then changes to and the machine lacks, once per tool."""
    return ToolChanges(path, tools).warnings(blocks)


class ToolChanges:
    """:func:`tool_change_warnings` over a program given a stretch of blocks at a time (a DIN file of any
    length is checked without holding it)."""

    def __init__(self, path: str, tools):
        self.path = path
        self.tools = tools
        self.selected = None  # (value, line, column) of the last literal T word
        self.warned = set()

    def warnings(self, blocks) -> list[Diagnostic]:
        """The warnings of the next ``blocks`` of the program (as :func:`tool_change_warnings` takes them)."""
        out = []
        for line, column, value, m6 in blocks:
            if value is not None:
                self.selected = (value, line, column)
            if m6 and self.selected is not None and self.selected[0] not in self.warned:
                fault = missing_tool(self.selected[0], self.tools)
                if fault is not None:
                    self.warned.add(self.selected[0])
                    out.append(Diagnostic("NC008", f"{fault} of the machine file: the run stops at the tool "
                                          f"change M6 (line {line})", Span(self.path, self.selected[1],
                                                                           self.selected[2]), severity="warning"))
        return out
