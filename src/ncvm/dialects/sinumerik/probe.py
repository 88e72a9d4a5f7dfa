"""The channel's probe inputs 1 and 2 as MEAS M (@720, L4357-4396) sees them.

A probe switches when the scenario says so (``[[scenario]]`` kind "probe", with the machine positions of
the axes at the trigger point); a switch the NC has not used yet stays latched until a MEAS M takes it.
"""

from __future__ import annotations

from collections.abc import Callable

from ...diagnostics import RuntimeFault


class Probe:
    """Latched probe switches; ``_scenario`` is the channel's list of scenario events still to come."""

    def __init__(self, scenario: list, advance_scenario: Callable[[], None]):
        self._scenario = scenario
        self.advance_scenario = advance_scenario
        self.probes: list[dict] = []

    def hit(self, probe: int) -> dict:
        """The next switch of input ``probe``: latched already, or the first the scenario has for it."""
        self.advance_scenario()
        for i, ev in enumerate(self._scenario):
            if ev.kind == "probe" and int(ev.data.get("input", 1)) == probe:
                self._scenario.pop(i)
                self.probes.append(ev.data)
                break
        hits = [p for p in self.probes if int(p.get("input", 1)) == probe]
        if not hits:
            raise RuntimeFault("SIN007", f"MEAS M: probe {probe} never switches (no probe event in the scenario)")
        hit = hits[0]
        self.probes.remove(hit)
        return hit

    @staticmethod
    def trigger_point(hit: dict, start: dict, end: dict) -> dict:
        """Machine positions of the traversing axes when the probe switches: those the probe event gives;
        the others on the block's straight path at the point the given ones locate."""
        pos = {n: float(v) for n, v in hit.get("position", {}).items() if n in start}
        known = next((n for n in pos if abs(end[n] - start[n]) > 1e-12), None)
        out = {}
        for name in start:
            if name in pos:
                out[name] = pos[name]
            elif known is None:
                raise RuntimeFault("SIN007", f"MEAS M: the probe event gives no position for axis {name}")
            else:
                t = (pos[known] - start[known]) / (end[known] - start[known])
                if not -1e-9 <= t <= 1.0 + 1e-9:
                    raise RuntimeFault("SIN007", f"MEAS M: the probe position {known} = {pos[known]:g} is not on "
                                                 f"the block's path ({start[known]:g} to {end[known]:g})")
                out[name] = start[name] + t * (end[name] - start[name])
        return out
