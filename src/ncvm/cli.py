"""The ``ncvm`` command: run, check and compile programs of the legacy CNC languages.

Exit codes of ``run``: 0 normal end, 1 compile errors or a run-time fault (or stdout was
closed, as by ``| head``: the run stops there), 2 usage error, 70 internal error (a bug in ncvm: please report it).
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

import click

from . import __version__, termstyle
from .diagnostics import Diagnostic, Span, UsageError
from .dialects import REGISTRY
from .lazy import lazy
from .outpaths import PLOT_SUFFIXES, SCREEN_PICTURE, Output, OutputError, check_outputs, replacing
from .progress import Progress
from .source import STDIN_ARG, is_pipe, program_name
from .termstyle import say
from .timefmt import hms as _hms

# The API, the machine and the sinks are imported by the commands that use them (issue 18, start-up):
# ``ncvm --version`` loads click and this module only, ``ncvm check`` no numpy; json only for --json output.
json = lazy("json")

EXIT_OK, EXIT_FAULT, EXIT_USAGE, EXIT_INTERNAL = 0, 1, 2, 70
#: the end of each command's --help: what its exit codes mean
_BUG = "2 usage error, 70 internal error (a bug in ncvm)"
EXITS = {
    "run": "0 the program ended normally (a batch: every program did), 1 a compile error, a run-time fault or "
           "stdout closed (a batch: a program failed: error or limit violation), 128 + the signal stopped by SIGTERM "
           "or SIGHUP (RUN009), " + _BUG,
    "check": "0 no errors, 1 a program has errors, " + _BUG,
    "compile": "0 written, 1 compile errors, " + _BUG,
    "translate": "0 written, 1 the run failed or the translation was refused, 128 + the signal stopped by "
                 "SIGTERM or SIGHUP (RUN009), " + _BUG,
    "machine-schema": "0 printed, " + _BUG,
}
#: the README's table of exit codes, the end of ``ncvm --help``
EXIT_TABLE = ("Exit codes: 0 the run ended normally, check found no error, compile wrote its files; 1 an error "
              "in the program (compile error, run-time fault, check found one) or Ctrl-C (RUN004); 2 usage error "
              "(a bad option, a missing or unreadable file, an output that may not be written, a state directory "
              "in use); 70 internal error (a bug in ncvm); 128 + the signal: run or translate stopped by SIGTERM or "
              "SIGHUP (RUN009). Each command's --help names its own.")


def exits_text(name: str) -> str:
    return f"Exit codes: {EXITS[name]}."
DEFAULT_STATE = ".ncvm"


def _internal_error(exc: BaseException) -> None:
    if os.environ.get("NCVM_DEBUG") == "1":
        import traceback  # only here: start-up (issue 18)

        traceback.print_exception(exc)
    click.echo(f"ncvm: internal error: {type(exc).__name__}: {exc}", err=True)
    click.echo("This is a bug in ncvm, not in your program. Please report it with the program and the "
               "command line (NCVM_DEBUG=1 shows the traceback).", err=True)


def _detach_stdout() -> None:
    """Point stdout at /dev/null, so that flushing it at exit does not fail once more."""
    devnull = os.open(os.devnull, os.O_WRONLY)
    os.dup2(devnull, sys.stdout.fileno())
    os.close(devnull)


_JSON = "ncvm.json"  # ctx.meta: --json is on the command line


def _stop(ctx, stderr_line: str, status: str, code: str | None, message: str, exit_code: int) -> None:
    """End the command before or outside a run: one line on stderr and, with --json, a document on stdout
    with the keys of a run's error (no source position), so stdout is always JSON."""
    click.echo(stderr_line, err=True)
    if ctx.meta.get(_JSON):
        error = {"code": code, "message": message, "file": None, "line": None, "column": None}
        click.echo(json.dumps({"status": status, "error": error}, indent=2))
    ctx.exit(exit_code)


def _usage_error(ctx, message: str) -> None:
    """Exit 2 with the message on stderr; with --json also the usage_error document on stdout."""
    _stop(ctx, f"ncvm: error: {message}", "usage_error", None, message, EXIT_USAGE)


