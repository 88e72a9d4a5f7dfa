"""Where a run-time fault struck: the traceback of generated code back to program lines.

Generated code does not track its position while it runs (runtime.codegen): each compiled unit
carries its :class:`~ncvm.runtime.codegen.PySource` line map instead, and a fault is located
afterwards from the Python traceback. :func:`generated_frames` is that one walk, for every
dialect: the frames of the traceback that run generated code, outermost first, each with the
program line and column of the generated line it stopped on. The dialects build their fault
position (the innermost frame) and call stack from it in their own terms: CPL names frames after
files, SINUMERIK after its call frames, rw_SymPas after its routines.
"""

from __future__ import annotations

import sys
from collections.abc import Mapping
from types import FrameType, TracebackType
from typing import TYPE_CHECKING, NamedTuple

if TYPE_CHECKING:
    from .codegen import PySource


class GeneratedFrame(NamedTuple):
    """One frame of generated code in a traceback."""

    filename: str  # the generated code's file name (its PySource's)
    line: int  # the program line of the generated line it stopped on (0: none)
    col: int | None  # the program column, where the front end gave one
    frame: FrameType  # the Python frame: its function name and local variables


def generated_frames(tb: TracebackType | None, sources: Mapping[str, PySource]) -> list[GeneratedFrame]:
    """The frames of ``tb`` running code generated from one of ``sources`` (by file name), outermost first."""
    out = []
    while tb is not None:
        frame = tb.tb_frame
        name = frame.f_code.co_filename
        src = sources.get(name)
        if src is not None:
            py_line = tb.tb_lineno
            out.append(GeneratedFrame(name, src.source_line(py_line), src.source_col(py_line), frame))
        tb = tb.tb_next
    return out


def raised_by_generated(tb: TracebackType | None, sources: Mapping[str, PySource]) -> bool:
    """Whether the innermost frame of ``tb`` runs generated code: the exception came from the statement's own
    operation (arithmetic, a subscript, a math function it calls directly), not from a function of ncvm's that
    it called. A Python error raised inside ncvm is ncvm's fault, whatever the program did."""
    if tb is None:
        return False
    while tb.tb_next is not None:
        tb = tb.tb_next
    return tb.tb_frame.f_code.co_filename in sources


def fault_line(tb: TracebackType | None, source: PySource) -> int | None:
    """The program line where the innermost frame of ``source``'s code stopped; None when it is not in ``tb``."""
    frames = generated_frames(tb, {source.filename: source})
    return frames[-1].line if frames else None


def running_line(sources: Mapping[str, PySource]) -> tuple[str, int] | None:
    """The file name and program line of the innermost frame of generated code running now (None: none):
    where a run reads an input, for the mark of a frozen decision (ncvm translate). A walk up the stack,
    made only when such an input is read."""
    frame = sys._getframe(1)
    while frame is not None:
        src = sources.get(frame.f_code.co_filename)
        if src is not None:
            return frame.f_code.co_filename, src.source_line(frame.f_lineno)
        frame = frame.f_back
    return None
