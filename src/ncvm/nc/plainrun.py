"""Runs of plain motion blocks, executed as whole columns with numpy.

Most of a CAM-generated DIN program is consecutive blocks made of nothing but
an N number, one motion G code (G0 to G3) and X Y Z I J K F words. The reader
(:func:`ncvm.nc.block.read_din_segments`) keeps such a stretch as a
:class:`~ncvm.nc.block.PlainRun`: one numpy column per address, NaN where a
block has no such word. :func:`execute_columns` then does for the whole run what
:meth:`NcKernel.execute` does block by block -- modal motion and feed carried
forward, G90/G91 targets, offsets, arc centres, the radius check, sweep
angles, extents and the moves' speed limits and tangents -- hands the moves to
the path planner (:mod:`ncvm.nc.planner`) as columns and to the canon interface
as one :class:`~ncvm.nc.canon.MoveBatch`. The results are the block-by-block
results (same formulas, same order of float operations, the clock summed in
move order); ``tests/nc/test_plain_run.py`` holds the two paths side by side.

A block that would fault (G1 without feed, an arc whose end lies on another
radius, an arc without centre words) is left to the caller, who hands it to
:meth:`NcKernel.execute`, so the fault and its message are the kernel's own.

A run shorter than :data:`~ncvm.nc.block.RUN_COLUMNS_FROM` blocks is not worth its columns (a few dozen
numpy calls whatever its length): it is executed block by block (:func:`~ncvm.nc.block.columnar`), with the
same results to the last bit (``tests/nc/test_short_runs.py``). A short run read from text goes from its
lines' regex matches straight to the kernel's moves (:func:`execute_short_run`), without a Block or the kernel's
general dispatch per line (issue 18: a drilling program's runs of four blocks between two dwells).
"""

from __future__ import annotations

import math
from itertools import compress, groupby, islice, repeat
from operator import attrgetter, is_not

from ..lazy import lazy
from . import arcs
from .block import PLAIN_WORDS, ROW_WORD, Block, PlainRun, block_row, columnar, row_g, row_line, row_src
from .canon import BatchArcs, MoveBatch, Src
from .dynamics import arc_limits_columns, lengths_columns, straight_limits_columns
from .kernel import PLANES
from .planner import LOOKAHEAD, POSITIONING, arc_tangents_columns
from .profiles import MOTION

np = lazy("numpy")


RAPID, FEED, ARC = 0, 1, 2


def _carry(present: np.ndarray, values: np.ndarray, initial: float) -> np.ndarray:
    """Modal values: each row's own value where present, else the last one before it, else ``initial``."""
    last = np.maximum.accumulate(np.where(present, np.arange(len(present)), -1))
    return np.where(last >= 0, values[np.maximum(last, 0)], initial)


