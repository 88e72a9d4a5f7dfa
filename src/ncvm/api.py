"""The engine of runs, checks and compiles under the command line and the documented Python API
(:mod:`ncvm.public`, docs/api.md).

A run is put together here: the API chooses the canon sinks from the run options (toolpath recorder,
soft-limit check, trace, G-code, plot points), hands them to the :class:`Session` with the run's checks
(front ends add theirs, e.g. CPL work areas) and turns the outcome into a :class:`RunResult`.
"""

from __future__ import annotations

import os
import stat
from functools import partial
from pathlib import Path
from typing import TYPE_CHECKING, Any

from . import records
from .diagnostics import CompileFailed, Diagnostic, Diagnostics, Span, UsageError
from .dialects import REGISTRY, detect_dialect, dialect_of_name, get_dialect
from .machine.config import load_machine, load_scenario
from .machine.model import Machine
from .machine.state import StateLock
from .nc.canon import CanonSink
from .records import Record
from .runtime.checks import Checks
from .runtime.memory import memory_limit
from .runtime.session import RunOptions, RunSinks, Session, run_guarded, set_default_sinks
from .sinks.areas import zone_check
from .sinks.limits import LimitCheck
from .sinks.toolpath import MotionSummary, ToolpathRecorder
from .sinks.workbounds import WorkBounds
from .source import forget_piped, is_pipe, program_name, read_head, read_piped, read_text

if TYPE_CHECKING:  # a run asked for its moves imports it (public.py)
    from .sinks.moves import MoveTable

# The trace, the G-code translation and the plot points are imported by the runs that ask for them (start-up).


def read_source(path: str | Path) -> str:
    try:
        return read_text(path)
    except OSError as e:
        raise UsageError(f"cannot read {path}: {e.strerror}") from None


def resolve(path: str | Path, dialect: str | None) -> tuple[str, str]:
    """(the program's text, its dialect)."""
    text, d = resolve_run(path, dialect)
    return (read_source(path) if text is None else text), d


def resolve_run(path: str | Path, dialect: str | None) -> tuple[str | None, str]:
    """(the program's text, its dialect) for a run or a check: the text is None for a dialect that reads its
    program from the file a stretch at a time (``Dialect.streams``), and the file is not read whole at all
    for it: a dialect told from the file's content is told from its head (issue 18: bounded memory for a
    file of any size)."""
    named = dialect or dialect_of_name(path)
    if is_pipe(path):
        return _piped(path, named)
    forget_piped()  # a file's diagnostics show its own lines, even under the name a pipe had
    text = None
    if named is None:
        text, named = _told_by_content(path)
    elif streams(named):
        try:
            with open(path, "rb"):
                pass
        except OSError as e:
            raise UsageError(f"cannot read {path}: {e.strerror}") from None
    if text is None and not streams(named):
        text = read_source(path)
    return text, named  # a streaming dialect's text: None


def _piped(path: str | Path, dialect: str | None) -> tuple[str, str]:
    """(the text, the dialect) of a program from a pipe (stdin ``-`` or a FIFO): read once, whole (a DIN run
    holds a piped program whole anyway: it cannot read it a second time), the dialect named or told by the
    content; only a dialect that reads its program a stretch at a time takes one (the others read their
    sub-programs and listings from the program's file and folder)."""
    if dialect is not None:
        get_dialect(dialect)  # an unknown one is said before the pipe is read
        if not streams(dialect):
            raise UsageError(pipe_refusal(path, dialect))
    try:
        text = read_piped(path)
    except OSError as e:
        raise UsageError(f"cannot read {program_name(path)}: {e.strerror}") from None
    named = dialect or detect_dialect(program_name(path), text)
    if not streams(named):
        raise UsageError(pipe_refusal(path, named))
    return text, named


def pipe_refusal(path: str | Path, dialect: str) -> str:
    """Why a program of ``dialect`` from a pipe is refused, and which dialects take one."""
    takes = [name for name in REGISTRY if streams(name)]
    return (f"{program_name(path)}: a program from a pipe is read by dialect {' and '.join(takes)} only; a "
            f"{dialect} program is read from its file (give the file)")


