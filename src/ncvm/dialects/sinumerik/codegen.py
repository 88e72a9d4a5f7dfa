"""Compiling a SINUMERIK part program to one Python function (a basic-block dispatch loop).

Every NC block becomes straight-line Python: @ code and R arithmetic run at
decode time, in block order; DIN words are collected into the block record
and handed to the NC kernel at the end of the block (or when a jump is taken
part-way through it: the words read so far stay in the block, the rest is
ignored). Jump targets become entry labels of a
``while True: if _blk <= k: ...`` chain, so ``@100 K-N`` loops are a
``continue``. R parameters the program names are Python locals, written back
to the channel's R array (``_R``) around anything that reaches R parameters
by number (pointers, push/pop, sub-program calls, multi-register results).
"""

from __future__ import annotations

from contextlib import contextmanager
from itertools import accumulate
from typing import NamedTuple

from ...diagnostics import Diagnostic, Span
from ...nc.axiswords import AXIS_LETTERS, is_dwell, is_missing_axis, missing_axis_message, names_axis
from ...nc.block import Block, acts
from ...nc.canon import Src
from ...nc.profiles.blockrules import dwell_time
from ...nc.profiles.check import refused_g_warnings
from ...nc.profiles.sinumerik8xx import SINUMERIK8XX
from ...nc.toolcheck import tool_change_warnings
from ...runtime.codegen import PySource
from .atcodes import AT_CODES, AtCode
from .finite import may_underflow, stays_in_range
from .ncdata import CENTRAL_R, R_LIMIT, R_SMALLEST
from .reader import Arith, AtInstr, NcBlock, Note, Operand, PartProgram, Word

#: M functions the kernel handles itself; any other goes to the PLC
_STANDARD_M = frozenset((0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 17, 30))
#: G80-G89 (internal G group 9): select or end a drilling cycle (drilling.py)
_CYCLE_G = frozenset(range(80, 90))
#: the word keys computed at run time that are axis words all the same: @440 (PRAP, the drilling cycles'
#: infeed) names an axis by its number, and axis_name gives a machine axis or refuses the block. A G0/G1
#: block of axis words goes straight to the kernel's straight-move path (``_lin``), as with constant axes
COMPUTED_AXIS_KEYS = ("_rt.positions.axis_name(",)


def constant_axis(axes: tuple[str, ...], op: Operand) -> str | None:
    """The axis a constant axis number of @440 names (``K3``: the third), known when the program compiles, as
    Positions.axis_name gives it at run time; None for a number read from an R parameter, or one the machine
    lacks (refused at run time, at its block, by axis_name)."""
    if op.kind != "K":
        return None
    v = op.value
    return axes[int(v) - 1] if v == int(v) and 1 <= v <= len(axes) else None


def _num(v: float) -> str:
    return repr(float(v))


def missing_axis(address: str, axes, dwell: bool = False, radius: str = "B") -> bool:
    """A word for an axis the machine lacks (NC011), or a letter no function of the sinumerik8xx profile reads
    (NC007, :func:`refused_word`); A and the radius address (B or U, machine data) without such axes are the
    angle and the circle radius, X in a dwell block (``dwell``, :func:`dwells`) the time."""
    return address not in ("A", radius) and (is_missing_axis(address, axes) and names_axis(address, dwell)
                                          or refused_letter(address, axes))


#: the one-letter addresses a function of the SINUMERIK blocks reads besides the axes (nc/profiles/sinumerik8xx.py)
READ_LETTERS = frozenset(a.letter for a in SINUMERIK8XX.addresses) | frozenset("GMN")


def refused_letter(address: str, axes) -> bool:
    return len(address) == 1 and address not in AXIS_LETTERS and address not in READ_LETTERS and address not in axes


def refused_word(address: str, axes) -> tuple[str, str]:
    """(code, message) of a word :func:`missing_axis` finds."""
    if refused_letter(address, axes):
        return "NC007", (f"address {address} is not supported by ncvm (no function of the sinumerik8xx profile "
                         "reads it)")
    return "NC011", missing_axis_message(address, axes)


def dwells(items) -> bool:
    """A dwell block (G4): its X is the time."""
    return is_dwell(it.value for it in items if isinstance(it, Word) and it.address == "G")


def _word_diagnostic(path: str, line: int, column, address: str, axes) -> Diagnostic:
    """NC011 (an error: the machine lacks the axis), or NC007 (a warning: ncvm reads no such address)."""
    code, message = refused_word(address, axes)
    if code == "NC011":
        return Diagnostic(code, message, Span(path, line, column))
    return Diagnostic(code, message + ": the run stops here", Span(path, line, column), severity="warning")


def refused_g_diagnostics(prog: PartProgram) -> list[Diagnostic]:
    """``ncvm check``: warnings for the G functions the SINUMERIK 810-880 profile refuses (nc/profiles/check.py)."""
    return refused_g_warnings(SINUMERIK8XX, prog.path, [(it.value, blk.line, it.col) for blk in prog.blocks
                                                         for it in blk.items if g_word(it)])


def tool_diagnostics(prog: PartProgram, tools) -> list[Diagnostic]:
    """``ncvm check``: NC008 where a literal T word selects a tool the machine file lacks and M6 changes to
    it (nc/toolcheck.py, the kernel's rule)."""
    blocks = []
    for blk in prog.blocks:
        t = next((it for it in blk.items if isinstance(it, Word) and it.address == "T"), None)
        m6 = any(isinstance(it, Word) and it.address == "M" and it.value == 6 for it in blk.items)
        blocks.append((blk.line, t.col if t else None, t.value if t else None, m6))
    return tool_change_warnings(prog.path, blocks, tools)


def g_word(it) -> bool:
    """A G word with a constant value (G=R.. is refused by the block compiler itself, SIN001)."""
    return isinstance(it, Word) and it.address == "G" and it.value is not None


def axis_diagnostics(prog: PartProgram, axes, radius: str = "B") -> list[Diagnostic]:
    """``ncvm check``: the words for axes the machine lacks, where a run refuses them, and the dwell blocks
    with a move."""
    return [_word_diagnostic(prog.path, blk.line, it.col, it.address, axes)
            for blk in prog.blocks for it in blk.items
            if isinstance(it, Word) and (it.value is not None or it.rref is not None)
            and missing_axis(it.address, axes, dwells(blk.items), radius)] + dwell_diagnostics(
        prog.path, ((blk.line, 0, blk.items) for blk in prog.blocks), axes)