def execute_columns(k, run: PlainRun, lo: int, hi: int) -> int | None:
    """Execute blocks ``lo``..``hi`` of ``run`` as columns, with the results of executing them one by one.

    Stops before the first block the kernel must judge itself (one that would
    fault) and returns its index, or None when every block was executed. When
    the kernel does per-block work these columns do not model
    (:meth:`NcKernel.columns_ok`), it judges every block itself.
    """
    if not k.columns_ok():
        return lo if lo < hi else None
    scale = k.scale
    words = {a: col[lo:hi] for a, col in run.words.items()}
    present = {a: ~np.isnan(col) for a, col in words.items()}
    g = run.g[lo:hi]
    motion = _carry(g >= 0, g, k.motion)
    feed = _carry(present["F"], words["F"] * scale if scale != 1.0 else words["F"], k.feed)
    prog, moved = _targets(k, words, present, hi - lo)
    is_arc = motion >= 2
    moved |= is_arc & (present["I"] | present["J"] | present["K"])

    # the first row the kernel must see itself: motion at feed without a feed, an arc without centre or plane axes
    an, bn, _nn, iw, jw = PLANES[k.plane]
    a, b = k.axis_of.get(an), k.axis_of.get(bn)
    no_centre = is_arc if a is None or b is None else is_arc & ~(present[iw] | present[jw])
    judged = np.flatnonzero(moved & (((motion >= 1) & (feed <= 0.0)) | no_centre))
    end_row = int(judged[0]) if len(judged) else hi - lo

    idx = np.flatnonzero(moved[:end_row])  # the rows that move
    if len(idx) == 0:
        return _finish(k, motion, feed, prog, end_row, lo, hi, None)
    end = np.column_stack([p[idx] + o for p, o in zip(prog, k.offset_vec)])
    start = np.vstack((np.asarray(k.machine_pos, dtype=float), end[:-1]))
    kind = np.minimum(motion[idx], ARC).astype(np.int8)
    move_feed = feed[idx]
    d = end - start
    length = lengths_columns(d)
    with np.errstate(divide="ignore", invalid="ignore"):
        u_in = d / length[:, None]
    u_out = u_in
    v, acc = straight_limits_columns(k.dyn, d, length, kind == RAPID, move_feed)
    arc_pos = np.flatnonzero(kind == ARC)
    found = None
    if len(arc_pos):
        centre_words = (words[iw][idx[arc_pos]], words[jw][idx[arc_pos]])
        done = _arcs(k, arc_pos, start, end, centre_words, move_feed[arc_pos], motion[idx[arc_pos]] == 2, a, b)
        if isinstance(done, int):  # an arc whose end lies on another radius: the rows before it, then stop
            stop = lo + int(idx[arc_pos[done]])
            before = execute_columns(k, run, lo, stop) if stop > lo else None  # passes: nothing before is judged
            return stop if before is None else before
        found, (length[arc_pos], v[arc_pos], acc[arc_pos], tangents) = done
        u_out = u_in.copy()
        u_in[arc_pos], u_out[arc_pos] = tangents
    # the moves to the planner (a straight move of length 0 takes no time), then to the canon, as one by one
    flags = np.where(kind == RAPID, POSITIONING, k.exact)
    timed = (kind == ARC) | (length > 0.0)
    if not timed.all():
        length, v, acc, flags, u_in, u_out = (c[timed] for c in (length, v, acc, flags, u_in, u_out))
    k.planner.add_columns(length, v, acc, flags, u_in, u_out)
    k.canon.move_batch(MoveBatch(kind, start, end, move_feed, run.file, run.lines[lo:hi][idx], found))
    return _finish(k, motion, feed, prog, end_row, lo, hi, end)


def _targets(k, words, present, rows: int) -> tuple[list, np.ndarray]:
    """Programmed position per axis and row (G90 carried forward, G91 summed), and which rows name an axis.

    The words of axes this machine lacks are ignored, as block by block.
    """
    moved = np.zeros(rows, dtype=bool)
    prog = []
    for i, name in enumerate(k.axis_names):
        has = present.get(name)
        if has is None or not has.any():
            prog.append(np.full(rows, k.prog[i]))
            continue
        moved |= has
        v = words[name] * k.scale if k.scale != 1.0 and name not in k.rotary else words[name]
        if k.absolute:
            prog.append(_carry(has, v, k.prog[i]))
        else:  # summed from the start value, in row order: the same float operations as one by one
            prog.append(np.cumsum(np.concatenate(([k.prog[i]], np.where(has, v, 0.0))))[1:])
    return prog, moved


def _finish(k, motion, feed, prog, end_row, lo, hi, end) -> int | None:
    """Leave the kernel's modal state and position as the last executed row left them."""
    if end_row:
        last = end_row - 1
        k.motion = int(motion[last])
        k.feed = float(feed[last])
        if end is not None:
            k.prog = [float(p[last]) for p in prog]
            k.machine_pos = tuple(end[-1].tolist())
    return None if end_row == hi - lo else lo + end_row