def _interrupted(ctx) -> None:
    """Exit 1 as an interrupted run does; with --json stdout is still a JSON document."""
    message = f"{ctx.invoked_subcommand or 'ncvm'} interrupted by the user"
    _stop(ctx, f"ncvm: error RUN004: {message}", "error", "RUN004", message, EXIT_FAULT)


class _Guarded(click.Group):
    """Turns usage errors into exit 2 and unexpected exceptions into exit 70 without a traceback.

    With ``--json`` a usage error (even a command line that does not parse) is a JSON document on
    stdout too, so a script can always read stdout as JSON.
    """

    #: name -> (module, attribute) of the commands in modules of their own, imported when named or listed
    #: (click's lazily loaded subcommands): building their options is start-up work a run would pay for
    #: every other command (issue 18); ``run`` is built here, since it is what start-up is measured by
    LAZY = {"check": ("ncvm.checkcmd", "check"), "compile": ("ncvm.compilecmd", "compile_cmd"),
            "machine-schema": ("ncvm.schemacmd", "machine_schema"), "state": ("ncvm.statecmd", "state"),
            "translate": ("ncvm.translatecmd", "translate_cmd")}

    def list_commands(self, ctx):
        return sorted({*super().list_commands(ctx), *self.LAZY})

    def get_command(self, ctx, name):
        if name in self.LAZY and name not in self.commands:
            from importlib import import_module

            module, attribute = self.LAZY[name]
            self.add_command(getattr(import_module(module), attribute), name)
        return super().get_command(ctx, name)

    def resolve_command(self, ctx, args):
        if self.get_command(ctx, args[0]) is None:  # no such command: click's "Did you mean" looks at those built
            for name in self.LAZY:
                self.get_command(ctx, name)
        return super().resolve_command(ctx, args)

    def parse_args(self, ctx, args):
        ctx.meta[_JSON] = "--json" in args[:args.index("--")] if "--" in args else "--json" in args
        try:
            return super().parse_args(ctx, args)
        except click.UsageError as e:  # an option before the command: ``ncvm --json run ...``
            if not ctx.meta.get(_JSON):
                raise
            _usage_error(ctx, "--json goes after the command: ncvm run --json PROGRAM, ncvm check --json ..."
                         if getattr(e, "option_name", None) == "--json" else e.format_message())

    def invoke(self, ctx):
        try:
            return super().invoke(ctx)
        except UsageError as e:
            _usage_error(ctx, str(e))
        except click.UsageError as e:
            if not ctx.meta.get(_JSON):
                raise
            _usage_error(ctx, e.format_message())
        except MemoryError:  # before a run could report it (reading a huge program); a run reports RUN006 itself
            message = "out of memory (the limit of a run is set with --max-memory)"
            _stop(ctx, f"ncvm: error RUN006: {message}", "error", "RUN006", message, EXIT_FAULT)
        except KeyboardInterrupt:  # Ctrl-C outside the run itself (which reports RUN004 with its result)
            _interrupted(ctx)
        except BrokenPipeError:  # stdout went away (`ncvm run ... | head`): stop as the other tools of a pipe do
            _detach_stdout()
            ctx.exit(EXIT_FAULT)
        except (click.exceptions.Exit, click.exceptions.Abort, click.ClickException):
            raise
        except Exception as e:  # noqa: BLE001 - the last line of defence
            _internal_error(e)
            ctx.exit(EXIT_INTERNAL)


@click.group(cls=_Guarded, context_settings={"help_option_names": ["-h", "--help"]}, epilog=EXIT_TABLE)
@click.version_option(__version__, prog_name="ncvm")
@click.option("--color/--no-color", default=None,
              help="Colours in diagnostics and summaries (default: on a terminal, unless NO_COLOR is set).")
def cli(color):
    """Check, run and compile programs of Bosch Rexroth CPL, Siemens CL 800 / SINUMERIK 800,
    ADDI-DATA rw_SymPas and plain DIN 66025 on a simulated controller."""
    termstyle.forced = color


DIALECT_OPT = click.option("--dialect", "-d", type=click.Choice(list(REGISTRY)),
                           help="Language of the program (default: from the file name, else the content).")
