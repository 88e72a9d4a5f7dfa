"""The channel's probe inputs 1 and 2 as MEAS M (@720, L4357-4396) sees them.

A probe switches when the scenario says so (a ``ProbeSwitch`` event of machine/scenario.py, with the
machine positions of the axes at the trigger point); a switch the NC has not used yet stays latched until
a MEAS M takes it. Where on the block's path it switches is nc/probe.py's ``trip_on_path``.
"""

from __future__ import annotations

from collections.abc import Callable

from ...diagnostics import RuntimeFault
from ...machine.scenario import EventQueue, ProbeSwitch
from ...nc.probe import OffPath, trip_on_path


class Probe:
    """Latched probe switches; ``scenario`` is the channel's queue of scenario events still to come."""

    def __init__(self, scenario: EventQueue, advance_scenario: Callable[[], None]):
        self._scenario = scenario
        self.advance_scenario = advance_scenario
        self.probes: list[ProbeSwitch] = []  # probe events whose time has come, not yet used by MEAS M

    def hit(self, probe: int) -> ProbeSwitch:
        """The next switch of input ``probe``: latched already, or the first the scenario has for it."""
        self.advance_scenario()
        ev = self._scenario.take(lambda e: e.__class__ is ProbeSwitch and e.input == probe)
        if ev is not None:
            self.probes.append(ev)
        hits = [p for p in self.probes if p.input == probe]
        if not hits:
            raise RuntimeFault("SIN007", f"MEAS M: probe {probe} never switches (no probe event in the scenario)")
        hit = hits[0]
        self.probes.remove(hit)
        return hit

    @staticmethod
    def trigger_point(hit: ProbeSwitch, start: dict, end: dict) -> dict:
        """Machine positions of the traversing axes when the probe switches (nc/probe.py)."""
        try:
            return trip_on_path(hit.position, start, end)
        except OffPath as e:
            raise RuntimeFault("SIN007", f"MEAS M: {e}") from None
