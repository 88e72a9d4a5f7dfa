"""Plain DIN 66025 / ISO 6983 programs: read every block, then run them through the kernel.

A run reads the program from its file a stretch at a time (issue 18: bounded memory for a file of any
size): once for its errors and refusals, holding its leading stretches while they are cheap enough
(:data:`HOLD_BYTES`), then, as it runs, again from the first stretch it did not hold."""

from __future__ import annotations

import math
import os
import re
from itertools import islice

from ...diagnostics import CompileFailed, RuntimeFault, Span, UsageError
from ...nc import blockskip, threads
from ...nc.axiswords import din_missing_axes
from ...nc.block import COLUMNS_FROM, PlainRun, columnar, din_stretches, file_stretches, text_stretches
from ...nc.canon import Src
from ...nc.cycles import CannedCycles
from ...nc.plainrun import execute_columns, execute_short_run
from ...nc.profiles.blockrules import block_refusal
from ...nc.profiles.iso import ISO
from ...nc.profiles.named import profile as named_profile
from ...source import lines as program_lines
from ...source import open_program
from ..base import Dialect
from .ngc import fold_extensions
from .options import arc_tolerance, options
from .support import address_refusal, block_error, refused_address
from .tape import Tape, cut_at

#: a run holds the leading stretches of a program it reads while they cost at most this much memory (in bytes,
#: as :func:`held_bytes` estimates them): a flat CAM program of up to about 150,000 lines (4.8 MB), a drilling
#: program of up to about 50,000 lines, is read once. It reads the rest a second time, a stretch at a time,
#: as it runs (issue 18: memory bounded by design; docs/decisions.md "a DIN program's memory", "read again
#: only past what it holds": 24 MB keeps a 500,000-line flat program's peak under those of other shapes)
HOLD_BYTES = 24 << 20
#: the memory held segments take (tracemalloc, CPython 3.11, numpy 2): a PlainRun held as columns whatever its
#: length (its object, word dict and nine arrays); a short run (nc.block.columnar: kept as its lines' matches)
#: and each of its blocks; a block read the general way (Block, G tuple, word dict, Src, skip pair); a line (its
#: row, its source string besides its characters: a run parses a block's line again when the kernel needs it)
RUN_BYTES, SHORT_RUN_BYTES, SHORT_BLOCK_BYTES, BLOCK_BYTES, LINE_BYTES = 1400, 200, 105, 500, 130
#: a line as DIN programs write them, for :meth:`DinDialect.sniff` (compiled into re's cache when first used)
_DIN_LINE = r"(?i)^\s*(N\d+\s*)?([GMXYZFST]-?\d|\(|%|/|$)"


def setup_kernel(kernel) -> None:
    """The iso profile's functions that live outside the kernel: the canned cycles and G33 (spindle-synchronised
    motion), as LinuxCNC has them (G94/G95 are rows of the profile)."""
    kernel.canned = CannedCycles()
    kernel.motion_modes.update(threads.ISO_THREADS)


