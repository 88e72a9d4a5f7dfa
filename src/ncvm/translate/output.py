"""The file a translation goes to: complete, or not there at all.

A regular file is written as a temporary body beside it and moved into place, header in front, only
when the run ended normally and the writer could say all of it (:meth:`TranslationFile.complete`); a
failed run leaves nothing (an existing file stays as it was). A stream (``/dev/stdout``, a pipe) cannot
wait: its header comes first, the setup summary before the end, and a failed run ends it with a marker
that says the file is incomplete.
"""

from __future__ import annotations

import os
import stat
import tempfile
from pathlib import Path
from typing import TYPE_CHECKING

from ..diagnostics import Diagnostic, NcvmError, Span
from ..outpaths import OutputError, replacing
from .targets import Target
from .writer import Translation

if TYPE_CHECKING:
    from ..machine.model import MotionData

#: every translation starts (after ISO's "%") with a comment that begins so; outpaths.py recognizes
#: a file ncvm wrote by it (and may write it again)
MARK = "written by ncvm"

#: run faults whose cure is an input of the command, with the hint the refusal gives
_NEEDS = {"CPL705": "give the operator's key presses with --keys"}


class TranslationRefused(NcvmError):
    """No output was written; ``diagnostic`` says why (TRN001, TRN002), at the block when there is one."""

    def __init__(self, diagnostic: Diagnostic):
        self.diagnostic = diagnostic
        super().__init__(diagnostic.message)


def written_by_ncvm(head: str) -> bool:
    """Whether a file starting with ``head`` is a translation (or flat G-code) ncvm wrote."""
    first = head.lstrip("%\r\n")
    return first.startswith((f"({MARK}", f"; {MARK}"))


def _is_stream(path: Path) -> bool:
    """Whether ``path`` must be written as it comes: not a regular file (a pipe, a device), a name under
    /dev or /proc (``/dev/stdout`` redirected into a file is still stdout: never replaced) other than the
    ordinary files of the /dev/shm file system, or a file this process already writes through its stdout or
    stderr."""
    for name in (str(path.absolute()), os.path.realpath(path)):
        if name.startswith(("/dev/", "/proc/")) and not name.startswith("/dev/shm/"):
            return True
    try:
        st = os.stat(path)
    except FileNotFoundError:
        return False
    if not stat.S_ISREG(st.st_mode):
        return True
    for fd in (1, 2):
        try:
            if os.path.samestat(st, os.fstat(fd)):
                return True
        except OSError:
            pass
    return False


class TranslationFile:
    """One output of a translation: ``writer`` is the canon sink, :meth:`complete` ends it."""

    def __init__(self, path: str | Path, target: Target, program: str, machine: str, frame: str = "work",
                 source_comments: bool = False, scenario_given: bool = False, stops_passed: bool = False,
                 motion: MotionData | None = None):
        self.path = Path(path)
        #: the file replaced at the end: through symbolic links (a link stays a link)
        self.real = Path(os.path.realpath(self.path))
        self.target = target
        self.program, self.machine = program, machine
        self.stream = _is_stream(self.path)
        try:
            if self.stream:
                self._body = None
                self._f = open(self.path, "w", encoding=target.charset, errors="backslashreplace")
            else:
                fd, name = tempfile.mkstemp(dir=self.real.parent, prefix=f".{self.real.name}.", suffix=".body")
                self._body = Path(name)
                self._f = os.fdopen(fd, "w", encoding=target.charset, errors="backslashreplace")
        except OSError as e:
            raise OutputError(self.path, e) from None
        self.writer = Translation(self._f, target, frame, source_comments, scenario_given, stops_passed, motion)
        self.writer.out_path = self.path
        if self.stream:
            self._write_lines(self._intro() + [target.note("the setup the simulation used is listed at the end")])

    def _intro(self) -> list[str]:
        t = self.target
        return ([t.wrapper] if t.wrapper else []) + [t.note(f"{MARK} from {self.program} for {t.title}")]

    def _write_lines(self, lines: list[str]) -> None:
        try:
            self._f.write("".join(line + "\n" for line in lines))
        except OSError as e:
            raise OutputError(self.path, e) from None

    def complete(self, error: Diagnostic | None, time_model: str | None = None) -> Diagnostic | None:
        """The run is over (``error``: how it failed; ``time_model``: its cycle-time model, as its summary names
        it): put the file in place, or say why there is none."""
        w = self.writer
        w.time_model = time_model
        refusal = None
        if error is not None:
            hint = _NEEDS.get(error.code)
            refusal = Diagnostic("TRN002", "translation refused: the run did not end normally: "
                                 f"{error.code}: {error.message}" + (f" ({hint})" if hint else "") +
                                 self._nothing_written(), error.span, notes=list(error.notes))
        else:
            w.finish_moves()
            if w.refusal is not None:
                r = w.refusal
                src = w.source(r.src) if r.src else None
                refusal = Diagnostic("TRN001", f"translation to {self.target.title} refused: {r.message}"
                                     + self._nothing_written(), Span(src.file, src.line) if src else None)
        try:
            if refusal is not None:
                if self.stream:
                    self._write_lines([self.target.note(f"!!! INCOMPLETE: {refusal.code}: {refusal.message} !!!")])
                    self._f.close()
                return refusal
            if self.stream:
                self._write_lines(w.header(self.program, self.machine))
                w.write_end()
                if self.target.wrapper:
                    self._write_lines([self.target.wrapper])
                self._f.close()
            else:
                w.write_end()
                self._f.close()
                self._assemble()
            return None
        except OSError as e:
            raise OutputError(self.path, e) from None
        finally:
            self.close()

    def _nothing_written(self) -> str:
        """How a refusal ends: a file is left as it was; a stream has had the blocks before the fault."""
        if self.stream:
            return (f"; the output to {self.path} is INCOMPLETE: the blocks before this went out, the rest "
                    "and the program end did not")
        return "; no output written"

    def close(self) -> None:
        """Close and drop the temporary body (after :meth:`complete`, or when the run did not start)."""
        try:
            self._f.close()
        except OSError:
            pass
        if self._body is not None:
            self._body.unlink(missing_ok=True)

    def _assemble(self) -> None:
        """Intro + header + body (+ the tape wrapper) into a temporary file beside the output, moved into place."""
        header = self._intro() + self.writer.header(self.program, self.machine)
        with replacing(self.real, ".part") as name, \
                open(name, "w", encoding=self.target.charset, errors="backslashreplace") as f, \
                open(self._body, encoding=self.target.charset) as b:
            f.write("".join(line + "\n" for line in header))
            for line in b:
                f.write(line)
            if self.target.wrapper:
                f.write(self.target.wrapper + "\n")
