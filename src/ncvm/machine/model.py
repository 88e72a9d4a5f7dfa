"""The simulated controller's state, as plain data.

Everything a program can read or change about "the machine" lives here:
axes with their soft limits and dynamics, zero-offset tables, the tool table,
machine data and setting data, the PLC image, alarms and the simulated clock.
Dialects read and write it through these objects only; the SQLite store
(:mod:`ncvm.machine.store`) keeps what the control would keep permanently.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Any

from ..records import Record
from .files import find_in

if TYPE_CHECKING:  # the events are read only when a machine file or --scenario has some (start-up, issue 18)
    from .scenario import Event


class Axis(Record):
    """One machine axis. Feeds and rapids in mm/min (deg/min rotary), acceleration in mm/s^2.

    Axis, Tool, MotionData and PlcImage are records rather than dataclasses: every run's start-up imports
    them (ncvm/records.py)."""

    __slots__ = ("name", "kind", "min", "max", "rapid", "max_feed", "accel")

    def __init__(self, name: str, kind: str = "linear", min: float = -1.0e9, max: float = 1.0e9,
                 rapid: float = 10000.0, max_feed: float = 5000.0, accel: float = 1000.0):
        self.name = name
        self.kind = kind  # "linear" or "rotary"
        self.min = min
        self.max = max
        self.rapid = rapid
        self.max_feed = max_feed
        self.accel = accel

    @property
    def rotary(self) -> bool:
        return self.kind == "rotary"


class Tool(Record):
    __slots__ = ("number", "length", "radius", "name")

    def __init__(self, number: int, length: float = 0.0, radius: float = 0.0, name: str = ""):
        self.number = number
        self.length = length
        self.radius = radius
        self.name = name


class SimClock:
    """Simulated time in seconds. Programs never see the wall clock, so runs repeat exactly.

    Moves wait untimed in the path planner (:mod:`ncvm.nc.planner`) until their look-ahead window is
    complete. Reading or setting ``now`` first calls ``pending`` (the planner's exact stop), so nothing
    ever reads a time a later block could change; ``settled`` is the time without that flush (a shadow
    kernel's start, the planner's own bookkeeping).
    """

    __slots__ = ("settled", "start_epoch", "pending")

    def __init__(self, now: float = 0.0, start_epoch: float = 1_700_000_000.0):
        self.settled = now
        self.start_epoch = start_epoch  # the controller's calendar at power-on (machine file: clock.start)
        self.pending = None  # called before ``now`` is read or set: times the moves still waiting

    @property
    def now(self) -> float:
        if self.pending is not None:
            self.pending()
        return self.settled

    @now.setter
    def now(self, value: float) -> None:
        if self.pending is not None:
            self.pending()
        self.settled = value

    def settle(self, now: float) -> None:
        """The planner has timed moves up to ``now``."""
        self.settled = now

    def advance(self, seconds: float) -> None:
        if seconds > 0.0:
            if self.pending is not None:
                self.pending()  # as ``now += seconds``, whose setter's second call finds nothing waiting
            self.settled += seconds

    def __repr__(self) -> str:
        return f"SimClock(now={self.settled!r}, start_epoch={self.start_epoch!r})"


class MotionData(Record):
    """The path control's machine data (machine file ``[motion]``): how move times are planned."""

    __slots__ = ("model", "lookahead", "corner_tolerance", "tool_change_time")

    def __init__(self, model: str = "lookahead", lookahead: int = 100, corner_tolerance: float = 0.02,
                 tool_change_time: float = 0.0):
        self.model = model  # "lookahead" (blocks blended in continuous-path mode) or "rest-to-rest"
        self.lookahead = lookahead  # blocks the control looks ahead (its block buffer)
        self.corner_tolerance = corner_tolerance  # mm a blended corner may deviate from the programmed corner
        self.tool_change_time = tool_change_time  # s an M6 tool change takes


class PlcImage(Record):
    """PLC interface image: inputs, outputs, flags (markers) and data words, by address."""

    __slots__ = ("inputs", "outputs", "flags", "words")

    def __init__(self, inputs: dict[str, Any] | None = None, outputs: dict[str, Any] | None = None,
                 flags: dict[str, Any] | None = None, words: dict[str, Any] | None = None):
        self.inputs = {} if inputs is None else inputs
        self.outputs = {} if outputs is None else outputs
        self.flags = {} if flags is None else flags
        self.words = {} if words is None else words


class Machine(Record):
    """A simulated controller: the data a real control holds about its machine. A record (``records.replace``
    makes a changed copy), not a dataclass: every run builds one at start-up."""

    __slots__ = ("name", "axes", "offsets", "tools", "machine_data", "setting_data", "plc", "alarms", "clock",
                 "motion", "start_position", "program_path", "file_root", "file_root_origin", "scenario", "sections", "source")

    def __init__(self, name: str = "machine", axes: list[Axis] | None = None,
                 offsets: dict[str, list[float]] | None = None, tools: dict[int, Tool] | None = None,
                 machine_data: dict[str, Any] | None = None, setting_data: dict[str, Any] | None = None,
                 plc: PlcImage | None = None, alarms: list[str] | None = None, clock: SimClock | None = None,
                 motion: MotionData | None = None, start_position: list[float] | None = None,
                 program_path: list[Path] | None = None, file_root: Path = Path("files"),
                 file_root_origin: Path | None = None,
                 scenario: list[Event] | None = None, sections: dict[str, Any] | None = None,
                 source: str = "<built-in>"):
        self.name = name
        self.axes = [] if axes is None else axes
        #: zero offsets by name ("G54".."G59" and dialect-specific tables), one value per axis
        self.offsets = {} if offsets is None else offsets
        self.tools = {} if tools is None else tools
        self.machine_data = {} if machine_data is None else machine_data
        self.setting_data = {} if setting_data is None else setting_data
        self.plc = PlcImage() if plc is None else plc
        self.alarms = [] if alarms is None else alarms
        self.clock = SimClock() if clock is None else clock
        self.motion = MotionData() if motion is None else motion
        self.start_position = start_position
        self.program_path = [Path(".")] if program_path is None else program_path
        self.file_root = file_root
        #: the controller's file root that ``file_root`` is a scratch copy of (``ncvm translate``), else None
        self.file_root_origin = file_root_origin
        self.scenario = [] if scenario is None else scenario
        #: raw TOML tables of dialect-specific sections ([cpl], [sin800], [sympas], ...)
        self.sections = {} if sections is None else sections
        self.source = source

    # -- derived lookups -------------------------------------------------
    @property
    def axis_names(self) -> tuple[str, ...]:
        return tuple(a.name for a in self.axes)

    def offset(self, table: str) -> list[float]:
        """The zero offset ``table`` (e.g. "G54"), zeros when the machine file leaves it out."""
        return self.offsets.setdefault(table, [0.0] * len(self.axes))

    def own_files(self) -> tuple[Path, ...]:
        """The machine file this machine was read from (none for the built-in machine): a program may not
        reach it even when the file root is its folder."""
        p = Path(self.source)
        return (p.absolute(),) if p.is_file() else ()

    def find_program(self, name: str, extensions: tuple[str, ...] = (), ignore_case: bool = True,
                     private: tuple[Path, ...] = ()) -> Path | None:
        """Search the program path for ``name`` as written, then with each extension (and, unless the
        control tells upper from lower case, in any case), each folder confining the name as a file
        root does (:func:`files.find_in`). ``private``: folders (the state directory) a name may not
        reach even inside a program folder."""
        candidates = [name] + [name + ext for ext in extensions if not name.lower().endswith(ext.lower())]
        return find_in(self.program_path, candidates, ignore_case, private)
