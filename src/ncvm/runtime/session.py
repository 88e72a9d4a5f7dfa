"""One run of one program on one simulated controller.

A :class:`Session` wires the machine, the permanent store and the NC kernel to the canon sinks the API
chose (api.py builds them: toolpath recorder, soft-limit check, trace, G-code, plot), and gives the
front ends what they share: operator output, step counter, variables to report, the run's checks
(:class:`~ncvm.runtime.checks.Checks`, where a front end adds its own). The API turns it into the result
of ``ncvm run`` (``api.RunResult``).
"""

from __future__ import annotations

import sys
from collections import deque
from pathlib import Path
from typing import Any, Callable, Protocol

from ..diagnostics import Diagnostic, RuntimeFault
from ..machine.model import Machine
from ..machine.store import Store
from ..nc.canon import Canon, CanonSink, Src
from ..nc.kernel import NcKernel, programmed_stop_line
from ..records import Record
from . import interrupt
from .checks import Checks
from .memory import default_max_memory, out_of_memory
from .steps import DEFAULT_MAX_STEPS, StepCounter, StepHook

#: operator output lines a result keeps: the first half and the last half of this many (docs/decisions.md)
MAX_OUTPUT_LINES = 20_000


#: an option not given (where None is a value a caller may give)
_DEFAULT: Any = object()


class RunOptions(Record):
    """How one run is made: its state directory, limits, sinks and operator input. A record (``records.replace``
    makes a changed copy; ``RunOptions.FIELDS`` names what a caller may set), not a dataclass: every run builds
    one at start-up."""

    FIELDS = ("state_dir", "scratch_state", "max_steps", "trace", "gcode", "plot", "plot_frame", "keep_toolpath",
              "max_output_lines", "max_memory", "echo", "hook", "extra_sinks", "keys", "keyboard", "editor_block",
              "scenario", "time_model", "screen", "screen_dir", "on_session", "on_operator_wait", "mmc_client")
    __slots__ = FIELDS

    def __init__(self, state_dir: Path = Path(".ncvm"), scratch_state: bool = False,
                 max_steps: int = DEFAULT_MAX_STEPS, trace: Path | None = None, gcode: Path | None = None,
                 plot: bool = False, plot_frame: str = "work", keep_toolpath: bool = False,
                 max_output_lines: int = MAX_OUTPUT_LINES, max_memory: Any = _DEFAULT, echo: bool = False,
                 hook: StepHook | None = None, extra_sinks: list[CanonSink] | None = None,
                 keys: Path | Any | None = None, keyboard: bool = False, editor_block: str | None = None,
                 scenario: Path | None = None, time_model: str | None = None, screen: Path | None = None,
                 screen_dir: Path | None = None, on_session: Callable[["Session"], None] | None = None,
                 on_operator_wait: Callable[[bool], None] | None = None,
                 mmc_client: Callable[[list, list], tuple] | None = None):
        self.state_dir = state_dir
        #: read the permanent data of ``state_dir`` and keep this run's changes in memory only (``ncvm translate``)
        self.scratch_state = scratch_state
        self.max_steps = max_steps
        self.trace = trace
        self.gcode = gcode
        self.plot = plot  # collect the (thinned) points of a toolpath plot while the program runs (session.plot)
        self.plot_frame = plot_frame  # the plot's coordinates: "work" (the program's) or "machine"
        self.keep_toolpath = keep_toolpath  # keep every move (session.recorder.arrays()); else only totals and checks
        self.max_output_lines = max_output_lines  # operator output lines kept for the result (first and last half)
        #: bytes the run may grow the process by; 0: no limit (not given: runtime.memory's default)
        self.max_memory = default_max_memory() if max_memory is _DEFAULT else max_memory
        self.echo = echo  # print operator output to stdout as it happens
        self.hook = hook
        self.extra_sinks = [] if extra_sinks is None else extra_sinks
        #: operator key presses and typed values for dialog programs: a key script file, or one read already
        self.keys = keys
        self.keyboard = keyboard  # without a key script: the operator types keys on stdin (a terminal)
        self.editor_block = editor_block  # the NC block selected in the editor, for a CPL editor dialog
        self.scenario = scenario  # scenario file: inputs, probe triggers, ... over simulated time
        #: "lookahead" or "rest-to-rest": the cycle-time model instead of the machine file's ``[motion] model``
        self.time_model = time_model
        self.screen = screen  # save the operator screen as it stands at the end (PNG)
        self.screen_dir = screen_dir  # save one screen picture per wait for the operator (softkey, input)
        self.on_session = on_session  # told of the session as soon as it exists
        #: told when the run starts (True) and stops (False) waiting for the operator at the terminal (keyboard)
        self.on_operator_wait = on_operator_wait
        #: CPL MMC (manual ch. 9): the client, ``client(names, values) -> (rc, {name: new value})``; None = no client
        self.mmc_client = mmc_client