def dwell_diagnostics(path: str, blocks, axes) -> list[Diagnostic]:
    """``ncvm check``: a dwell block with an axis word beside its time, which the run refuses (NC009: the dwell
    is a block of its own, CL 800 L5465; nc/profiles/blockrules.py). ``blocks``: (line, what to add to a
    word's column in the block for its column in the line, the block's Words)."""
    out = []
    for line, offset, items in blocks:
        words = [it for it in items if isinstance(it, Word) and (it.value is not None or it.rref is not None)]
        if not dwells(words):
            continue
        g = [w.value for w in words if w.address == "G" and w.value is not None]
        values = {w.address: (w.value if w.value is not None else 0.0) for w in words if w.address not in "GMH"}
        found = dwell_time(SINUMERIK8XX, g, values, axes)
        if found is not None:
            at = next(w.col for w in words if w.address == "G" and w.value == found[3])
            out.append(Diagnostic(found[0], found[1], Span(path, line, offset + at)))
    return out


class UnitCodegen:
    """Turns one :class:`PartProgram` into Python source for ``_unit(_rt)``."""

    def __init__(self, prog: PartProgram, unit: str, axis_names: tuple[str, ...], debug: bool = False,
                 decode_ahead: bool = False, strict: bool = False, radius: str = "B"):
        self.prog = prog
        self.radius = radius  # the circle radius address ([sin800] radius_address): the kernel's R
        self.debug = debug  # a debug build calls the step hook before every block
        # with decode-ahead every block goes through the channel's buffer (no direct kernel moves)
        self.decode_ahead = decode_ahead
        self.strict = strict  # [sin800] strict_nc: every R store rounds to 8 significant digits
        self.unit = unit
        self.axes = axis_names
        self.src = PySource(f"<sin800 {unit} {prog.path}>")
        self.consts: dict[str, object] = {}
        self.used: set[int] = set()
        self.labels: dict[int, int] = {}  # block index -> label ordinal
        self.dynamic_jumps = False
        self.written: set[int] = set()  # R parameters the program writes by number
        self.keeps_central = False  # a store into a central R by name or through a pointer (:meth:`kept`)
        #: what the item being lowered reads of R900-R999 (central R, kept from earlier runs): by number,
        #: and the pointer R parameters it reads through (any R, a central one too)
        self.central_reads: set[int] = set()
        self.pointer_reads: set[int] = set()
        #: block index -> (its place in its stretch, the stretch's length): see :meth:`_scan_stretches`
        self.stretch: dict[int, tuple[int, int]] = {}
        self.ahead = 0  # blocks of the current stretch counted into _st but not yet reached
        self.loop: int | None = None  # the label whose stretch is being generated as a while loop (_loops)
        #: generated body line index -> the blocks counted ahead there, where not 0 (a fault takes them back)
        self.ahead_at: dict[int, int] = {}

    # -- constants and R names -------------------------------------------
    def const(self, value: object, prefix: str = "_C") -> str:
        name = f"{prefix}{len(self.consts)}"
        self.consts[name] = value
        return name

    def r(self, n: int) -> str:
        self.used.add(n)
        return f"r{n}"

    def val(self, op: Operand) -> str:
        """Python expression reading a <Value>."""
        if op.kind == "K":
            return _num(op.value)
        if op.kind == "R":
            return self.read_r(int(op.value))
        self.pointer_reads.add(int(op.value))
        return f"_R[_ptr({self.r(int(op.value))})]"

    def read_r(self, n: int) -> str:
        """R parameter ``n`` read by name (a central one is noted for :meth:`central_check`)."""
        if n in CENTRAL_R:
            self.central_reads.add(n)
        return self.r(n)

    def central_check(self, out: PySource, start: int, line: int) -> None:
        """Before the lines of an item (from ``start``) that read central R parameters: the channel marks the
        first read of each left by an earlier run (a translation's FROZEN mark at this block). One test of an
        empty dict where none was left; reads through a pointer see ``_R`` brought up to date first."""
        if not self.central_reads and not self.pointer_reads:
            return
        reads = [f"({n}, r{n})" for n in sorted(self.central_reads)]
        reads += [f"(_ptr(r{n}), _R[_ptr(r{n})])" for n in sorted(self.pointer_reads)]
        self.central_reads, self.pointer_reads = set(), set()
        pad = "    " * out._indent
        lines = [f"{pad}if _left:"] + ([f"{pad}    @SYNC_OUT"] if "_ptr" in reads[-1] else [])
        lines.append(f"{pad}    _rt.central_read({line}, ({', '.join(reads)},))")
        out.lines[start:start] = lines
        out.line_map[start:start] = [line] * len(lines)
        out.col_map[start:start] = [None] * len(lines)
        if self.ahead_at:  # the item's own lines moved down: so do the blocks they count ahead (see leaving)
            self.ahead_at = {k + len(lines) if k >= start else k: n for k, n in self.ahead_at.items()}

    def store(self, op: Operand, expr: str) -> list[str]:
        """Python lines storing ``expr`` into a <Var>; a central R (R900-R999) is then written through to the
        store (:meth:`kept`), through a pointer only when the pointer names one (one comparison)."""
        if self.strict:
            expr = f"_nc8({expr})"
        if op.kind == "R":
            n = int(op.value)
            self.written.add(n)
            return [f"{self.r(n)} = {expr}", *self.kept(n)]
        self.keeps_central = True
        return [f"_R[(_p := _ptr({self.r(int(op.value))}))] = {expr}",
                f"if _p >= {CENTRAL_R.start}: _kc(_p, _R[_p])", "@SYNC_IN"]

    def kept(self, n: int) -> list[str]:
        """The line that writes central R ``n`` through to the permanent store after a store into it by name
        (``_kc``: the channel's ``central.put``, which writes only a changed value); none for a local R."""
        if n not in CENTRAL_R:
            return []
        self.keeps_central = True
        return [f"_kc({n}, r{n})"]

    # -- jump targets ----------------------------------------------------
    def find_target(self, index: int, number: int) -> int | None:
        """Block index of N|number| searched forward (number >= 0) or backward (< 0) from block ``index``."""
        blocks = self.prog.blocks
        if number < 0:
            want = -number
            for i in range(index, -1, -1):
                if blocks[i].n == want:
                    return i
            return None
        for i in range(index + 1, len(blocks)):
            if blocks[i].n == number:
                return i
        return None

    def _scan_labels(self) -> None:
        self.labels[0] = 0
        targets = set()
        for idx, blk in enumerate(self.prog.blocks):
            for it in blk.items:
                if not isinstance(it, AtInstr):
                    continue
                for number in _jump_numbers(it):
                    if number is None:
                        self.dynamic_jumps = True
                        continue
                    t = self.find_target(idx, number)
                    if t is not None:
                        targets.add(t)
        if self.dynamic_jumps:
            targets.update(i for i, b in enumerate(self.prog.blocks) if b.n is not None)
        for t in sorted(targets):
            if t not in self.labels:
                self.labels[t] = len(self.labels)
        # ordinals must grow with the block index for the `_blk <= k` chain
        ordered = sorted(self.labels)
        self.labels = {b: k for k, b in enumerate(ordered)}

    def _scan_stretches(self) -> None:
        """Stretches of consecutive blocks that only compute and branch (:func:`counts_ahead`), entered at
        their first block: such a stretch counts its blocks with one ``_st += n`` at its start. A jump out of
        it takes back the blocks it skips, a fault those not reached (``_AHEAD``), so the step count and the
        step limit stay exact per block."""
        if self.debug:
            return  # the step hook sees the count before every block
        blocks = self.prog.blocks
        idx = 0
        while idx < len(blocks):
            end = idx
            while end < len(blocks) and counts_ahead(blocks[end]) and (end == idx or end not in self.labels):
                end += 1
            for k in range(idx, end):
                self.stretch[k] = (k - idx, end - idx)
            idx = max(end, idx + 1)

    def _loops(self) -> set[int]:
        """The labelled blocks whose stretch up to the next label is a loop: some block in it jumps back to the
        label, and none jumps to an earlier label. Such a stretch runs as a Python ``while True:`` inside its
        ``if _blk <= k:`` (the jump back a ``continue`` of that loop, a jump forward ``_blk = j; break``),
        not through the dispatch chain on every pass."""
        if self.dynamic_jumps:
            return set()
        starts = sorted(self.labels)
        loops = set()
        for k, start in enumerate(starts):
            end = starts[k + 1] if k + 1 < len(starts) else len(self.prog.blocks)
            targets = {self.find_target(i, n) for i in range(start, end) for it in self.prog.blocks[i].items
                       if isinstance(it, AtInstr) for n in _jump_numbers(it)}
            targets.discard(None)
            if start in targets and min(targets) >= start:
                loops.add(start)
        return loops

    def _end_loop(self, out: PySource) -> None:
        """The end of a loop's stretch (:meth:`_loops`): falling off it goes on with the next label."""
        if self.loop is not None:
            if out.lines[-1] != "    " * out._indent + "continue":  # (not after the jump back)
                out.emit("break")
            self.loop = None

    # -- the unit --------------------------------------------------------
    def build(self) -> tuple[PySource, dict]:
        self._scan_labels()
        self._scan_stretches()
        loops = self._loops()
        body = PySource(self.src.filename)
        body._indent = 4
        run: list[Block] = []
        for idx, blk in enumerate(self.prog.blocks):
            if idx in self.labels:
                self._flush_run(body, run)
                self._end_loop(body)
                body._indent = 3
                body.emit(f"if _blk <= {self.labels[idx]}:", blk.line)
                body._indent = 4
                if idx in loops:
                    body.emit("while True:", blk.line)
                    body._indent = 5
                    self.loop = self.labels[idx]
            plain = None if self.debug else self._plain_block(blk)
            if plain is not None:
                run.append(plain)
                continue
            self._flush_run(body, run)
            self._block(body, idx, blk)
        self._flush_run(body, run)
        self._end_loop(body)
        src = self.src
        src.emit("def _unit(_rt):", 0)
        src._indent = 1
        src.emit("_R = _rt.R; _ex = _rt.execute; _K = _rt.kernel; _ctr = _rt.counter; _lin = _rt.linear")
        src.emit("_left = _rt.left  # central R left by earlier runs, not yet read (central_check)")
        src.emit("_cyc = _rt.drilling.armed  # the drilling cycle a block with an axis word calls (G81-G89)")
        if self.keeps_central:
            src.emit("_kc = _rt.central.put  # a store into a central R written through to the store")
        src.emit("_lim = _ctr.limit - _ctr.steps; _st = 0; _blk = 0")
        used = sorted(self.used)
        sync_in = "; ".join(f"r{n} = _R[{n}]" for n in used) or "pass"
        sync_out = "; ".join(f"_R[{n}] = r{n}" for n in used) or "pass"
        src.emit(sync_in)
        src.emit("try:")
        src._indent = 2
        src.emit("while True:")
        first = len(src.lines)  # the body's first line, less one (lines count from 1)
        if self.ahead_at:
            self.consts["_AHEAD"] = {first + i + 1: n for i, n in self.ahead_at.items()}
        for text, line, col in zip(body.lines, body.line_map, body.col_map):
            text = text.replace("@SYNC_IN", sync_in).replace("@SYNC_OUT", sync_out)
            src.lines.append(text)
            src.line_map.append(line)
            src.col_map.append(col)
        src._indent = 3
        src.emit("return 0", self.prog.blocks[-1].line if self.prog.blocks else 0)
        src._indent = 1
        if self.ahead_at:  # a fault inside a stretch: the blocks after the faulting one did not run
            src.emit("except BaseException as _e:")
            src.emit("    _st -= _AHEAD.get(_e.__traceback__.tb_lineno, 0)")
            src.emit("    raise")
        src.emit("finally:")
        src._indent = 2
        src.emit(sync_out)
        src.emit("_ctr.steps += _st")
        return src, self.consts

    # -- runs of constant blocks -------------------------------------------
    def _plain_block(self, blk: NcBlock) -> Block | None:
        """The Block of a block made only of constant DIN words and notes, with nothing that calls,
        ends, stops or needs the dialect (L, D, G16, G58/G59, M0/M1/M2/M17/M30); else None."""
        if blk.skip:
            return None
        g: list[float] = []
        m: list[int] = []
        words: dict[str, float] = {}
        msg = None
        for it in blk.items:
            if isinstance(it, Note):
                if it.text.upper().startswith("MSG"):
                    msg = it.text[3:].lstrip(" ,:").strip()
                continue
            if not isinstance(it, Word) or it.value is None or it.address in ("L", "D"):
                return None
            if it.address == "A" and "A" not in self.axes:
                return None  # the angle address needs the start point (rotation.py)
            if missing_axis(it.address, self.axes, dwells(blk.items), self.radius):
                return None  # refused where it stands (NC011)
            if it.address == self.radius and self.radius not in self.axes:
                return None  # the circle radius: the block passes the corner rounding (rounding.py)
            if it.address == "G":
                if it.value in (16, 58, 59) or it.value in _CYCLE_G:
                    return None
                g.append(int(it.value) if it.value == int(it.value) else it.value)
            elif it.address == "M":
                if int(it.value) in (0, 1, 2, 17, 30) or int(it.value) not in _STANDARD_M:
                    return None  # stops and ends need checks; PLC M functions may load R parameters
                m.append(int(it.value))
            elif it.address == "H" and "H" in words and "H" not in self.axes:
                words["H"] = more_h(words["H"], it.value)  # every H goes to the PLC (auxiliary_h)
            else:
                words["R" if it.address == self.radius and self.radius not in self.axes else it.address] = it.value
        if not g and not m and not words and msg is None:
            return Block((), (), {}, blk.n, None, Src(self.prog.path, blk.line))  # a block that only counts
        return Block(tuple(g), tuple(m), words, blk.n, msg, Src(self.prog.path, blk.line))

    def _flush_run(self, out: PySource, run: list[Block]) -> None:
        """Consecutive constant blocks run from a tuple: one generated line instead of one per block. Under a
        selected drilling cycle the run goes block by block, each counted before the cycle it calls."""
        if not run:
            return
        line = run[0].src.line
        todo = tuple(b for b in run if acts(b))
        if any(_positions(self.axes, b.words, b.g) for b in todo):  # a selected cycle runs after each that travels
            out.emit("if _cyc:", line)
            out._indent += 1
            self.cycle_call(out, line, f"_rt.drilling.run_blocks({self.const(tuple(run), '_ALL')}, {line})")
            out._indent -= 1
            out.emit("else:", line)
            out._indent += 1
            self._count_run(out, line, run, todo)
            out._indent -= 1
        else:
            self._count_run(out, line, run, todo)
        run.clear()

    def _count_run(self, out: PySource, line: int, run: list[Block], todo: tuple) -> None:
        """The run counted at its head and executed; when it would pass the step limit, the blocks that fit
        run and the run stops with RUN001 at the first that does not (exact, as a DIN run)."""
        many = self.const(todo, "_RUN") if len(todo) > 1 else None
        out.emit(f"_st += {len(run)}", line)
        out.emit("if _st > _lim:", line)
        out._indent += 1
        out.emit(f"_st -= {len(run)}; _k = _lim - _st; _st = _lim", line)
        if todo:  # the blocks of todo among the first k of the run, for every k
            fit = self.const(tuple(accumulate(map(acts, run), initial=0)), "_FIT")
            out.emit(f"for _b in {many or self.const(todo, '_RUN')}[:{fit}[_k]]: _ex(_b)", line)
        out.emit(f"_rt.runaway({self.const(tuple(b.src.line for b in run), '_LN')}[_k])", line)
        out._indent -= 1
        if many:
            out.emit(f"for _b in {many}: _ex(_b)", line)
        elif todo:
            out.emit(f"_ex({self.const(todo[0], '_B')})", line)

    def cycle_call(self, out: PySource, line: int, call: str) -> None:
        """Lines that run the selected drilling cycle (``call``), as an L call runs its sub-program."""
        out.emit("_ctr.steps += _st; _st = 0", line)
        out.emit("@SYNC_OUT", line)
        out.emit(call, line)
        out.emit("@SYNC_IN", line)
        out.emit("_ex = _rt.execute; _lin = _rt.linear; _cyc = _rt.drilling.armed", line)
        out.emit("_lim = _ctr.limit - _ctr.steps", line)
        out.emit("if _K.ended or _rt.halted: return 1", line)

    # -- one block -------------------------------------------------------
    def _block(self, out: PySource, idx: int, blk: NcBlock) -> None:
        line = blk.line
        if blk.skip:
            out.emit(f"_rt.block_skip_read({line})", line)
            out.emit("if not _rt.block_skip:", line)
            out._indent += 1
        place, length = self.stretch.get(idx, (0, 1))
        if place == 0:  # the stretch is counted at its head and not begun when it would pass the step limit (as CPL)
            out.emit(f"_st += {length}", line)
            out.emit(f"if _st > _lim: _st -= {length}; _rt.runaway({line})", line)
        self.ahead = length - 1 - place
        start = len(out.lines)
        if self.debug:
            out.emit("@SYNC_OUT", line)
            out.emit(f"_rt.debug_block({line})", line)
        rec = _Record(self, blk)
        items = blk.items
        # does an item after position i run code that may change R parameters?
        writes_after = [False] * len(items)
        for i in range(len(items) - 2, -1, -1):
            writes_after[i] = writes_after[i + 1] or isinstance(items[i + 1], (Arith, AtInstr))
        checks = _arith_checks(items)
        for i, it in enumerate(items):
            item_start = len(out.col_map)
            self._item(out, idx, blk, rec, it, i, checks, writes_after)
            self.central_check(out, item_start, line)
            out.col_map[item_start:] = [it.col if c is None else c for c in out.col_map[item_start:]]  # faults at the item
            if rec.jumped:
                break  # an unconditional jump: the rest of the block is never read
        else:
            rec.finish(out)
        if self.ahead:
            for i in range(start, len(out.lines)):
                self.ahead_at.setdefault(i, self.ahead)
        if blk.skip:
            out._indent -= 1

    def _item(self, out: PySource, idx: int, blk: NcBlock, rec: "_Record", it, i: int, checks: set[int],
              writes_after: list[bool]) -> None:
        """The lines of one item of a block."""
        line = blk.line
        if isinstance(it, Word):
            rec.word(out, it, writes_after[i])
        elif isinstance(it, Arith):
            rec.settle_int_sec(out)
            if i in checks and not self.strict:
                out.emit(f"_v = {self._arith_expr(it)}", line)
                out.emit(_RANGE_CHECK, line)
                out.emit(f"{self.r(it.target)} = _v", line)
            elif not self.strict and may_underflow(it.terms):  # (R*0.5: in range, but it may get too small)
                target = self.r(it.target)
                out.emit(f"{target} = {self._arith_expr(it)}", line)
                out.emit(f"if -{R_SMALLEST!r} < {target} < {R_SMALLEST!r}: {target} = _r_value({target})", line)
            else:
                out.emit(f"{self.r(it.target)} = {self._arith_expr(it)}", line)
            for text in self.kept(it.target):
                out.emit(text, line)
        elif isinstance(it, Note):
            rec.note(it)
        elif isinstance(it, AtInstr):
            rec.settle_int_sec(out)
            rec.jumped = not self._at(out, idx, blk, it, rec)

    def _arith_expr(self, it: Arith) -> str:
        """The value an R assignment stores (strict_nc: rounded and range-checked)."""
        expr = ""
        for k, (op, term) in enumerate(it.terms):
            v = self.val(term)
            if k == 0:
                expr = f"-{v}" if op == "-" else v
            else:
                expr = f"({expr} {op} {v})"
        self.written.add(it.target)
        if self.strict:
            expr = f"_nc8({expr})"
        return expr

    def _jump(self, out: PySource, idx: int, blk: NcBlock, number: int, rec: "_Record") -> None:
        """Lines that leave the block for block ``number`` (±, as ncvm writes object text)."""
        rec.finish(out, jumping=True)
        target = self.find_target(idx, number)
        if target is None:
            out.emit(f"_rt.no_block({number}, {blk.line})")
            return
        label = self.labels[target]
        with self.leaving(out):  # (a jump back lands on a label: the head of a stretch or run, which tests the limit)
            if self.loop is None:
                out.emit(f"_blk = {label}; continue")
            else:  # inside a loop's stretch: to its head, or on after it (never to an earlier label: _loops)
                out.emit("continue" if label == self.loop else f"_blk = {label}; break")

    @contextmanager
    def leaving(self, out: PySource):
        """The lines of a jump out of a stretch: first the blocks counted ahead are taken back (they are not
        run), so the lines emitted inside count none ahead."""
        if self.ahead:
            out.emit(f"_st -= {self.ahead}")
            self.ahead_at[len(out.lines) - 1] = self.ahead
        start = len(out.lines)
        yield
        self.ahead_at.update(dict.fromkeys(range(start, len(out.lines)), 0))

    def _at(self, out: PySource, idx: int, blk: NcBlock, it: AtInstr, rec: "_Record") -> bool:
        """Lower one @ code by its row's ``lower``; False when the rest of the block is never read."""
        if any(o.kind == "P" for o in it.operands):
            out.emit("@SYNC_OUT", blk.line)
        at = _Site(out, idx, blk, it, AT_CODES[it.code], rec)
        return getattr(self, f"lower_{at.row.lower}")(at)

    def _lines(self, at: "_Site", lines: list[str]) -> bool:
        """Emit a statement's lines. Each line that writes the R array itself (a store through a pointer,
        a read, a call of the channel) reloads the named R parameters after it: a reload here as well
        would discard a result stored into a named R parameter (``@201 R22 P21``)."""
        for text in lines:
            at.out.emit(text, at.blk.line)
        return True

    # -- main groups 0 and 1: program structure, branching ---------------
    def lower_ess(self, at: "_Site") -> bool:
        return self._lines(at, ["_rt.ess()"])

    def lower_push(self, at: "_Site") -> bool:
        return self._push_pop(at, "push")

    def lower_pop(self, at: "_Site") -> bool:
        return self._push_pop(at, "pop")

    def _push_pop(self, at: "_Site", fn: str) -> bool:
        ops = at.it.operands
        regs = [int(o.value) for o in ops[1:]] if at.row.kinds is None else \
            list(range(int(ops[0].value), int(ops[1].value) + 1))
        regs_c = self.const(tuple(regs), "_P")
        return self._lines(at, ["@SYNC_OUT", f"_rt.{fn}({regs_c}, {at.blk.line})", "@SYNC_IN"])

    def lower_goto(self, at: "_Site") -> bool:
        out, idx, blk, rec, op = at.out, at.idx, at.blk, at.rec, at.it.operands[0]
        if op.kind == "K":
            self._jump(out, idx, blk, int(op.value), rec)
            return False
        rec.finish(out, jumping=True)
        table = self.const({b.n: [] for b in self.prog.blocks if b.n is not None}, "_T")
        for i, b in enumerate(self.prog.blocks):
            if b.n is not None:
                self.consts[table][b.n].append((i, self.labels[i]))
        out.emit(f"_blk = _rt.dynamic_target({table}, {self.val(op)}, {idx}, {blk.line})")
        with self.leaving(out):
            out.emit("continue")
        return False

    def lower_case(self, at: "_Site") -> bool:
        ops, out = at.it.operands, at.out
        var = self.val(ops[0])
        first = True
        for value, target in zip(ops[1::2], ops[2::2]):
            out.emit(f"{'if' if first else 'elif'} {var} == {self.val(value)}:", at.blk.line)
            first = False
            out._indent += 1
            self._jump(out, at.idx, at.blk, int(target.value), at.rec)
            out._indent -= 1
        return True

    def lower_branch(self, at: "_Site") -> bool:
        """Jump when the row's condition holds (ncvm's reading; the CL 800 manual is silent)."""
        ops, out = at.it.operands, at.out
        test = at.row.expr.format(a=self.val(ops[0]), b=self.val(ops[1]), line=at.blk.line, col=at.it.col)
        out.emit(f"if {test}:", at.blk.line)
        out._indent += 1
        self._jump(out, at.idx, at.blk, int(ops[2].value), at.rec)
        out._indent -= 1
        return True

    # -- main group 2: general data transfer ------------------------------
    def lower_clear(self, at: "_Site") -> bool:
        return self._lines(at, self.store(at.it.operands[0], "0.0"))

    def lower_assign(self, at: "_Site") -> bool:
        ops = at.it.operands
        return self._lines(at, self.store(ops[0], self.val(ops[1])))

    def lower_xchg(self, at: "_Site") -> bool:
        ops = at.it.operands
        if ops[0].kind == "R" and ops[1].kind == "R":
            a, b = self.val(ops[0]), self.val(ops[1])
            na, nb = int(ops[0].value), int(ops[1].value)
            if na in CENTRAL_R and nb in CENTRAL_R:  # one write holds both (a kill never leaves half a swap)
                return self._lines(at, [f"{a}, {b} = {b}, {a}", f"_R[{nb}] = {b}", *self.kept(na)])
            return self._lines(at, [f"{a}, {b} = {b}, {a}", *self.kept(na), *self.kept(nb)])
        return self._lines(at, [f"_rt.xchg({self._ref(ops[0])}, {self._ref(ops[1])})", "@SYNC_IN"])

    def lower_bit(self, at: "_Site") -> bool:
        ops = at.it.operands
        return self._lines(at, self.store(ops[0], f"_rt.bit({self.val(ops[1])}, {int(ops[2].value)})"))

    def lower_mib_clear(self, at: "_Site") -> bool:
        ops = at.it.operands
        return self._lines(at, [f"_rt.mib_clear({self.val(ops[0])}, {self.val(ops[1])})"])

    def lower_mib_read(self, at: "_Site") -> bool:
        ops = at.it.operands
        return self._lines(at, self.store(ops[0], f"_rt.mib_read({self.val(ops[1])})"))

    def lower_mib_write(self, at: "_Site") -> bool:
        ops = at.it.operands
        return self._lines(at, [f"_rt.mib_write({self.val(ops[0])}, {self.val(ops[1])})"])

    # -- main groups 3 and 4: system memory --------------------------------
    def lower_read(self, at: "_Site") -> bool:
        code, ops = at.it.code, at.it.operands
        args = ", ".join(self.val(o) for o in ops[1:])
        if ops[0].kind == "R":
            self.written.add(int(ops[0].value))
            target = str(int(ops[0].value))
        else:
            target = f"_ptr({self.r(int(ops[0].value))})"
        return self._lines(at, ["@SYNC_OUT", f"_rt.read({code!r}, {target}, ({args}{',' if args else ''}))",
                                "@SYNC_IN"])

    def lower_write(self, at: "_Site") -> bool:
        return self._lines(at, [self._write(at)])

    def lower_write_rotation(self, at: "_Site") -> bool:
        """A rotation angle may switch block shaping on or off: the execute and linear functions change."""
        return self._lines(at, [self._write(at), "_ex = _rt.execute; _lin = _rt.linear"])

    def _write(self, at: "_Site") -> str:
        args = ", ".join(self.val(o) for o in at.it.operands)
        return f"_rt.write({at.it.code!r}, ({args}{',' if args else ''}), {at.blk.line})"

    def lower_setpoint(self, at: "_Site") -> bool:
        at.rec.setpoint(at.out, at.it.code, at.it.operands)
        return True

    # -- main group 6: mathematical and logical functions -----------------
    def lower_math(self, at: "_Site") -> bool:
        ops, row = at.it.operands, at.row
        target = ops[0]
        expr = row.expr.format(me=self.val(target), x=self.val(ops[1]) if len(ops) > 1 else None,
                               y=self.val(ops[2]) if len(ops) > 2 else None,
                               k=int(ops[1].value) if len(ops) > 1 else None)
        if row.overflows and not self.strict:  # (strict stores check the range themselves)
            # checked inline as R arithmetic is (a hot path: @620 INC counts loops); _r_value names the error
            at.out.emit(f"_v = {expr}", at.blk.line)
            at.out.emit(_RANGE_CHECK, at.blk.line)
            expr = "_v"
        elif row.underflows and not self.strict:  # SIN 180: 1.2e-16 (checked inline: a hot path)
            expr = f"(_v if not -{R_SMALLEST!r} < (_v := {expr}) < {R_SMALLEST!r} else _r_value(_v))"
        return self._lines(at, self.store(target, expr))

    # -- main group 7: NC-specific functions --------------------------------
    def lower_pos_msys(self, at: "_Site") -> bool:
        at.rec.machine_coords = True
        return True

    def lower_int_sec(self, at: "_Site") -> bool:
        """INT SEC works on the destination written in the same block."""
        ops = at.it.operands
        if any(o.kind == "P" for o in ops):
            at.out.emit("@SYNC_OUT", at.blk.line)
        at.rec.int_sec = (self._ref(ops[0]), self._ref(ops[1]))
        return True

    def lower_meas_m(self, at: "_Site") -> bool:
        """MEAS M cuts the motion of its own block at the probe's trigger point."""
        ops = at.it.operands
        at.rec.meas = (self._ref(ops[0]), self.val(ops[1]))
        return True

    def lower_rel(self, at: "_Site") -> bool:
        """REL waits once its own block has executed (L4409-4413)."""
        at.rec.rel = tuple(at.rec.capture(at.out, o) for o in at.it.operands)
        return True

    def lower_inta(self, at: "_Site") -> bool:
        """INTA cuts the motion of its own block when the input fires (L4417-4436)."""
        at.rec.inta = tuple(at.rec.capture(at.out, o) for o in at.it.operands)
        return True

    def lower_nc_refs(self, at: "_Site") -> bool:
        """PREP REF / PREP CYC: the R numbers of the results (and of the sub-program for PREP REF)."""
        code, ops = at.it.code, at.it.operands
        refs = ", ".join(self._ref(o) if i == 0 or code == "710" else self.val(o) for i, o in enumerate(ops))
        return self._lines(at, ["@SYNC_OUT", f"_rt.nc_function({code!r}, ({refs},), {at.blk.line})", "@SYNC_IN"])

    def lower_stop_dec(self, at: "_Site") -> bool:
        """STOP DEC hands over R parameters loaded during execution."""
        return self._lines(at, ["@SYNC_OUT", f"_rt.nc_function({at.it.code!r}, (), {at.blk.line})", "@SYNC_IN"])

    # -- main group a: I/O --------------------------------------------------
    def lower_io(self, at: "_Site") -> bool:
        args = ", ".join(self.val(o) for o in at.it.operands)
        return self._lines(at, [f"_rt.io({at.it.code!r}, ({args}{',' if args else ''}))"])

    def lower_io_out(self, at: "_Site") -> bool:
        """OUTP PARA outputs the R parameters as they are now."""
        args = ", ".join(self.val(o) for o in at.it.operands)
        return self._lines(at, ["@SYNC_OUT", f"_rt.io({at.it.code!r}, ({args},))"])

    def lower_io_in(self, at: "_Site") -> bool:
        """INP may load R parameters."""
        args = ", ".join(self.val(o) for o in at.it.operands)
        return self._lines(at, ["@SYNC_OUT", f"_rt.io({at.it.code!r}, ({args},))", "@SYNC_IN"])

    def _ref(self, op: Operand) -> str:
        """The R number an operand designates (pointers resolved at run time)."""
        if op.kind == "R":
            return str(int(op.value))
        return f"_ptr({self.r(int(op.value))})"


