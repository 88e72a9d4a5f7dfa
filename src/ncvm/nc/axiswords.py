"""Axis words for axes the machine does not have.

A control refuses a block that programs an axis it does not have; the kernel
only moves the axes it knows, so without this check ``G1 A10`` on an X/Y/Z
machine would end normally with no move. Front ends check the addresses of a
block once, where the block is read or compiled, never per move.
"""

from __future__ import annotations

from ..diagnostics import Diagnostic, Span
from ..lazy import lazy
from .block import PLAIN_WORDS, PlainRun, word_column

np = lazy("numpy")


#: DIN 66025 axis addresses: X Y Z, the parallel axes U V W, the rotary axes A B C
AXIS_LETTERS = frozenset("XYZUVWABC")
#: the axis addresses of a plain block (nc.block.PLAIN_WORDS)
_PLAIN_AXES = tuple(a for a in PLAIN_WORDS if a in AXIS_LETTERS)


def is_missing_axis(address: str, axes) -> bool:
    """Whether ``address`` names an axis and ``axes`` (the machine's axis names) has no such axis. An address
    of more than one character (CPL's ``X2``, ``Q1``, ``U_CH1``) can only be an axis name."""
    return (address[:1] in AXIS_LETTERS or len(address) > 1) and address not in axes


def names_axis(address: str, dwell: bool) -> bool:
    """Whether ``address`` stands for an axis in its block: in a dwell block (G4) X is the time, as the kernel
    reads it (P, X or F seconds), not an axis."""
    return not (dwell and address == "X")


def is_dwell(g_codes) -> bool:
    return any(g == 4 for g in g_codes)


def missing_axis_message(address: str, axes) -> str:
    return f"axis {address} is not configured on this machine (its axes: {' '.join(axes) or 'none'})"


def din_missing_axes(path: str, line_at, segments: list, axes, skip_active: bool = False) -> list:
    """The blocks of a plain DIN program (:func:`~ncvm.nc.block.read_din_segments`) with a word for an axis
    the machine lacks, in program order: (segment index, row within a PlainRun or None, Diagnostic NC011).
    With ``skip_active`` the skipped blocks (``/``) are left out, as a run leaves them out. ``line_at(n)``:
    the source line ``n`` of such a block (asked only when there is one), for the word's column."""
    found = []  # (segment index, row, line, address)
    plain_missing = [a for a in _PLAIN_AXES if a not in axes]
    for i, seg in enumerate(segments):
        if isinstance(seg, PlainRun):
            if plain_missing:  # never on a machine with X, Y and Z
                has = np.array([~np.isnan(seg.words[a]) for a in plain_missing])
                for row in np.flatnonzero(has.any(axis=0)).tolist():
                    found.append((i, row, int(seg.lines[row]), plain_missing[int(np.argmax(has[:, row]))]))
            continue
        blk, skip = seg
        if skip and skip_active:
            continue
        address = next((a for a in blk.words if is_missing_axis(a, axes) and names_axis(a, is_dwell(blk.g))), None)
        if address is not None:
            found.append((i, None, blk.src.line, address))
    if not found:
        return []
    out = []
    for i, row, line, a in found:
        text = line_at(line)
        out.append((i, row, Diagnostic("NC011", missing_axis_message(a, axes),
                                       Span(path, line, word_column(text, a) if text is not None else None))))
    return out