MACHINE_OPT = click.option("--machine", "-m", type=click.Path(dir_okay=False), help="Machine file (TOML).")


def _batch_options(f):
    """The options of a batch run (docs/batch.md)."""
    f = click.option("--shared-state", is_flag=True,
                     help="Batch: every program runs in turn on the --state directory itself and its permanent "
                          "writes stay (default: each program on its own copy, writes reported).")(f)
    f = click.option("--report", type=click.Path(dir_okay=False),
                     help="Batch: write the report (.json, .csv or JUnit .xml).")(f)
    f = click.option("--cluster", metavar="tcp://HOST:PORT",
                     help="Batch: run on this dask scheduler (pip install 'ncvm[cluster]').")(f)
    return click.option("--jobs", "-j", type=click.IntRange(min=1),
                        help="Batch: programs run at once in local processes (default: the number of cores).")(f)


@cli.command(epilog=exits_text("run"))
@click.argument("programs", nargs=-1, required=True, type=click.Path())
@DIALECT_OPT
@MACHINE_OPT
@click.option("--state", "state_dir", type=click.Path(file_okay=False), default=DEFAULT_STATE, show_default=True,
              help="State directory (permanent store, controller files).")
@click.option("--json", "as_json", is_flag=True, help="Print one JSON document with the whole result.")
@click.option("--trace", type=click.Path(dir_okay=False), help="Write every canon call as JSON lines.")
@click.option("--gcode", type=click.Path(dir_okay=False), help="Write the motion as flat G-code.")
@click.option("--plot", type=click.Path(dir_okay=False), help="Draw the toolpath (.png, .svg or .pdf).")
@click.option("--plot-frame", type=click.Choice(["work", "machine"]), default="work", show_default=True,
              help="Coordinates of the plot and of the summary line's bounds: the program's (zero offsets and "
                   "tool length taken off) or the machine's.")
@click.option("--max-steps", type=click.IntRange(min=1), default=100_000_000, show_default=True,
              help="Stop a runaway program after this many statements and blocks.")
@click.option("--max-memory", metavar="SIZE",
              help="Stop the run (error RUN006) when it would need more memory than this, e.g. 2G or 512M; "
                   "0: no limit. Default: 8G, or half the machine's memory when that is less.")
@click.option("--scenario", type=click.Path(dir_okay=False, exists=True),
              help="What happens over simulated time: [[scenario]] tables as in a machine file.")
@click.option("--keys", type=click.Path(dir_okay=False, exists=True),
              help="Operator key presses and typed values for dialog programs (a key script). Without it, "
                   "and without --json, a terminal on stdin asks the operator at each SFK/INP.")
@click.option("--editor-block", metavar="TEXT",
              help="The NC block selected in the editor, for a CPL editor dialog (INP#(0) reads its call "
                   "parameters, PRN#(0) overwrites it).")
@click.option("--screen", type=click.Path(dir_okay=False), help="Save the operator screen at the end (.png).")
@click.option("--screen-dir", type=click.Path(file_okay=False),
              help="Save one screen picture per wait for the operator (softkeys, input).")
@click.option("--time-model", type=click.Choice(["lookahead", "rest-to-rest"]),
              help="How move times are planned (default: the machine file's [motion] model, lookahead): blocks "
                   "blended in continuous-path mode, or every block from rest to rest.")
