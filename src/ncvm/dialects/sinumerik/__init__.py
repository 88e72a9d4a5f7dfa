"""SINUMERIK 800 NC (dialect ``sin800``): runs @ code part programs and the DIN blocks around them.

Main programs (``%MPF<n>``, ``.mpf``) and sub-programs (``%SPF<n>``, ``.spf``,
the object text the CL 800 compiler writes) are read into blocks, compiled to
one Python function each (codegen) and run on one NC channel (runtime) that
drives the shared NC kernel. Sub-programs ``L<n>`` are found as ``L<n>.spf``
or as a file starting ``%SPF<n>`` along the machine's program path.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

from ...diagnostics import CompileFailed, Diagnostic, RuntimeFault, Span
from ...machine.files import heads
from ...nc.canon import NOBODY, Src
from ...runtime.codegen import PySource
from ...source import read_text
from ..base import Dialect
from .codegen import UnitCodegen, axis_diagnostics, refused_g_diagnostics, tool_diagnostics
from .drilling import missing_cycle_warnings
from .lint import stop_dec_lint
from .ncdata import NAMESPACE, NcData
from .options import options
from .reader import PartProgram, Word, read_program
from .rounding import rounding_diagnostics
from .runtime import NAMESPACE_GLOBALS, Channel
from .v24 import PROGRAM_SUFFIXES

_HEADER = re.compile(r"^\s*%\s*(SPF|MPF)\s*(\d+)\s*$", re.I | re.M)
_AT = re.compile(r"@[0-9a-f]{3}\b", re.I)
_SPF_NAME = re.compile(r"^(?:L|SPF)?0*(\d+)$", re.I)


@dataclass
class Unit:
    """One compiled part program."""

    path: str
    program: PartProgram
    source: PySource
    fn: object
    written: frozenset[int] = frozenset()


def compile_unit(path: str, text: str, axis_names: tuple[str, ...], name: str, debug: bool = False,
                 decode_ahead: bool = False, strict: bool = False, radius: str = "B") -> Unit:
    prog, diags = read_program(path, text)
    if diags:
        raise CompileFailed(diags)
    gen = UnitCodegen(prog, name, axis_names, debug, decode_ahead, strict, radius)
    source, consts = gen.build()
    namespace = dict(NAMESPACE_GLOBALS)
    namespace.update(consts)
    exec(source.compile(), namespace)
    return Unit(path, prog, source, namespace["_unit"], frozenset(gen.written))


def sub_program_calls(prog: PartProgram) -> list[tuple[int, int, int]]:
    """(number, line, column) of each literal ``L<n>`` call of a program (an ``L=R..`` call is the run's)."""
    return [(int(it.value), blk.line, it.col) for blk in prog.blocks for it in blk.items
            if isinstance(it, Word) and it.address == "L" and it.value is not None]


class SubProgramLibrary:
    """Finds, reads and compiles sub-programs L<n> along the program path, once each."""

    def __init__(self, machine, debug: bool = False, decode_ahead: bool = False, strict: bool = False,
                 radius: str = "B"):
        self.machine = machine
        self.debug = debug
        self.decode_ahead = decode_ahead
        self.strict = strict
        self.radius = radius
        self.units: dict[int, Unit | None] = {}

    def __call__(self, number: int) -> Unit | None:
        if number not in self.units:
            path = self.find(number)
            if path is None:
                self.units[number] = None
            else:
                text = read_text(path)
                self.units[number] = compile_unit(str(path), text, self.machine.axis_names, f"L{number}",
                                                  self.debug, self.decode_ahead, self.strict, self.radius)
        return self.units[number]

    def find(self, number: int) -> Path | None:
        for name in (f"L{number}", f"SPF{number}", f"{number}"):
            p = self.machine.find_program(name, (".spf", ".SPF"))
            if p is not None:
                return p
        for p, head in heads(self.machine.program_path, PROGRAM_SUFFIXES):
            m = _HEADER.search(head)
            if m and m.group(1).upper() == "SPF" and int(m.group(2)) == number:
                return p
        return None


class Sin800Dialect(Dialect):
    id = "sin800"

    def sniff(self, text: str) -> int:
        head = text.lstrip()[:20].upper().replace(" ", "")
        if head.startswith("%SPF") or head.startswith("%MPF"):
            return 95
        return 70 if _AT.search(text) else 0

    def check(self, path, text, machine, all_errors=False):
        """Every program the run enters by a literal ``L<n>`` is checked too (as the CPL check follows CALL); a
        sub-program the run does not find is warned RUN002 at its call, as a missing drilling cycle L81 is."""
        library = SubProgramLibrary(machine)
        todo, seen, out = [(path, text)], {str(path)}, []
        while todo:
            at, body = todo.pop(0)
            prog, diags = read_program(at, body)
            if diags:
                out += diags if all_errors else diags[:1]
                continue
            out += self._check_program(prog, machine, library)
            for number, line, column in sub_program_calls(prog):
                found = library.find(number)
                if found is None:
                    out.append(Diagnostic("RUN002", f"sub-program L{number} not found (looked for L{number}.spf and "
                                          f"%SPF{number} files along the program path): the run stops here",
                                          Span(prog.path, line, column), severity="warning"))
                elif str(found) not in seen:
                    seen.add(str(found))
                    todo.append((str(found), read_text(found)))
        return out

    @staticmethod
    def _check_program(prog: PartProgram, machine, library) -> list:
        radius = options(machine).radius_address
        # the lint (§10.5) and what the run will refuse are warnings
        cycles = missing_cycle_warnings(prog, library.find)
        return (axis_diagnostics(prog, machine.axis_names, radius) + refused_g_diagnostics(prog) + cycles
                + stop_dec_lint(prog) + tool_diagnostics(prog, machine.tools) + rounding_diagnostics(prog, radius, machine.axis_names))

    def run(self, path, text, session):
        """Run a main program or @ code object text (``%SPF<n>`` / ``%MPF<n>``)."""
        machine = session.machine
        debug = session.steps.hook is not None
        sec = options(machine)
        ahead = sec.decode_ahead > 0
        strict = sec.strict_nc
        unit = compile_unit(path, text, machine.axis_names, "main", debug, ahead, strict, sec.radius_address)
        data = NcData.from_machine(machine)
        store = session.store
        stored = store.items(NAMESPACE)
        data.overlay(stored, session.options.state_dir)
        for offset in data.carried_offsets(stored, machine.axis_names):  # never a silent shift
            session.say(f"NC state: {offset} kept from an earlier run (the NC keeps its offsets; "
                        f"delete {session.options.state_dir} to start from the machine file)")
        library = SubProgramLibrary(machine, debug, ahead, strict, sec.radius_address)
        channel = Channel(session, data, library, stored)
        data.store = store  # NC data the program changes are written through (NcData.changed)
        if session.kernel.canon.frozen is not NOBODY:  # a sink marks input from outside the program (translate)
            channel.left = {int(n): float(v) for n, v in stored.get("central_r", {}).items() if v != 0.0}
        name = f"%{unit.program.kind}{unit.program.number}" if unit.program.kind else Path(path).name
        initial = list(channel.R)
        try:
            try:
                channel.run_unit(unit, name, None)
            except (RuntimeFault, CompileFailed, MemoryError) as stop:
                raise channel.execute_decoded(stop) from None
            channel.stop_dec()  # the end of the program: every decoded block executes
            if not session.kernel.ended and not channel.halted:
                last = unit.program.blocks[-1].line if unit.program.blocks else 1
                session.kernel.end_program(Src(path, last))
        finally:
            written = set(unit.written)
            for sub in library.units.values():
                if sub is not None:
                    written |= sub.written
            self._finish(session, channel, data, initial, written)

    def _finish(self, session, channel: Channel, data: NcData, initial: list, written: set) -> None:
        """Persist what the NC keeps and the program's statements have not written through yet (the PRESET
        offsets taking effect, what a fault or Ctrl-C stopped on its way); report R parameters that are
        non-zero, changed or written."""
        data.preset_takes_effect()  # at program end or, after a fault, at the reset that follows (L3240)
        channel.central.check()
        data.changed()
        R = channel.R
        session.variables = {f"R{n}": R[n] for n in range(1000)
                             if R[n] != 0.0 or R[n] != initial[n] or n in written}
        if channel.panel.v24:
            session.variables["V24"] = list(channel.panel.v24)


DIALECT = Sin800Dialect()
