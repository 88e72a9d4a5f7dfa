"""The DIN 66025 kernel: modal state, offsets and the conversion of blocks into canon calls.

Like LinuxCNC's rs274ngc ``convert_*`` stage, :meth:`NcKernel.execute` takes a
read block, checks it against the modal state and turns it into calls of the
canonical machining interface, in a fixed order: message, feed, speed, tool
select and change, spindle, coolant, dwell, plane, units, compensation,
tool length, coordinate system, distance mode, set position, motion, stop/end.

Coordinates: the kernel keeps the *programmed* position (workpiece
coordinates, mm) and the sum of active offsets per axis; machine position =
programmed + offsets. Canon calls carry machine positions.

The G functions a block may carry, and what each does, come from the kernel's control profile
(:mod:`ncvm.nc.profiles`, selected with :meth:`NcKernel.use_profile`; ``iso`` by default): a G number
is one dict lookup, whose row says whether it sets modal state at once, is the block's motion, a dwell,
and so on. A number the profile lacks stops the block with NC004.

Dialect extension points: ``g_handlers`` maps extra G numbers to handlers
(``handler(kernel, g, words, src) -> bool``, True when the block's axis words
were parameters, not a target), run after the block's other G codes; ``motion_modes`` maps a dialect's
own modal motion G numbers (threads) to their move functions; and
:meth:`NcKernel.set_transform` puts a coordinate transformation between the
programmed position and the offsets: machine = transform(programmed) + offsets.
"""

from __future__ import annotations

import copy
import math
from operator import add, sub

from ..diagnostics import RuntimeFault, Span
from ..machine.model import Machine, PlcImage, SimClock
from ..records import replace
from . import arcs, cutter, threads
from .canon import NOBODY, ArcSpec, Canon, Frame, Src
from .dynamics import AxisDynamics, arc_limits, path_limits
from .fastmove import make_linear
from .planner import LOOKAHEAD, POSITIONING, STOP_END, Planner, arc_tangents
from .profiles import AFTER_TOOL_CHANGE, CYCLE, DWELL, LATE, MACHINE, MOTION, POSITION, SET, Profile, unknown_g
from .profiles import INCH as INCH  # the unit of G70, read by the dialects
from .toolcheck import missing_tool

#: plane G number -> (first axis, second axis, normal axis, first centre word, second centre word)
PLANES = {17: ("X", "Y", "Z", "I", "J"), 18: ("Z", "X", "Y", "K", "I"), 19: ("Y", "Z", "X", "J", "K")}
NON_AXIS = frozenset("FSTDHIJKRPLN")
_MOTION_G = frozenset((0, 1, 2, 3))
#: G number -> what it does to the path control: "block" (exact stop at the end of this block: G09),
#: "exact" (modal exact stop), "continuous" (modal continuous path), "blend" (continuous path, P the corner
#: tolerance: LinuxCNC's G64 P). ISO/DIN here; each control names its own (docs/decisions.md, docs/planner.md)
ISO_PATH_CODES = {9: "block", 60: "exact", 61: "exact", 61.1: "exact", 64: "blend"}