@_batch_options
def run(programs, dialect, machine, state_dir, as_json, trace, gcode, plot, plot_frame, max_steps, max_memory, scenario,
        keys, editor_block, screen, screen_dir, time_model, jobs, cluster, report, shared_state):
    """Run PROGRAMS on the simulated controller: one program, or a batch of programs and folders.

    Without --machine the machine.toml in the program's folder is used (named on stderr), as by check
    and compile, else the built-in 3-axis mill. In a batch each program uses the nearest machine.toml
    upwards (up to the folder named), sub-programs are not run, and each program starts from a copy of
    the state directory (docs/batch.md). Exit 1 when any program failed (error or limit violation).
    One program or many, a <name>.scenario.toml and <name>.keys beside a program are its scenario and key
    presses unless --scenario / --keys name others (named on stderr).
    """
    single = {"--trace": trace, "--gcode": gcode, "--plot": plot, "--scenario": scenario, "--keys": keys,
              "--editor-block": editor_block, "--screen": screen, "--screen-dir": screen_dir, "--time-model": time_model}
    if len(programs) > 1 or Path(programs[0]).is_dir() or jobs or cluster or report or shared_state:
        alone(programs, "runs")
        from .archive.command import run_batch_command

        run_batch_command(programs, dialect, machine, state_dir, as_json, max_steps, max_memory, jobs, cluster,
                          report, shared_state, [k for k, v in single.items() if v is not None])
    from . import api
    from .runtime.interrupt import Terminated, ended_by_termination
    from .runtime.memory import parse_size
    from .runtime.session import RunOptions

    program = programs[0]
    if piped_program(program, dialect):
        not_from_stdin(program, {"--machine": machine, "--scenario": scenario, "--keys": keys})
    else:
        check_program(program)
    if not state_dir.strip():  # an unset variable: the store would land in the current directory
        raise UsageError("--state is empty; give the state directory (default .ncvm)")
    from_stdin = program == STDIN_ARG
    if not from_stdin:  # stdin has no name for companions
        scenario, keys = _own_inputs(program, scenario, keys)
    inputs = {"program": None if from_stdin else program, **machine_input(program, machine), "--scenario": scenario,
              "--keys": keys}
    machine = api.machine_for(program, machine or folder_machine(program, say=True), Path(state_dir))
    check_outputs([Output("--trace", trace), Output("--gcode", gcode), Output("--plot", plot, PLOT_SUFFIXES),
                   Output("--screen", screen, (".png",)),
                   Output("--screen-dir", screen_dir, folder=True, names=SCREEN_PICTURE)],
                  inputs, state=state_dir, json_stdout=as_json, program_path=machine.program_path,
                  file_root=str(machine.file_root))
    key_script = read_key_script(keys) if keys else None
    as_path = lambda value: Path(value) if value else None  # noqa: E731
    keyboard = keys is None and not as_json and not from_stdin and _stdin_is_terminal()
    options = RunOptions(state_dir=Path(state_dir), max_steps=max_steps, trace=as_path(trace),
                         gcode=as_path(gcode), echo=not as_json, scenario=as_path(scenario), keys=key_script,
                         keyboard=keyboard, editor_block=editor_block, screen=as_path(screen),
                         screen_dir=as_path(screen_dir), plot=bool(plot), plot_frame=plot_frame,
                         time_model=time_model)
    if max_memory is not None:
        options.max_memory = parse_size(max_memory)
    # moves, steps and simulated time of a run longer than a second; it steps aside at the operator's prompts
    progress = Progress(enabled=sys.stderr.isatty() and not as_json)
    options.on_session = lambda s: setattr(progress, "session", s)
    options.on_operator_wait = progress.operator_waits
    try:
        with ended_by_termination("run", _not_written(gcode, plot, trace)):
            with progress:
                result, session = api.run(program, dialect, machine, options)
            if plot:
                _plot(plot, program_name(program), result, session)
    except Terminated as e:  # as translate ends: the shell's convention for a command ended by a signal
        _stop(click.get_current_context(), f"ncvm: error {e.code}: {e}", "error", e.code, str(e), 128 + e.signum)
    if (screen or screen_dir) and session.screen is None:
        click.echo(f"ncvm: warning: dialect '{result['dialect']}' has no operator screen; nothing saved", err=True)
    if editor_block is not None and result["dialect"] != "cpl":
        click.echo(f"ncvm: warning: dialect '{result['dialect']}' has no editor dialog; --editor-block ignored",
                   err=True)
    if as_json:
        click.echo(json.dumps(result, indent=2))
    else:
        if result["error"]:
            e = result["error"]
            span = Span(e["file"], e["line"], e["column"]) if e["file"] and e["line"] else None
            say(Diagnostic(e["code"], e["message"], span, notes=e.get("stack", [])).render())
        for v in result["limit_violations"]:
            say(f"warning: {v}")
        if "editor_block" in result:
            click.echo(f"ncvm: editor block: {result['editor_block']}", err=True)
        say(_summary(result, plot_frame))
    sys.exit(EXIT_FAULT if result["error"] else EXIT_OK)