def _told_by_content(path: str | Path) -> tuple[str | None, str]:
    """(None, the dialect) of a file from its head (source.read_head); (the whole text, the dialect) of a pipe
    or a device, which can be read once only."""
    try:
        regular = stat.S_ISREG(os.stat(path).st_mode)
        text = read_head(path) if regular else None
    except OSError:
        regular, text = False, None  # read_source says why
    if regular:
        return None, detect_dialect(path, text)
    text = read_source(path)
    return text, detect_dialect(path, text)


def streams(dialect: str) -> bool:
    """Whether ``dialect`` reads its program a stretch at a time (and so takes one from a pipe)."""
    try:
        return get_dialect(dialect).streams
    except UsageError:  # no such dialect: said where it is used
        return False


def machine_for(path: str | Path, machine: Machine | str | Path | None, state_dir: Path = Path(".ncvm")) -> Machine:
    """The given machine, or the built-in default with the program's folder on its program path.

    The built-in machine keeps the controller's files under the state directory.
    """
    if isinstance(machine, Machine):
        return machine
    m = load_machine(machine, base_dir=Path(path).parent)
    if machine is None:
        m.program_path = [Path(path).parent]
        m.file_root = state_dir / "files"
    return m


def check(path: str | Path, dialect: str | None = None, machine: Machine | str | Path | None = None,
          all_errors: bool = False) -> Diagnostics:
    """The program's diagnostics: the first :data:`~ncvm.diagnostics.MAX_KEPT` of them, the others counted (a
    DIN program is read a stretch at a time, as a run reads it)."""
    text, d = resolve_run(path, dialect)
    return Diagnostics.capped(get_dialect(d).check(program_name(path), text, machine_for(path, machine), all_errors))


