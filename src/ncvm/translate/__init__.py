"""``ncvm translate``: a program for a modern control (LinuxCNC, SINUMERIK 840D, ISO / Fanuc style) from
the run of a legacy one, safe by construction (docs/translate.md).

The program runs on the simulated controller with a :class:`~ncvm.translate.writer.Translation` among its
canon sinks; :class:`~ncvm.translate.output.TranslationFile` puts the output in place only when the run
ended normally and the writer could say all of it, else :class:`TranslationRefused` says why.
"""

from __future__ import annotations

import dataclasses
import shutil
import tempfile
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path

from .. import records
from ..diagnostics import Diagnostic
from ..machine.model import Machine
from ..machine.state import StateError
from ..runtime.interrupt import Terminated, ended_by_termination
from ..runtime.session import RunOptions
from .output import TranslationFile, TranslationRefused
from .targets import TARGETS, Target

__all__ = ["TARGETS", "Terminated", "Translated", "TranslationFile", "TranslationRefused", "translate"]


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
    warnings: list[str] = dataclasses.field(default_factory=list)  # the run's limit violations, as run says them
    #: TRN003 at its block: where the file does what the simulated control did not, or what its machine made of it
    diagnostics: list[Diagnostic] = dataclasses.field(default_factory=list)


def translate(program: str | Path, out: str | Path, target: str = "linuxcnc", frame: str = "work",
              source_comments: bool = False, dialect: str | None = None, machine: Machine | str | Path | None = None,
              options: RunOptions | None = None) -> Translated:
    """Run ``program`` and write it as ``target``'s program to ``out`` (replaced only when all went well)."""
    from .. import api  # the API puts runs together and writes ``run --gcode`` through this package

    options = records.replace(options or RunOptions(), keyboard=False, echo=False, gcode=None, scratch_state=True)
    given = api.machine_for(program, machine, options.state_dir)
    m = _past_programmed_stops(given)
    stops_passed = m is not given
    with _scratch_files(m) as m, ended_by_termination("translation", "no output written"):
        return _translate(program, out, target, frame, source_comments, dialect, m, options, stops_passed)


def _translate(program, out, target, frame, source_comments, dialect, m: Machine, options: RunOptions,
               stops_passed: bool) -> Translated:
    from .. import api

    file = TranslationFile(out, TARGETS[target], Path(program).name, m.name, frame, source_comments,
                           scenario_given=bool(options.scenario or m.scenario), stops_passed=stops_passed,
                           motion=m.motion)
    try:
        options.extra_sinks = [*options.extra_sinks, file.writer]
        result = api.run_program(program, dialect, m, options)
    except BaseException:
        file.close()
        raise
    refusal = file.complete(result.error, result.cycle_time_model)
    if refusal is not None:
        raise TranslationRefused(refusal)
    w = file.writer
    return Translated(Path(out), file.target, w.lines, w.moves, w.setup.frozen, w.setup.probes,
                      {n: lengths[-1] for (_, n, _), lengths in w.setup.tools.items()}, list(result.limit_violations),
                      list(w.warnings))


def _past_programmed_stops(m: Machine) -> Machine:
    """The machine with SINUMERIK ``m0 = "stop"`` read as ``"continue"``: that setting ends a simulated run at
    M0, but the new control stops at the written M0 and the operator's cycle start runs the rest, so the
    translation is the whole program, M0 included (docs/decisions.md)."""
    sec = m.sections.get("sin800")
    if not isinstance(sec, dict) or sec.get("m0") != "stop":
        return m
    return records.replace(m, sections={**m.sections, "sin800": {**sec, "m0": "continue"}})


@contextmanager
def _scratch_files(m: Machine):
    """The machine with a scratch copy of its file root (the controller's files): what the program writes,
    erases or reads back ends with the translation, which leaves the user's files as it found them, so
    translating twice gives the same file (docs/translate.md)."""
    root = Path(m.file_root)
    with tempfile.TemporaryDirectory(prefix="ncvm-files-") as folder:
        copy = Path(folder) / root.name
        try:
            if root.is_dir():
                shutil.copytree(root, copy, symlinks=True)
        except (OSError, shutil.Error) as e:
            raise StateError(f"cannot read the controller's files in {root} ({e})") from None
        yield records.replace(m, file_root=copy, file_root_origin=root)
