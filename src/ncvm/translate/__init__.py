"""``ncvm translate``: a program for a modern control (LinuxCNC, SINUMERIK 840D, ISO / Fanuc style) from
the run of a legacy one, safe by construction (docs/translate.md).

The program runs on the simulated controller with a :class:`~ncvm.translate.writer.Translation` among its
canon sinks. Its lines go to a temporary file beside the output; only a run that ended normally, and
that the writer could say all of, is moved into place, with the header of what the simulation used in
front. Otherwise nothing is written and :class:`TranslationRefused` says why.
"""

from __future__ import annotations

import dataclasses
import os
import tempfile
from dataclasses import dataclass
from pathlib import Path

from ..diagnostics import Diagnostic, NcvmError, Span
from ..machine.model import Machine
from ..runtime.session import RunOptions
from .targets import TARGETS, Target
from .writer import Translation

#: run faults whose cure is an input of the translate command, with the hint the refusal gives
_NEEDS = {"CPL705": "give the operator's key presses with --keys"}


class TranslationRefused(NcvmError):
    """No output was written; ``diagnostic`` says why (TRN001, TRN002), at the block when there is one."""

    def __init__(self, diagnostic: Diagnostic):
        self.diagnostic = diagnostic
        super().__init__(diagnostic.message)


@dataclass
class Translated:
    """A translation written: where, for which target, and what it holds."""

    path: Path
    target: Target
    lines: int
    moves: int
    frozen: int
    probes: int
    tools: dict[int, float]  # tool offset number -> the (last) length the simulation used


def translate(program: str | Path, out: str | Path, target: str = "linuxcnc", frame: str = "work",
              source_comments: bool = False, dialect: str | None = None, machine: Machine | str | Path | None = None,
              options: RunOptions | None = None) -> Translated:
    """Run ``program`` and write it as ``target``'s program to ``out`` (replaced only when all went well)."""
    from .. import api  # the API puts runs together; it imports no translation

    tgt = TARGETS[target]
    options = dataclasses.replace(options or RunOptions(), keyboard=False, echo=False)
    out = Path(out)
    m = api.machine_for(program, machine, options.state_dir)
    fd, body_name = tempfile.mkstemp(dir=out.parent, prefix=f".{out.name}.", suffix=".body")
    body = Path(body_name)
    try:
        with os.fdopen(fd, "w", encoding="ascii", errors="replace") as f:
            writer = Translation(f, tgt, frame, source_comments, scenario_given=bool(options.scenario or m.scenario))
            options.extra_sinks = [*options.extra_sinks, writer]
            result = api.run_program(program, dialect, m, options)
            if result.error is not None:
                raise TranslationRefused(_run_failed(result.error))
            writer.finish()
        if writer.refusal is not None:
            r = writer.refusal
            raise TranslationRefused(Diagnostic("TRN001", f"translation to {tgt.title} refused: {r.message}; "
                                                "no output written", Span(r.src.file, r.src.line) if r.src else None))
        _assemble(out, writer.header(Path(program).name, m.name or "the machine file"), body, tgt)
    finally:
        body.unlink(missing_ok=True)
    s = writer.setup
    return Translated(out, tgt, writer.lines, writer.moves, s.frozen, s.probes,
                      {n: lengths[-1] for n, lengths in s.tools.items()})


def _run_failed(error: Diagnostic) -> Diagnostic:
    hint = _NEEDS.get(error.code)
    why = f"{error.code}: {error.message}" + (f" ({hint})" if hint else "")
    return Diagnostic("TRN002", f"translation refused: the run did not end normally: {why}; no output written",
                      error.span, notes=list(error.notes))


def _assemble(out: Path, header: list[str], body: Path, target: Target) -> None:
    """Header + body (+ the tape wrapper) into a temporary file beside ``out``, then moved into place."""
    fd, name = tempfile.mkstemp(dir=out.parent, prefix=f".{out.name}.", suffix=".part")
    try:
        with os.fdopen(fd, "w", encoding="ascii", errors="replace") as f, open(body, encoding="ascii") as b:
            if target.wrapper:
                f.write(target.wrapper + "\n")
            f.write("\n".join(header) + "\n")
            for line in b:
                f.write(line)
            if target.wrapper:
                f.write(target.wrapper + "\n")
        os.replace(name, out)
    except BaseException:
        Path(name).unlink(missing_ok=True)
        raise