class RunResult(Record):
    """The outcome of one run; :meth:`to_json` is the document of ``ncvm run --json`` (README.md)."""

    __slots__ = ("dialect", "error", "output", "output_dropped", "variables", "position", "motion", "cycle_time_s",
                 "cycle_time_model", "steps", "limit_violations", "extra", "session", "path", "machine",
                 "move_table")
    #: compared and shown: not the session and the move table (what the caller may use, not the outcome)
    _SHOWN = tuple(f for f in __slots__ if f not in ("session", "move_table"))

    def __init__(self, dialect: str, error: Diagnostic | None, output: list[str], output_dropped: int,
                 variables: dict[str, Any], position: dict[str, float], motion: MotionSummary, cycle_time_s: float,
                 cycle_time_model: str, steps: int, limit_violations: list[str], extra: dict[str, Any],
                 session: Session | None = None, path: str | None = None, machine: str | None = None,
                 move_table: MoveTable | None = None):
        self.dialect = dialect
        self.error = error
        self.output = output
        self.output_dropped = output_dropped  # operator output lines between the kept first and last half
        self.variables = variables
        self.position = position  # workpiece coordinates at the end
        self.motion = motion
        self.cycle_time_s = cycle_time_s
        self.cycle_time_model = cycle_time_model  # "look-ahead", "rest-to-rest" or "card" (rw_SymPas): the model
        self.steps = steps
        self.limit_violations = limit_violations  # soft limits first, then the front end's checks (work areas ...)
        self.extra = extra  # dialect-specific parts of the document (Session.extra)
        #: its recorder, plot points, screen ... for the caller; None for a program run by a batch elsewhere
        self.session = session
        self.path = path  # the program file; None for program text
        self.machine = machine  # the machine file (a batch names it; "built-in": the default machine)
        self.move_table = move_table  # recorded on request only

    def _fields(self) -> tuple[str, ...]:
        return self._SHOWN

    @property
    def status(self) -> str:
        return "error" if self.error else "ok"

    @property
    def failed(self) -> bool:
        """Stopped with an error or violated a limit (a soft limit, a CPL work area): a batch fails it."""
        return bool(self.error or self.limit_violations)

    @property
    def moves(self):
        """Every move of the run as a numpy structured array (:meth:`MoveTable.array`); only a run asked
        for them records them (``ncvm.run(..., moves=True)``)."""
        if self.move_table is None:
            raise ValueError("the moves were not recorded: run the program with ncvm.run(..., moves=True)")
        return self.move_table.array(self.session.axis_labels if self.session else None)

    def moves_frame(self):
        """:attr:`moves` as a pandas DataFrame (the optional extra ``ncvm[frames]``)."""
        try:
            import pandas
        except ImportError:
            raise ImportError("RunResult.moves_frame() needs pandas: pip install 'ncvm[frames]'") from None
        return pandas.DataFrame(self.moves)

    @classmethod
    def from_record(cls, record: dict) -> RunResult:
        """The result of a program as a batch reported it (:mod:`ncvm.archive.report`)."""
        e = record["error"]
        error = None
        if e:
            span = Span(e["file"], e["line"], e["column"]) if e["file"] and e["line"] else None
            error = Diagnostic(e["code"], e["message"], span, notes=list(e.get("stack", ())))
        m = record["motion"]
        motion = MotionSummary(**m) if m else MotionSummary(0, 0, 0, 0.0, 0.0, {})
        return cls(dialect=record["dialect"], error=error, output=record["output_lines"],
                   output_dropped=record.get("output_dropped", 0), variables=record.get("variables", {}),
                   position=record["position"], motion=motion, cycle_time_s=record["cycle_time_s"],
                   cycle_time_model=record.get("cycle_time_model", ""), steps=record["steps"],
                   limit_violations=record["limit_violations"], extra={}, path=record["path"],
                   machine=record["machine"])

    @classmethod
    def of(cls, session: Session, recorder: ToolpathRecorder, error: Diagnostic | None) -> RunResult:
        """The result of ``session``, whose moves ``recorder`` recorded, ended by ``error`` (or None)."""
        labels = session.axis_labels  # the program's axis names (rw_SymPas A1 ...)
        motion = recorder.summary()
        if session.work_bounds is not None:
            motion.bounds_program = session.work_bounds.bounds(motion.bounds)
        if labels:  # the summary is this run's own, as bounds_program above
            for key in ("bounds", "bounds_program"):
                if getattr(motion, key):
                    setattr(motion, key, {labels.get(a, a): b for a, b in getattr(motion, key).items()})
        return cls(
            dialect=session.dialect, error=error, output=session.output.lines(),
            output_dropped=session.output.dropped, variables=dict(session.variables),
            position={labels.get(a, a): v for a, v in session.kernel.workpiece_position().items()}, motion=motion,
            cycle_time_s=session.machine.clock.now,
            cycle_time_model=session.cycle_time_model(),
            # every dialect counts the statements and blocks that ran, never past the limit (docs/decisions.md)
            steps=min(session.steps.steps, session.steps.limit) if error and error.code == "RUN001" else session.steps.steps,
            limit_violations=[v.message() for v in session.checks.violations(session.source_place, labels)],
            extra=dict(session.extra), session=session)

    def to_json(self) -> dict:
        out = {
            "status": self.status,
            "dialect": self.dialect,
            "error": None,
            "output": self.output,
            "output_dropped": self.output_dropped,
            "variables": {k: _jsonable(v) for k, v in self.variables.items()},
            "position": self.position,
            "motion": self.motion.to_json(),
            "cycle_time_s": self.cycle_time_s,
            "steps": self.steps,
            "limit_violations": self.limit_violations,
            "cycle_time_model": self.cycle_time_model,
        }
        out.update({k: _jsonable(v) for k, v in self.extra.items()})
        if self.error:
            e = self.error
            out["error"] = {"code": e.code, "message": e.message, "file": e.span.file if e.span else None,
                            "line": e.span.line if e.span else None, "column": e.span.column if e.span else None}
            if e.notes:
                out["error"]["stack"] = list(e.notes)
        return _jsonable(out)  # no Infinity or NaN anywhere: they are not JSON


def _jsonable(v: Any) -> Any:
    if isinstance(v, (bool, int, str)) or v is None:
        return v
    if isinstance(v, float):
        return v if v == v and v not in (float("inf"), float("-inf")) else str(v)
    if isinstance(v, (list, tuple)):
        return [_jsonable(x) for x in v]
    if isinstance(v, dict):
        return {str(k): _jsonable(x) for k, x in v.items()}
    if hasattr(v, "item"):  # numpy scalars
        return _jsonable(v.item())
    return str(v)