class _Site(NamedTuple):
    """Where an @ code is lowered: the output, the block and its record, the instruction and its row."""

    out: PySource
    idx: int
    blk: NcBlock
    it: AtInstr
    row: AtCode
    rec: "_Record"


def _arith_checks(items: list) -> set[int]:
    """Indexes of the R assignments of a block whose result must be checked for the R parameter range
    (only arithmetic can leave it; :mod:`.finite` says which)."""
    return {i for i, it in enumerate(items) if isinstance(it, Arith) and not stays_in_range(it.terms)}


#: ``_v`` stored only in the R parameter range; the test is false for NaN too (its comparisons are); a value
#: below the smallest magnitude is stored as the NC holds it (r_value)
_RANGE_CHECK = (f"if not ({R_SMALLEST!r} <= _v <= {R_LIMIT!r} or -{R_LIMIT!r} <= _v <= -{R_SMALLEST!r}) "
                f"and _v != 0.0: _v = _r_value(_v)")

#: the @ code lowerings that only compute, move R values or branch: nothing in them reads the step count
_COMPUTING = frozenset(("math", "assign", "clear", "xchg", "branch", "goto", "case"))


def counts_ahead(blk: NcBlock) -> bool:
    """A block that only computes and branches (R arithmetic, the @ codes of :data:`_COMPUTING` but those that
    read an input, notes without a message): nothing in it executes, calls, waits or ends, so its step may be
    counted at the start of its stretch (:meth:`UnitCodegen._scan_stretches`)."""
    if blk.skip:
        return False
    work = False
    for it in blk.items:
        if isinstance(it, Arith):
            work = True
        elif isinstance(it, AtInstr):
            row = AT_CODES[it.code]
            if row.lower not in _COMPUTING or (row.lower == "branch" and "_rt." in row.expr):
                return False
            work = True
        elif not isinstance(it, Note) or it.text.upper().startswith("MSG"):
            return False
    return work


