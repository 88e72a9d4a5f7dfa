"""Bosch Rexroth CPL (Customer Programming Language, Typ3 osa / PNC): CPL blocks mixed with DIN 66025 NC blocks.

Pipeline: lexer (line classification, tokens) -> parser (flat statements) -> linker (structure pairing,
jump targets, sub-programs; cached by content) -> checker (types, type errors) -> codegen (Python source)
-> runtime (motion queue, permanents, calls) -> NC kernel.
"""

from __future__ import annotations

import re

from ...diagnostics import CompileFailed, read_lines
from ...source import lines as program_lines
from ..base import Dialect
from .axiswords import axis_diagnostics, block_rule_diagnostics, refused_diagnostics, tool_diagnostics
from .checker import check
from .codegen import generate
from .lexer import ETX
from .linker import link
from .linktables import LinkTables
from .runtime import CplRuntime
from .unlinked import din_call_warnings

_CPL_LINE = re.compile(r"^\s*\d+\s*(REM|IF|FOR|WHILE|GOTO|CALL|DIM|CASE|[A-Z#@][A-Z0-9_]*[%!?$]?\s*(\(.*\))?\s*=)",
                       re.I)


class CplDialect(Dialect):
    id = "cpl"

    def sniff(self, text: str) -> int:
        lines = [ln for ln in program_lines(text) if ln.strip()]
        if lines and lines[-1].startswith(ETX):  # the control's end-of-file marker: a file it kept (L3867)
            return 100
        lines = lines[:200]
        if not lines:
            return 0
        hits = sum(1 for ln in lines if _CPL_LINE.match(ln))
        return min(100, int(300 * hits / len(lines)))

    def link(self, path, text, machine, tables=None):
        res = link(path, text, machine, tables)
        diags = list(res.diagnostics)
        for ln in res.units.values():  # type errors of every program whose own blocks link (check lists them all)
            if not ln.diagnostics:
                if ln.unit is None:
                    types, more = check(ln)
                    uc, more = (None, more) if more else generate(ln, types)
                    if more:
                        diags.extend(more)
                    else:
                        ln.unit = uc
                        if tables is not None:
                            tables.save(ln.prog.path, ln.key, ln)
        files = {p: k for k, p in enumerate(dict.fromkeys(d.span.file for d in diags if d.span))}
        diags.sort(key=lambda d: (files[d.span.file], d.span.line, d.span.column or 0) if d.span else (-1, 0, 0))
        return res, diags

    def check(self, path, text, machine, all_errors=False):
        res, diags = self.link(path, text, machine)
        for ln in res.units.values():
            lines = program_lines(text) if ln.prog.path == path else read_lines(ln.prog.path)
            diags += axis_diagnostics(ln.prog, machine.axis_names, lines)
            diags += refused_diagnostics(ln.prog, machine.axis_names, lines)
            diags += block_rule_diagnostics(ln.prog, machine.axis_names, lines)
            diags += tool_diagnostics(ln.prog, machine.tools, lines)
        return diags + din_call_warnings(res, machine)

    def run(self, path, text, session):
        tables = LinkTables(session.options.state_dir / "link", session.machine.file_root,
                            read_only=session.options.scratch_state)
        res, diags = self.link(path, text, session.machine, tables)
        if diags:
            raise CompileFailed(diags)
        CplRuntime(session, res).run_main()


DIALECT = CplDialect()
