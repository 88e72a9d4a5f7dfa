"""The STOP DEC lint (CL 800 manual L4287-4328, L2668): reads of the executed state after a change.

The NC decodes blocks ahead of execution, so a read of actual values, of the
external inputs, or of the R parameters a measurement fills sees stale data
unless ``STOP DEC`` (@714) comes between the motion and the read. The spindle
reads (ACSP, ACSS, AGS) go stale also after a block that changes the spindle
(S, M3/M4/M5, the gear stages M40-M45, G96/G97) or lets time pass (G04). The lint
walks the blocks in program order (jumps are not followed) and warns, never
fails: the program may be correct on a control whose buffer happens to be empty.
"""

from __future__ import annotations

from ...diagnostics import Diagnostic, Span
from .reader import AtInstr, PartProgram, Word

CODE = "SIN010"
#: @ codes that read the executed state: actual values (L6549-6556) and the external inputs (IF/WHILE INT)
ACTUAL_READS = {"360": "ACPW", "361": "ACPM", "362": "ACP", "363": "ACSP", "364": "ACSS", "367": "ACAS",
                "36a": "ACD", "36b": "ACG", "187": "IF INT", "188": "IF INT NOT", "197": "WHILE INT",
                "198": "WHILE INT NOT", "3e4": "AGS"}
#: reads of the spindle, which a spindle block or the time a block takes changes as well
SPINDLE_READS = frozenset(("363", "364", "3e4"))
_SPINDLE_M = frozenset((3, 4, 5, 40, 41, 42, 43, 44, 45))
#: @ codes that put axis setpoints into their block: PRAP, PRAD, PANG, PRIP, MEAS M
MOTION_CODES = frozenset(("440", "446", "447", "448", "720"))
#: DIN addresses that are not axis or interpolation words
_NOT_MOTION = frozenset("GMFSTDLPHN")


def _is_motion(it) -> bool:
    """An item that moves an axis when its block executes (a sub-program call may move)."""
    if isinstance(it, Word):
        return it.address == "L" or (it.address not in _NOT_MOTION and (it.value is not None or bool(it.rref)))
    return isinstance(it, AtInstr) and it.code in MOTION_CODES


def _dwells(items) -> bool:
    """G04 X<seconds> is a dwell: its X is a time, not a position."""
    return any(isinstance(it, Word) and it.address == "G" and it.value == 4 for it in items)


def _turns_spindle(items) -> int | None:
    """The column of the block's first spindle word (or dwell); None when it has none."""
    for it in items:
        if not isinstance(it, Word):
            continue
        if it.address == "S" or (it.address == "M" and it.value in _SPINDLE_M) or \
                (it.address == "G" and it.value in (4, 96, 97)):
            return it.col
    return None


def _same_place(line: int, col: int) -> tuple[int, int]:
    return line, col


def stop_dec_lint(prog: PartProgram, place=_same_place, path: str | None = None) -> list[Diagnostic]:
    """Warnings (severity "warning") for reads of the executed state with no STOP DEC since the last motion,
    and for a MEAS M whose next block is not STOP DEC. ``place`` maps a (line, column) of the program to
    the one reported, in ``path`` (default the program's): a CL 800 check reports at its source."""
    out: list[Diagnostic] = []
    path = prog.path if path is None else path
    moved_at: tuple[int, int] | None = None  # the last motion with no STOP DEC after it
    spun_at: tuple[int, int] | None = None  # the last spindle block (or dwell) with no STOP DEC after it
    measured_at: tuple[int, int] | None = None  # a MEAS M still waiting for its STOP DEC
    for blk in prog.blocks:
        if measured_at is not None and blk.items:
            first = blk.items[0]
            if not (isinstance(first, AtInstr) and first.code == "714"):
                line, col = place(*measured_at)
                out.append(Diagnostic(CODE, f"MEAS M in line {line} is not followed by STOP DEC; "
                                            "the measured values reach the R parameters only after the block "
                                            "has executed", Span(path, line, col), severity="warning"))
            measured_at = None
        dwell = _dwells(blk.items)
        here: tuple[int, int] | None = None  # the first motion of this block: it executes after the block's reads
        for it in blk.items:
            if here is None and not dwell and _is_motion(it):
                here = (blk.line, it.col)
            if not isinstance(it, AtInstr):
                continue
            changed_at = moved_at
            if it.code in SPINDLE_READS and spun_at is not None and (moved_at is None or spun_at > moved_at):
                changed_at = spun_at
            if it.code == "714":
                moved_at = spun_at = None
            elif it.code in ACTUAL_READS and here is not None:
                out.append(Diagnostic(CODE, f"{ACTUAL_READS[it.code]} reads the executed state, but the motion in "
                                            f"line {place(*here)[0]} is in the same NC block and executes after "
                                            "the read: end the block (LF) before STOP DEC",
                                      Span(path, *place(blk.line, it.col)), severity="warning"))
            elif it.code in ACTUAL_READS and changed_at is not None:
                what = "motion" if changed_at == moved_at else "spindle block"
                out.append(Diagnostic(CODE, f"{ACTUAL_READS[it.code]} reads the executed state, but the {what} "
                                            f"in line {place(*changed_at)[0]} has no STOP DEC since: it may see "
                                            "stale data", Span(path, *place(blk.line, it.col)), severity="warning"))
            elif it.code == "720":
                measured_at = (blk.line, it.col)
        if here is not None:
            moved_at = here
        col = _turns_spindle(blk.items)
        if col is not None:
            spun_at = (blk.line, col)
    return out