class MoveLog(Protocol):
    """The sink that records the moves (the API's toolpath recorder): checks watch it, the progress line
    counts it."""

    def __len__(self) -> int: ...


class RunSinks(Record):
    """The sinks of one run as the API chose them (api.run_sinks): the canon sinks, the one of them that
    records the moves, the checks of the recorded moves and the points of a toolpath plot (kept for the
    caller to draw). Empty: the kernel moves and nothing is recorded."""

    __slots__ = ("canon", "recorder", "checks", "plot", "gcode", "work_bounds")

    def __init__(self, canon: list[CanonSink] | None = None, recorder: MoveLog | None = None,
                 checks: Checks | None = None, plot: Any = None, gcode: Any = None, work_bounds: Any = None):
        self.canon = [] if canon is None else canon
        self.recorder = recorder
        self.checks = Checks() if checks is None else checks
        self.plot = plot
        self.gcode = gcode  # the --gcode translation file (translate.output.TranslationFile), completed by the API
        self.work_bounds = work_bounds  # the bounds in the program's work frame (sinks.workbounds.WorkBounds)


#: the sinks of a session built without them: api.py installs its choice when it is imported (the ncvm
#: package imports it), so runtime/ neither chooses nor imports a sink
_default_sinks: Callable[[Machine, RunOptions], RunSinks] | None = None


def set_default_sinks(choose: Callable[[Machine, RunOptions], RunSinks]) -> None:
    global _default_sinks
    _default_sinks = choose


