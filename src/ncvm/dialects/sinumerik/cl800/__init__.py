"""Siemens CL 800 cycle language (WS 800 A): check, compile to @ code, run on the SINUMERIK 800 NC.

``check`` reports the WS 800 A's messages (the first error, or all with
``--all``); ``compile`` writes the object program ``%SPF<n>`` and optionally the
cross-reference listing; ``run`` compiles and hands the @ code to the ``sin800``
dialect, as the object program was loaded into the NC.
"""

from __future__ import annotations

import re
from dataclasses import asdict, dataclass
from pathlib import Path

from ....diagnostics import CompileFailed, RuntimeFault, Span, UsageError
from ....machine.config import dialect_options
from ....nc.canon import Src
from ....outpaths import refuse_overwrite, write_output
from ....records import replace
from ... import get_dialect
from ...base import Dialect
from .. import SubProgramLibrary
from ..options import options as sin800_options
from . import ast
from .axiswords import axis_diagnostics
from .checker import check_program
from .codegen import MARK, ObjectProgram, compile_program, marked, written_by_ncvm
from .errors import CompilerMessage
from .stopdec import nc_diagnostics

_SNIFF = re.compile(r"^\s*(PROGRAM\s+\d+\s*;|EXTERNAL\s+\d+\s*;|CHANNEL\s+NC\s+\d+|BEGIN\b|END\.|ENDEXTERN)", re.M)


def search_path(path: str, machine) -> list[Path]:
    """Where GLOBAL/CENTRAL lists are looked for: next to the program, then the machine's program path."""
    folders = [Path(path).parent]
    for p in getattr(machine, "program_path", []) or []:
        if Path(p) not in folders:
            folders.append(Path(p))
    return folders


@dataclass(frozen=True)
class Options:
    """The machine file's [cl800] section (docs/cl800.md; its schema is machine/sections.py's CL800)."""

    strict: bool = False  # drop the compiler's leniencies
    control: str = "880"  # the target control: 810, 820, 850 or 880


#: the [cl800] keys and their defaults
OPTIONS = asdict(Options())


def options(machine) -> Options:
    """The [cl800] section of the machine; an unknown key or a wrong value is a usage error."""
    return dialect_options(Options, getattr(machine, "sections", {}), "cl800")


_PROGRAM_START = re.compile(r"\s*PROGRAM\b")


def _strip_comments(text: str) -> str:
    return re.sub(r"\(\*.*?\*\)", lambda m: "\n" * m.group(0).count("\n"), text, flags=re.S)


def _last_text_line(text: str) -> tuple[int, str]:
    """(line number, text) of the last line that holds more than blanks and comments."""
    lines = _strip_comments(text).split("\n")
    for n in range(len(lines), 0, -1):
        if lines[n - 1].strip():
            return n, lines[n - 1].strip()
    return 1, ""


