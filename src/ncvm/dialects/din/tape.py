"""Where a DIN program opened with ``%`` ends: at its closing ``%`` line or at a block with M2/M30.

ISO 6983 / RS-274 programs as CAM posts write them open with a ``%`` line (the tape start) and close with
another. rs274, the DIN reference, holds such a file to it: once the first line is ``%``, a file that ends
before a ``%`` line ("File ended with no percent sign") or a program end (M2/M30, after which nothing more is
read) is refused, and nothing after the closing ``%`` is read. Such a file was cut short: a CAM post or a
``cat`` that died mid-stream, a copy made in half; run, it would end "normally" with half a part. A file
that does not open with ``%`` may end without M2/M30, as DIN programs often do (docs/decisions.md, "a
program opened with % and cut short").
"""

from __future__ import annotations

import re

from ...diagnostics import Diagnostic, Span
from ...nc.block import PlainRun

#: the M functions that end a program (the profile's M2 and M30)
PROGRAM_ENDS = frozenset((2, 30))
CODE = "NC016"


#: what a tape mark's line may hold besides the ``%``: comments (a CAM post's "% (START)")
_COMMENTS = re.compile(r"\([^)]*\)|;.*")


def is_percent(line: str) -> bool:
    """Whether a program line is a tape mark: ``%`` alone, blanks (and a CR) and comments around it (the block
    reader refuses a ``%`` with words after it, NC001)."""
    text = line.strip()
    return text == "%" or (text[:1] == "%" and _COMMENTS.sub("", text).strip() == "%")


def segment_line(seg) -> int:
    """The program line of a segment's first block."""
    return seg.line(0) if seg.__class__ is PlainRun else seg[0].src.line


class Tape:
    """The tape marks of a program read a stretch at a time (:meth:`through`), then :meth:`diagnostics`."""

    def __init__(self, path: str, skip_active: bool):
        self.path = path
        self.skip_active = skip_active  # a block skipped (/) does not end the program
        self.opening: int | None = None  # the opening % line; 0: the program does not open with %
        self.closing: int | None = None  # the closing % line
        self.ended: int | None = None  # the line of the first block with M2/M30 that runs (before the closing %)
        self.last: tuple[int, str] | None = None  # the last non-blank line read up to the closing %
        self.after: tuple[int, str] | None = None  # the first non-blank line after the closing %
        self.stray: int | None = None  # the first % line of a program that does not open with %

    def through(self, stretches):
        """``stretches`` (:class:`~ncvm.nc.block.DinStretch` es from the program's start) as the program has
        them: the one with the closing ``%`` cut there, those after it empty (kept, so that stretches are
        counted as the file has them)."""
        for stretch in stretches:
            yield self._take(stretch)

    def _take(self, stretch):
        lines, first = stretch.lines, stretch.first
        if self.closing is not None:  # past the program's end
            if self.after is None:
                self.after = _first_text(lines, first, 0)
            return stretch._replace(segments=[], diags=[])
        if self.opening is None:
            found = _first_text(lines, first, 0)
            if found is None:  # blank so far
                return stretch
            self.opening = found[0] if is_percent(found[1]) else 0
        stray = None  # a % line of a program that does not open with one, before its program end
        if not self.opening:
            if self.stray is None and self.ended is None:
                stray = next((first + k + 1 for k, line in enumerate(lines) if "%" in line and is_percent(line)), None)
        else:
            start = max(0, self.opening - first)  # not the opening % itself
            closing = next((first + k + 1 for k in range(start, len(lines))
                            if "%" in lines[k] and is_percent(lines[k])), None)
            if closing is not None:
                self.closing = closing
                self.after = _first_text(lines, first, closing - first)
                stretch = stretch._replace(segments=[seg for seg in stretch.segments if segment_line(seg) < closing],
                                           diags=[d for d in stretch.diags if d.span is None or d.span.line < closing])
            else:
                self.last = _last_text(lines, first) or self.last
        if self.ended is None:
            self.ended = next((segment_line(seg) for seg in stretch.segments if seg.__class__ is not PlainRun
                               and not (seg[1] and self.skip_active) and not PROGRAM_ENDS.isdisjoint(seg[0].m)), None)
        if stray is not None and (self.ended is None or stray < self.ended):  # after M30: never read (as rs274)
            self.stray = stray
        if self.ended is not None:  # nothing after the program end is read (as rs274), checked or run
            stretch = stretch._replace(segments=cut_at(stretch.segments, self.ended + 1),
                                       diags=[d for d in stretch.diags if d.span is None or d.span.line <= self.ended])
        return stretch

    def cut_short(self) -> Diagnostic | None:
        """The error of a program opened with ``%`` that ends with neither a ``%`` line nor M2/M30 (at its last
        line that is not blank, just past its text: where the file was cut), or of a ``%`` line in a program
        that does not open with one (rs274 refuses it: a tape mark stands first and last, and its lines after a
        closing mark would run here); None when it ends as it should."""
        if self.stray is not None:
            return Diagnostic(CODE, f"a % tape mark at line {self.stray} in a program that does not open with %: "
                                    "a tape opens and closes with %, nothing runs after its closing % (rs274 refuses "
                                    "it too); put a % first or take this one out", Span(self.path, self.stray, 1))
        if not self.opening or self.closing is not None or self.ended is not None:
            return None
        line, text = self.last
        return Diagnostic(CODE, f"program opened with % (line {self.opening}) ends at line {line} with no closing % "
                                "and no M2/M30: the file may be cut short (rs274: \"File ended with no percent "
                                "sign\"); nothing is run", Span(self.path, line, len(text.rstrip()) + 1))

    def past_end(self) -> Diagnostic | None:
        """The warning of a check for lines after the closing ``%``: not the program's, neither read nor run."""
        if self.after is None:
            return None
        line = self.after[0]
        return Diagnostic(CODE, f"the program ends at its closing % (line {self.closing}): line {line} and the "
                                "lines after it are not read or run (as rs274 reads no further)",
                          Span(self.path, line, 1), severity="warning")

    def diagnostics(self) -> list[Diagnostic]:
        """What :meth:`cut_short` and :meth:`past_end` say."""
        return [d for d in (self.cut_short(), self.past_end()) if d is not None]


def cut_at(segments: list, closing: int | None) -> list:
    """``segments`` of a stretch read again, without those after the ``closing`` % line (None: all)."""
    if closing is None:
        return segments
    return [seg for seg in segments if segment_line(seg) < closing]


def _first_text(lines: list, first: int, start: int) -> tuple[int, str] | None:
    """(program line, text) of the first line that is not blank in ``lines`` from index ``start`` on."""
    k = next((k for k in range(start, len(lines)) if lines[k].strip()), None)
    return None if k is None else (first + k + 1, lines[k])


def _last_text(lines: list, first: int) -> tuple[int, str] | None:
    """(program line, text) of the last line that is not blank in ``lines``."""
    k = next((k for k in range(len(lines) - 1, -1, -1) if lines[k].strip()), None)
    return None if k is None else (first + k + 1, lines[k])
