"""The canonical machining interface: the only way motion leaves an interpreter.

As in LinuxCNC's ``canon.hh``, every interpreter (the DIN kernel, the CPL and
CL 800 / SINUMERIK front ends, the rw_SymPas card) calls these methods and
knows nothing about who listens. Sinks (toolpath recorder, trace, G-code
writer, cycle-time estimate, limit check, plot) subclass :class:`CanonSink`.

Positions are tuples with one float per machine axis, in axis order, in
*machine* coordinates (all offsets applied): what the machine really does.
``src`` is a :class:`Src` naming the file and physical line that caused the call.
"""

from __future__ import annotations

import inspect
from typing import NamedTuple

from ..records import FrozenRecord, Record


class Src(NamedTuple):
    """Where a canon call came from."""

    file: str
    line: int


class ArcSpec(FrozenRecord):
    """A circular (or helical) move in the plane spanned by axes ``a`` and ``b``.

    ``center`` is in machine coordinates of the plane axes; ``cw`` is the
    direction seen from the positive end of the plane normal, as in G2; ``turns``
    counts extra full circles (0 for an ordinary arc). Axes other than ``a`` and
    ``b`` move linearly from start to end (helix).
    """

    __slots__ = ("a", "b", "center", "cw", "radius", "turns")

    def __init__(self, a: int, b: int, center: tuple[float, float], cw: bool, radius: float, turns: int = 0):
        self.a = a
        self.b = b
        self.center = center
        self.cw = cw
        self.radius = radius
        self.turns = turns


class Frame(FrozenRecord):
    """What lies between the program's coordinates and the machine's, for the moves that follow (canon call
    :meth:`CanonSink.frame`, made when it changes, never per move).

    ``work_offset`` is the selected zero offset ("G54".."G59"; "G53" for a move programmed in machine
    coordinates; None when none is selected) and ``zero`` its values per axis; ``shift`` is what the control
    adds on top of it (G92, SINUMERIK programmable / external / DRF / PRESET offsets, CPL shifts);
    ``tool_length`` acts on axis ``tool_axis`` and came from tool offset number ``tool_offset`` (H or D
    word; 0: none); ``transformed`` tells that a coordinate transformation (rotation, scaling, mirroring)
    sits between the programmed position and the offsets. ``tool_kept``: a move in machine coordinates
    that keeps the tool length in force (SINUMERIK G53 / POS MSYS, CL 800 manual L4083; LinuxCNC's drops it).
    """

    __slots__ = ("work_offset", "zero", "shift", "tool_length", "tool_axis", "tool_offset", "transformed",
                 "tool_kept", "tool_subtracted")

    def __init__(self, work_offset: str | None, zero: tuple[float, ...], shift: tuple[float, ...],
                 tool_length: float = 0.0, tool_axis: int | None = None, tool_offset: int = 0,
                 transformed: bool = False, tool_kept: bool = False, tool_subtracted: bool = False):
        self.work_offset = work_offset
        self.zero = zero
        self.shift = shift
        self.tool_length = tool_length
        self.tool_axis = tool_axis
        self.tool_offset = tool_offset
        self.transformed = transformed
        self.tool_kept = tool_kept
        self.tool_subtracted = tool_subtracted  # G44: offset ``tool_offset``'s length taken off (tool_length < 0)

    def removed(self) -> tuple[float, ...]:
        """Per axis, what the work coordinates take off the machine's: the zero offset and the tool length
        (the shift and any transformation stay in them, as programmed moves of the program)."""
        out = list(self.zero)
        if self.tool_axis is not None:
            out[self.tool_axis] += self.tool_length
        return tuple(out)


def plain_frame(n_axes: int) -> Frame:
    """The frame of a run before any offset: work coordinates are the machine's."""
    return Frame(None, (0.0,) * n_axes, (0.0,) * n_axes)