class Cl800Dialect(Dialect):
    id = "cl800"

    def sniff(self, text: str) -> int:
        hits = len(_SNIFF.findall(text[:20000]))
        return min(100, 30 * hits)

    def analyse(self, path: str, text: str, machine):
        opts = options(machine)
        prog, sym, errors = check_program(path, text, search_path(path, machine), opts.strict, opts.control)
        return prog, sym, errors

    def check(self, path, text, machine, all_errors=False):
        prog, sym, errors = self.analyse(path, text, machine)
        diags = [e.diagnostic() for e in errors]
        errs = [d for d in diags if d.severity == "error"]
        if not all_errors and errs:
            return [errs[0]]
        if not errs and isinstance(prog, ast.Program):
            try:
                obj = compile_program(path, prog, sym)  # S064, S120, S125-S127 show only while generating code
            except CompilerMessage as e:
                diags.append(e.diagnostic())
            else:
                diags += nc_diagnostics(path, obj, SubProgramLibrary(machine).find)
        radius = sin800_options(machine).radius_address  # the NC's machine data, [sin800]
        return diags + axis_diagnostics(path, prog, machine.axis_names, radius)

    def build(self, path: str, text: str, machine) -> ObjectProgram:
        last = _last_text_line(text)
        if _PROGRAM_START.match(_strip_comments(text)) and not re.search(r"\bEND\s*\.\s*$", last[1]):
            # the WS 800 A compiles only a program file that ends with END.<CR> (E300, L6236)
            raise CompileFailed([CompilerMessage("E300", path, last[0], None, "the file does not end with END.")
                                 .diagnostic()])
        prog, sym, errors = self.analyse(path, text, machine)
        errs = [e for e in errors if not e.code.startswith("W")]
        if errs:
            raise CompileFailed([errs[0].diagnostic()])
        if isinstance(prog, ast.ExtList):
            raise UsageError(f"{path}: external lists are not compiled (WS 800 A compiles programs only)")
        try:
            return compile_program(path, prog, sym)
        except CompilerMessage as e:
            raise CompileFailed([e.diagnostic()]) from None

    def compile(self, path, text, machine, out, xref, force=False, xref_named=True):
        """The object program; with ``xref`` the cross-reference listing instead, which a dedicated
        compilation writes without object code (L361), unless ``out`` asks for the object as well.
        Without ``out`` the object is ``L<n>.spf`` beside the source, and a listing whose name the user did
        not give (``xref_named`` false) is the source's, ``.lst``: such a file is replaced only as ncvm
        wrote it (its mark line), or any with ``force``."""
        obj = self.build(path, text, machine)
        if xref:
            refuse_overwrite("compile", Path(xref), path)
            if not xref_named and not force:
                _refuse_a_file_ncvm_did_not_write(Path(xref), "--xref LISTING")
            write_output(Path(xref), marked(obj.xref()))
            if not out:
                return Path(xref)
        target = Path(out) if out else Path(path).with_name(f"L{obj.number}.spf")
        refuse_overwrite("compile", target, path)
        if not out and not force:
            _refuse_a_file_ncvm_did_not_write(target)
        write_output(target, obj.file_text())
        return target

    def run(self, path, text, session):
        obj = self.build(path, text, session.machine)
        obj_path = str(Path(path).with_name(f"L{obj.number}.spf"))
        session.source_place = _ObjectPlaces(path, obj_path, obj).source
        try:
            get_dialect("sin800").run(obj_path, obj.text(), session)
        except RuntimeFault as fault:
            where = _ObjectPlaces(path, obj_path, obj)
            fault.notes += where.note(fault.span)
            fault.span = where.place(fault.span)
            fault.stack = [replace(f, span=where.place(f.span)) for f in fault.stack]
            raise
        except CompileFailed as failed:  # the NC's reader refused a block (DIN code the compiler passed on)
            where = _ObjectPlaces(path, obj_path, obj)
            for d in failed.diagnostics:
                d.notes = where.note(d.span) + d.notes
                d.span = where.place(d.span)
            raise


def _refuse_a_file_ncvm_did_not_write(target: Path, option: str = "-o") -> None:
    """The name ncvm chose may be a file someone wrote or edited by hand (``L101.spf``, ``prog.lst``): keep it."""
    try:
        text = target.read_text(encoding="latin-1")
    except FileNotFoundError:
        return
    except OSError as e:
        raise UsageError(f"compile {target}: cannot read the file there: {e.strerror}") from None
    if not written_by_ncvm(text):
        raise UsageError(f"compile {target}: the file exists and ncvm did not write it (no {MARK} line at its end, "
                         "or the file was changed since ncvm wrote it); "
                         f"give another name with {option}, or --force to overwrite it")


class _ObjectPlaces:
    """Places in the object program, which a run of the source never writes to disk, as the CL 800
    statements that produced their blocks; the object block itself goes into a note."""

    def __init__(self, path: str, obj_path: str, obj: ObjectProgram):
        self.path, self.obj_path, self.obj = path, obj_path, obj

    def place(self, span: Span | None) -> Span | None:
        if span is None or span.file != self.obj_path:
            return span
        return Span(self.path, self.obj.source_line(span.line, span.column))

    def source(self, src: Src, column: int | None = None) -> Src:
        """``src`` (a block the NC ran) as a place in the source: where M0 lines, limit messages and the
        trace point; ``column``: the statement whose words stand there (an IF INT that reads an input)."""
        if src.file != self.obj_path:
            return src
        if column is not None:
            return Src(self.path, self.obj.source_line(src.line, column))
        return Src(self.path, self.obj.executed_line(src.line))

    def note(self, span: Span | None) -> list[str]:
        if span is None or span.file != self.obj_path or not 2 <= span.line <= len(self.obj.blocks) + 1:
            return []
        return [f"object program {Path(self.obj_path).name} line {span.line}: "
                f"{self.obj.blocks[span.line - 2].text()}"]


DIALECT = Cl800Dialect()
