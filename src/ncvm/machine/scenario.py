"""Scenario events: what happens to the machine over simulated time (``[[scenario]]`` tables), typed.

Each kind of event is one dataclass whose fields name its addressing: an input changes by the interface
bit's address (CPL), by byte and bit (SINUMERIK external input) or by axis and digital input (rw_SymPas),
and each is its own type, so a controller takes the forms it can use and refuses the others by name
(:func:`refuse`). spec.py declares the TOML form and checks it when the file is read (eventforms.py);
:func:`from_table` builds the events from the checked tables. :class:`EventQueue` (eventqueue.py) hands
them out in time order as simulated time reaches them.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, ClassVar

from .eventqueue import EventQueue, of_type, refuse  # noqa: F401 (what a controller takes, with the types)


@dataclass(frozen=True)
class Event:
    """Something that happens at ``time`` (s of simulated time from the start)."""

    time: float
    kind: ClassVar[str] = ""
    #: the addressing in words, for a controller's refusal
    form: ClassVar[str] = ""

    def said(self) -> str:
        """The event in the user's words (a translation's FROZEN mark), its time left to the caller."""
        return self.kind


@dataclass(frozen=True)
class InterfaceBit(Event):
    """CPL: the PLC interface bit ``address`` ("IC(bit,group,index)") gets ``value``."""

    address: str = ""
    value: bool = True
    kind: ClassVar[str] = "input"
    form: ClassVar[str] = "an input by address (CPL)"

    def said(self) -> str:
        return f"PLC input IC {self.address} = {int(self.value)}"


@dataclass(frozen=True)
class ExternalInput(Event):
    """SINUMERIK: external input ``byte`` (1, 2), ``bit`` (0-7) gets ``value``."""

    byte: int = 1
    bit: int = 0
    value: bool = True
    kind: ClassVar[str] = "input"
    form: ClassVar[str] = "an input by byte and bit (SINUMERIK)"

    def said(self) -> str:
        return f"external input {self.byte}.{self.bit} = {int(self.value)}"


@dataclass(frozen=True)
class AxisInput(Event):
    """rw_SymPas: digital input ``bit`` (1-32) of the axis ``axis`` gets ``value``."""

    axis: str = ""
    bit: int = 1
    value: bool = True
    kind: ClassVar[str] = "input"
    form: ClassVar[str] = "an input by axis and bit (rw_SymPas)"

    def said(self) -> str:
        return f"digital input {self.axis}.{self.bit} = {int(self.value)}"


@dataclass(frozen=True)
class ProbeSwitch(Event):
    """The probe on input ``input`` switches where the axes reach ``position`` (axis name, upper case ->
    machine coordinate); CPL writes the axes as keys of the event, SINUMERIK in a ``position`` table."""

    position: dict[str, float] = field(default_factory=dict)
    input: int = 1
    kind: ClassVar[str] = "probe"
    form: ClassVar[str] = "a probe event"

    def said(self) -> str:
        return f"probe input {self.input} switches at {_position(self.position)}"


@dataclass(frozen=True)
class FixedStop(Event):
    """CPL G375: the axes stop against a fixed stop at ``position`` (axis name -> machine coordinate)."""

    position: dict[str, float] = field(default_factory=dict)
    kind: ClassVar[str] = "fixed_stop"
    form: ClassVar[str] = "a fixed_stop event (CPL)"

    def said(self) -> str:
        return f"fixed stop at {_position(self.position)}"


@dataclass(frozen=True)
class SercosLock(Event):
    """CPL: the SERCOS service channel is locked (or free again) from now on."""

    locked: bool = True
    kind: ClassVar[str] = "sercos"
    form: ClassVar[str] = "a sercos event (CPL)"

    def said(self) -> str:
        return f"SERCOS service channel {'locked' if self.locked else 'free'}"


@dataclass(frozen=True)
class PlcChange(Event):
    """SINUMERIK: a PLC I/Q/P/F bit (``bit`` given) or whole byte changes."""

    plc: int = 1
    area: str = "I"
    byte: int = 0
    bit: int | None = None
    value: Any = None  # a bit: true/false; a byte: digit-coded number or bit-pattern string
    kind: ClassVar[str] = "plc"
    form: ClassVar[str] = "a plc event (SINUMERIK)"

    def said(self) -> str:
        where = f"{self.area}{self.byte}.{self.bit}" if self.bit is not None else f"{self.area}B{self.byte}"
        value = int(self.value) if isinstance(self.value, bool) else self.value
        return f"PLC {self.plc} {where} = {value}"


@dataclass(frozen=True)
class PlcTimer(Event):
    """SINUMERIK: the PLC program starts or resets a timer."""

    number: int = 0
    plc: int = 1
    action: str = "start"
    value: float | None = None
    base: float | None = None
    kind: ClassVar[str] = "timer"
    form: ClassVar[str] = "a timer event (SINUMERIK)"

    def said(self) -> str:
        return f"PLC {self.plc} timer T{self.number} {self.action}" + _value(self.value)


@dataclass(frozen=True)
class PlcCounter(Event):
    """SINUMERIK: the PLC program counts a counter up or down, sets or resets it."""

    number: int = 0
    plc: int = 1
    action: str = "up"
    value: int | None = None
    kind: ClassVar[str] = "counter"
    form: ClassVar[str] = "a counter event (SINUMERIK)"

    def said(self) -> str:
        return f"PLC {self.plc} counter C{self.number} {self.action}" + _value(self.value)


@dataclass(frozen=True)
class Alarm(Event):
    """SINUMERIK: NC alarm ``number`` becomes pending."""

    number: int = 0
    kind: ClassVar[str] = "alarm"
    form: ClassVar[str] = "an alarm event (SINUMERIK)"

    def said(self) -> str:
        return f"NC alarm {self.number} pending"


@dataclass(frozen=True)
class PositionError(Event):
    """rw_SymPas: the following error of an axis becomes ``value``."""

    axis: str = ""
    value: float = 0.0
    kind: ClassVar[str] = "poserr"
    form: ClassVar[str] = "a poserr event (rw_SymPas)"

    def said(self) -> str:
        return f"following error of {self.axis} = {self.value:g}"


@dataclass(frozen=True)
class CommonInteger(Event):
    """rw_SymPas: the common integer CI<index> becomes ``value``."""

    index: int = 0
    value: int = 0
    kind: ClassVar[str] = "ci"
    form: ClassVar[str] = "a ci event (rw_SymPas)"


# -- reading the checked tables ----------------------------------------------------------------
def _axes(table: dict) -> dict[str, float]:
    return {str(k).upper(): float(v) for k, v in table.items()}


def from_table(entry: dict) -> Event:
    """The typed event of one ``[[scenario]]`` table the schema has checked."""
    t, kind, d = float(entry["time"]), entry["kind"], entry
    if kind == "input":
        value = bool(d.get("value", True))
        if "address" in d:
            return InterfaceBit(t, str(d["address"]), value)
        if "axis" in d:
            return AxisInput(t, str(d["axis"]), int(d["bit"]), value)
        return ExternalInput(t, int(d.get("byte", 1)), int(d.get("bit", 0)), value)
    if kind == "probe":
        given = d.get("position", {k: v for k, v in d.items() if k not in ("time", "kind", "input")})
        return ProbeSwitch(t, _axes(given), int(d.get("input", 1)))
    if kind == "fixed_stop":
        return FixedStop(t, _axes({k: v for k, v in d.items() if k not in ("time", "kind")}))
    if kind == "sercos":
        return SercosLock(t, bool(d.get("locked", True)))
    if kind == "plc":
        return PlcChange(t, int(d.get("plc", 1)), str(d.get("area", "I")).upper(), int(d.get("byte", 0)),
                         int(d["bit"]) if "bit" in d else None, d.get("value"))
    if kind == "timer":
        return PlcTimer(t, int(d["number"]), int(d.get("plc", 1)), str(d.get("action", "start")),
                        d.get("value"), d.get("base"))
    if kind == "counter":
        return PlcCounter(t, int(d["number"]), int(d.get("plc", 1)), str(d.get("action", "up")), d.get("value"))
    if kind == "alarm":
        return Alarm(t, int(d["number"]))
    if kind == "poserr":
        return PositionError(t, str(d["axis"]), float(d.get("value", 0.0)))
    if kind == "ci":
        return CommonInteger(t, int(d.get("index", 0)), int(d.get("value", 0)))
    raise ValueError(f"scenario kind {kind!r} has no event type")  # spec.py admits only the kinds above


def from_tables(entries: list[dict]) -> list[Event]:
    """The events of a machine or scenario file, in time order (events at the same time as written)."""
    return sorted((from_table(e) for e in entries), key=lambda e: e.time)


def _position(position: dict[str, float]) -> str:
    return " ".join(f"{axis}{value:g}" for axis, value in position.items())


def _value(value) -> str:
    return "" if value is None else f" {value:g}"