def _arcs(k, arc_pos, start, end, centre_words, feed, cw, a: int, b: int) -> tuple[BatchArcs, tuple] | int:
    """Centre (I/J/K words), radius check, sweep, length, extent, path speed and acceleration and tangents
    of the arcs at ``arc_pos`` among the moves, or the index (among the arcs) of the first whose end lies on
    another radius."""
    sa, sb = start[arc_pos, a], start[arc_pos, b]
    ea, eb = end[arc_pos, a], end[arc_pos, b]
    ca = sa + np.nan_to_num(centre_words[0]) * k.scale
    cb = sb + np.nan_to_num(centre_words[1]) * k.scale
    r0 = np.hypot(sa - ca, sb - cb)
    bad = np.flatnonzero(k.arc_tolerance.refuses_columns(r0, np.hypot(ea - ca, eb - cb), k.scale != 1.0))
    if len(bad):
        return int(bad[0])
    angle, a0 = arcs.sweep_columns(sa, sb, ea, eb, ca, cb, cw)
    length = arcs.arc_length_columns(r0, angle, arcs.helix_travel_columns(start[arc_pos], end[arc_pos], a, b))
    # no plane axis above its own limits anywhere on the arc (NcKernel.arc_out)
    v, acc = arc_limits_columns(end[arc_pos] - start[arc_pos], a, b, length, feed / 60.0, k.dyn.max_feed,
                                k.dyn.accel)
    if k.planner.model == LOOKAHEAD:  # the centripetal acceleration the plane axes can give (NcKernel.arc_out)
        v = np.minimum(v, np.sqrt(min(k.dyn.accel[a], k.dyn.accel[b]) * r0))
    centre = np.column_stack((ca, cb))
    arcs_found = BatchArcs(arc_pos, a, b, centre, cw, r0, angle, length,
                           arcs.arc_plane_extent_columns(sa, sb, ca, cb, r0, a0, angle))
    tangents = arc_tangents_columns(start[arc_pos], end[arc_pos], a, b, centre, r0, angle, length)
    return arcs_found, (length, v, acc, tangents)


_SRC, _FILE = row_src, attrgetter("file")
_G_COLUMN, _LINE_COLUMN = row_g, row_line
_WORD_COLUMN = {a: ROW_WORD[a] for a in PLAIN_WORDS}


def plain_segments(items: list, addresses: str | set = PLAIN_WORDS) -> list:
    """A motion queue's items as segments: :class:`PlainRun` stretches and single blocks.

    Plain rows (tuples laid out as :class:`~ncvm.nc.block.PlainRow`) are plain by
    construction; a :class:`Block` itself (a front end's other subclasses carry
    more than words) is plain when :func:`block_row` can hold it. A stretch of
    plain items from one file becomes a run; other blocks stay as they are.
    ``addresses`` are the words the rows can have at all (the front end knows
    which its code builds): the other columns are NaN without reading a row.
    """
    items = list(items)
    used = set(addresses)
    others = []  # the items that stay blocks; the scan for them runs in C (most items are rows)
    for i in compress(range(len(items)), map(is_not, map(type, items), repeat(tuple))):
        it = items[i]
        row = block_row(it) if it.__class__ is Block else None
        if row is None:
            others.append(i)
        else:
            items[i] = row
            used.update(it.words)
    out: list = []
    lo = 0
    for i in others + [len(items)]:
        if i > lo:
            _runs(items[lo:i], used, out)
        if i < len(items):
            out.append(items[i])
        lo = i + 1
    return out


def _runs(rows: list, used: set, out: list) -> None:
    """Plain rows as one run per stretch of one file."""
    files = list(map(_FILE, map(_SRC, rows)))
    if files.count(files[0]) == len(files):  # the common case: one file
        out.append(_columns(files[0], rows, used))
        return
    lo = 0
    for file, group in groupby(files):
        hi = lo + len(list(group))
        out.append(_columns(file, rows[lo:hi], used))
        lo = hi


