"""Programs excluded from linking: ``CALL name DIN`` or ``(DIN)`` in their first line (manual §3.3 L1096-1121).

Such a program may hold DIN blocks only. CPL in it, including CPL syntax inside NC blocks (``X[expr]``,
a standalone ``[A$]``, a variable as a call parameter), is a run-time error (CPL030). Its G/M/P sub-program
calls run, with constant parameters: the PDIM example of §3.4 (L1161-1175) calls ``P SP["TEST"]`` from such a
program, and the string constant reaches the sub-program as one passed without linking. A sub-program only
such a program reaches was not linked with the main program; it is linked when it is called.
"""

from __future__ import annotations

from ...diagnostics import CompileFailed, Diagnostic
from ...nc.block import Block
from ...nc.canon import Src
from ...source import read_text
from . import ast as A
from .axiswords import CODE as AXIS_CODE
from .axiswords import detail, refused_blocks
from .errors import CplError, diag, fault
from .linker import call_table, find_din_program, link, link_one
from .system.gfuncs import prepare
from .system.transforms import NO_TRAVEL_G

AXIS_LETTERS = frozenset("XYZABCUVW")


def run_unlinked(rt, target: str, name: str) -> None:
    """Run the DIN blocks of ``target`` on the runtime ``rt`` (its queue, its calls, its modal sub-program)."""
    text = read_text(target)
    ln = link_one(target, text, rt.calls)
    found = cpl_in(ln, name)
    if found is not None:
        _excluded(rt, target, *found)
    refused = refused_blocks(ln.prog, rt.kernel.axis_of)
    for s in ln.prog.stmts:
        if s.skip:
            rt.block_skip_read(Src(target, s.line))
            if rt.block_skip:
                continue
        if s.line in refused:  # a word for an axis the machine lacks (1938), once the blocks before it ran
            rt.drain()
            address, column = refused[s.line]
            raise fault(AXIS_CODE, detail(address, rt.kernel.axis_names), target, s.line, s.cpl, column=column)
        words = {w.address: w.value for w in s.words if w.address not in ("G", "M")}
        g = tuple(int(w.value) if w.value == int(w.value) else w.value for w in s.words if w.address == "G")
        m = tuple(int(w.value) for w in s.words if w.address == "M" and w.value not in (2, 30))
        if g or m or words or s.msg is not None:
            rt.enqueue(prepare(rt, Block(g, m, words, s.n, s.msg, Src(target, s.line))))
        if 80 in g:
            rt.modal[0] = None
        elif (rt.modal[0] is not None and any(a[0] in AXIS_LETTERS for a in words) and not NO_TRAVEL_G.intersection(g)
              and not (s.call is not None and s.call[2])):  # a new selection runs the new cycle only
            rt.modal_call(target, s.line)
        if s.call is not None:
            prog, args, modal = s.call
            values = _constants(args, name, s.line)
            rt.call(target, prog, values, False, s.line)
            if modal:
                rt.modal[0] = (prog, values)
        if s.wait:
            rt.drain()
        if s.ends:
            return


def cpl_in(ln, name: str) -> tuple[str, A.Stmt] | None:
    """The first CPL element of a program excluded from linking, as (what it is, where), or None."""
    for s in ln.prog.stmts:
        if not isinstance(s, A.NcBlock):
            return f"{name} contains CPL blocks", s
        if any(w.expr is not None for w in s.words) or s.loose:
            return f"{name} uses CPL expressions [ ] in an NC block (line {s.line})", s
        if s.call is not None:
            try:
                _constants(s.call[1], name, s.line)
            except CplError as e:
                return e.detail, s
    if ln.prog.diagnostics:
        d = ln.prog.diagnostics[0]
        return f"{name} contains CPL blocks", A.Stmt(d.span.line, d.span.column or 1)
    return None


def din_call_warnings(res, machine) -> list[Diagnostic]:
    """What ``ncvm check`` can say of the CALL ... DIN sub-programs, which are not linked (L1097) and fail
    only when the call runs: one that holds CPL (CPL030, L1104), one not there (yet: a program may write it
    before the call). Warnings: the run is not refused for them."""
    calls = call_table(machine)
    out = []
    for ln in res.units.values():
        for name, din, s in ln.calls:
            if not din:
                continue
            found = find_din_program(machine, name)
            if found is None:
                detail, code = f"{name} is not there now; CALL ... DIN looks for it when the call runs", "CPL005"
            else:
                try:
                    hit = cpl_in(link_one(str(found), read_text(found), calls), name)
                except OSError:
                    continue  # the run reports it when the call is reached
                if hit is None:
                    continue
                detail, code = f"{hit[0]}: the run stops when the call is reached", "CPL030"
            d = diag(code, detail, ln.prog.path, s.line, s.col or None, s.cpl)
            d.severity = "warning"
            out.append(d)
    return out


def _excluded(rt, target: str, detail: str, s: A.Stmt):
    """CPL030. In a sub-program the error points at the call (the caller's position); an excluded main program
    has no caller, so the error points at the offending block itself."""
    if rt.stack:
        raise CplError("CPL030", detail)
    raise fault("CPL030", detail, target, s.line, s.cpl, column=s.col or 1)


def _constants(args: list, name: str, line: int) -> tuple:
    """The parameters of a call in a DIN program: constants only (a variable or an expression is CPL)."""
    out = []
    for a in args:
        neg = isinstance(a, A.Unary) and a.op == "-"
        e = a.operand if neg else a
        if isinstance(e, A.Num):
            out.append(-e.value if neg else e.value)
        elif not neg and isinstance(e, (A.Str, A.BoolLit)):
            out.append(e.value)
        elif not neg and e is None:
            out.append(None)
        else:
            raise CplError("CPL030", f"{name} passes a CPL expression as a sub-program parameter (line {line})")
    return tuple(out)


def link_late(rt, target: str) -> None:
    """Link a program reached only through an excluded one, with the programs it reaches, before it runs;
    a link error stops the run as it would stop the start of a linked program. "(DIN)" keeps it unlinked."""
    res = link(target, read_text(target), rt.machine)
    if res.main.prog.din_only:
        return
    if res.diagnostics:
        raise CompileFailed(res.diagnostics)
    rt.linked.units.update(res.units)
    rt.linked.resolve.update(res.resolve)