def run_sinks(machine: Machine, options: RunOptions, program: str = "the program") -> RunSinks:
    """The sinks of a run: the toolpath recorder and the soft-limit check always; the trace, the G-code
    and the plot points when the options ask for them; then the caller's ``extra_sinks``. The G-code is
    the LinuxCNC translation of ``program`` (docs/translate.md), put in place by :func:`run_program`."""
    recorder = ToolpathRecorder(keep=options.keep_toolpath)
    checks = Checks(area_check=partial(zone_check, recorder=recorder))
    checks.add(LimitCheck(machine.axes, recorder))  # reported first, before the front end's checks
    work_bounds = WorkBounds(recorder)  # told of the work frame of the moves (a listener of the session's canon)
    canon: list[CanonSink] = [recorder]
    if options.trace:
        from .sinks.trace import JsonlTrace

        canon.append(JsonlTrace(options.trace))
    gcode = None
    if options.gcode:
        from .translate.output import TranslationFile
        from .translate.targets import LINUXCNC

        gcode = TranslationFile(options.gcode, LINUXCNC, program, machine.name,
                                scenario_given=bool(options.scenario or machine.scenario), motion=machine.motion)
        canon.append(gcode.writer)
    canon.extend(options.extra_sinks)
    plot = None
    if options.plot:
        from .sinks.plot import PlotPoints

        plot = PlotPoints(recorder, frame=options.plot_frame)
        canon.append(plot)  # told of the work frame and of the channel (rw_SymPas task) of the moves
    return RunSinks(canon, recorder, checks, plot, gcode, work_bounds)


#: a Session built directly (tests, tools driving a front end) gets the same sinks as a run
set_default_sinks(run_sinks)


def run_program(path: str | Path, dialect: str | None = None, machine: Machine | str | Path | None = None,
                options: RunOptions | None = None) -> RunResult:
    """Run a program on the simulated controller.

    The run (reading the program included) may grow the process by ``options.max_memory``: past it the
    result is error RUN006, or MemoryError when the program could not even be read.
    """
    options = options or RunOptions()
    with memory_limit(options.max_memory):
        text, d = resolve_run(path, dialect)
        front = get_dialect(d)
        m = machine_for(path, machine, options.state_dir)
        if options.scenario:
            # what happens over simulated time in this run, on top of the machine file's own scenario
            # (a copy: a Machine the caller passes again for the next run keeps its own scenario)
            m = records.replace(m, scenario=sorted([*m.scenario, *load_scenario(options.scenario, m.axis_names)],
                                                       key=lambda e: e.time))
        # the controller's memory: one run at a time, refused at once (a translation reads it, writes nothing)
        with StateLock(options.state_dir, reader=options.scratch_state):
            sinks = run_sinks(m, options, Path(program_name(path)).name)
            session = Session(m, options, dialect=d, sinks=sinks)
            for sink in sinks.canon:  # the trace and the moves table name the user's source lines (a CL 800 .cl8)
                if hasattr(sink, "place"):
                    sink.place = lambda src: session.source_place(src)
            error: Diagnostic | None
            try:
                error = run_guarded(session, lambda: front.run(program_name(path), text, session))
            except CompileFailed as e:
                error = e.diagnostics[0]
            except BaseException:
                if sinks.gcode is not None:
                    sinks.gcode.close()
                raise
            finally:
                session.close()
            if sinks.gcode is not None:  # in place, or nothing (a stream: marked incomplete)
                refused = sinks.gcode.complete(error, session.cycle_time_model())
                error = error or refused
    return RunResult.of(session, sinks.recorder, error)


def run(path: str | Path, dialect: str | None = None, machine: Machine | str | Path | None = None,
        options: RunOptions | None = None) -> tuple[dict, Session]:
    """Run a program (as :func:`run_program`); returns the result document of ``ncvm run --json`` and the
    session: the command line's form. The documented Python API is ``ncvm.run`` (:mod:`ncvm.public`)."""
    result = run_program(path, dialect, machine, options)
    return result.to_json(), result.session


def compile_program(path: str | Path, out: str | Path | None = None, xref: str | Path | None = None,
                    dialect: str | None = None, machine: Machine | str | Path | None = None,
                    force: bool = False, xref_named: bool = True) -> Path:
    """Compile a program; without ``out`` the dialect names the object (and the listing, ``xref_named``
    false) and replaces only a file it wrote itself there, or any with ``force``."""
    text, d = resolve(path, dialect)
    return get_dialect(d).compile(str(path), text, machine_for(path, machine),
                                  Path(out) if out else None, Path(xref) if xref else None, force,
                                  xref_named)