class DinDialect(Dialect):
    id = "din"
    streams = True

    def sniff(self, text: str) -> int:
        lines = [ln for ln in program_lines(text)[:200] if ln.strip()]
        if not lines:
            return 0
        hits = sum(1 for ln in lines if re.match(_DIN_LINE, ln))
        return int(100 * hits / len(lines))

    def check(self, path, text, machine, all_errors=False):
        """Every diagnostic of the program, read from its file a stretch at a time (``text`` None) or from
        ``text`` (dialects/din/check.py)."""
        from .check import check_stretches  # a run needs none of it (start-up)

        profile = named_profile(options(machine).profile)
        tape = Tape(path, bool(machine.setting_data.get("block_skip", True)))
        with ProgramStretches(path, text) as program:
            return check_stretches(path, tape.through(program(COLUMNS_FROM)), machine, profile, tape)

    def run(self, path, text, session):
        kernel = session.kernel
        opts = options(session.machine)
        kernel.arc_tolerance = arc_tolerance(opts)
        profile = named_profile(opts.profile)  # [din] profile: the control whose G table the blocks are read with
        kernel.use_profile(profile)
        if profile is ISO:
            setup_kernel(kernel)  # LinuxCNC's canned cycles and G33 belong to the iso rows
        skip_active = bool(session.machine.setting_data.get("block_skip", True))
        with ProgramStretches(path, text) as program:
            self._run(path, program, session, skip_active, profile)

    def _run(self, path, program, session, skip_active, profile):
        kernel = session.kernel
        stretches, refused = self._read(path, program, kernel.axis_of, skip_active, profile)
        counter = session.steps
        limit = counter.limit - counter.steps
        hook = counter.hook  # single-block stepping and breakpoints; None unless a debugger is attached
        done = 0
        last_src = None
        index = 0  # segments of the stretches before this one
        try:
            for segments in stretches:
                first, index = index, index + len(segments)
                if refused and refused[0] < index:  # the refused block is in this stretch: run up to it
                    at, row = refused[0] - first, refused[1]
                    segments = segments[:at] + ([segments[at].head(row)] if row else [])
                done, last_src = self._execute(path, segments, kernel, counter, limit, hook, skip_active, done,
                                               last_src)
                if kernel.ended or (refused and refused[0] < index):
                    break
                segments = None  # run: not held while the next stretch is read
            if refused and not kernel.ended:
                refusal = refused[2]
                if done >= limit:
                    counter.runaway(path, refusal.span.line)
                done += 1
                raise RuntimeFault(refusal.code, refusal.message, refusal.span)
        finally:
            counter.steps += done
        if not kernel.ended and last_src is not None:
            kernel.end_program(last_src)

    @staticmethod
    def _read(path, program, axes, skip_active, profile):
        """(the program's stretches of segments, the first refused block as (segment index, row, Diagnostic) or
        None); a program with errors fails to compile. The leading stretches read are held while they cost at
        most :data:`HOLD_BYTES` together: a program that fits is read once. The rest is read a second time as
        it runs, from the first stretch not held on, the first reading having been for its errors and refusals
        only (issue 18: bounded memory). A program that cannot be read again (a pipe) is held. A program
        opened with ``%`` ends at its closing ``%`` (nothing after it is read) or fails to compile when it has
        neither that nor M2/M30: it was cut short (dialects/din/tape.py)."""
        held, cost = [], 0  # the leading stretches' segments held, what they cost
        again = None  # the first stretch not held
        budget = HOLD_BYTES if program.again else math.inf
        diags, refused, index = [], None, 0
        error_lines = {}  # the source lines of the syntax errors (NC001), for fold_extensions
        tape = Tape(path, skip_active)
        for stretch in tape.through(program(COLUMNS_FROM)):  # a short program line by line: no numpy (issue 18, start-up)
            segments = stretch.segments
            diags += stretch.diags
            error_lines.update((d.span.line, stretch.line(d.span.line)) for d in stretch.diags if d.code == "NC001")
            if refused is None and not diags:
                # a block with a word for an axis the machine lacks is refused when the run reaches it (found
                # here, once, so the blocks before it run as they are)
                first = sorted(din_missing_axes(path, stretch.line, segments, axes, skip_active)
                               + _refused_blocks(path, stretch, axes, skip_active, profile),
                               key=lambda r: (r[0], r[1] or 0))[:1]
                refused = (index + first[0][0], first[0][1], first[0][2]) if first else None
            index += len(segments)
            if again is None:
                cost += held_bytes(stretch)
                if cost > budget:
                    again = len(held)  # the stretches from this one on are read again
                else:
                    held.append(segments)
            del stretch, segments  # not held here while the next stretch is read
        cut = tape.cut_short()
        if diags or cut is not None:
            raise CompileFailed(fold_extensions(diags, error_lines.get) + ([cut] if cut is not None else []))
        return _held_then_read(held, program, again, tape.closing), refused

    @staticmethod
    def _execute(path, segments, kernel, counter, limit, hook, skip_active, done, last_src):
        """Run ``segments`` (until the program ends); returns the blocks done so far and the last block's place.
        A fault counts the blocks done up to it (the faulting block with them)."""
        start = done
        try:
            for seg in segments:
                if isinstance(seg, PlainRun):
                    last_src = Src(path, seg.line(len(seg) - 1))
                    if hook is None:  # a run of plain motion blocks (none ends the program), up to the step limit
                        count = min(len(seg), limit - done)
                        if columnar(len(seg)):  # column-wise
                            lo = 0
                            while (bad := execute_columns(kernel, seg, lo, count)) is not None:
                                done += bad - lo + 1
                                kernel.execute(seg.block(bad))  # left to the kernel: it may fault
                                lo = bad + 1
                            done += count - lo
                        else:  # a short run: block by block, each counted before it runs (it may fault)
                            counted = [0]
                            try:
                                execute_short_run(kernel, seg, count, counted)
                            finally:
                                done += counted[0]
                        if count < len(seg):
                            counter.runaway(path, seg.line(count))
                        continue
                    blocks = ((blk, False) for blk in seg.blocks())  # stepped
                else:
                    blocks = (seg,)
                    last_src = seg[0].src
                for blk, skip in blocks:
                    if skip:
                        blockskip.tell(kernel.canon, skip_active, blk.src)
                        if skip_active:
                            continue
                    if done >= limit:
                        counter.runaway(blk.src.file, blk.src.line)
                    done += 1
                    if hook is not None:
                        hook(blk.src.file, blk.src.line, kernel.workpiece_position())
                    kernel.execute(blk)
                    if kernel.ended:
                        return done, last_src
            return done, last_src
        except BaseException:  # a fault or the step limit: the caller's count has not seen these blocks
            counter.steps += done - start
            raise