def _not_written(gcode, plot, trace) -> str:
    """What a run stopped by a signal leaves of its outputs (the trace streams: its lines up to the stop)."""
    lost = [f"{option} {path}" for option, path in (("--gcode", gcode), ("--plot", plot)) if path]
    said = [f"no {' or '.join(lost)} written"] if lost else []
    return "; ".join(said + ([f"the trace {trace} ends where the run stopped"] if trace else []))


def _plot(plot: str, program, result: dict, session) -> None:
    """Draw the plot into a temporary file beside ``plot``, put in place only when it is whole."""
    from .sinks.plotview import plot_run

    try:
        with replacing(Path(plot)) as drawn:
            plot_run(drawn, program, result, session)
    except OSError as e:
        raise OutputError(plot, e) from None


def read_key_script(path: str):
    """The key script, read once (``--keys /dev/stdin`` is a pipe); one that does not read is a usage error
    before the run, not a fault at its first wait."""
    # CPL's key script: a dialect loads when a run needs it (the registry is lazy by design), not at start-up
    from .dialects.cpl.io.errors import CplRuntimeError
    from .dialects.cpl.io.screen import KeyScript

    try:
        return KeyScript.from_file(path)
    except CplRuntimeError as e:
        raise UsageError(f"--keys {path}: {e.message}") from None
    except UnicodeDecodeError as e:
        raise UsageError(f"--keys {path}: not UTF-8 text (byte {e.start + 1})") from None
    except OSError as e:
        raise UsageError(f"--keys {path}: cannot read: {e.strerror}") from None


def _stdin_is_terminal() -> bool:
    try:
        return sys.stdin is not None and sys.stdin.isatty()
    except (ValueError, OSError):  # closed or detached stdin
        return False


SUMMARY_WIDTH = 160  # characters of the run's summary line (docs/decisions.md)


def _summary(result: dict, frame: str = "work") -> str:
    """One compact line (at most SUMMARY_WIDTH characters); every figure in full stands in ``--json``.
    Bounds say their frame: the program's work frame (``frame`` "work", as the plot draws) or the machine's;
    on a machine with many axes they are rounded to whole millimetres/degrees, and axes that do not fit are
    named as left to ``--json``."""
    m = result["motion"]
    # a document without the program's bounds (written by an older ncvm) says the machine's, and so
    bounds, frame = (m["bounds_program"], "program") if frame == "work" and "bounds_program" in m \
        else (m["bounds"], "machine")
    # a front end may say how a run without error ended ("ended": e.g. by a system reset)
    status = result.get("ended", "ended normally") if result["status"] == "ok" \
        else f"stopped with error {result['error']['code']}"
    moves = m["rapid_moves"] + m["feed_moves"] + m["arc_moves"]
    cycle = _hms(round(result["cycle_time_s"], 1))[:-2]  # m:ss.s
    head = (f"ncvm: {status}: {result['steps']:,} steps, {moves:,} move{'' if moves == 1 else 's'}, "
            f"path {m['rapid_length'] + m['feed_length']:,.1f} mm, cycle {cycle}"
            + (f" ({result['cycle_time_model']})" if "cycle_time_model" in result else ""))
    return head + _fitted_bounds(bounds, frame, SUMMARY_WIDTH - len(head))


def _fitted_bounds(bounds: dict, frame: str, room: int) -> str:
    """``, <frame> X[lo,hi] ...`` in at most ``room`` characters: to 0.01, else rounded to whole units, else
    the axes that fit and how many more ``--json`` holds."""
    if not bounds:
        return ""
    for digits in (2, 0):
        text = f", {frame} " + " ".join(f"{a}[{_short(lo, digits)},{_short(hi, digits)}]"
                                       for a, (lo, hi) in bounds.items())
        if len(text) <= room:
            return text
    items = list(bounds.items())
    for n in range(len(items) - 1, 0, -1):
        rest = f" +{len(items) - n} axes in --json"
        text = f", {frame} " + " ".join(f"{a}[{_short(lo, 0)},{_short(hi, 0)}]" for a, (lo, hi) in items[:n])
        if len(text + rest) <= room:
            return text + rest
    return f", {frame} bounds in --json"