def _columns(file: str, rows: list, used: set) -> PlainRun:
    n = len(rows)
    if not columnar(n):  # a short run stays rows (no numpy): it runs block by block
        return PlainRun(file, None, None, None, origin=rows)
    words = {a: np.fromiter(map(get, rows), float, n) if a in used else np.full(n, math.nan)
             for a, get in _WORD_COLUMN.items()}
    return PlainRun(file, np.fromiter(map(_LINE_COLUMN, rows), np.int64, n),
                    np.fromiter(map(_G_COLUMN, rows), np.int64, n), words, origin=rows)


def execute_segments(kernel, segments, execute=None) -> None:
    """Execute what :func:`plain_segments` made until program end: runs column-wise, short runs
    (:func:`~ncvm.nc.block.columnar`) and other blocks one by one.

    ``execute`` runs a single block (default: the kernel's own ``execute``).
    """
    execute = execute or kernel.execute
    for seg in segments:
        if kernel.ended:
            return
        if isinstance(seg, PlainRun) and not columnar(len(seg)):
            for blk in seg.blocks():
                if kernel.ended:
                    return
                execute(blk)
        elif isinstance(seg, PlainRun):
            lo, hi = 0, len(seg)
            while (bad := execute_columns(kernel, seg, lo, hi)) is not None:
                kernel.execute(seg.block(bad))  # a block the columns leave to the kernel (one that faults, or any under G96 or a transformation)
                lo = bad + 1
        else:
            execute(seg)


_MOTION_CODES = (0, 1, 2, 3)
_PLAIN = frozenset(PLAIN_WORDS)


def plain_moves_ok(k) -> bool:
    """Whether a plain block may skip :meth:`NcKernel.execute`'s general dispatch now: what
    :meth:`NcKernel.columns_ok` asks, and G0-G3 the profile's motion functions (no path control, thread mode
    or handler of their own), no address handler for a plain word. Then the block's F and motion are all
    ``execute`` does before its move."""
    table = k.g_table
    return (k.columns_ok() and not k.css and not k.per_rev
            and all(table.get(g, (None,))[0] == MOTION and g not in k.path_codes and g not in k.motion_modes
                    and g not in k.g_handlers for g in _MOTION_CODES)
            and not _PLAIN.intersection(k.word_handlers))


def execute_short_run(k, run: PlainRun, count: int, counted: list) -> None:
    """Execute the first ``count`` blocks of a short run read from text (its lines' regex matches, groups N, G,
    then :data:`PLAIN_WORDS`) with the results of :meth:`NcKernel.execute` on the Blocks the line parser makes
    of them (:func:`~ncvm.nc.block._blocks`): per block its F word, its motion, then the kernel's straight
    move (``k.linear``) or its arc (``k._move``), with their faults. ``counted[0]`` is left at the blocks
    counted, the one that faulted with them (a run counts each block before it runs). A run made of rows or
    Blocks, or without :func:`plain_moves_ok`: block by block through ``execute``."""
    i = -1
    try:
        if run.matches is None or not plain_moves_ok(k):
            for blk in islice(run.blocks(), count):
                i += 1
                k.execute(blk)
            return
        file, scale, first = run.file, k.scale, run.line(0)
        for i, (_n, g, x, y, z, ii, jj, kk, f, _rest) in enumerate(run.matches[:count]):
            # unrolled as nc.block._blocks unrolls it (Blocks of the same matches): a call costs a third of a block
            words = {}
            if x:
                words["X"] = float(x)
            if y:
                words["Y"] = float(y)
            if z:
                words["Z"] = float(z)
            if ii:
                words["I"] = float(ii)
            if jj:
                words["J"] = float(jj)
            if kk:
                words["K"] = float(kk)
            if f:
                feed = words["F"] = float(f)
                k.feed = feed * scale if scale != 1.0 else feed
            motion = int(g) if g else k.motion
            k.motion = motion
            if motion < 2:
                k.linear(k, motion, words, Src(file, first + i))
            else:
                k._move(motion, words, False, Src(file, first + i))
    finally:
        counted[0] = i + 1