def _held_then_read(held: list, program, again: int | None, closing: int | None = None):
    """The segments of each stretch ``held``, let go as they are handed on (a run's memory is not the held
    stretches and the rest at once), then those of the program read again from stretch ``again`` on (None:
    none), up to its ``closing`` % line (None: to its end)."""
    held.reverse()
    while held:
        yield held.pop()
    if again is not None:
        for stretch in program(COLUMNS_FROM, again):
            segments = cut_at(stretch.segments, closing)
            past = closing is not None and stretch.first + len(stretch.lines) >= closing
            del stretch
            yield segments
            del segments  # not held here while the next stretch is read
            if past:  # the program ends at its closing %: nothing after it is read
                return


def _refused_blocks(path: str, stretch, axes, skip_active: bool, profile) -> list:
    """The first block of a stretch with an address the profile refuses (NC007) or that breaks one of the
    control's block rules (two functions of one modal group ...: nc/profiles/blockrules.py), as (segment index,
    None, Diagnostic); plain runs have none."""
    for i, seg in enumerate(stretch.segments):
        if isinstance(seg, PlainRun) or (seg[1] and skip_active):
            continue
        blk = seg[0]
        address = refused_address(blk, axes)
        if address is not None:
            return [(i, None, address_refusal(path, blk, stretch.line(blk.src.line), address))]
        found = block_refusal(profile, blk.g, blk.m, blk.words, axes)
        if found is not None:
            return [(i, None, block_error(path, blk, stretch.line(blk.src.line), found))]
    return []


def held_bytes(stretch) -> int:
    """What holding a stretch's segments costs, in bytes (:data:`RUN_BYTES`...; within 10 % of what tracemalloc
    measures for flat CAM output, drilling cycles and comments between blocks, a sixth over for M-code blocks)."""
    segments = stretch.segments
    runs = [len(seg) for seg in segments if seg.__class__ is PlainRun]
    short = [n for n in runs if not columnar(n)]
    return ((len(runs) - len(short)) * RUN_BYTES + len(short) * SHORT_RUN_BYTES + sum(short) * SHORT_BLOCK_BYTES
            + (len(segments) - len(runs)) * BLOCK_BYTES + len(stretch.lines) * LINE_BYTES + stretch.chars)


