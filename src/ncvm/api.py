"""The public Python API: load a machine, check, run and compile programs."""

from __future__ import annotations

import dataclasses
from pathlib import Path

from .diagnostics import CompileFailed, Diagnostic, UsageError
from .dialects import detect_dialect, get_dialect
from .machine.config import load_machine, load_scenario
from .machine.model import Machine
from .machine.state import StateLock
from .runtime.memory import memory_limit
from .runtime.session import RunOptions, Session, run_guarded
from .source import read_text


def read_source(path: str | Path) -> str:
    try:
        return read_text(path)
    except OSError as e:
        raise UsageError(f"cannot read {path}: {e.strerror}") from None


def resolve(path: str | Path, dialect: str | None) -> tuple[str, str]:
    text = read_source(path)
    return text, dialect or detect_dialect(path, text)


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
          all_errors: bool = False) -> list[Diagnostic]:
    text, d = resolve(path, dialect)
    return get_dialect(d).check(str(path), text, machine_for(path, machine), all_errors)


def run(path: str | Path, dialect: str | None = None, machine: Machine | str | Path | None = None,
        options: RunOptions | None = None) -> tuple[dict, Session]:
    """Run a program; returns the result document of ``ncvm run --json`` and the session.

    The run (reading the program included) may grow the process by ``options.max_memory``: past it the
    result is error RUN006, or MemoryError when the program could not even be read.
    """
    options = options or RunOptions()
    with memory_limit(options.max_memory):
        text, d = resolve(path, dialect)
        front = get_dialect(d)
        m = machine_for(path, machine, options.state_dir)
        if options.scenario:
            # what happens over simulated time in this run, on top of the machine file's own scenario
            # (a copy: a Machine the caller passes again for the next run keeps its own scenario)
            m = dataclasses.replace(m, scenario=sorted([*m.scenario, *load_scenario(options.scenario, m.axis_names)],
                                                       key=lambda e: e.time))
        with StateLock(options.state_dir):  # the controller's memory: one run at a time, refused at once
            session = Session(m, options, dialect=d)
            error: Diagnostic | None
            try:
                error = run_guarded(session, lambda: front.run(str(path), text, session))
            except CompileFailed as e:
                error = e.diagnostics[0]
            finally:
                session.close()
    return session.result(error), session


def compile_program(path: str | Path, out: str | Path | None = None, xref: str | Path | None = None,
                    dialect: str | None = None, machine: Machine | str | Path | None = None) -> Path:
    text, d = resolve(path, dialect)
    return get_dialect(d).compile(str(path), text, machine_for(path, machine),
                                  Path(out) if out else None, Path(xref) if xref else None)
