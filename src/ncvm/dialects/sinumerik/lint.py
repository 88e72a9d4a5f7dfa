"""The STOP DEC lint (digest §10.5; manual L4287-4328, L2668): reads of the executed state after a change.

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


def _moves(items) -> bool:
    if any(isinstance(it, Word) and it.address == "G" and it.value == 4 for it in items):
        return False  # G04 X<seconds> is a dwell: its X is a time, not a position
    for it in items:
        if isinstance(it, Word) and it.address not in _NOT_MOTION and (it.value is not None or it.rref):
            return True
        if isinstance(it, Word) and it.address == "L":
            return True  # a sub-program may move
        if isinstance(it, AtInstr) and it.code in MOTION_CODES:
            return True
    return False


def _turns_spindle(items) -> bool:
    for it in items:
        if not isinstance(it, Word):
            continue
        if it.address == "S" or (it.address == "M" and it.value in _SPINDLE_M) or \
                (it.address == "G" and it.value in (4, 96, 97)):
            return True
    return False


def stop_dec_lint(prog: PartProgram) -> list[Diagnostic]:
    """Warnings (severity "warning") for reads of the executed state with no STOP DEC since the last motion,
    and for a MEAS M whose next block is not STOP DEC."""
    out: list[Diagnostic] = []
    moved_at: int | None = None  # line of the last motion block with no STOP DEC after it
    spun_at: int | None = None  # line of the last spindle block (or dwell) with no STOP DEC after it
    measured_at: int | None = None  # line of a MEAS M still waiting for its STOP DEC
    for blk in prog.blocks:
        if measured_at is not None and blk.items:
            first = blk.items[0]
            if not (isinstance(first, AtInstr) and first.code == "714"):
                out.append(Diagnostic(CODE, f"MEAS M in line {measured_at} is not followed by STOP DEC; "
                                            "the measured values reach the R parameters only after the block "
                                            "has executed", Span(prog.path, measured_at, 1), severity="warning"))
            measured_at = None
        for it in blk.items:
            if not isinstance(it, AtInstr):
                continue
            changed_at = moved_at
            if it.code in SPINDLE_READS and spun_at is not None and (moved_at is None or spun_at > moved_at):
                changed_at = spun_at
            if it.code == "714":
                moved_at = spun_at = None
            elif it.code in ACTUAL_READS and changed_at is not None:
                what = "motion" if changed_at == moved_at else "spindle block"
                out.append(Diagnostic(CODE, f"{ACTUAL_READS[it.code]} reads the executed state, but the {what} "
                                            f"in line {changed_at} has no STOP DEC since: it may see stale data",
                                      Span(prog.path, blk.line, it.col), severity="warning"))
            elif it.code == "720":
                measured_at = blk.line
        if _moves(blk.items):
            moved_at = blk.line
        if _turns_spindle(blk.items):
            spun_at = blk.line
    return out