class ProgramStretches:
    """A program's :class:`~ncvm.nc.block.DinStretch` es from its start, as often as called: read from its file
    (``text`` None; one open file for every pass, so each pass reads the same file) or from a text.

    A file read again is the file its first whole pass read, or the pass stops with RUN008 before the first
    stretch that differs: a run reads a long program a second time as it runs, and what it runs must be what
    its first reading checked (an editor or a CAM post writing over the file in place)."""

    def __init__(self, path: str, text: str | None):
        self.path = path
        self.flat = None if text is None else text.replace("\r\n", "\n").replace("\r", "\n")
        try:
            self.file = open_program(path) if text is None else None
        except OSError as e:
            raise UsageError(f"cannot read {path}: {e.strerror}") from None
        #: whether it can be read again from its start (a pipe is read once)
        self.again = self.file is None or self.file.seekable()
        #: the file's pieces as its first whole pass read them: (first line, characters, hash, where the file
        #: stood before it) each, then (the line after the last, None, None, where the file stood at its end);
        #: None before that pass ends
        self.read_as = None
        self.opened = self._stamp()  # the file's size and times when its first pass began

    def _stamp(self) -> tuple | None:
        """The open file's size and modification times (None: a text or a pipe)."""
        if self.file is None or not self.again:
            return None
        st = os.fstat(self.file.fileno())
        return st.st_size, st.st_mtime_ns, st.st_ctime_ns

    def __call__(self, columns_from: int = 0, start: int = 0):
        """The stretches from the program's start, or from its ``start``-th stretch (0-based) on after a whole
        pass (``columns_from``: :func:`~ncvm.nc.block.din_stretches`)."""
        if self.file is None:  # a text does not change
            pieces = text_stretches(self.flat)
            first = sum(piece.count("\n") for piece in islice(pieces, start))
            return din_stretches(self.path, pieces, columns_from, first)
        if start and self.read_as is None:
            raise ValueError("a program file is read from a later stretch on only after a whole pass")
        if not self.again:  # a pipe is read once
            return din_stretches(self.path, file_stretches(self.file), columns_from)
        if self.read_as is None:
            return din_stretches(self.path, self._recorded(file_stretches(self.file)), columns_from)
        line, _, _, at = self.read_as[start]
        pieces = file_stretches(self.file, at if start else None)
        return din_stretches(self.path, self._verified(pieces, start), columns_from, line - 1)

    def _recorded(self, pieces):
        """``pieces``, each noted (:attr:`read_as`) for the passes after this one (a hash within the run's one
        process: a few milliseconds for a 500,000-line program)."""
        seen, line, at = [], 1, 0
        for piece in pieces:
            seen.append((line, len(piece), hash(piece), at))
            line += piece.count("\n")
            yield piece
            at = self.file.tell()  # the piece's end (a text file's position: an opaque number for seek)
        seen.append((line, None, None, at))
        self.read_as = seen
        if self._stamp() != self.opened:  # written to while this pass read it: it may have read two versions
            for _ in self._verified(file_stretches(self.file), 0):  # RUN008 unless the file reads as it did
                pass

    def _verified(self, pieces, start: int):
        """``pieces`` from the ``start``-th on, each the one the first pass read (its length and hash), ending
        where that pass ended; else run-time error RUN008 at the first line of the first piece that differs,
        before it is yielded (the blocks before it run). A file cut before where the pieces start (its position
        cannot be restored) has changed too."""
        seen = self.read_as
        k = start - 1
        try:
            for k, piece in enumerate(pieces, start):
                if seen[k][1] != len(piece) or seen[k][2] != hash(piece):  # past the end: (line, None, None, at)
                    self._changed(seen[k][0])
                yield piece
        except OSError:  # seek: "can't restore logical file position"
            self._changed(seen[k + 1][0])
        if k + 2 != len(seen):  # it ends before the first pass's end
            self._changed(seen[k + 1][0])

    def _changed(self, line: int):
        raise RuntimeFault("RUN008", f"program file {self.path} changed while it ran (line {line}): the run "
                           "stops; what ran before is reported", Span(self.path, line))

    def __enter__(self) -> "ProgramStretches":
        return self

    def __exit__(self, *exc) -> None:
        if self.file is not None:
            self.file.close()


DIALECT = DinDialect()
