"""The translation writer: the run's canon calls as a program for a modern control, one :class:`Target`.

Positions are written in the program's work coordinates by default: the canon gives machine positions,
the kernel's ``frame`` calls say which zero offset and tool length lie between, and the writer takes
them off again and writes the zero offset selection (G54...) and the tool length call (G43 H, D) where
the program made them. It never writes an offset table. What the run decided from outside input (canon
``frozen``), probe moves, and the setup the simulation used are written as comments; anything a target
cannot say stops the translation (:attr:`Translation.refusal`) instead of being written differently.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING

from ..diagnostics import Diagnostic, Span, read_lines_at
from ..nc import arcs
from ..nc.canon import CanonSink, Frame, Src, plain_frame
from ..outpaths import OutputError
from .targets import Target

if TYPE_CHECKING:
    from ..machine.model import MotionData

PLANE_OF = {("X", "Y"): "G17", ("Z", "X"): "G18", ("Y", "Z"): "G19"}
CENTRE_WORDS = {"X": "I", "Y": "J", "Z": "K"}


#: the decimals of every written position (0.1 um)
DECIMALS = 4


def number(v: float) -> str:
    text = f"{v:.{DECIMALS}f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


def number_with_point(v: float) -> str:
    """A length, angle or dwell for a Fanuc-style control: ``X10.`` (without the point it is 0.010 mm)."""
    text = number(v)
    return text if "." in text else text + "."


@dataclass
class Refusal:
    """Why the translation stopped: the block (None: the whole program) and the reason."""

    src: Src | None
    message: str


@dataclass
class Setup:
    """What the simulation used that the new control must be set up with (the header lists it)."""

    offsets: dict[str, list[tuple[float, ...]]] = field(default_factory=dict)  # zero offset -> values moved under
    #: (tool in the spindle, tool offset number, its call) -> lengths moved under: an 840D D is an edge of the
    #: active tool; the length of a G44 as measured (it is taken off)
    tools: dict[tuple[int, int, str], list[float]] = field(default_factory=dict)
    shifts: set[tuple[float, ...]] = field(default_factory=set)  # G92 / additive offsets baked into positions
    transformed: bool = False
    machine_moves: int = 0
    frozen: int = 0
    probes: int = 0
    left_out: list[str] = field(default_factory=list)  # machine functions written as comments
    homed: list = field(default_factory=list)  # (axis names, block) of each home search, written as comments
    #: two feed moves in a row ran in continuous path at the machine's corner tolerance (a bare G64): the cycle
    #: time blended the corner between them within it
    blended: bool = False


class Translation(CanonSink):
    """Writes the canon calls as ``target``'s program lines into ``out`` (an open text file).

    ``frame`` "work" (the default) writes work coordinates, "machine" the simulated machine's.
    The header (what the simulation used) is known only at the end: :meth:`header` gives it.
    """

    def __init__(self, out, target: Target, frame: str = "work", source_comments: bool = False,
                 scenario_given: bool = False, stops_passed: bool = False, motion: MotionData | None = None):
        self.out = out
        self.out_path = getattr(out, "name", "the output")  # named in a write error
        self.t = target
        self.num = number_with_point if target.decimal_point else number  # length, angle and dwell words
        self.work = frame == "work"
        self.source_comments = source_comments
        self.scenario_given = scenario_given
        self.stops_passed = stops_passed  # the simulated control stops at M0 ([sin800] m0 = "stop"); this goes on
        self.motion = motion  # the simulated machine's path control data (the header names its corner tolerance)
        #: the run's cycle-time model as its summary names it ("look-ahead", "rest-to-rest", "card"), known at its end
        self.time_model: str | None = None
        #: where a place the NC ran stands in the user's source (the API gives it Session.source_place: a CL 800
        #: program's .cl8 line, not its object program's block)
        self.place = None
        #: what the translation says on the console beside the file (TRN003), at the block
        self.warnings: list[Diagnostic] = []
        self.names: tuple[str, ...] = ()
        self.frame_now: Frame | None = None
        self.removed: tuple[float, ...] = ()
        self.setup = Setup()
        self.refusal: Refusal | None = None
        self.ended: Src | None = None
        self.lines = 0
        self.moves = 0
        self._offset_written: str | None = None
        self._tool_written: tuple[int, float] = (0, 0.0)
        self._plane = "G17"
        self._feed: float | None = None
        self._after: list[tuple[str, Src]] = []  # M5 / M9 of a block, written after its move
        self._placed = False  # the refusal names no block yet: the next move's block
        self._moved_in: Src | None = None  # the block of the last move (a cycle moves again after its M5)
        self._turning: str | None = None  # the spindle word in force ("M3 S500"), None: stopped
        self._turning_line = -1  # the line count when it was written
        self._probe: tuple[dict | None, dict | None, Src] | None = None
        self._frozen: list[tuple[str, Src | None]] = []
        self._frozen_pending: set = set()
        self._frozen_seen: set = set()
        self._unsaid: tuple[str, Src | None] | None = None  # a machine input read with no scenario to say it
        self._tool = 0
        self._restart: tuple[str, Src] | None = None  # the spindle word after M6, until the program gives one
        self._hidden: list[int] = []
        self._tool_number = 0
        self._frame_unrecorded = True
        self._frame_src: Src | None = None  # the block of the last frame change
        #: the tool length call of a frame change, written before the next line (after a tool change of its block)
        self._tool_pending: tuple[Frame, Src | None] | None = None
        self._written: set[str] = set()  # the axes written in a move so far
        self._tool_frame: Frame | None = None  # the frame of the tool length written last
        self._per_rev: float | None = None  # G95: the F in mm per revolution
        self._homing: tuple[int, ...] | None = None  # the axes the next move homes
        self._programmed: tuple[set[int], Src] | None = None  # the axis words of the next move's block
        self._css: tuple[float, float, float] | None = None  # G96's last speed: (speed, wanted, limit)
        #: the path control in force (mode, tolerance, block) and as the output has it (the target's power-on
        #: mode until one is written); an exact stop of the next move alone (G09)
        self._path: tuple[str, float | None, Src | None] = ("continuous", None, None)
        self._path_written: tuple[str, float | None] = (target.path_power_on, None)
        self._exact_block: Src | None = None
        self._stop_word = ""  # the exact stop word of the next move's line
        self._blends = False  # the last move was a feed move in continuous path: nothing has stopped the axes since
        self._stands_in: Src | None = None  # the last block with an M function, dwell or tool change: it ends at rest

    # -- output ----------------------------------------------------------
    def source(self, src: Src) -> Src:
        """``src`` as the user's source names it (comments, marks, warnings and refusals)."""
        return src if self.place is None else self.place(src)

    def refuse(self, src: Src | None, message: str) -> None:
        if self.refusal is None:
            self.refusal = Refusal(src, message)

    def _line(self, text: str, src: Src | None = None, *, remark: bool = False) -> None:
        """Write one program line of ``src``; ``remark``: the line is a comment or an operator message."""
        if self.refusal is not None:
            return
        if self._unsaid is not None:
            what, where = self._unsaid
            self.refuse(where or src, f"the path depends on a machine input that no scenario gave ({what}: its "
                                      "rest value, never read): give the inputs with --scenario")
            return
        if self._tool_pending is not None:
            self._tool_length()
        if self._restart is not None:
            restart, self._restart = self._restart, None
            self._line(*restart)
        if self._frozen:
            notes, self._frozen = self._frozen, []
            self._frozen_pending.clear()
            for what, where in notes:
                where = where or src  # an input read between blocks: the block it leads to
                if (what, where) in self._frozen_seen:
                    continue
                self._frozen_seen.add((what, where))
                placed = self.source(where) if where else None
                at = f" at {Path(placed.file).name}:{placed.line}" if placed else ""
                self._write(self.t.note(f"FROZEN: {what}{at}; the path below follows the simulated value"))
                self.setup.frozen += 1
        if self.source_comments and src is not None:
            placed = self.source(src)
            ref = self.t.note(f"{Path(placed.file).name}:{placed.line}")
            if remark:
                self._write(ref)  # its own line: a second comment would hide LinuxCNC's (MSG, ...)
            else:
                text += " " + ref
        self._write(text)
        self.lines += 1

    def _move_line(self, text: str, src: Src) -> None:
        """The line of a move: with the exact stop of this block alone in front where there is one (G9)."""
        stop, self._stop_word = self._stop_word, ""
        self._line(f"{stop} {text}" if stop else text, src)

    def _note(self, text: str, src: Src | None) -> None:
        """``text`` as a comment line of the target."""
        self._line(self.t.note(text), src, remark=True)

    def _write(self, text: str) -> None:
        try:
            self.out.write(text + "\n")
        except OSError as e:  # a full disk: the run stops with a usage error naming the file
            raise OutputError(self.out_path, e) from None

    def _flush_after(self, src: Src | None = None) -> None:
        """Write the M5 / M9 held back, in program order: before a move, those of earlier blocks (``src``:
        the moving block's, which wait for its move: DIN 66025, they act at the end of the block);
        else all of them."""
        if not self._after:
            return
        if src is None:
            now, self._after = self._after, []
        else:
            now = [a for a in self._after if a[1] != src]
            self._after = [a for a in self._after if a[1] == src]
        for text, s in now:
            self._line(text, s)

    def _tool_length(self) -> None:
        """The tool length call of the last frame change: written before anything else, but after the tool
        change of its own block (the 840D's D and the length of H belong to the tool the M6 loads)."""
        frame, src = self._tool_pending
        self._tool_pending = None
        if frame.tool_length == 0.0:
            self._line(self.t.tool_length_off, src)
            return
        n = frame.tool_offset or self._tool
        if not n:
            self.refuse(src, f"a tool length of {number(frame.tool_length)} mm without a tool offset "
                             "number or a tool in the spindle")
            return
        self._tool_number = n
        form = self.t.tool_length_minus if frame.tool_subtracted else self.t.tool_length_on
        if form is None:
            self.refuse(src, f"G44 H{n} (the tool length taken off): {self.t.title} has no G44, and G43 "
                             "with a negative length would ask the user for a wrong tool length")
            return
        self._line(form.format(n=n), src)
        if self.t.edge_of_tool and self.work:  # every edge selected is listed, also one no move is made with
            self.setup.tools.setdefault((self._tool, n, form), [frame.tool_length])

    def _axes(self, p, start=None, machine_frame: bool = False, always=()) -> str:
        """The axis words of end point ``p``: only the axes that move from ``start`` (and ``always``), as the
        program programmed them; an axis standing still is left out, so that no position the program did
        not program (the simulated home, a G53 retract height) is re-expressed through the simulated offsets.
        A move in which nothing moves gets the axes written before (none: its motion word alone).
        ``machine_frame``: a G53 / SUPA move, in machine coordinates (no tool length: see _straight)."""
        removed = (0.0,) * len(self.names) if machine_frame else self.removed
        if start is None:
            use = set(range(len(self.names)))
        else:
            use = {i for i, (a, b) in enumerate(zip(start, p)) if abs(a - b) > 1e-9} | set(always)
            if self._programmed is not None:  # the block's own axis words, also those standing where they are
                use |= self._programmed[0]
                self._programmed = None
            if not use:
                use = {i for i in range(len(self.names)) if self.names[i] in self._written}
        self._written.update(self.names[i] for i in use)
        return " ".join(f"{n}{self.num(p[i] - removed[i])}" for i, n in enumerate(self.names)
                        if i in use and n in self.t.axes)

    def _feed_word(self, feed: float) -> str:
        """The F word where the feed changes: under G95 the program's feed per revolution, not the path feed."""
        if self._per_rev is not None:
            feed = self._per_rev
        if feed != self._feed:
            self._feed = feed
            return f" F{number(feed)}"
        return ""

    # -- the canon calls -------------------------------------------------
    def begin(self, axis_names, start):
        self.names = tuple(axis_names)
        self._hidden = [i for i, n in enumerate(self.names) if n not in self.t.axes]
        self.frame_now = plain_frame(len(self.names))
        self.removed = self.frame_now.removed()
        self._line(self.t.preamble)
        if not self.work:
            self._line(self.t.machine_frame)

    def frame(self, frame, src):
        self.frame_now = frame
        self._frame_src = src
        if not self.work:
            return
        self._flush_after(src)  # the M5 / M9 of earlier blocks come before this block's words
        if frame.work_offset == "G53":
            return  # one move in machine coordinates: written with its prefix
        self.removed = frame.removed()
        if any(frame.shift):
            if not self.moves and not self.setup.shifts:  # perhaps not this program's: say it at the first move
                values = " ".join(f"{n}{number(v)}" for n, v in zip(self.names, frame.shift) if v)
                self.frozen(f"an added zero offset ({values}) is in force before the first move: set by the "
                            "program's first blocks or left by an earlier run (the stored NC data)", src)
            self.setup.shifts.add(tuple(round(v, 6) for v in frame.shift))
        self.setup.transformed |= frame.transformed
        if frame.work_offset != self._offset_written:
            name = self.t.work_offsets.get(frame.work_offset) if frame.work_offset else None
            if name is None:
                self._placed = src is None  # a frame change between blocks: named by the next block that moves
                self.refuse(src, f"the program selects {frame.work_offset or 'no zero offset'}, which "
                                 f"{self.t.title} cannot select (translate with --frame machine)")
                return
            self._offset_written = frame.work_offset
            self._line(name, src)
        tool = (frame.tool_offset, frame.tool_length)
        if tool != self._tool_written:
            self._tool_written = tool
            self._tool_pending = (frame, src)
            self._tool_frame = frame
        self._frame_unrecorded = True

    def _record_setup(self) -> None:
        """The zero offset and tool length a move is made under, for the header (once per frame change)."""
        self._frame_unrecorded = False
        f = self.frame_now
        if not self.work or f.work_offset in (None, "G53"):
            return
        seen = self.setup.offsets.setdefault(f.work_offset, [])
        if any(zero != f.zero for zero in seen):
            self._rewritten(f"zero offset {f.work_offset}", self._zero_text(seen[-1]), self._zero_text(f.zero),
                            self.t.work_offsets[f.work_offset])
            return
        if f.zero not in seen:
            seen.append(f.zero)
        if f.tool_length:
            tool = self._tool if self.t.edge_of_tool else 0
            form = self.t.tool_length_minus if f.tool_subtracted else self.t.tool_length_on
            if form is None:  # refused where it was selected (no G44 on the target)
                return
            call = form.format(n=self._tool_number)
            lengths = self.setup.tools.setdefault((tool, self._tool_number, form), [])
            length = -f.tool_length if f.tool_subtracted else f.tool_length  # G44: the length as measured
            if lengths and length not in lengths:
                self._rewritten(f"the tool length of {call}", f"{number(lengths[-1])} mm", f"{number(length)} mm",
                                f"{call} of {f'tool T{tool}' if tool else 'the tool table'}")
                return
            if length not in lengths:
                lengths.append(length)

    def _rewritten(self, what: str, before: str, now: str, entry: str) -> None:
        """One rule for zero offsets and tool lengths: an entry of the new control holds one value, so a
        program that rewrites one after moves under it is refused, at the rewriting block or, for a rewrite
        between blocks (CPL FXC, SINUMERIK @430), at the block that moves with the new value."""
        self.refuse(self._frame_src or self._moved_in, f"the program rewrites {what} after moves with it ({before} before, {now} "
                                     f"now): {entry} of the new control holds one value (translate with "
                                     "--frame machine)")

    def _zero_text(self, zero) -> str:
        return " ".join(f"{n}{number(v)}" for n, v in zip(self.names, zero) if n in self.t.axes)

    def _warn(self, src: Src | None, message: str, word: str = r"\S") -> None:
        """A TRN003 warning at ``src``, its column that of the first match of ``word`` in the source line."""
        if src is None:
            self.warnings.append(Diagnostic("TRN003", message, None, "warning"))
            return
        src = self.source(src)
        text = read_lines_at(src.file, {src.line}).get(src.line, "")
        found = re.search(word, text, re.IGNORECASE)
        span = Span(src.file, src.line, found.start() + 1, found.end() + 1) if found else Span(src.file, src.line, 1)
        self.warnings.append(Diagnostic("TRN003", message, span, "warning"))

    def frozen(self, what, src, scenario=False, warn=False):
        if warn:
            self._warn(src, f"{what}; the translation writes the move as the run made it (marked FROZEN)")
        if scenario and not self.scenario_given:  # nothing said what the input is: the run took its rest value
            self._unsaid = self._unsaid or (what, src)
            return
        key = (what, src)
        if key not in self._frozen_pending:  # a polling loop reads the same input again and again
            self._frozen_pending.add(key)
            self._frozen.append(key)

    def path_control(self, mode, tolerance, src):
        if mode == "block":
            self._exact_block = src
        else:
            self._path = (mode, tolerance, src)

    def _path_words(self, src: Src, fed: bool) -> str:
        """Before a move (``fed``: not a rapid, which ends at rest): the path control where the output's differs
        from the run's (a word of its own line), and the exact stop of this move alone (returned: a word of the
        move's line, or "")."""
        mode, tolerance, at = self._path
        block = self._exact_block is not None and self._exact_block == src
        self._exact_block = None
        if block and self.t.exact_stop_block is None:  # the modal exact stop for this move, the mode after it
            mode, tolerance, at = "exact", None, src
        if fed and self._blends and mode == "continuous" and tolerance is None:
            self.setup.blended = True  # the junction takes the tolerance of the block that starts at it
        self._blends = fed and mode == "continuous" and not block and src != self._stands_in
        if (mode, tolerance) != self._path_written:
            self._path_written = (mode, tolerance)
            self._line(self._path_word(mode, tolerance, at or src), at or src)
        return self.t.exact_stop_block if block and self.t.exact_stop_block and mode != "exact" else ""

    def _stand(self, src: Src) -> None:
        """The axes stand at ``src`` (an M function, a dwell, a tool change: the kernel's exact stops), before
        and after its block's move: no corner there blends."""
        self._blends = False
        self._stands_in = src

    def _path_word(self, mode: str, tolerance: float | None, src: Src) -> str:
        if mode == "exact":
            return self.t.path_exact
        if tolerance is None:
            return self.t.path_continuous
        if tolerance <= 0:  # corners within 0 mm: the run stops at each; LinuxCNC's G64 P0 would be no bound at all
            self._note(f"G64 P{number(tolerance)}: a stop at every corner, written as {self.t.path_exact}", src)
            return self.t.path_exact
        if self.t.path_tolerance is not None:
            return self.t.path_tolerance.format(tol=self.num(tolerance))
        self._warn(src, f"G64 P{number(tolerance)}: {self.t.title}'s continuous path ({self.t.path_continuous}) "
                        "takes no corner tolerance; written without it: set the tolerance on the new control",
                   r"(?<![A-Z\d.])P")
        self._note(f"the program's corner tolerance P{number(tolerance)} is not written: {self.t.title}'s "
                   f"{self.t.path_continuous} takes none; set it on the new control", src)
        return self.t.path_continuous

    def programmed(self, axes, src):
        use = {self.names.index(n) for n in axes if n in self.names}
        self._programmed = (use, src) if use else None

    def probe(self, trip, target, src):
        self._probe = (trip, target, src)

    def _machine_prefix(self, src) -> str:
        f = self.frame_now
        if self.work and f is not None and f.work_offset == "G53":
            self.setup.machine_moves += 1
            return self.t.machine_move + " "
        return ""

    def _moved_unwritten(self, start, end, src) -> bool:
        """Refuse a move of an axis the target has no address for (never left out of a move silently)."""
        for i in self._hidden:
            if abs(end[i] - start[i]) > 1e-9:
                self.refuse(src, f"axis {self.names[i]} moves, and {self.t.title} has no address for it")
                return True
        return False

    def _move_starts(self, start, end, src, fed: bool = True) -> bool:
        """What every move does first (the block's M5/M9 wait, the setup is recorded); False: refused."""
        if self._placed and self.refusal is not None:
            self._placed = False
            self.refusal.src = src
        self._flush_after(src)
        if self._programmed is not None and self._programmed[1] != src:
            self._programmed = None  # the block that programmed them made no move
        if self._tool_pending is not None:
            self._tool_length()
        self._stop_word = self._path_words(src, fed)
        self.moves += 1
        self._moved_in = src
        if self._frame_unrecorded:
            self._record_setup()
        return not (self._hidden and self._moved_unwritten(start, end, src))

    def _straight(self, code: str, start, end, feed: float | None, src: Src) -> None:
        if self._homing is not None and self._home(start, end, src):
            return
        if not self._move_starts(start, end, src, code != "G0"):
            return
        if self._probe is not None:
            self._probe_move(start, end, feed, src)
            return
        prefix = self._machine_prefix(src)
        restore = None
        if prefix and code == "G1" and self.t.machine_move_rapid:
            self.refuse(src, f"a feed move in machine coordinates: {self.t.title}'s {self.t.machine_move} "
                             "positions at rapid traverse whatever the motion mode (translate with --frame "
                             "machine, or for another target)")
            return
        if prefix and self.frame_now.tool_kept:
            self._tool_kept_move(code, start, end, feed, src)
            return
        if prefix and self.t.machine_move_keeps_tool and self._tool_written[1]:
            # the control keeps the tool length in its machine move (840D SUPA): off for the move, else
            # the simulated length would be baked into the machine position; on again for what follows
            restore = self._tool_frame
            self._line(self.t.tool_length_off, src)
        feed_word = self._feed_word(feed) if feed is not None else ""
        self._move_line(f"{prefix}{code} {self._axes(end, start, bool(prefix))}".rstrip() + feed_word, src)
        if restore is not None:
            self._tool_pending = (restore, src)

    def _tool_kept_move(self, code: str, start, end, feed: float | None, src: Src) -> None:
        """A move in machine coordinates with the tool length in force (SINUMERIK G53 / POS MSYS): the 840D's
        SUPA keeps it too, so the programmed machine position is written with the tool offset left on; a
        target whose machine move drops it (G53) is refused: the slide position would carry the simulated
        tool length into the program."""
        f = self.frame_now
        if not self.t.machine_move_keeps_tool:
            self.refuse(src, f"a move in machine coordinates with the tool length kept ({number(f.tool_length)} "
                             f"mm, SINUMERIK G53 / POS MSYS): {self.t.title}'s {self.t.machine_move} drops the "
                             "tool length, so the position would carry the simulated one (translate with "
                             "--frame machine, or cancel the tool offset before the move)")
            return
        p = list(end)
        p[f.tool_axis] -= f.tool_length
        q = list(start)
        q[f.tool_axis] -= f.tool_length
        feed_word = self._feed_word(feed) if feed is not None else ""
        self._move_line(f"{self.t.machine_move} {code} {self._axes(p, q, True)}".rstrip() + feed_word, src)

    def _probe_move(self, start, end, feed, src) -> None:
        """The move after a canon ``probe`` call: the target's probe move to the programmed end point."""
        trip, target, psrc = self._probe
        self._probe = None
        self.setup.probes += 1
        if self.t.probe is None:
            self.refuse(psrc, f"a probe move: {self.t.title} has no standard probe move")
            return
        if target is None:
            self.refuse(psrc, "a measurement that does not stop at the probe contact (on-the-fly measurement "
                              f"or a fixed stop) has no equivalent in {self.t.title}")
            return
        if trip is None and not self.scenario_given:
            self.refuse(psrc, "the probe move did not switch because the run has no scenario saying where the "
                              "probe switches (give it with --scenario)")
            return
        if self._machine_prefix(src):
            self.refuse(psrc, "a probe move in machine coordinates (G53)")
            return
        goal = tuple(target.get(n, v) for n, v in zip(self.names, end))
        if feed is None:  # a probe move programmed at rapid: the control probes at the modal feed
            if not self._feed:
                self.refuse(psrc, "a probe move at rapid traverse with no feed rate to probe at")
                return
            feed = self._feed
        if trip is None:  # the program went on without contact: a probe move that ends without an error
            self.frozen("measured value: the simulated probe made no contact", psrc)
            word = self.t.probe_no_contact
        else:
            seen = ", ".join(f"{n}{number(v - self.removed[self.names.index(n)])}" for n, v in trip.items())
            self.frozen(f"measured value: the simulated probe switched at {seen}", psrc)
            word = self.t.probe
        self._move_line(word.format(axes=self._axes(goal, start), feed=self._feed_word(feed)), src)

    def rapid(self, start, end, src):
        self._straight("G0", start, end, None, src)

    def feed(self, start, end, feed, src):
        self._straight("G1", start, end, feed, src)

    def thread(self, start, end, lead, varying, feed, src):
        if not self._move_starts(start, end, src):
            return
        if self.t.thread is None:
            self.refuse(src, f"a thread (G33): {self.t.title} is not written with threads by ncvm")
        elif varying:
            self.refuse(src, f"a thread of growing or shrinking lead (G34/G35): {self.t.title} has no such thread")
        elif self._machine_prefix(src):
            self.refuse(src, "a thread in machine coordinates (G53)")
        else:
            self._move_line(self.t.thread.format(axes=self._axes(end, start), lead=f"{lead:.6f}".rstrip("0").rstrip(".")), src)  # a lead error adds up turn by turn

    def arc(self, start, end, spec, feed, src):
        if not self._move_starts(start, end, src):
            return
        if self._probe is not None:
            self.refuse(self._probe[2], "a probe move along an arc")
            return
        a, b, cw = spec.a, spec.b, spec.cw
        an, bn = self.names[a], self.names[b]
        if (an, bn) not in PLANE_OF and (bn, an) in PLANE_OF:  # X-Z is G18's Z-X: seen from there it turns back
            a, b, an, bn, cw = b, a, bn, an, not cw
        plane = PLANE_OF.get((an, bn))
        if plane is None or an not in CENTRE_WORDS or bn not in CENTRE_WORDS:
            self.refuse(src, f"an arc in the plane of {an} and {bn}, which has no G17/G18/G19")
            return
        if self._machine_prefix(src):
            self.refuse(src, "an arc in machine coordinates (G53)")
            return
        if spec.turns and self.t.turns is None:
            self.refuse(src, f"a helix of {spec.turns + 1} turns: {self.t.title} has no word for full turns")
            return
        if self._below_resolution(start, end, spec):
            self._below_resolution_move(start, end, feed, src)
            return
        if plane != self._plane:
            self._plane = plane
            self._line(plane, src)
        centre = spec.center if a == spec.a else spec.center[::-1]
        ci = self.num(centre[0] - start[a])
        cj = self.num(centre[1] - start[b])
        turns = self.t.turns.format(n=self._turns(spec.turns)) if spec.turns else ""
        self._move_line(f"{'G2' if cw else 'G3'} {self._axes(end, start, always=(a, b))} {CENTRE_WORDS[an]}{ci} {CENTRE_WORDS[bn]}{cj}"
                   f"{turns}{self._feed_word(feed)}", src)

    def _below_resolution(self, start, end, spec) -> bool:
        """The arc as written (end point and centre rounded to the written decimals) would sweep another
        angle than the run's: an arc shorter than the resolution, whose rounded end is its rounded start
        (a full circle on every G-code control) or lies behind it (almost a full turn)."""
        a, b = spec.a, spec.b
        ra, rb = self.removed[a], self.removed[b]
        sa, sb = round(start[a] - ra, DECIMALS), round(start[b] - rb, DECIMALS)
        ca = sa + round(spec.center[0] - start[a], DECIMALS)
        cb = sb + round(spec.center[1] - start[b], DECIMALS)
        written = arcs.sweep(sa, sb, round(end[a] - ra, DECIMALS), round(end[b] - rb, DECIMALS), ca, cb,
                             spec.cw, spec.turns)
        run = arcs.sweep(start[a], start[b], end[a], end[b], *spec.center, spec.cw, spec.turns)
        return abs(written - run) > math.pi

    def _below_resolution_move(self, start, end, feed, src) -> None:
        """An arc below the output's resolution: the straight move to its rounded end point, or nothing
        where no written position changes (docs/translate.md)."""
        if all(round(e - r, DECIMALS) == round(s - r, DECIMALS) for s, e, r in zip(start, end, self.removed)):
            self._programmed = None
            return
        self._move_line(f"G1 {self._axes(end, start)}{self._feed_word(feed)}", src)

    def _turns(self, extra: int) -> int:
        """LinuxCNC's P counts the turns begun (1 + the full ones), SINUMERIK's TURN the full ones."""
        return extra + 1 if self.t.turns.strip().startswith("P") else extra

    def homing(self, axes, src):
        self._homing = tuple(axes)

    def _home(self, start, end, src) -> bool:
        """A home search: not a move of the program. Written as a comment that says to home the axes on the
        new control (a control homes at its own reference switches, which no G-code move can reproduce);
        the axes it moved are then unknown to the translation until the program moves them. Always True
        (the move is dealt with): a move of another axis at the same time is refused."""
        axes, self._homing = self._homing, None
        moved = {i for i, (a, b) in enumerate(zip(start, end)) if abs(a - b) > 1e-9}
        if not moved <= set(axes):
            self.refuse(src, "a home search at the same time as a move of another axis")
            return True
        names = " ".join(self.names[i] for i in sorted(set(axes)))
        if (names, src) not in self.setup.homed:
            self.setup.homed.append((names, src))
            self._note(f"HOMING {names}: the program's reference run, not written as a move: home "
                       f"{names} on the new control before running this program", src)
        self._written.difference_update(self.names[i] for i in axes)
        return True

    def feed_per_rev(self, feed, src):
        self._flush_after(src)
        if (feed is None) != (self._per_rev is None):
            self._line("G94" if feed is None else "G95", src)
            self._feed = None  # F means something else now: written again with the next move
        self._per_rev = feed

    def radius_compensation(self, g, radius, src):
        self.refuse(src, f"cutter radius compensation G{g}: the run gives the tool centre's path for the simulated "
                         f"radius {number(radius)} mm, and ncvm does not write the programmed contour with "
                         f"G{g}; a cutter of another radius would cut the part off size")

    def tapping(self, g, src):
        self.refuse(src, f"a tapping cycle G{g}: ncvm writes a canned cycle as its moves, and a tap fed by plain "
                         "G1 moves is not tied to the spindle (program the target's tapping cycle by hand)")

    def dwell(self, seconds, src):
        self._stand(src)
        self._flush_after()
        self._line(self.t.dwell.format(s=self.num(seconds)), src)

    def _tool_word(self, text: str, src: Src) -> tuple | None:
        """Write the T word ``text`` of block ``src`` before the tool length of its own block (the 840D's D
        and the length of H belong to the tool the T names); that length, held back, is returned."""
        held = self._tool_pending if self._tool_pending is not None and self._tool_pending[1] == src else None
        self._tool_pending = None if held else self._tool_pending
        self._flush_after()
        self._line(text, src)
        return held

    def tool_select(self, tool, src):
        """A T word without M6, written as programmed; on the 840D, whose T selects the tool its D is an
        edge of, it names the tool the header lists the edge under until an M6 loads one."""
        if self.t.edge_of_tool and not self._tool:
            self._tool = tool
            self._frame_unrecorded = True
        held = self._tool_word(f"T{tool}", src)
        if held is not None:
            self._tool_pending = held
            self._tool_length()

    def tool_change(self, tool, src):
        self._stand(src)
        held = self._tool_word(f"T{tool} M6", src)
        self._tool = tool
        self._frame_unrecorded = True  # the header names the length for the new tool too (an 840D D is its edge)
        if held is not None:  # the block's own tool length: for the tool just loaded
            self._tool_pending = held
            self._tool_length()
        elif self.t.edge_of_tool:  # the 840D activates the new tool's default edge: the D the run used
            self._edge_after_change(src)
        if self._turning is not None:  # M6 stops the spindle on the new control; it turned on in the run
            self._restart = (self._turning, src)  # written before what follows, unless the program restarts it

    def _edge_after_change(self, src: Src) -> None:
        """After an 840D tool change: the tool length in force as an edge of the new tool, D0 where none is
        (or under --frame machine, whose positions hold every length already)."""
        if self.work and self._tool_written[1] and self._tool_frame is not None:
            self._tool_pending = (self._tool_frame, src)
            self._tool_length()
        else:
            self._line(self.t.tool_length_off, src)

    def _speed(self, speed: float, src: Src) -> str:
        """The S word's value: a target of integer S (ISO) gets it rounded, with a comment where it changed."""
        if not self.t.decimal_point or speed == round(speed):
            return self.num(speed) if not self.t.decimal_point else str(round(speed))
        self._note(f"S{number(speed)} rounded to S{round(speed)}: this control's S is an integer", src)
        return str(round(speed))

    def css_speed(self, speed, wanted, limit, src):
        self._css = (speed, wanted, limit)

    def _css_checked(self, speed: float, src: Src) -> bool:
        """A G96 speed the spindle turns at: refused where no limit bounded it (the new control would get the
        radius's speed, S63662 at 0.5 mm, where the old machine's maximum held it); marked where the limit cut
        it (the S word is the speed the spindle turned, not the one the cutting speed asked for)."""
        if self._css is None or self._css[0] != speed:
            return True
        _, wanted, limit = self._css
        if math.isinf(limit):
            self.refuse(src, f"G96 constant cutting speed with no spindle speed limit: the run's S{number(speed)} "
                             "here follows the radius without bound (towards the centre the speed grows past any "
                             "spindle's; the old machine's maximum, which held it there, is not in the machine file); "
                             "program the limit (DIN: G96 D<max>; SINUMERIK: G92 S<max> or [sin800] gears)")
            return False
        if wanted > limit * (1 + 1e-9):
            self._note(f"S{number(speed)}: the spindle speed limit of the simulated control (G96 D, G92 S or the "
                       f"gear stage's maximum) held the spindle there; the cutting speed asked for "
                       f"S{number(wanted)}", src)
        return True

    def spindle(self, speed, direction, src):
        self._stand(src)
        self._restart = None  # the program's own spindle word after a tool change: written once
        if direction == 0:
            self._turning = None
            if src == self._moved_in:  # a stop between the moves of one block (a boring cycle): here
                self._flush_after()
                self._line("M5", src)
            else:
                self._after.append(("M5", src))
            return
        self._flush_after()
        if not self._css_checked(speed, src):
            return
        turning = f"{'M3' if direction > 0 else 'M4'} S{self._speed(speed, src)}"
        if turning == self._turning and self.lines == self._turning_line:
            return  # the run says it again (its S word, then its M3): written once
        self._turning = turning
        self._line(turning, src)
        self._turning_line = self.lines

    def coolant(self, mode, src):
        self._stand(src)
        if mode == "off":
            self._after.append(("M9", src))
            return
        self._flush_after()
        self._line({"mist": "M7", "flood": "M8"}[mode], src)

    def aux(self, code, src):
        self._stand(src)
        self._flush_after()
        self.setup.left_out.append(code)
        self._note(f"{code}: a machine function of the simulated control, not written", src)

    def message(self, text, src):
        self._flush_after()
        for part in self.t.fit(self.t.message, self.t.escape(text)):  # a long one as several
            self._line(part, src, remark=True)

    def stop(self, kind, src):
        """A program stop; DIN G88's stop (the operator retracts by hand) is the target's M0."""
        self._stand(src)
        if kind == "M0" and self.stops_passed:
            self._warn(src, 'the simulated control ends the run at this M0 ([sin800] m0 = "stop"); the translation '
                            "goes on past it, as the new control does after the operator's cycle start",
                       r"(?<![A-Z])M0*0(?![\d.])")
        self._flush_after()
        self._line("M0" if kind == "G88" else kind, src)

    def program_end(self, src):
        self.ended = src

    def finish_moves(self) -> None:
        """The run ended normally: the last M5/M9 out (a probe move with no move after it is refused)."""
        self._restart = None  # no spindle restart after the last tool change: nothing moves any more
        self._flush_after()
        if self._unsaid is not None:
            self._line("")  # the refusal of an input no scenario gave, at the end of the program too
        if self._probe is not None:
            self.refuse(self._probe[2], "a probe move with no move after it")

    def write_end(self) -> None:
        """The program end: always, even where the program has none (an rw_SymPas program)."""
        self._line(self.t.program_end, self.ended)

    def _blending(self, machine: str) -> str | None:
        """The header's word on continuous path without a tolerance, where the cycle time blended corners in it:
        what it assumed, and what the bare G64 written does on the new control (LinuxCNC: no bound at all), since
        its corner rounding is that control's setting (docs/decisions.md); None: nothing to say."""
        t, m = self.t, self.motion
        if not self.setup.blended or m is None or self.time_model == "card":  # rw_SymPas: the card's own model
            return None
        what = f"continuous path ({t.path_continuous} without a tolerance): "
        own = f"on the new control {t.path_continuous} is {t.bare_continuous}"
        if self.time_model == "rest-to-rest":
            why = f"{machine}'s [motion] model" if m.model == "rest-to-rest" else "the run's --time-model"
            return f"{what}the run timed every move from rest to rest ({why}); {own}"
        tol = m.corner_tolerance
        if tol > 0:
            assumed = f"corners blended within {number(tol)} mm"
            keep = t.path_tolerance and f"; {t.path_tolerance.format(tol=self.num(tol))} keeps that bound"
        else:
            assumed, keep = "a stop at every corner (only moves in line blended)", f"; {t.path_exact} stops at each"
        return (f"{what}the cycle time assumed {assumed} ({machine}'s [motion] corner_tolerance {number(tol)} mm); "
                f"{own}{keep or ''}")

    def header(self, program: str, machine: str) -> list[str]:
        """The comment lines at the top: how the positions are meant, and what the new control must hold."""
        t, s = self.t, self.setup
        note = t.note
        out = []
        if self.work:
            out.append(note("positions in WORK coordinates: set these zero offsets and tool lengths on the "
                            "new control before running it"))
            for name, zeros in sorted(s.offsets.items()):
                values = " then ".join(" ".join(f"{n}{number(v)}" for n, v in zip(self.names, zero) if n in t.axes)
                                       for zero in zeros)
                out.append(note(f"zero offset {name} -> {t.work_offsets[name]}: simulated as {values} ({machine})"))
            for (tool, n, form), lengths in sorted(s.tools.items()):
                out.append(note(f"{f'tool T{tool} edge ' if tool else 'tool offset '}{form.format(n=n)}: length "
                                f"{' then '.join(number(v) for v in lengths)} mm in the simulation"))
            if not s.tools:
                out.append(note("no tool length compensation was used"))
            for shift in sorted(s.shifts):
                values = " ".join(f"{n}{number(v)}" for n, v in zip(self.names, shift) if n in t.axes and v)
                out.append(note(f"an added offset ({values}: G92 or the control's extra zero offsets) "
                                "is included in the positions"))
            if s.transformed:
                out.append(note("a coordinate transformation of the program is included in the positions"))
            if s.machine_moves:
                out.append(note(f"{s.machine_moves} moves in machine coordinates ({t.machine_move})"))
        else:
            out += [note("!!! MACHINE COORDINATES OF THE SIMULATED MACHINE: every offset and tool length is "
                         "included in the positions !!!"),
                    note("!!! run only on a control whose active zero offset and tool length are all zero "
                         "!!!")]
        blending = self._blending(machine)
        if blending:
            out.append(note(blending))
        if s.homed:
            names = sorted({n for axes, _ in s.homed for n in axes.split()})
            out.append(note(f"the program homes {' '.join(names)} (marked HOMING below): home them on the new "
                            "control; the zero offset above is the simulated reference point"))
        if s.probes:
            out.append(note(f"{s.probes} probe moves"))
        if s.frozen:
            out.append(note(f"{s.frozen} decisions of the run are frozen (marked FROZEN below): the path "
                            "follows the simulated inputs"))
        if s.left_out:
            out.append(note(f"machine functions not written: {', '.join(sorted(set(s.left_out)))}"))
        extra = [n for n in self.names if n not in t.axes]
        if extra:
            out.append(note(f"axes {' '.join(extra)} have no address on {t.title} and are left out"))
        return out