class BatchArcs(Record):
    """The arcs among a :class:`MoveBatch`'s moves, as columns (all in one plane, the ``a``-``b`` plane).

    BatchArcs and MoveBatch are records, not dataclasses: every run's start-up imports them
    (ncvm/records.py)."""

    __slots__ = ("rows", "a", "b", "center", "cw", "radius", "angle", "length", "extent")

    def __init__(self, rows, a: int, b: int, center, cw, radius, angle, length, extent):
        self.rows = rows  # numpy int column: the batch row of each arc
        self.a = a
        self.b = b
        self.center = center  # numpy (arcs, 2), machine coordinates of the plane axes
        self.cw = cw  # numpy bool column
        self.radius = radius
        self.angle = angle  # sweep, radians (negative for G2)
        self.length = length
        self.extent = extent  # numpy (arcs, 4): lo_a, hi_a, lo_b, hi_b reached in the plane

    def spec(self, k: int) -> ArcSpec:
        """The :class:`ArcSpec` of arc ``k`` (built when a sink or a plot wants one)."""
        ca, cb = self.center[k].tolist()
        return ArcSpec(self.a, self.b, (ca, cb), bool(self.cw[k]), float(self.radius[k]))

    def specs(self) -> dict[int, ArcSpec]:
        """Batch row -> :class:`ArcSpec` of each arc."""
        return {row: self.spec(k) for k, row in enumerate(self.rows.tolist())}


class MoveBatch(Record):
    """Many consecutive moves in one call (a run of plain blocks executed column-wise).

    Row ``i`` is the move ``kind[i]`` (0 rapid, 1 straight feed, 2 arc) from
    ``start[i]`` to ``end[i]`` at ``feed[i]``; ``arcs`` describes the arcs among them.
    """

    __slots__ = ("kind", "start", "end", "feed", "file", "lines", "arcs")

    def __init__(self, kind, start, end, feed, file: str, lines, arcs: BatchArcs | None = None):
        self.kind = kind  # numpy int8 column
        self.start = start  # numpy (moves, axes)
        self.end = end
        self.feed = feed
        self.file = file
        self.lines = lines  # numpy int column: the physical line of each move's block
        self.arcs = arcs

    def __len__(self) -> int:
        return len(self.kind)