def _positions(axes, words: dict, g) -> bool:
    """A constant block that travels: an axis word, not the time of a dwell."""
    return any(a in axes for a in words) and not is_dwell(g)


def _jump_numbers(it: AtInstr):
    code, ops = it.code, it.operands
    if code == "100":
        yield int(ops[0].value) if ops[0].kind == "K" else None
    elif code == "111":
        for t in it.operands[2::2]:
            yield int(t.value)
    elif AT_CODES[code].lower == "branch":
        yield int(ops[2].value)


def more_h(values, value: float) -> tuple:
    """The H values of a block with one more: every auxiliary function goes to the PLC, as every M word
    does, in the block's order (L3072); the block carries their tuple (profile ``auxiliary_h``)."""
    return (*values, value) if values.__class__ is tuple else (values, value)


class _Record:
    """The block record under construction: DIN words, setpoints from @44x, the L call."""

    def __init__(self, cg: UnitCodegen, blk: NcBlock):
        self.cg = cg
        self.blk = blk
        self.g: list[float] = []
        self.m: list[int] = []
        self.words: list[tuple[str, str, bool]] = []  # (key expr, value expr, constant?)
        self.msg: str | None = None
        self.machine_coords = False
        self.call: str | None = None
        self.passes = "1"
        self.d: str | None = None
        self.g16: list[tuple[str, bool]] = []
        self.int_sec: tuple[str, str] | None = None
        self.meas: tuple[str, str] | None = None
        self.rel: tuple[str, ...] | None = None
        self.inta: tuple[str, ...] | None = None
        self.angle = False  # the block carries the programmed angle (PANG or the angle address word)
        self.cycle_g: int | None = None  # G80-G89 in the block
        self.jumped = False  # an unconditional jump was taken: the rest of the block is never read
        self._captured = 0

    def note(self, it: Note) -> None:
        if it.text.upper().startswith("MSG"):
            self.msg = it.text[3:].lstrip(" ,:").strip()

    def word(self, out: PySource, w: Word, captured: bool = True) -> None:
        """Add a DIN word; ``captured``: later items of the block may change the R parameter it reads."""
        cg = self.cg
        a = w.address
        if w.value is None and w.rref is None:
            if 16 in self.g or self.g16:
                self.g16.append((a.rstrip("-"), a.endswith("-")))
                return
            out.emit(f"_rt.fault('SIN001', 'address {a} without a value', {self.blk.line})")
            return
        if w.rref is not None:
            sign, n = w.rref
            expr = cg.read_r(n) if sign > 0 else f"-{cg.read_r(n)}"
            const = False
        else:
            expr = _num(w.value)
            const = True
        if a == "G" or a == "M":
            if not const:
                out.emit(f"_rt.fault('SIN001', '{a}=R{w.rref[1]}: G and M words take numbers only', "
                         f"{self.blk.line})")
                return
            if a == "G":
                gv = float(w.value)
                self.g.append(int(gv) if gv == int(gv) else gv)
                if gv in _CYCLE_G:
                    self.cycle_g = int(gv)
            else:
                self.m.append(int(w.value))
            return
        if a == "L":
            self.call = f"_int({expr})" if not const else str(int(w.value))
            return
        if a == "D":
            self.d = expr
            return
        if a == cg.radius and a not in cg.axes:
            a = "R"  # SINUMERIK 8xx radius address for circles (machine data: B100 in L4237, or U)
        if a == "A" and "A" not in cg.axes:
            # the angle address (NC MD byte 5001 = 11, L2325-2326) when A is not an axis
            self.angle = True
            self.words.append(("_rt.angle_key()", expr, False))
            return
        if missing_axis(a, cg.axes, dwells(self.blk.items), cg.radius):
            out.emit(f"_rt.refuse_axis({refused_word(a, cg.axes)!r}, {self.blk.line}, {w.col})", self.blk.line)
            return
        if not const and captured:
            # the value is the one R has where the word stands; later @ code in the block may change R
            tmp = f"_w{self._captured}"
            self._captured += 1
            out.emit(f"{tmp} = {expr}", self.blk.line)
            expr = tmp
        if a == "H" and "H" not in cg.axes and any(k == "'H'" for k, _v, _c in self.words):
            self.more_h(expr)
            return
        self.words.append((repr(a), expr, const))

    def more_h(self, expr: str) -> None:
        """A further H word of the block, as the module's :func:`more_h`, for values known at run time."""
        i = next(i for i, w in enumerate(self.words) if w[0] == "'H'")
        before = self.words[i][1]
        values = f"{before[:-1]}, {expr})" if before.startswith("(") else f"({before}, {expr})"
        self.words[i] = ("'H'", values, False)

    def capture(self, out: PySource, op: Operand) -> str:
        """A temporary holding the operand's value where the @ code stands in the block."""
        tmp = f"_w{self._captured}"
        self._captured += 1
        out.emit(f"{tmp} = {self.cg.val(op)}", self.blk.line)
        return tmp

    def setpoint(self, out: PySource, code: str, ops: list[Operand]) -> None:
        """@440 PRAP, @442 PRSS, @446 PRAD, @447 PANG, @448 PRIP, @44b/@44c control bits."""
        cg = self.cg
        line = self.blk.line
        tmp = self.capture(out, ops[-1])
        if code in ("440", "448"):
            axis = cg.val(ops[0])
            key = f"_rt.positions.axis_name({axis}, {line})"
            if code == "448":
                key = f"_rt.positions.centre_name({axis}, {line})"
            elif (name := constant_axis(cg.axes, ops[0])) is not None:
                key = repr(name)  # an axis word as any other (L81's infeed: @440 K3)
            self.words.append((key, tmp, False))
        elif code == "442":
            self.words.append((f"_rt.spindle.word({cg.val(ops[0])}, {line})", tmp, False))
        elif code == "446":
            self.words.append(("'R'", tmp, False))
        elif code == "447":
            self.angle = True
            self.words.append(("_rt.angle_key()", tmp, False))
        else:
            out.emit(f"_rt.write({code!r}, ({', '.join(cg.val(o) for o in ops)},), {line})", line)

    def _emit_int_sec(self, out: PySource, g: list, words: list) -> None:
        line = self.blk.line
        pairs = ", ".join(f"{k}: {v}" for k, v, _c in words)
        out.emit("@SYNC_OUT", line)
        out.emit(f"_rt.cycles.int_sec({self.int_sec[0]}, {self.int_sec[1]}, {tuple(g)!r}, {{{pairs}}}, {line})", line)
        out.emit("@SYNC_IN", line)

    def settle_int_sec(self, out: PySource) -> None:
        """INT SEC computes once its destination words are read: an @ instruction or R word after them in
        the same block sees the result (the REPEAT test after INT SEC, manual L1449-1466). The words are
        consumed without motion, as at the end of the block."""
        if self.int_sec is None or not self.words or self.call is not None:
            return
        g = [x for x in self.g if x not in (58, 59, 16)] + ([53] if self.machine_coords else [])
        self._emit_int_sec(out, g, self.words)
        self.int_sec = None
        self.words = []

    def finish(self, out: PySource, jumping: bool = False) -> None:
        """Lines that execute the block record collected so far."""
        cg = self.cg
        line = self.blk.line
        g = [x for x in self.g if x not in (58, 59, 16)]
        if self.machine_coords:
            g.append(53)
        m17 = 17 in self.m
        m = [x for x in self.m if x != 17]
        src = Src(cg.prog.path, line)
        words = self.words
        axis_keys = {repr(a) for a in cg.axes}
        if self.call is not None:
            words = [w for w in words if w[0] != "'P'"]
            passes = [w for w in self.words if w[0] == "'P'"]
            self.passes = f"_int({passes[-1][1]})" if passes else "1"
        if self.cycle_g is not None:
            out.emit(f"_rt.drilling.select({self.cycle_g}); _cyc = _rt.drilling.armed", line)
        # a block with an axis word and an L call: the cycle at the block's position, then the sub-program
        travels = (self.meas is None and self.inta is None and self.int_sec is None
                   and any(k in axis_keys or k.startswith("_rt.positions.axis_name(") for k, _v, _c in words)
                   and not dwells(self.blk.items) and not any(x in (58, 59) for x in self.g))
        if self.g16:
            out.emit(f"_rt.positions.g16({self.g16!r}, {line})", line)
        if any(x in (58, 59) for x in self.g):
            # the axis words are the offset; F, S, T ... keep their meaning in the block (docs/decisions.md)
            group = 1 if 58 in self.g else 2
            axis_keys = {repr(a) for a in cg.axes}
            pairs = ", ".join(f"({k}, {v})" for k, v, _c in words if k in axis_keys)
            out.emit(f"_rt.offsets.programmable_zo({group}, [{pairs}], {line})", line)
            words = [w for w in words if w[0] not in axis_keys]
        if self.d is not None:
            out.emit(f"_rt.offsets.select_d({self.d}, {line})", line)
        if self.int_sec is not None:
            self._emit_int_sec(out, g, words)
            words = []
        if self.meas is not None:
            pairs = ", ".join(f"{k}: {v}" for k, v, _c in words)
            out.emit("@SYNC_OUT", line)
            if self.angle:
                out.emit("_rt.use_angle()", line)
            out.emit(f"_wm = _meas_m(_rt, {self.meas[0]}, {self.meas[1]}, {tuple(g)!r}, {{{pairs}}}, {line})", line)
            out.emit("@SYNC_IN", line)
            srcname = cg.const(src, "_S")
            out.emit(f"_ex(_Block({tuple(g)!r}, {tuple(m)!r}, _wm, {self.blk.n!r}, {self.msg!r}, {srcname}))", line)
            g, m, words = [], [], []
        if self.inta is not None:
            pairs = ", ".join(f"{k}: {v}" for k, v, _c in words)
            ax, byte, bit = self.inta
            srcname = cg.const(src, "_S")
            if self.angle:
                out.emit("_rt.use_angle()", line)
            out.emit(f"_wm = _rt.rel_inta.inta({ax}, {byte}, {bit}, {tuple(g)!r}, {{{pairs}}}, {line})", line)
            out.emit(f"_rt.execute_now(_Block({tuple(g)!r}, {tuple(m)!r}, _wm, {self.blk.n!r}, {self.msg!r}, "
                     f"{srcname})); _rt.rel_inta.inta_done()", line)
            if any(x in (0, 1, 2, 30) for x in m):
                out.emit("if (_K.ended or _K.stopped_at) and _rt.halt(): return 1", line)
            g, m, words = [], [], []
        fast = (not cg.decode_ahead and not m and self.msg is None and len(g) <= 1 and all(x in (0, 1) for x in g) and words
                and all(k in axis_keys or k.startswith(COMPUTED_AXIS_KEYS) for k, _v, _c in words))
        if fast:
            # a plain G0/G1 block: straight to the kernel's move path, as execute() would do
            d = ", ".join(f"{k}: {v}" for k, v, _c in words)
            srcname = cg.const(src, "_S")
            if g:
                out.emit(f"_K.motion = {g[0]}; _lin(_K, {g[0]}, {{{d}}}, {srcname})", line)
            else:
                out.emit("_mo = _K.motion", line)
                out.emit(f"if _mo < 2: _lin(_K, _mo, {{{d}}}, {srcname})", line)
                out.emit(f"else: _ex(_Block((), (), {{{d}}}, {self.blk.n!r}, None, {srcname}))", line)
        elif g or m or words or self.msg is not None:
            if any(k == "'R'" for k, _v, _c in words):  # a circle radius: a G1 block rounds its corner
                out.emit("_rt.use_rounding(); _ex = _rt.execute; _lin = _rt.linear", line)
            # a machine-specific M function may hand PLC data to R parameters ([sin800] m_functions)
            plc_m = any(x not in _STANDARD_M for x in m)
            if plc_m:
                out.emit("@SYNC_OUT", line)
            ex = "_rt.execute_angle" if self.angle else "_ex"
            if all(c for _k, _v, c in words):
                blk = Block(tuple(g), tuple(m), {eval(k): float(v) for k, v, _c in words}, self.blk.n,
                            self.msg, src)
                name = cg.const(blk, "_B")
                out.emit(f"{ex}({name})", line)
            else:
                srcname = cg.const(src, "_S")
                d = ", ".join(f"{k}: {v}" for k, v, _c in words)
                out.emit(f"{ex}(_Block({tuple(g)!r}, {tuple(m)!r}, {{{d}}}, {self.blk.n!r}, {self.msg!r}, "
                         f"{srcname}))", line)
            if plc_m:
                out.emit("@SYNC_IN", line)
            if any(x in (0, 1, 2, 30) for x in m):
                out.emit("if (_K.ended or _K.stopped_at) and _rt.halt(): return 1", line)
        if travels:  # a selected drilling cycle runs where the block took the tool
            out.emit("if _cyc:", line)
            out._indent += 1
            cg.cycle_call(out, line, f"_rt.drilling.call({line})")
            out._indent -= 1
        if any(x in (40, 41, 42) for x in self.g):  # compensation on or off: the straight-move path changes
            out.emit("_rt.route(); _ex = _rt.execute; _lin = _rt.linear", line)
        if self.rel is not None:
            out.emit(f"_rt.rel_inta.read_in_inhibit({self.rel[0]}, {self.rel[1]}, {line})", line)
        if self.call is not None:
            out.emit("_ctr.steps += _st; _st = 0", line)
            out.emit("@SYNC_OUT", line)
            out.emit(f"_rt.call({self.call}, {self.passes}, {line})", line)
            out.emit("@SYNC_IN", line)
            out.emit("_ex = _rt.execute; _lin = _rt.linear; _cyc = _rt.drilling.armed", line)
            out.emit("_lim = _ctr.limit - _ctr.steps", line)
            out.emit("if _K.ended or _rt.halted: return 1", line)
        if m17 and not jumping:
            out.emit("return 0", line)
