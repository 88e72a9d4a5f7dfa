"""``ncvm check`` of CL 800: the NC's STOP DEC lint (SIN010, :mod:`..lint`) on the object program, reported
at the CL 800 statements that produced it.

A read of actual values after a move, or of a measurement's result, needs STOP DEC between them (L2598,
L2668, L4287-4301); the object program shows where the compiler put each statement, so the sin800
lint judges it as it judges a hand-written program, and each warning names the source lines.
"""

from __future__ import annotations

from ....diagnostics import Diagnostic
from ..lint import stop_dec_lint
from ..reader import read_program
from .codegen import ObjectProgram


def stop_dec_diagnostics(path: str, obj: ObjectProgram) -> list[Diagnostic]:
    prog, problems = read_program(path, obj.text())
    if problems:
        return []  # DIN code the NC cannot read: the run reports it where it stands
    return stop_dec_lint(prog, lambda line, col: (obj.source_line(line, col), None), path)