class CanonSink:
    """Receiver of canonical machining calls. Every method is a no-op here."""

    def begin(self, axis_names: tuple[str, ...], start: tuple[float, ...]) -> None:
        """Called once before the first move: the axes and the machine position at start."""

    def rapid(self, start: tuple, end: tuple, src: Src) -> None:
        """Positioning at rapid rate (G0)."""

    def feed(self, start: tuple, end: tuple, feed: float, src: Src) -> None:
        """Straight move at ``feed`` (mm/min)."""

    def arc(self, start: tuple, end: tuple, spec: ArcSpec, feed: float, src: Src) -> None:
        """Circular or helical move at ``feed`` (mm/min)."""

    def thread(self, start: tuple, end: tuple, lead: float, varying: bool, feed: float, src: Src) -> None:
        """Straight move in step with the spindle (G33-G35): ``lead`` the path distance per revolution (its
        mean where ``varying``, a G34/G35 lead that grows or shrinks), ``feed`` the mean path feed (mm/min).
        By default the straight move at that feed (:meth:`feed`): a path, a time, a limit check."""
        self.feed(start, end, feed, src)

    def move_batch(self, batch: MoveBatch) -> None:
        """Many moves at once; by default each is replayed as its :meth:`rapid`, :meth:`feed` or :meth:`arc` call."""
        starts, ends = batch.start.tolist(), batch.end.tolist()
        arcs = batch.arcs.specs() if batch.arcs is not None else {}
        rows = zip(batch.kind.tolist(), batch.feed.tolist(), batch.lines.tolist())
        for i, (kind, feed, line) in enumerate(rows):
            start, end, src = tuple(starts[i]), tuple(ends[i]), Src(batch.file, line)
            if kind == 0:
                self.rapid(start, end, src)
            elif kind == 1:
                self.feed(start, end, feed, src)
            else:
                self.arc(start, end, arcs[i], feed, src)

    def timing(self, times, entry, exit) -> None:
        """The path planner (:mod:`ncvm.nc.planner`) has timed the next moves, oldest first: sequences of
        their times (s) and entry and exit path speeds (mm/min), numpy columns or lists (:func:`floats`). Moves are timed in the order of their
        rapid, feed and arc calls (a straight move of length 0 is not timed: it takes no time), but a
        move may be timed before or after its call, as its look-ahead window completes. All three None:
        the moves from now on are timed by the front end's own model (the rw_SymPas card), not reported."""

    def frame(self, frame: Frame, src: Src | None) -> None:
        """The coordinate frame changed (zero offset selected or rewritten, tool length, shift, G53 move):
        the moves that follow are in ``frame``; their positions stay machine coordinates."""

    def frozen(self, what: str, src: Src | None, scenario: bool = False, warn: bool = False) -> None:
        """The run read an input from outside the program (``what`` names it: a key, a PLC input, a scenario
        event, a measured value, a random number): the path from here on may depend on it. ``scenario``: a
        machine input that only a scenario (``--scenario``) says; without one the run took its rest value.
        ``warn``: the path left the program's there (a move the machine's limit cut short): said as a warning too."""

    def tapping(self, g: int, src: Src) -> None:
        """The moves that follow, in and out of one hole, are tapping cycle ``g`` (G74/G84): the tap is fed in
        step with the spindle, which reverses at the bottom; they come as plain feed moves and spindle calls."""

    def programmed(self, axes: tuple[str, ...], src: Src) -> None:
        """The block at ``src`` programs the axis words ``axes`` for the move it makes next (also an axis whose
        programmed position equals where it stands): a writer of programs writes them, whatever moves."""

    def dwell(self, seconds: float, src: Src) -> None:
        """Wait with axes standing still."""

    def path_control(self, mode: str, tolerance: float | None, src: Src | None) -> None:
        """The path control the program selected (DIN G61/G64, SINUMERIK G60/G64/G9, CPL G61/G62): "exact"
        (every move ends at rest), "continuous" (moves blend; ``tolerance`` the programmed corner tolerance in
        mm, LinuxCNC's G64 P, None: none programmed) or "block" (the next move alone ends at rest: G09)."""

    def feed_per_rev(self, feed: float | None, src: Src | None) -> None:
        """Feed per revolution (G95): the F of the moves that follow is ``feed`` mm per spindle revolution (their
        ``feed`` is the path feed it gives, mm/min); None: feed per minute again (G94)."""

    def homing(self, axes: tuple[int, ...], src: Src) -> None:
        """The next move is a home search of ``axes`` (indices): the control's reference run, which makes the
        reference point the axis zero (the rw_SymPas card's JHL/JHR/JHI)."""

    def radius_compensation(self, g: int, radius: float, src: Src) -> None:
        """Cutter radius compensation ``g`` (41 left, 42 right of the contour) with ``radius`` starts: the moves
        that follow are the tool centre's path, the programmed contour offset by the radius."""

    def channel(self, number: int, src: Src | None) -> None:
        """The moves that follow are made by channel ``number``: one of the programs a control runs at the
        same time (the rw_SymPas card's CNC tasks)."""

    def tool_change(self, tool: int, src: Src) -> None:
        """Tool ``tool`` is now in the spindle."""

    def tool_select(self, tool: int, src: Src) -> None:
        """A T word without M6: tool ``tool`` selected (prepared; on some controls' PLC changed), as programmed."""

    def tool_offset(self, length: float, src: Src) -> None:
        """Active tool length compensation changed."""

    def spindle(self, speed: float, direction: int, src: Src) -> None:
        """Spindle: direction 1 clockwise (M3), -1 counter-clockwise (M4), 0 stopped (M5)."""

    def css_speed(self, speed: float, wanted: float, limit: float, src: Src | None) -> None:
        """G96 constant cutting speed gives the spindle a new ``speed`` (rev/min, told by :meth:`spindle` when it
        turns): the cutting speed at the radius here asks for ``wanted``, the spindle speed limit in force (G96 D,
        G92 S, the gear stage's maximum) is ``limit`` (inf: none), and ``speed`` is the smaller."""

    def coolant(self, mode: str, src: Src) -> None:
        """Coolant: "flood", "mist" or "off"."""

    def aux(self, code: str, src: Src) -> None:
        """An auxiliary function handed to the PLC (e.g. a machine-specific M function)."""

    def probe(self, trip: dict[str, float] | None, target: dict[str, float] | None, src: Src) -> None:
        """A probe move (LinuxCNC's STRAIGHT_PROBE: CPL G75/G275/G375, SINUMERIK MEAS M) follows, cut where
        the probe switches: ``trip`` is the latched machine position of each measured axis, None when the
        probe does not switch (the move reaches its target); ``target`` the machine end point the block
        programmed for its moving axes (where a probe search ends without contact), None for a measurement
        that does not stop at the probe's contact (on-the-fly measurement, a fixed stop)."""

    def message(self, text: str, src: Src) -> None:
        """An operator message (MSG, comment directed at the operator)."""

    def stop(self, kind: str, src: Src) -> None:
        """Program stop: "M0" (stop), "M1" (optional stop)."""

    def program_end(self, src: Src) -> None:
        """End of the main program (M2, M30, END)."""

    def end(self) -> None:
        """The run is over (normally or by a fault): flush files."""


