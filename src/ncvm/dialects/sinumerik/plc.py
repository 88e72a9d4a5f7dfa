"""PLC timers and counters (PLCT @3a4, PLCC @3a5; manual L2849-2866, L4972-4974): running in simulated time.

The manual gives only the reads; the model is that of a SIMATIC S5 PLC, whose data (blocks DB/DX, data
words, flags) the manual's PLC statements address. An S5 timer holds a time value of up to 999 units of
a time base (0.01, 0.1, 1 or 10 s); once started it counts down one unit per time base until 0. PLCT
reads it "as a value in seconds with 2 digits after the decimal point". An S5 counter holds 0-999 and
counts up or down by one on each rising edge at its count inputs, or is set to a preset value. The NC
program has no statement that writes a timer or a counter. What starts and counts them is the PLC
program, which is not simulated: the machine file says which events drive each one (an M function the
NC outputs to the PLC, a rising edge of a PLC I/Q/F bit), and the scenario can drive them at given times
(docs/sin800.md, docs/decisions.md).
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass

from ...diagnostics import UsageError

TIME_BASES = (0.01, 0.1, 1.0, 10.0)
MAX_UNITS = 999  # 3 decades of the S5 time value and counter value
TIMER_ACTIONS = ("start", "reset")
TIMER_KEYS = (*TIMER_ACTIONS, "value", "base", "done")
COUNTER_ACTIONS = ("up", "down", "set", "reset")
_TRIGGER = re.compile(r"^(?:M(\d+)|([IQF])(\d+)\.([0-7]))$")


def time_value(where: str, seconds, base=None) -> tuple[int, float]:
    """(units, time base) of a time in seconds: the given base, else the finest base that holds it in
    999 units. A time that is not a whole number of units of its base cannot be loaded into an S5 timer."""
    if isinstance(seconds, bool) or not isinstance(seconds, (int, float)) or seconds < 0:
        raise UsageError(f"{where}: a timer value must be a number of seconds >= 0")
    if base is not None and (isinstance(base, bool) or float(base) not in TIME_BASES):
        raise UsageError(f"{where}: the time base must be 0.01, 0.1, 1 or 10 (seconds)")
    bases = (float(base),) if base is not None else TIME_BASES
    for b in bases:
        units = seconds / b
        if units <= MAX_UNITS + 1e-9:
            n = round(units)
            if abs(units - n) > 1e-6:
                raise UsageError(f"{where}: {seconds:g} s is not a whole number of {b:g} s units")
            return n, b
    raise UsageError(f"{where}: {seconds:g} s exceeds {MAX_UNITS} units of the time base "
                     f"({MAX_UNITS * bases[-1]:g} s)")


@dataclass
class Timer:
    """An S5 timer: ``units`` of ``base`` seconds, counting down from ``started`` (None: standing)."""

    units: int = 0
    base: float = 0.01
    started: float | None = None
    load: tuple[int, float] | None = None  # the time value a start trigger loads
    done: tuple[str, int, int] | None = None  # the PLC bit (area, byte, bit) set when the time has run out
    signalled: bool = False  # the done bit of this run has been set

    def expiry(self) -> float | None:
        """When a running timer reaches 0 and its done bit is still to be set."""
        if self.started is None or self.done is None or self.signalled:
            return None
        return self.started + self.units * self.base

    def seconds(self, now: float) -> float:
        """Remaining time at ``now``: one unit less per elapsed time base, at least 0."""
        units = self.units
        if self.started is not None:
            units = max(0, units - math.floor((now - self.started) / self.base + 1e-9))
        return round(units * self.base, 2)

    def start(self, now: float, value: tuple[int, float] | None = None) -> None:
        self.units, self.base = value or self.load or (self.units, self.base)
        self.started = now
        self.signalled = False

    def reset(self) -> None:
        self.units, self.started = 0, None


@dataclass
class Counter:
    """An S5 counter: 0-999; counting beyond the limits leaves it at 999 or 0."""

    value: int = 0
    preset: int = 0  # the value a set trigger loads

    def act(self, action: str, value: int | None = None) -> None:
        if action == "up":
            self.value = min(MAX_UNITS, self.value + 1)
        elif action == "down":
            self.value = max(0, self.value - 1)
        elif action == "set":
            self.value = self.preset if value is None else value
        else:
            self.value = 0


class PlcClock:
    """Timers and counters of the PLCs, and the events that drive them."""

    def __init__(self, where: str, plcs: dict[int, dict]):
        self.timers: dict[tuple[int, int], Timer] = {}
        self.counters: dict[tuple[int, int], Counter] = {}
        self.triggers: dict[tuple, list[tuple[str, tuple[int, int], str]]] = {}
        #: (plc, area, byte, bit, value, time) -> None: sets a PLC bit (the channel's, with edge detection)
        self.write_bit = None
        self.timed_bits = False  # some timer has a done bit (else expire() has nothing to do)
        for plc, areas in plcs.items():
            for number, seconds in areas.get("T", {}).items():
                units, base = time_value(f"{where}.plc.{plc}.T.{number}", seconds)
                self.timers[(plc, _number(where, number))] = Timer(units, base)
            for number, value in areas.get("C", {}).items():
                self.counters[(plc, _number(where, number))] = Counter(_count(f"{where}.plc.{plc}.C.{number}",
                                                                              value))
            for number, spec in areas.get("TIMERS", {}).items():
                self._wire(f"{where}.plc.{plc}.timers.{number}", "T", (plc, _number(where, number)), spec)
            for number, spec in areas.get("COUNTERS", {}).items():
                self._wire(f"{where}.plc.{plc}.counters.{number}", "C", (plc, _number(where, number)), spec)

    def _wire(self, where: str, kind: str, key: tuple[int, int], spec) -> None:
        actions = TIMER_ACTIONS if kind == "T" else COUNTER_ACTIONS
        if not isinstance(spec, dict):
            raise UsageError(f"{where}: must be a table like {{ {actions[0]} = \"M71\" }}")
        known = TIMER_KEYS if kind == "T" else (*actions, "value")
        for name in spec:
            if name not in known:
                raise UsageError(f"{where}: unknown key '{name}' (known: {', '.join(known)})")
        if kind == "T":
            timer = self.timers.setdefault(key, Timer())
            if "value" in spec:
                timer.load = time_value(f"{where}.value", spec["value"], spec.get("base"))
            elif "start" in spec:
                raise UsageError(f"{where}: a timer started by '{spec['start']}' needs the time 'value' it loads")
            if "done" in spec:
                area, _plc, bit = _trigger(f"{where}.done", key[0], spec["done"])
                if area not in ("Q", "F"):
                    raise UsageError(f"{where}.done: '{spec['done']}' is not an output or flag bit (Q4.0, F20.0)")
                byte, bit = bit.split(".")
                timer.done = (area, int(byte), int(bit))
                self.timed_bits = True
        else:
            counter = self.counters.setdefault(key, Counter())
            if "value" in spec:
                counter.preset = _count(f"{where}.value", spec["value"])
        for action in actions:
            if action in spec:
                self.triggers.setdefault(_trigger(f"{where}.{action}", key[0], spec[action]), []).append(
                    (kind, key, action))

    # -- reads (@3a4, @3a5) ------------------------------------------------
    def timer_seconds(self, plc: int, number: int, now: float) -> float:
        timer = self.timers.get((plc, number))
        return timer.seconds(now) if timer else 0.0

    def counter_value(self, plc: int, number: int) -> float:
        counter = self.counters.get((plc, number))
        return float(counter.value) if counter else 0.0

    # -- events ------------------------------------------------------------
    def m_function(self, code: str, now: float) -> None:
        """The NC outputs an M function to the PLC: the timers and counters wired to it act."""
        for trigger in [t for t in self.triggers if t[0] == "M" and t[2] == code]:
            self._fire(trigger, now)

    def byte_changed(self, plc: int, area: str, byte: int, old: int, new: int, now: float) -> None:
        """A PLC byte changed: rising edges of wired bits drive their timers and counters."""
        rising = new & ~old
        if not rising:
            return
        for bit in range(8):
            if rising >> bit & 1:
                self._fire((area, plc, f"{byte}.{bit}"), now)

    def expire(self, until: float) -> None:
        """Set the done bits of timers that have run out by ``until``, earliest first (a done bit may start
        or count others)."""
        while self.timed_bits:
            due = [(when, key) for key, t in self.timers.items()
                   if (when := t.expiry()) is not None and when <= until + 1e-9]
            if not due:
                return
            when, key = min(due)
            timer = self.timers[key]
            timer.signalled = True
            self.write_bit(key[0], *timer.done, 1, when)

    def _fire(self, trigger: tuple, now: float) -> None:
        for kind, key, action in self.triggers.get(trigger, ()):
            self.act(kind, key, action, None, now)

    def act(self, kind: str, key: tuple[int, int], action: str, value, now: float) -> None:
        if kind == "T":
            timer = self.timers.setdefault(key, Timer())
            if action == "start":
                timer.start(now, value)
            else:
                timer.reset()
            if timer.done is not None:  # 0 from the start or reset until the time has run out
                self.write_bit(key[0], *timer.done, 0, now)
        else:
            self.counters.setdefault(key, Counter()).act(action, value)

    def parse_event(self, ev) -> tuple:
        """A ``[[scenario]]`` timer or counter event (PlcTimer, PlcCounter; the machine file's schema has
        checked its keys) as (kind, key, action, value) for :meth:`act` (with the event's time): the PLC
        program acts at that time."""
        where = f"scenario {ev.kind} event at {ev.time:g} s"
        timer = ev.kind == "timer"
        key = (ev.plc, ev.number)
        value = None
        if ev.value is not None and ev.action in ("start", "set"):
            value = time_value(where, ev.value, ev.base) if timer else _count(where, ev.value)
        elif ev.action == "start" and self.timers.get(key, Timer()).load is None:
            raise UsageError(f"{where}: starting timer {key[1]} needs the time 'value' it loads")
        return ("T" if timer else "C"), key, ev.action, value


def _number(where: str, number) -> int:
    try:
        n = int(str(number))
    except ValueError:
        n = -1
    if not 0 <= n <= 255:
        raise UsageError(f"{where}: timer/counter number '{number}' is not 0-255")
    return n


def _count(where: str, value) -> int:
    if isinstance(value, bool) or not isinstance(value, (int, float)) or value != int(value) \
            or not 0 <= value <= MAX_UNITS:
        raise UsageError(f"{where}: a counter value must be a whole number 0-{MAX_UNITS}")
    return int(value)


def _trigger(where: str, plc: int, text) -> tuple:
    """"M71" -> ("M", plc, "M71"); "I1.2" -> ("I", plc, "1.2")."""
    m = _TRIGGER.match(str(text).strip().upper())
    if m is None:
        raise UsageError(f"{where}: '{text}' is not an M function (M71) or a PLC bit (I1.2, Q4.0, F10.7)")
    if m.group(1) is not None:
        return "M", plc, f"M{int(m.group(1))}"
    byte = int(m.group(3))
    if byte > (255 if m.group(2) == "F" else 127):
        raise UsageError(f"{where}: byte {byte} outside the PLC's {m.group(2)} bytes")
    return m.group(2), plc, f"{byte}.{m.group(4)}"
