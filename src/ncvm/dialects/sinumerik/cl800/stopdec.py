"""``ncvm check`` of CL 800: the NC's warnings on the object program, reported at the CL 800 statements that
produced it: the STOP DEC lint (SIN010, :mod:`..lint`) and the drilling cycles L81-L89 the run will not find
(RUN002, :func:`..drilling.missing_cycle_warnings`).

A read of actual values after a move, or of a measurement's result, needs STOP DEC between them (L2598,
L2668, L4287-4301); the object program shows where the compiler put each statement, so the sin800
lint judges it as it judges a hand-written program, and each warning names the source lines.
"""

from __future__ import annotations

from ....diagnostics import Diagnostic
from ..drilling import missing_cycle_warnings
from ..lint import stop_dec_lint
from ..reader import read_program
from .codegen import ObjectProgram


def nc_diagnostics(path: str, obj: ObjectProgram, find) -> list[Diagnostic]:
    """The NC's warnings; ``find``: the sub-program library's lookup (number -> path or None)."""
    prog, problems = read_program(path, obj.text())
    if problems:
        return []  # DIN code the NC cannot read: the run reports it where it stands
    where = lambda line, col: (obj.source_line(line, col), None)  # noqa: E731
    return stop_dec_lint(prog, where, path) + missing_cycle_warnings(prog, find, where)