def floats(column) -> list[float]:
    """A column of :meth:`CanonSink.timing` as a list of floats: the planner gives numpy columns for a large
    plan and lists for a few moves (no numpy)."""
    return column if isinstance(column, list) else column.tolist()


_METHODS = ("begin", "rapid", "feed", "arc", "thread", "move_batch", "timing", "frame", "frozen", "channel", "programmed", "tapping", "dwell",
            "path_control", "feed_per_rev", "radius_compensation", "homing",
            "tool_change", "tool_select", "tool_offset", "spindle", "css_speed", "coolant", "aux", "probe", "message", "stop", "program_end", "end")


class Canon:
    """Fans each canon call out to the sinks, then to the listeners, that override it.

    Sinks are given at construction (what a run records and writes); listeners are added and removed
    while it runs, by the controller parts that react to canon calls (a front end keeping the last
    message, a PLC answering M functions, a recorder of the moves of a block). A listener is a
    :class:`CanonSink` subclass that overrides the calls it cares about. Methods are bound when the
    set changes, so a call costs one Python call per interested receiver and nothing for the others.
    """

    def __init__(self, sinks: list[CanonSink]):
        self.sinks = list(sinks)
        self.listeners: list[CanonSink] = []
        self._bind(_METHODS)

    def add(self, listener: CanonSink) -> CanonSink:
        """Call ``listener``'s overridden canon methods after the sinks' (and earlier listeners'); returns it."""
        self.listeners.append(listener)
        self._bind(_names(listener))
        return listener

    def remove(self, listener: CanonSink) -> None:
        """Stop calling ``listener``."""
        self.listeners.remove(listener)
        self._bind(_names(listener))

    def _bind(self, names) -> None:
        receivers = self.sinks + self.listeners
        for name in names:
            bound = [getattr(s, name) for s in receivers if _overrides(s, name)]
            setattr(self, name, _fan_out(bound, name))


def _names(sink: CanonSink) -> list[str]:
    """The canon calls ``sink`` takes part in."""
    return [name for name in _METHODS if _overrides(sink, name)]


def _overrides(sink: CanonSink, name: str) -> bool:
    """Whether ``sink`` cares about canon call ``name`` (a batch of moves matters to any sink that takes moves)."""
    names = (("move_batch", "rapid", "feed", "arc") if name == "move_batch" else
             ("thread", "feed") if name == "thread" else (name,))  # a thread is a feed move to a feed sink
    return any(getattr(type(sink), n) is not getattr(CanonSink, n) for n in names)


def _two_maker(name: str):
    """``make(f, g)`` -> a function calling f then g with canon call ``name``'s parameters spelled out:
    no ``*args`` packing on the hot path (every move calls it). Compiled once per call name."""
    sig = [p for p in inspect.signature(getattr(CanonSink, name)).parameters.values() if p.name != "self"]
    params = ", ".join(p.name for p in sig)
    heads = ", ".join(p.name if p.default is p.empty else f"{p.name}={p.default!r}" for p in sig)
    namespace: dict = {}
    exec(f"def make(f, g):\n    def two({heads}):\n        f({params})\n        g({params})\n    return two\n",
         namespace)
    return namespace["make"]


_TWO: dict = {}  # the makers, compiled when a call name first has two sinks (start-up)


def _nothing(*args) -> None:
    return None


#: what a canon call that no sink or listener takes is bound to: ``canon.frame is NOBODY`` tells a front end
#: that it need not work out what it would tell
NOBODY = _nothing


def _fan_out(bound, name: str):
    if not bound:
        return _nothing
    if len(bound) == 1:
        return bound[0]
    if len(bound) == 2:
        make = _TWO.get(name) or _TWO.setdefault(name, _two_maker(name))
        return make(*bound)

    def many(*args):
        for f in bound:
            f(*args)

    return many
