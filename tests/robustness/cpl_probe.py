"""Run generated CPL programs and sort out faults that come from inside ncvm rather than from the program.

CplRuntime.to_fault turns a Python exception into a CPL error (TypeError on a NUL into CPL020, IndexError into
CPL031, ...) only when the generated code raised it itself (pyfaults); this probe checks that independently. A
fault is genuine when the exception was raised by the generated code itself or by a deliberate ``raise`` in
the dialect's library; an exception raised by any other library line is an internal error in disguise.
"""

from __future__ import annotations

import linecache
import traceback
from contextlib import contextmanager
from pathlib import Path

from ncvm.api import check, run
from ncvm.diagnostics import CompileFailed
from ncvm.dialects.cpl import runtime as cpl_runtime
from ncvm.runtime.session import RunOptions

CPL_DIR = Path(cpl_runtime.__file__).parent
#: library calls whose ValueError or ZeroDivisionError is the documented result for a user's argument
DOMAIN_CALLS = ("math.sqrt(", "math.asin(", "math.acos(", "math.tan(", "sqrt(", "asin(", "acos(")


def suspect_origin(rt, e: BaseException) -> str | None:
    """None when the exception that became a fault is a genuine run-time error, else where it came from."""
    if isinstance(e, (cpl_runtime.CplError, cpl_runtime.CplRuntimeError)):
        return None
    tb = traceback.extract_tb(e.__traceback__)
    if not tb:
        return None
    fs = tb[-1]
    if isinstance(e, (TypeError, AttributeError)) and "NoneType" not in str(e):
        # not NUL in an operation: a call that does not fit its function (wrong argument count, ...)
        return f"{type(e).__name__}: {e} at {fs.filename}:{fs.lineno}"
    if fs.filename in rt._codes:
        return None
    line = (fs.line or linecache.getline(fs.filename, fs.lineno)).strip()
    inside = Path(fs.filename).resolve().is_relative_to(CPL_DIR.resolve())
    if inside and line.startswith("raise "):
        return None
    if inside and isinstance(e, (ValueError, OverflowError)) and any(c in line for c in DOMAIN_CALLS):
        return None
    return f"{type(e).__name__}: {e} at {fs.filename}:{fs.lineno}: {line}"


@contextmanager
def watch_faults(found: list):
    """Record the suspect origin of every fault made by CplRuntime.to_fault while the block runs."""
    original = cpl_runtime.CplRuntime.to_fault

    def to_fault(self, e):
        where = suspect_origin(self, e)
        if where is not None:
            found.append(where)
        return original(self, e)

    cpl_runtime.CplRuntime.to_fault = to_fault
    try:
        yield
    finally:
        cpl_runtime.CplRuntime.to_fault = original


def run_program(folder: Path, main: str, subs: dict[str, str], max_steps: int = 20_000) -> tuple[dict | None, list]:
    """Write the program into folder, check and run it; returns the result and the suspect faults."""
    folder.mkdir(parents=True, exist_ok=True)
    for name, text in subs.items():
        (folder / f"{name}.cpl").write_text(text, encoding="latin-1")
    path = folder / "MAIN.cpl"
    path.write_text(main, encoding="latin-1")
    found: list = []
    with watch_faults(found):
        try:
            check(path)
        except CompileFailed:
            pass
        result, _ = run(path, options=RunOptions(state_dir=folder / ".ncvm", max_steps=max_steps))
    return result, found
