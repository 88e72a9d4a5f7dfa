"""The documented Python API (docs/api.md): what ``import ncvm`` offers.

``run`` and ``check`` take a program file or program text, ``batch`` a list of programs and folders as
``ncvm run`` does (the same discovery, machine files, pool and cluster: :mod:`ncvm.archive`). They build
on the engine of :mod:`ncvm.api`, which the command line uses too.

A ``str`` with a line end is program text; any other ``str`` or a ``Path`` names a program file (or a FIFO
a DIN program is written to, read once). Program
text runs as a file of its own in a temporary folder (a dialect that reads or writes files next to its
program does so there); errors name it ``<text>``; sub-programs it calls are found in the current
directory, or on the program path of the machine file given.
"""

from __future__ import annotations

import tempfile
from contextlib import contextmanager
from pathlib import Path

from . import api, records
from .archive.batch import run_batch
from .archive.report import write as write_report
from .diagnostics import Diagnostic, Diagnostics, UsageError
from .dialects import REGISTRY, detect_dialect, get_dialect
from .machine.config import load_machine
from .machine.model import Machine
from .runtime.companions import KEYS_SUFFIX, SCENARIO_SUFFIX, beside
from .runtime.session import RunOptions
from .runtime.steps import DEFAULT_MAX_STEPS
from .sinks.moves import MoveTable
from .source import STDIN_ARG, is_pipe

#: the name program text goes by in results and diagnostics
TEXT_NAME = "<text>"

MachineLike = Machine | str | Path | None


def run(program: str | Path, dialect: str | None = None, machine: MachineLike = None, *, moves: bool = False,
        options: RunOptions | None = None, **option_fields) -> api.RunResult:
    """Run a program (a file, or program text) on the simulated controller; a :class:`~ncvm.api.RunResult`.

    ``machine``: a :class:`Machine`, a machine file, or None: the ``machine.toml`` of the program's folder
    when there is one, else the built-in 3-axis mill. ``moves``: record every move (``result.moves``,
    ``result.moves_frame()``); without it a run keeps only totals, as ``ncvm run`` does, so that a long
    program runs in bounded memory. Further keywords are fields of :class:`RunOptions` (``max_steps``,
    ``state_dir``, ``keys``, ``scenario``, ``time_model`` ...), or pass ``options`` whole.
    """
    options = _options(options, option_fields)
    table = MoveTable() if moves else None
    if table is not None:
        options.extra_sinks = [*options.extra_sinks, table]
    with _program_file(program, dialect) as (path, text_dialect):
        m = _machine(path, machine, options.state_dir, is_text=text_dialect is not None)
        if text_dialect is None:  # the program's own key presses and scenario, as ncvm run and batch take them
            own = beside(path)
            options.keys = options.keys or own.get(KEYS_SUFFIX)
            options.scenario = options.scenario or own.get(SCENARIO_SUFFIX)
        result = api.run_program(path, text_dialect or dialect, m, options)
        if result.error is not None and result.error.code == "RUN004":
            # Ctrl-C is the operator's, not an error of the program: the run has closed its files, and the
            # script that called it stops as Python scripts do
            raise KeyboardInterrupt
        result.move_table = table
        result.path = None if text_dialect else str(program)
        result.machine = _machine_name(machine, path)
        if text_dialect:  # the temporary file is <text>
            result.error = _text_named(result.error, path)
            result.limit_violations = [v.replace(str(path), TEXT_NAME) for v in result.limit_violations]
            if table is not None:
                table.file_names[str(path)] = TEXT_NAME
    return result


def check(program: str | Path, dialect: str | None = None, machine: MachineLike = None,
          all_errors: bool = False) -> Diagnostics:
    """The errors the control would report for a program (a file, or program text), without running it:
    :class:`Diagnostic` objects (``code``, ``message``, ``span`` with ``file``, ``line``, ``column``;
    ``notes``). Empty: the program is fine. ``all_errors``: go on after the first error. The first
    :data:`~ncvm.diagnostics.MAX_KEPT` are listed; ``left_out`` counts the others by severity."""
    with _program_file(program, dialect) as (path, text_dialect):
        m = _machine(path, machine, Path(".ncvm"), is_text=text_dialect is not None)
        found = api.check(path, text_dialect or dialect, m, all_errors)
        return Diagnostics([_text_named(d, path) for d in found], found.left_out) if text_dialect else found