class NcKernel:
    """Executes blocks on a :class:`Machine`, reporting motion through a :class:`Canon`."""

    def __init__(self, machine: Machine, canon: Canon, profile: Profile | None = None):
        self.machine = machine
        self.canon = canon
        names = machine.axis_names
        self.axis_names = names
        self.axis_of = {n: i for i, n in enumerate(names)}
        self.n_axes = len(names)
        #: the rotary axes: their words are degrees in inch programs too (CPL manual L1329-1337, L1975), so
        #: the unit ``scale`` of G20/G70 never multiplies them (:meth:`unit_of`)
        self.rotary = frozenset(a.name for a in machine.axes if a.rotary)
        self.dyn = AxisDynamics(machine.axes)
        motion = machine.motion
        #: the path planner: moves wait in it untimed until their look-ahead window is complete (nc.planner)
        self.planner = Planner(machine.clock, canon, self.dyn, motion.model, motion.lookahead,
                               motion.corner_tolerance)
        #: the G codes of the path control (see ISO_PATH_CODES); a front end sets its control's
        self.path_codes = ISO_PATH_CODES
        #: the row flags of a move at feed: STOP_END under modal exact stop, 0 in continuous-path mode
        self.exact = 0
        self.tool_change_time = float(motion.tool_change_time)
        self._fast_linear = make_linear(names, self.rotary)
        #: the straight move (G0/G1 without G53): ``linear(kernel, motion, words, src)``, a plain function of
        #: the kernel (generated code calls it without a bound method). The generated fast path, or the
        #: general one while a transform is set (see set_transform); a front end calls it, never replaces it
        self.linear = self._fast_linear
        #: G number -> handler(kernel, g, words, src) -> True when the block's axis words are parameters
        self.g_handlers: dict = {}
        #: a dialect's own modal motion modes beside G0-G3 (the threads G33-G35, nc/threads.py): G number ->
        #: ``move(kernel, g, words, src)``, run for every block with axis words while the mode is active
        self.motion_modes: dict = {}
        #: the control profile: its G table (``g_table``, G number -> (run, handler)) and the handlers of the
        #: addresses it reads (``word_handlers``), see use_profile
        if profile is None:
            from .profiles.iso import ISO as profile
        self.use_profile(profile)
        #: None, or an object with forward(vec), inverse(vec) and plane_similarity(a, b) (see set_transform)
        self.transform = None
        #: the active cutter radius compensation (:class:`ncvm.nc.cutter.CutterComp`), None under G40
        self.comp = None
        #: where G41/G42 take the tool radius: ``radius(kernel, g, words, src) -> mm``; a front end whose
        #: control numbers its tool data otherwise sets its own (or a refusal)
        self.cutter_radius = cutter.iso_radius
        #: where a profile's length compensation word (Bosch H) takes its length:
        #: ``length(kernel, table, group, src) -> mm``; None: the machine's tool table (profiles.typ3osa)
        self.length_compensation = None
        #: when an arc's end lies too far off its start radius (a machine datum of the control's profile)
        self.arc_tolerance = arcs.KERNEL
        #: None, or the canned cycles of a profile that has them (:class:`ncvm.nc.cycles.CannedCycles`): then
        #: its G codes (G73, G74, G80-G89, G98, G99) are its own, and G80 leaves no motion mode active
        self.canned = None
        # modal state
        self.motion = 0
        self.plane = 17
        #: SINUMERIK G16 with the plane's axes in the other order (G16 X Z: X horizontal, Z vertical, G18's
        #: plane seen mirrored): G2 and G3 turn the other way round than in ``plane``
        self.plane_mirrored = False
        #: SINUMERIK G16 naming a plane that no G17-G19 is (G16 X A): an arc there is refused, naming it
        self.plane_unknown: str | None = None
        self.absolute = True
        self.scale = 1.0  # 1.0 mm, 25.4 inch
        self.feed = 0.0  # mm/min
        self.speed = 0.0  # programmed spindle speed (S, rev/min)
        self.spindle_dir = 0
        # the spindle turns with the simulated clock: the angle it had turned at _spindle_t (degrees)
        self._spindle_angle = 0.0
        self._spindle_t = machine.clock.now
        self.css = False  # G96 constant cutting speed: S is the cutting speed, the speed follows the radius
        self.cutting_speed = 0.0  # m/min (ft/min with inch)
        self.css_speed = 0.0  # the speed G96 gives at the current radius (rev/min)
        self.max_speed = math.inf  # spindle speed limit under G96 (set by the dialect)
        self.css_axis = self.axis_of.get("X")  # the transverse axis whose position is the radius
        self.css_diameter = False  # that axis is programmed as a diameter
        #: G95: F is a feed per revolution (mm/rev), kept here; ``feed`` is then the path feed it gives at the
        #: spindle speed of each move's start (nc/threads.py)
        self.per_rev = False
        self.feed_per_rev = 0.0
        #: the G94/G95 switch that last set F to 0 and the F it cleared (None: none yet), for NC006's words
        self.feed_switch: tuple[int, float] | None = None
        #: G96 or G95 is on: every move first re-reads the spindle (spindle_update)
        self.spindle_bound = False
        self.tool = 0  # tool in spindle
        self.next_tool = 0
        self.work_offset = "G54"
        self.tool_length = 0.0
        self.tool_offset = 0  # the H (D) number the tool length came from
        self.tool_subtracted = False  # G44: the length of the offset taken off
        self.tool_axis = self.axis_of.get("Z")
        self.g92 = [0.0] * self.n_axes
        #: offsets a control adds on top of the selected work offset (SINUMERIK programmable, external,
        #: DRF and PRESET offsets), one value per axis; set with set_additive_offset
        self.additive = [0.0] * self.n_axes
        # positions
        start = list(machine.start_position or [0.0] * self.n_axes)
        self.machine_pos = tuple(start)
        self.offset_vec = [0.0] * self.n_axes
        self._recompute_offsets()
        self.prog = [m - o for m, o in zip(start, self.offset_vec)]
        self.ended = False
        self.stopped_at: str | None = None
        #: M0 ends the run (a dialect's option); by default the run goes on as after the operator's cycle start
        self.m0_stops = False
        #: the block number of the last programmed stop (None: the block has none)
        self.stop_block: int | None = None
        canon.begin(names, self.machine_pos)
        self._frame: Frame | None = None
        self._announce_frame(None)


    def use_profile(self, profile: Profile) -> None:
        """Read blocks as the control of ``profile`` does (a dialect selects its control's profile)."""
        self.profile = profile
        self.g_table = profile.dispatch
        self.word_handlers = profile.word_handlers
        #: group -> G number programmed, for the groups whose active function is all ncvm models of them
        #: (profiles.modal_only); a group not in it has the profile's default
        self.modal: dict = {}

    def active_in(self, group: str):
        """The G number active in a ``modal`` group of the profile."""
        return self.modal.get(group, self.profile.defaults.get(group))

    # -- copies and placement ----------------------------------------------
    def fork(self) -> NcKernel:
        """A copy that runs blocks ahead of this kernel (a shadow of the state after the prepared blocks, a
        look-ahead): the same modal state, offsets and position, its own clock (at this one's time) and PLC
        image, and no canon output. Running blocks on either leaves the other as it is; the machine's tables
        (zero offsets, tools) stay shared."""
        k = copy.copy(self)
        m = copy.copy(self.machine)
        m.clock = SimClock(m.clock.settled, m.clock.start_epoch)  # no flush: the shadow's time is its own
        plc = m.plc
        m.plc = PlcImage(dict(plc.inputs), dict(plc.outputs), dict(plc.flags), dict(plc.words))
        k.machine = m
        k.canon = Canon([])
        k.planner = self.planner.fork(m.clock, k.canon)
        k.prog, k.g92, k.offset_vec, k.additive = list(self.prog), list(self.g92), list(self.offset_vec), \
            list(self.additive)
        k.canned = copy.copy(self.canned)
        k.modal = dict(self.modal)
        return k

    def place(self, machine_pos, prog=None) -> None:
        """Put the axes at ``machine_pos`` without a move and without a canon call (a control that moved
        them itself, e.g. a card's axis commands). The programmed position follows from the active offsets
        and transform, or is ``prog`` when the caller keeps its own zero point."""
        self.machine_pos = tuple(machine_pos)
        self.prog = list(prog) if prog is not None else self.program_position(self.machine_pos)

    # -- offsets ---------------------------------------------------------
    def _recompute_offsets(self) -> None:
        wo = self.machine.offset(self.work_offset) if self.work_offset else [0.0] * self.n_axes
        vec = [w + g + a for w, g, a in zip(wo, self.g92, self.additive)]
        if self.tool_axis is not None:
            vec[self.tool_axis] += self.tool_length
        self.offset_vec = vec

    def _set_offsets_keep_machine(self, src: Src | None = None) -> None:
        """After an offset change the tool stays put; the programmed position moves."""
        self._recompute_offsets()
        self.prog = self.program_position(self.machine_pos)
        self._announce_frame(src)

    def frame(self, work_offset: str | None = "") -> Frame:
        """The coordinate frame now (``work_offset`` given: with that name and no zero offset, a G53 move)."""
        if work_offset == "":
            work_offset = self.work_offset
            zero = tuple(self.machine.offset(work_offset)) if work_offset else (0.0,) * self.n_axes
        else:
            zero = (0.0,) * self.n_axes
        tool = self.tool_length if self.tool_axis is not None else 0.0
        shift = tuple(o - z - (tool if i == self.tool_axis else 0.0)
                      for i, (o, z) in enumerate(zip(self.offset_vec, zero)))
        return Frame(work_offset, zero, shift, self.tool_length, self.tool_axis, self.tool_offset,
                     self.transform is not None, tool_subtracted=self.tool_subtracted)

    def _announce_frame(self, src: Src | None) -> None:
        """Tell the canon the frame when it changed (offset changes only: nothing per move)."""
        frame = self.frame()
        if frame != self._frame:
            self._frame = frame
            self.canon.frame(frame, src)

    def program_position(self, mcs) -> list[float]:
        """The programmed position (mm) that puts the machine at ``mcs`` with the active offsets and transform."""
        rel = [m - o for m, o in zip(mcs, self.offset_vec)]
        return rel if self.transform is None else self.transform.inverse(rel)

    def set_transform(self, transform) -> None:
        """Put a coordinate transformation between programmed positions and offsets (None: none).

        ``transform.forward(vec)`` maps a programmed position to the position before the offsets,
        ``inverse`` back; ``plane_similarity(a, b)`` gives (factor, mirrored) when circles in that plane
        stay circles, else None. While one is set, straight moves leave the generated fast path
        (which knows nothing of it). The tool stays put; the programmed position moves.
        """
        if self.comp is not None and transform is not None:
            self.fault("NC005", "a coordinate transformation while cutter radius compensation is on is not "
                       "supported by ncvm (G40 first)", None)
        self.transform = transform
        if self.comp is None:  # compensation keeps its own straight-move path
            self.linear = self._fast_linear if transform is None else _transformed_linear
        self._set_offsets_keep_machine()

    def set_work_offset(self, name: str | None, src: Src | None = None) -> None:
        self.work_offset = name
        self._set_offsets_keep_machine(src)

    def set_additive_offset(self, vec) -> None:
        """Offsets added to the selected work offset (per axis); the tool stays where it is."""
        self.additive = [float(v) for v in vec]
        self._set_offsets_keep_machine()

    def refresh_offsets(self) -> None:
        """Re-read the work offset tables after a program changed them; the tool stays where it is."""
        self._set_offsets_keep_machine()

    def set_tool_length(self, length: float, src: Src, number: int = 0, subtracted: bool = False) -> None:
        """Tool length compensation ``length`` on the tool axis, from tool offset ``number`` (H or D; 0: none);
        ``subtracted``: G44, the offset's length taken off (``length`` is then its negative)."""
        self.tool_length = length
        self.tool_offset = number if length else 0
        self.tool_subtracted = subtracted and bool(length)
        self._set_offsets_keep_machine(src)
        self.canon.tool_offset(length, src)

    def shown_position(self) -> list[float]:
        """The programmed position (mm) as the control shows it: as programmed, or with the transform applied
        when the transform says the control shows it so (``transform.shown``, SINUMERIK's rotation)."""
        t = self.transform
        return self.prog if t is None or not getattr(t, "shown", False) else t.forward(self.prog)

    def workpiece_position(self) -> dict[str, float]:
        """Programmed position per axis in the current unit, as a program sees it (:meth:`shown_position`)."""
        return {n: p / self.unit_of(n) for n, p in zip(self.axis_names, self.shown_position())}

    def unit_of(self, name: str) -> float:
        """mm per programmed unit of axis ``name``: ``scale`` (1.0 or 25.4), 1.0 for a rotary axis (degrees)."""
        return 1.0 if name in self.rotary else self.scale

    # -- faults ----------------------------------------------------------
    def fault(self, code: str, message: str, src: Src | None):
        span = Span(src.file, src.line) if src else None
        raise RuntimeFault(code, message, span)

    # -- the block -------------------------------------------------------
    def execute(self, block) -> None:
        src = block.src
        words = block.words
        canon = self.canon
        if self.comp is not None:
            self.comp.check_block(block)
        if block.msg is not None:
            canon.message(block.msg, src)
        dwell_block = False
        set_position = False
        machine_coords = False
        motion = self.motion
        handlers = self.g_handlers
        extra = None
        after_change = None
        cycle_g = False
        block_stop = False
        path_codes = self.path_codes
        motion_modes = self.motion_modes
        table = self.g_table
        for g in block.g:
            if handlers and g in handlers:
                extra = [g] if extra is None else extra + [g]
                continue
            if g in path_codes:
                block_stop = self._path_mode(path_codes[g], words, src) or block_stop
                continue
            if motion_modes and g in motion_modes:
                motion = g
                continue
            entry = table.get(g)
            if entry is None:
                unknown_g(self, g, src)
            run = entry[0]
            if run == SET:
                entry[1](self, g, words, src)
            elif run == MOTION:
                motion = g
            elif run == DWELL:
                dwell_block = (g, entry[1])
            elif run == LATE:
                extra = [g] if extra is None else extra + [g]
            elif run == AFTER_TOOL_CHANGE:
                after_change = [g] if after_change is None else after_change + [g]
            elif run == CYCLE:
                if self.canned is None or g not in self.canned.codes:
                    if g != 80:
                        self.fault("NC004", f"G{g:g} is not supported", src)
                elif self.comp is not None and g < 98:
                    self.fault("NC012", f"G{g}: no canned cycle while cutter radius compensation is on", src)
                elif g >= 98:
                    self.canned.retract_to_r = g == 99
                elif g == 80 and any(table.get(x, (None,))[0] == MOTION for x in block.g):
                    pass  # rs274: G80 gives way to the block's motion code (G0 G80 X1 moves)
                else:
                    motion, cycle_g = g, True
            elif run == POSITION:  # the handler, if any, checks the block before its words act
                set_position = True
                if entry[1] is not None:
                    entry[1](self, g, words, src)
            elif run == MACHINE:  # the handler: the offsets the control keeps in the block (None: none)
                machine_coords = entry[1] or True
            else:  # ALONE: the block is this function alone (G10 L2 writes a table)
                entry[1](self, g, words, src)
                return
        if machine_coords is True and motion > 1:  # LinuxCNC's G53 (no offset kept): "Must use g0 or g1 with g53"
            self.fault("NC009", f"G53 (machine coordinates) under G{motion:g}: a move in machine coordinates is G0 or "
                       "G1", src)
        dwell = None if dwell_block is False else dwell_block[1](self, dwell_block[0], words, block.g, src)  # (s, alone)
        words_taken = False
        if extra is not None:
            for g in extra:
                handler = handlers[g] if g in handlers else table[g][1]
                words_taken = handler(self, g, words, src) or words_taken
        if self.word_handlers:
            for letter, handler in self.word_handlers.items():
                if letter in words:
                    handler(self, words[letter], words, src)
        if "F" in words and not (dwell is not None and dwell[1]) and not (motion_modes and motion in motion_modes):
            if self.per_rev:
                self.feed_per_rev = words["F"] * self.scale if self.scale != 1.0 else words["F"]
                canon.feed_per_rev(self.feed_per_rev, src)
            else:
                self.feed = words["F"] * self.scale if self.scale != 1.0 else words["F"]
        if "S" in words:
            if self.css:
                self.cutting_speed = words["S"]
            else:
                self._spindle_fold()
                self.speed = words["S"]
                if self.spindle_dir:
                    canon.spindle(self.speed, self.spindle_dir, src)
        if self.css:
            self._css_update(src)
        if "T" in words:
            self.next_tool = int(words["T"])
            if canon.tool_select is not NOBODY and 6 not in block.m:  # a translation keeps the T word
                canon.tool_select(self.next_tool, src)
        if block.m:
            self.planner.stop()  # M functions are exact stops: the axes stand while the PLC acts
            block_stop = True
            for mc in block.m:
                self._m_before(mc, src)
        if after_change is not None:  # the profile's order of execution: the tool change first
            for g in after_change:
                table[g][1](self, g, words, src)
        if dwell is not None:  # the dwell, then the block's move where the profile's row makes one (rs274 G4 P)
            self.planner.stop()
            self.machine.clock.advance(dwell[0])
            canon.dwell(dwell[0], src)
        if dwell is not None and dwell[1]:
            pass
        elif set_position:
            self._set_position(words)
        elif words_taken:
            self.motion = motion
        elif motion >= 73 and self.canned is not None:
            self.canned.block(self, motion, cycle_g, words, src)
        else:
            if motion < 2 and "R" in words:  # rs274: "R word with no G code that uses it"; never dropped silently
                self.fault("NC009", "a circle radius (R; SINUMERIK B or U) on a straight move (G0/G1): no function of the block uses "
                           "it (a corner rounding between straight blocks is not supported by ncvm)", src)
            if machine_coords and not self.absolute:  # rs274: "Cannot use G53 incremental"; CL 800 gives none
                self.fault("NC009", "G53 (machine coordinates) under G91: a machine position is absolute, "
                           "an incremental one is not supported (G90 first)", src)
            self.motion = motion
            if canon.programmed is not NOBODY:  # a translation writes the block's axis words, not only those that move
                canon.programmed(tuple(a for a in words if a in self.axis_of), src)
            if motion < 2 and not machine_coords:
                self.linear(self, motion, words, src)  # the common case, without the _move call
            else:
                self._move(motion, words, machine_coords, src)
        if block_stop:
            self.planner.stop()
        for mc in block.m:
            self._m_after(mc, src, block.n)

    def _path_mode(self, mode: str, words, src: Src) -> bool:
        """A G code of the path control (see ISO_PATH_CODES); True when the block ends in an exact stop."""
        tolerance = None
        if mode == "exact":
            self.exact = STOP_END
        elif mode != "block":
            self.exact = 0
            if mode == "blend":  # G64 P sets the corner tolerance; a bare G64 gives back the machine's
                if "P" in words:
                    if words["P"] < 0.0:
                        self.fault("NC004", f"G64 P{words['P']:g}: the path tolerance cannot be negative", src)
                    tolerance = words["P"] * self.scale
                self.planner.set_tolerance(float(self.machine.motion.corner_tolerance) if tolerance is None else tolerance)
        if self.canon.path_control is not NOBODY:  # a translation writes it
            self.canon.path_control("exact" if mode == "exact" else mode if mode == "block" else "continuous",
                                    tolerance, src)
        return mode == "block"

    def time_model(self) -> str:
        """The cycle-time model of this run, as the summary names it."""
        return "look-ahead" if self.planner.model == LOOKAHEAD else "rest-to-rest"

    def no_feed_message(self, g: int) -> str:
        """NC006: a move at feed with no feed rate, or with a negative one, or under G95 with the spindle standing."""
        if self.per_rev:
            standing = threads.no_feed_message(self, g)
            if standing is not None:
                return standing
        if self.feed < 0.0:
            return f"G{g} with a negative feed rate F{self.feed / self.scale:g} (program a positive F word)"
        cleared = threads.cleared_feed_message(self, g)
        if cleared is not None:
            return cleared
        return f"G{g} with feed rate 0 (program an F word)"

    def columns_ok(self) -> bool:
        """Whether plain motion blocks may run column-wise (:mod:`ncvm.nc.plainrun`) now: not while a coordinate
        transformation maps every target, nor under G96 or G95, where each move re-reads the spindle, nor
        when a dialect handles a motion G code itself, nor for a sink that takes each block's axis words."""
        return self.canon.programmed is NOBODY and self.transform is None and not self.spindle_bound and self.comp is None and self.motion < 4 and not (
            self.g_handlers and _MOTION_G & self.g_handlers.keys())

    # -- spindle -----------------------------------------------------------
    def spindle_speed(self) -> float:
        """The commanded speed (rev/min): S, or under G96 the speed for the current radius."""
        return self.css_speed if self.css else self.speed

    def _spindle_fold(self) -> None:
        """Add the turn since the last change; call before the speed or the direction changes."""
        now = self.machine.clock.now
        if self.spindle_dir:
            self._spindle_angle += self.spindle_dir * self.spindle_speed() * 6.0 * (now - self._spindle_t)
        self._spindle_t = now

    def spindle_angle(self) -> float:
        """Spindle position in degrees, 0 <= angle < 360: M3 counts up, M4 down (speed/60 rev per second)."""
        if self.css:
            self._css_update(None)
        self._spindle_fold()
        self._spindle_angle %= 360.0
        return self._spindle_angle

    def actual_speed(self) -> float:
        """Actual spindle speed (rev/min), negative for M4, 0 while the spindle stands (M5, not started)."""
        if self.css:
            self._css_update(None)
        return self.spindle_dir * self.spindle_speed()

    def spindle_update(self, src: Src) -> None:
        """Before a move: G96's speed for the radius here, then G95's path feed for that speed."""
        if self.css:
            self._css_update(src)
        if self.per_rev:
            threads.per_rev_feed(self)

    def _css_update(self, src: Src | None, announce: bool = True) -> None:
        """G96: speed = cutting speed / (2 pi r) at the transverse axis position now. Blocks update it at
        their start, so during a move the spindle keeps the speed of the move's start point."""
        if self.css_axis is None:
            self.fault("NC004", "G96 needs a transverse axis X for the radius", src)
        r = abs(self.prog[self.css_axis]) / (2.0 if self.css_diameter else 1.0)
        surface = self.cutting_speed * (304.8 if self.scale != 1.0 else 1000.0)  # mm/min
        wanted = math.inf
        if r > 1e-9:
            wanted = surface / (2.0 * math.pi * r)
            rpm = min(self.max_speed, wanted)
        elif surface == 0.0:
            rpm = wanted = 0.0
        elif not math.isinf(self.max_speed):
            rpm = self.max_speed
        elif self.spindle_dir:
            self.fault("NC010", "G96 at radius 0 needs a spindle speed limit (the machine's maximum spindle speed)",
                       src)
        else:
            rpm = 0.0  # decided when the spindle starts
        if rpm != self.css_speed:
            self._spindle_fold()
            self.css_speed = rpm
            if self.canon.css_speed is not NOBODY:  # a translation writes no speed that no limit bounded
                self.canon.css_speed(rpm, wanted, self.max_speed, src)
            if self.spindle_dir and announce:
                self.canon.spindle(rpm, self.spindle_dir, src)

    def _g97(self) -> None:
        """G97 ends G96; the spindle keeps the speed it has (DIN 66025)."""
        if self.css:
            self._spindle_fold()
            self.speed = self.css_speed
            self.css = False
            self.spindle_bound = self.per_rev

    def _tool(self, number: int, src: Src):
        tool = self.machine.tools.get(number)
        if tool is None:
            self.fault("NC008", f"tool {number} is not in the tool table", src)
        return tool

    def _m_before(self, mc: int, src: Src) -> None:
        canon = self.canon
        if mc == 6:
            fault = missing_tool(self.next_tool, self.machine.tools)
            if fault is not None:
                self.fault("NC008", fault, src)
            self.tool = self.next_tool
            canon.tool_change(self.tool, src)
            self.machine.clock.advance(self.tool_change_time)
        elif mc == 3 or mc == 4:
            self._spindle_fold()
            self.spindle_dir = 1 if mc == 3 else -1
            if self.css:
                self._css_update(src, announce=False)
            canon.spindle(self.spindle_speed(), self.spindle_dir, src)
        elif mc == 5:
            self._spindle_fold()
            self.spindle_dir = 0
            canon.spindle(0.0, 0, src)
        elif mc == 7:
            canon.coolant("mist", src)
        elif mc == 8:
            canon.coolant("flood", src)
        elif mc == 9:
            canon.coolant("off", src)
        elif mc in (0, 1, 2, 30):
            pass
        else:
            self.machine.plc.outputs[f"M{mc}"] = True
            canon.aux(f"M{mc}", src)

    def turn_spindle(self, direction: int, src: Src) -> None:
        """Start the spindle clockwise (1), counter-clockwise (-1) or stop it (0), as M3, M4, M5 do."""
        self._m_before(3 if direction > 0 else 4 if direction < 0 else 5, src)

    def _m_after(self, mc: int, src: Src, n: int | None = None) -> None:
        if mc == 0 or mc == 1:
            self.stopped_at = f"M{mc}"
            self.stop_block = n
            self.canon.stop(f"M{mc}", src)
        elif mc == 2 or mc == 30:
            self.end_program(src)

    def end_program(self, src: Src) -> None:
        self.planner.stop()
        if not self.ended:
            self.ended = True
            self.canon.program_end(src)
            if self.comp is not None:
                self.comp.detach()

    def _set_offset_table(self, words, src: Src) -> None:
        """G10 L2 P<n>: write zero offset table n (1 = G54 ... 6 = G59) from the axis words, no motion."""
        number = int(words.get("P", 0))
        if int(words.get("L", 0)) != 2 or not 1 <= number <= 6:
            self.fault("NC004", "G10 is supported as G10 L2 P1..P6 (set zero offset G54..G59)", src)
        table = self.machine.offset(f"G{53 + number}")
        for name, i in self.axis_of.items():
            if name in words:
                table[i] = words[name] * self.unit_of(name)
        self._set_offsets_keep_machine(src)

    def _set_position(self, words) -> None:
        if self.transform is not None:
            self._set_position_transformed(words)
            return
        for name, i in self.axis_of.items():
            if name in words:
                value = words[name] * self.unit_of(name)
                self.g92[i] = self.machine_pos[i] - (self.offset_vec[i] - self.g92[i]) - value
        self._set_offsets_keep_machine()

    def _set_position_transformed(self, words) -> None:
        """G92 under a transformation: the named axes read the given values; the G92 shift of every axis
        takes up what the transformation makes of them, so the tool stays put."""
        prog = list(self.prog)
        for name, i in self.axis_of.items():
            if name in words:
                prog[i] = words[name] * self.unit_of(name)
        base = self.transform.forward(prog)
        self.g92 = [m - (o - g) - b for m, o, g, b in zip(self.machine_pos, self.offset_vec, self.g92, base)]
        self._set_offsets_keep_machine()

    # -- motion ----------------------------------------------------------
    def machine_kept(self, machine_coords) -> list[float] | None:
        """The offsets a block in machine coordinates keeps, per axis (None: none, LinuxCNC's G53): the
        profile's MACHINE row names them (SINUMERIK: the tool length, docs/decisions.md)."""
        return machine_coords(self) if callable(machine_coords) else None

    def _target(self, words, machine_coords) -> tuple[list[float], bool]:
        prog = list(self.prog)
        moved = False
        scale = self.scale
        axis_of = self.axis_of
        kept = self.machine_kept(machine_coords) if machine_coords else None
        for name, v in words.items():
            i = axis_of.get(name)
            if i is None:
                continue
            if scale != 1.0 and name not in self.rotary:
                v *= scale
            if machine_coords:
                prog[i] = v - self.offset_vec[i] + (kept[i] if kept else 0.0)
            elif self.absolute:
                prog[i] = v
            else:
                prog[i] += v
            moved = True
        return prog, moved

    def _move(self, motion: int, words, machine_coords, src: Src) -> None:
        if motion < 2 and not machine_coords:
            self.linear(self, motion, words, src)
            return
        self._general_move(motion, words, machine_coords, src)

    def straight_to(self, prog, rapid: bool, src: Src) -> None:
        """A straight move to the programmed position ``prog`` (mm, every axis), at rapid or at the modal feed:
        the moves a canned cycle makes."""
        if self.spindle_bound:
            self.spindle_update(src)
        start = self.machine_pos
        end = tuple(map(add, prog if self.transform is None else self.transform.forward(prog), self.offset_vec))
        self.straight_out(0 if rapid else 1, start, end, self.feed, src, self.canon)
        self.prog = list(prog)
        self.machine_pos = end

    def _general_move(self, motion: int, words, machine_coords, src: Src) -> None:
        if self.spindle_bound:
            self.spindle_update(src)
        if motion > 3 and motion in self.motion_modes:
            self.motion_modes[motion](self, motion, words, src)
            return
        if self.comp is not None:
            self.comp.move(motion, words, src)
            return
        prog, moved = self._target(words, machine_coords)
        if not moved and not (motion >= 2 and ("I" in words or "J" in words or "K" in words)):
            return
        start = self.machine_pos
        if self.transform is None:
            end = tuple(map(add, prog, self.offset_vec))
        elif machine_coords:
            # G53: the named axes go to machine positions, past the transformation; the others stay
            kept = self.machine_kept(machine_coords) or (0.0,) * self.n_axes
            end = tuple(words[n] * self.unit_of(n) + o if n in words else p
                        for n, p, o in zip(self.axis_names, start, kept))
            prog = self.program_position(end)
        else:
            end = tuple(map(add, self.transform.forward(prog), self.offset_vec))
        if machine_coords:  # the move's frame is the machine's (G53), for this move only
            frame = self.frame("G53")
            if self.machine_kept(machine_coords) and frame.tool_length:
                frame = replace(frame, tool_kept=True)
            self.canon.frame(frame, src)
            self._frame = None
        if motion < 2:
            if motion and self.feed <= 0.0:
                self.fault("NC006", self.no_feed_message(1), src)
            self.straight_out(motion, start, end, self.feed, src, self.canon)
        else:
            self._arc(motion == 2, start, end, words, src, prog)
        self.prog = prog
        self.machine_pos = end
        if machine_coords:
            self._announce_frame(src)

    def _arc(self, cw: bool, start, end, words, src: Src, prog) -> None:
        if self.feed <= 0.0:
            self.fault("NC006", self.no_feed_message(2 if cw else 3), src)
        if self.plane_unknown is not None:
            self.fault("NC004", f"G{2 if cw else 3} in the plane of {self.plane_unknown}: ncvm draws circles in "
                       "the planes of X, Y and Z only", src)
        cw ^= self.plane_mirrored
        an, bn = PLANES[self.plane][:2]
        if an not in self.axis_of or bn not in self.axis_of:
            self.fault("NC004", f"plane G{self.plane} needs axes {an} and {bn}", src)
        a, b = self.axis_of[an], self.axis_of[bn]
        t = self.transform
        if t is None:
            sa, sb, ea, eb = start[a], start[b], end[a], end[b]
        else:  # the circle is programmed untransformed: its geometry first, then its centre mapped
            sa, sb, ea, eb = self.prog[a], self.prog[b], prog[a], prog[b]
        ca, cb, radius = self.arc_centre(cw, sa, sb, ea, eb, words, src)
        if t is not None:
            similar = t.plane_similarity(a, b)
            if similar is None:
                self.fault("NC004", f"G{2 if cw else 3}: the active transformation does not keep circles in "
                           f"the {an}{bn} plane (unequal scaling factors)", src)
            factor, mirrored = similar
            centre = list(self.prog)
            centre[a], centre[b] = ca, cb
            centre = t.forward(centre)
            ca, cb = centre[a] + self.offset_vec[a], centre[b] + self.offset_vec[b]
            radius *= factor
            cw ^= mirrored
            sa, sb, ea, eb = start[a], start[b], end[a], end[b]
        turns = max(0, int(words.get("P", 1)) - 1)
        self.arc_out(start, end, ArcSpec(a, b, (ca, cb), cw, radius, turns), self.feed, src, self.canon)

    def arc_centre(self, cw: bool, sa: float, sb: float, ea: float, eb: float, words, src: Src):
        """(centre a, centre b, radius) of the arc from (sa, sb) to (ea, eb) in the active plane, from its R or
        its centre words; faults as the control does on a missing centre or unequal radii."""
        _an, _bn, _nn, iw, jw = PLANES[self.plane]
        try:
            if "R" in words and iw not in words and jw not in words:
                ca, cb = arcs.center_from_radius(sa, sb, ea, eb, words["R"] * self.scale, cw,
                                                 self.arc_tolerance.reach)
            elif iw in words or jw in words:
                ca = sa + words.get(iw, 0.0) * self.scale
                cb = sb + words.get(jw, 0.0) * self.scale
            else:
                self.fault("NC003", f"G{2 if cw else 3} needs a centre ({iw}/{jw}) or a radius (R)", src)
            return ca, cb, arcs.check_radii(sa, sb, ea, eb, ca, cb, self.arc_tolerance, self.scale != 1.0)
        except arcs.ArcError as e:
            self.fault("NC002", str(e), src)

    def straight_out(self, motion: int, start, end, feed: float, src: Src, canon) -> None:
        """A straight move (0 rapid, 1 at ``feed``) leaves: the clock runs its time, ``canon`` hears it."""
        deltas = tuple(map(sub, end, start))
        length = math.sqrt(sum(d * d for d in deltas))
        if length > 0.0:
            dyn = self.dyn
            rapid = motion == 0
            v, a = path_limits(deltas, length, math.inf if rapid else feed / 60.0,
                               dyn.rapid if rapid else dyn.max_feed, dyn.accel)
            u = tuple(d / length for d in deltas)
            self.planner.add(length, v, a, POSITIONING if rapid else self.exact, u, u)
        if motion == 0:
            canon.rapid(start, end, src)
        else:
            canon.feed(start, end, feed, src)

    def arc_out(self, start, end, spec: ArcSpec, feed: float, src: Src, canon) -> None:
        """An arc leaves: the clock runs its time, ``canon`` hears it."""
        sa, sb, ea, eb = start[spec.a], start[spec.b], end[spec.a], end[spec.b]
        angle = arcs.sweep(sa, sb, ea, eb, *spec.center, spec.cw, spec.turns)
        length = arcs.arc_length(spec.radius, angle, arcs.helix_travel(start, end, spec.a, spec.b))
        v, a = arc_limits(tuple(map(sub, end, start)), spec.a, spec.b, length, feed / 60.0, self.dyn.max_feed,
                          self.dyn.accel)
        planner = self.planner
        if planner.model == LOOKAHEAD:  # the centripetal acceleration the plane axes can give: v^2 <= a r
            v = min(v, math.sqrt(min(self.dyn.accel[spec.a], self.dyn.accel[spec.b]) * spec.radius))
        u_in, u_out = arc_tangents(start, end, spec, angle, length, self.n_axes)
        planner.add(length, v, a, self.exact if length > 0.0 else POSITIONING, u_in, u_out)
        canon.arc(start, end, spec, feed, src)


def _transformed_linear(kernel: NcKernel, motion: int, words, src: Src) -> None:
    """The straight move while a transformation is active: the general path, not the generated one."""
    kernel._general_move(motion, words, False, src)


def programmed_stop_line(kernel: NcKernel, src: Src, numbered: bool = True) -> str:
    """The operator's line for an M0 (the same in every dialect): where it stood, and whether the run ends
    there or goes on as after the operator's cycle start. ``numbered``: the block's N number is the user's
    (not one a compiler gave the block, as in a CL 800 object program)."""
    where = f"N{kernel.stop_block}" if numbered and kernel.stop_block is not None else f"line {src.line}"
    return f"M0 at {where}: programmed stop ({'run ends' if kernel.m0_stops else 'continued'})"
