"""What a controller takes of a scenario: the events of the types it uses (:func:`refuse` names any other),
handed out in time order by an :class:`EventQueue`.

Apart from the event types (scenario.py), so that a controller whose machine has no scenario events
imports none of them (start-up, issue 18).
"""

from __future__ import annotations

import bisect
from typing import TYPE_CHECKING, Iterator

from ..diagnostics import UsageError

if TYPE_CHECKING:
    from .scenario import Event


def refuse(events: list[Event], takes: tuple[type, ...], control: str) -> None:
    """Raise a usage error naming the first event of a type ``control`` cannot use: no event of the
    machine file is silently ignored."""
    for ev in events:
        if not isinstance(ev, takes):
            forms = ", ".join(dict.fromkeys(t.form for t in takes)) or "none"
            raise UsageError(f"scenario event at {ev.time:g} s: {ev.form}, which the {control} cannot use "
                             f"(scenario events it takes: {forms})")


def of_type(events: list[Event], *types: type) -> list[Event]:
    return [e for e in events if isinstance(e, types)]


class EventQueue:
    """Events in time order, handed out when simulated time reaches them (:meth:`due`); an event may also
    be taken out ahead of its time (:meth:`take`: the next probe event a measuring block uses)."""

    __slots__ = ("_events", "_times")

    def __init__(self, events: list[Event] = ()):
        self._events = sorted(events, key=lambda e: e.time)
        self._times = [e.time for e in self._events]

    def __bool__(self) -> bool:
        return bool(self._events)

    def __len__(self) -> int:
        return len(self._events)

    def __iter__(self) -> Iterator[Event]:
        """The events still to come, in time order (they stay queued)."""
        return iter(list(self._events))

    def next_time(self) -> float | None:
        """When the next event happens; None when none is left."""
        return self._times[0] if self._times else None

    def due(self, now: float) -> Iterator[Event]:
        """Pop the events whose time has come (time <= ``now``), in order; one at a time, so an event's
        effect may look at the queue."""
        while self._times and self._times[0] <= now:
            self._times.pop(0)
            yield self._events.pop(0)

    def pop(self) -> Event:
        """Remove and return the next event (the queue must not be empty)."""
        self._times.pop(0)
        return self._events.pop(0)

    def take(self, match) -> Event | None:
        """Remove and return the first queued event ``match(event)`` accepts, whatever its time."""
        for i, ev in enumerate(self._events):
            if match(ev):
                del self._events[i], self._times[i]
                return ev
        return None

    def push(self, ev: Event) -> None:
        i = bisect.bisect_right(self._times, ev.time)
        self._times.insert(i, ev.time)
        self._events.insert(i, ev)