class Batch(list):
    """The results of a batch (a list of :class:`RunResult`, one per main program in the order found), with
    the files skipped and why, the summary, and the report of ``ncvm run --report``."""

    def __init__(self, document: dict):
        super().__init__(api.RunResult.from_record(r) for r in document["programs"])
        self.document = document
        self.skipped: list[dict] = document["skipped"]  # {"path", "reason"}
        self.summary: dict = document["summary"]

    def write_report(self, path: str | Path) -> None:
        """The report as ``--report`` writes it: .json, .csv or JUnit .xml by the file's extension."""
        write_report(self.document, path)


def batch(paths, dialect: str | None = None, machine: str | Path | None = None, jobs: int | None = None,
          cluster: str | None = None, state: str | Path = ".ncvm", shared_state: bool = False,
          max_steps: int = DEFAULT_MAX_STEPS, max_memory: int | None = None) -> Batch:
    """Run every main program of ``paths`` (files and folders) as ``ncvm run PATHS...`` does (docs/batch.md):
    the same programs, machine files, results. ``jobs``: local processes (default: the cores; 1: this
    process); ``cluster``: the address of a dask scheduler (``ncvm[cluster]``). ``state``: the permanent
    state every program starts from, as ``--state`` (a copy each, an absent one empty; ``shared_state``:
    that directory itself, in turn, its writes kept)."""
    if jobs and cluster:
        raise UsageError("jobs and cluster exclude each other: the cluster's workers run the programs")
    if isinstance(paths, (str, Path)):
        paths = [paths]
    doc = run_batch([str(p) for p in paths], dialect, str(machine) if machine else None, jobs=jobs,
                    cluster=cluster, state=state, shared_state=shared_state, max_steps=max_steps,
                    max_memory=max_memory, details=True)
    return Batch(doc)


def _options(options: RunOptions | None, fields: dict) -> RunOptions:
    known = set(RunOptions.FIELDS)
    unknown = sorted(set(fields) - known)
    if unknown:
        raise TypeError(f"unknown run option(s) {', '.join(unknown)}; the options are {', '.join(sorted(known))}")
    options = records.replace(options or RunOptions(), **fields)
    for name in ("state_dir", "trace", "gcode", "keys", "scenario", "screen", "screen_dir"):
        value = getattr(options, name)
        if isinstance(value, str):
            setattr(options, name, Path(value))
    return options


@contextmanager
def _program_file(program: str | Path, dialect: str | None):
    """The program as a file, and the dialect of program text (None for a file): program text is written
    to a temporary folder, removed after."""
    if isinstance(program, str) and ("\n" in program or "\r" in program):
        try:
            d = dialect or detect_dialect(TEXT_NAME, program)
        except UsageError as e:  # the command line's words for the API's
            raise UsageError(str(e).replace("pass --dialect", "pass dialect=")) from None
        get_dialect(d)  # an unknown dialect is a usage error that lists the known ones
        ext = REGISTRY[d].extensions[0]
        with tempfile.TemporaryDirectory(prefix="ncvm-text-") as tmp:
            path = Path(tmp) / f"program{ext}"
            path.write_text(program, encoding="latin-1")
            yield path, d
        return
    path = Path(program)
    fifo = str(path) != STDIN_ARG and is_pipe(path)  # a DIN program a writer gives (api.resolve_run)
    if not path.is_file() and not fifo:
        raise UsageError(f"no such program file: {program} (program text is a str with a line end)")
    yield (path.absolute() if str(path) == STDIN_ARG else path), None  # a file named "-" is a file, not stdin


def _machine(path: Path, machine: MachineLike, state_dir: Path, is_text: bool) -> Machine:
    if machine is None and not is_text and (path.parent / "machine.toml").is_file():
        machine = path.parent / "machine.toml"  # the program's folder's machine file, as ncvm run takes it
    m = api.machine_for(path, machine, state_dir)
    if is_text and machine is None:
        m.program_path = [Path.cwd()]  # program text calls the programs of the current directory
    elif is_text:
        m.program_path = [*m.program_path, Path.cwd()]
    return m


def _machine_name(machine: MachineLike, path: Path) -> str:
    if isinstance(machine, Machine):
        return machine.name
    if machine is not None:
        return str(machine)
    own = path.parent / "machine.toml"
    return str(own) if own.is_file() else "built-in"


def _text_named(d: Diagnostic | None, path: Path) -> Diagnostic | None:
    """``d`` with the temporary file of program text named ``<text>``."""
    if d is None or d.span is None or d.span.file != str(path):
        return d
    return records.replace(d, span=records.replace(d.span, file=TEXT_NAME))


__all__ = ["Batch", "Machine", "RunOptions", "batch", "check", "load_machine", "run"]