def _short(value: float, digits: int = 2) -> str:
    """A bound to 0.01 (or whole units) without trailing zeros: 50, -0.03, 12.5."""
    text = f"{value:.{digits}f}"
    text = text.rstrip("0").rstrip(".") if digits else text
    return "0" if text == "-0" else text


def piped_program(program: str, dialect: str | None) -> bool:
    """Whether ``program`` is read from a pipe: ``-`` (stdin) or a FIFO. One is taken with its dialect named,
    one that reads a pipe (-d din): nothing tells the dialect before the pipe is read, and the other dialects
    read their programs from files (their sub-programs from the program's folder)."""
    if not is_pipe(program):
        return False
    name = program_name(program)
    if dialect is None:
        raise UsageError(f"{name}: a program from a pipe needs its dialect named (-d din): nothing tells it before "
                         "the pipe is read")
    from .api import pipe_refusal, streams

    if not streams(dialect):
        raise UsageError(pipe_refusal(program, dialect))
    return True


def alone(programs, runs: str) -> None:
    """A program from a pipe (``-``, a FIFO) is one command's only program: a batch ``runs`` files."""
    for program in programs:
        if is_pipe(program):
            raise UsageError(f"{program_name(program)}: a program from a pipe {runs} alone, not in a batch "
                             "(a batch reads files and folders)")


def not_from_stdin(program: str, inputs: dict[str, str | None]) -> None:
    """No other input of a run that reads its program from stdin is read from stdin too (``--keys -``,
    ``--keys /dev/stdin``): the program takes all of it."""
    if program != STDIN_ARG:
        return
    try:
        stdin = os.fstat(0)
    except OSError:
        return  # no stdin: reading the program says so
    for option, path in inputs.items():
        try:
            same = path is not None and (path == STDIN_ARG or os.path.samestat(os.stat(path), stdin))
        except OSError:
            same = False
        if same:
            raise UsageError(f"{option} {path}: is stdin, which carries the program; give a file")


def check_program(program: str) -> None:
    path = Path(program)
    if program == STDIN_ARG and not path.exists():
        raise UsageError(f"{program}: this command reads its program from a file, not from standard input (a DIN "
                         "program from a pipe: ncvm run or check -d din -)")
    if not path.exists():
        raise UsageError(f"no such program: {program}")
    if not path.is_file():
        raise UsageError(f"{program}: not a file (a program is read from a file)")


def machine_input(program: str, machine: str | None) -> dict[str, str | None]:
    """The machine file among the inputs no output may overwrite: the given one or the folder's."""
    return {"--machine": machine} if machine else {"machine file": folder_machine(program)}


def folder_machine(program: str, say: bool = False) -> str | None:
    """The machine file of a program's own folder (``machine.toml``), if there is one; ``say``: name it on
    stderr (a run that is not told which machine says which one it took)."""
    path = Path(program).parent / "machine.toml"
    if not path.is_file():
        return None
    if say:  # a program from stdin stands in the current folder
        where = "the current folder: the program is read from stdin" if program == STDIN_ARG else "the program's folder"
        click.echo(f"ncvm: machine file {path} ({where})", err=True)
    return str(path)


def _own_inputs(program: str, scenario: str | None, keys: str | None) -> tuple[str | None, str | None]:
    """--scenario and --keys, else the program's own <name>.scenario.toml and <name>.keys (named on stderr),
    as a batch takes them (:mod:`ncvm.runtime.companions`)."""
    from .runtime.companions import KEYS_SUFFIX, SCENARIO_SUFFIX, beside

    own = beside(program)
    if scenario is None and SCENARIO_SUFFIX in own:
        scenario = str(own[SCENARIO_SUFFIX])
        click.echo(f"ncvm: scenario {scenario} (beside the program)", err=True)
    if keys is None and KEYS_SUFFIX in own:
        keys = str(own[KEYS_SUFFIX])
        click.echo(f"ncvm: key presses {keys} (beside the program)", err=True)
    return scenario, keys


def main() -> None:
    cli(prog_name="ncvm")