class Session:
    """Everything one run shares between a front end, the kernel and the sinks (see :class:`RunSinks`)."""

    def __init__(self, machine: Machine, options: RunOptions | None = None, dialect: str = "",
                 sinks: RunSinks | None = None):
        self.machine = machine
        self.options = options or RunOptions()
        self.dialect = dialect
        self.output = OperatorOutput(self.options.max_output_lines)
        self.variables: dict[str, Any] = {}
        #: dialect-specific parts of the result document (e.g. the rw_SymPas card's LPR recordings)
        self.extra: dict[str, Any] = {}
        self.controller: Any = None  # the dialect's controller of this run (the rw_SymPas card), for tools
        self.steps = StepCounter(self.options.max_steps, self.options.hook)
        chosen = sinks or (_default_sinks(machine, self.options) if _default_sinks else RunSinks())
        self.recorder = chosen.recorder
        self.plot = chosen.plot
        self.work_bounds = chosen.work_bounds
        #: the checks of the recorded moves; a front end adds its own (e.g. CPL's work areas and dead ranges)
        self.checks = chosen.checks
        sinks = chosen.canon
        self.sinks = sinks
        self.canon = Canon(sinks)
        if self.work_bounds is not None:  # a listener: a front end that tells one frame for the run removes it
            self.canon.add(self.work_bounds)
        #: where a place of the program the NC runs stands in the user's source: itself, except for a
        #: program compiled to another one first (a CL 800 run's object program, which is never on disk)
        #: (``column``: the statement at that column of the block, where one block holds several: a CL 800 IF INT
        #: and the DIN words after it)
        self.source_place: Callable[..., Src] = _same_place
        #: the program's names of machine axes it names otherwise (rw_SymPas A1 ...): the result reports
        #: positions, bounds and limit violations under them (api.RunResult)
        self.axis_labels: dict[str, str] = {}
        messages = OperatorMessages(self.say, lambda src: self.source_place(src))
        self.canon.add(messages)
        self.kernel = messages.kernel = NcKernel(machine, self.canon)
        if self.options.time_model:
            self.kernel.planner.model = self.options.time_model
        #: the cycle-time model when a front end times its moves itself (rw_SymPas: "card"), else None
        self.time_model: str | None = None
        self._store: Store | None = None
        #: the operator screen of dialects that have one (CPL dialogs); anything with ``save_png(path)``
        self.screen = None
        #: told when the session has closed, while the run still holds its state directory (:meth:`when_closed`)
        self._closed: list[Callable[[], None]] = []
        if self.options.on_session:
            self.options.on_session(self)

    # -- shared services -------------------------------------------------
    @property
    def store(self) -> Store:
        """The permanent store, opened on first use (a run that keeps nothing creates no store file)."""
        if self._store is None:
            self._store = Store(self.options.state_dir, self.options.scratch_state)
        return self._store

    def say(self, text: str) -> None:
        """A line shown to the operator (screen, message window)."""
        for line in str(text).split("\n"):
            self.output.append(line)
            if self.options.echo:
                print(line, flush=True)

    # -- the run ---------------------------------------------------------
    def cycle_time_model(self) -> str:
        """The run's cycle-time model as its summary names it: the kernel's, or "card" where the front end
        timed its moves itself (rw_SymPas)."""
        return self.time_model or self.kernel.time_model()

    def close(self) -> None:
        self.kernel.planner.stop()  # the moves still waiting are timed (they end at rest) before the sinks end
        for s in self.sinks:
            s.end()
        if self._store is not None:
            self._store.close()
            self._store = None
        for told in self._closed:
            told()

    def when_closed(self, told: Callable[[], None]) -> None:
        """Call ``told()`` once the session has closed (its store synced), still inside the run's hold of the
        state directory: what the run left there is then its own, no other run's (a batch's comparison)."""
        self._closed.append(told)

def _same_place(src: Src, column: int | None = None) -> Src:
    return src


def run_guarded(session: Session, runner) -> Diagnostic | None:
    """Call ``runner()``; a run-time fault becomes a Diagnostic. CompileFailed and bugs propagate."""
    try:
        with interrupt.deferring():
            runner()
    except RuntimeFault as f:
        return f.diagnostic()
    except RecursionError:
        return Diagnostic("RUN003", "call nesting too deep (recursion without end?)", None)
    except KeyboardInterrupt:
        if session.options.on_operator_wait is not None:  # the progress line leaves the screen first
            session.options.on_operator_wait(True)
        print("interrupted", file=sys.stderr)
        return Diagnostic("RUN004", "run interrupted by the user", None)
    except MemoryError:
        return out_of_memory(session.options.max_memory)
    return None


class OperatorMessages(CanonSink):
    """Shows the program's operator messages (canon ``message``) and its programmed stops (M0) to the
    operator."""

    def __init__(self, say, place: Callable[[Src], Src]):
        self.say, self.place = say, place
        self.kernel: NcKernel | None = None

    def message(self, text: str, src) -> None:
        self.say(text)

    def stop(self, kind: str, src) -> None:
        if kind == "M0" and self.kernel is not None:
            placed = self.place(src)  # a CL 800 run: the .cl8 line, not the object block and its number
            self.say(programmed_stop_line(self.kernel, placed, numbered=placed == src))


class OperatorOutput:
    """The operator output a result keeps: at most ``limit`` lines, the first half and the last half of them;
    ``dropped`` counts the lines between the two that were not kept."""

    def __init__(self, limit: int):
        self.head: list[str] = []
        self.head_size = limit - limit // 2
        self.tail: deque[str] = deque(maxlen=limit // 2)
        self.dropped = 0

    def append(self, line: str) -> None:
        if len(self.head) < self.head_size:
            self.head.append(line)
            return
        if len(self.tail) == self.tail.maxlen:
            self.dropped += 1
        self.tail.append(line)

    def lines(self) -> list[str]:
        return self.head + list(self.tail)

    def __iter__(self):
        return iter(self.lines())

    def __len__(self) -> int:
        return len(self.head) + len(self.tail)
