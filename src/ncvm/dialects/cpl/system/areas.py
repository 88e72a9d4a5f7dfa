"""Work areas and dead ranges (manual §4.9 L2266-2275, SD group 200) checked against the motion.

The areas are machine data (`[cpl] areas`): rectangles on two axes of the channel, a centre and an
extension per axis, in machine coordinates and mm. The active ones become a zone check of the run, so a
move that enters an active dead range or leaves an active work area is reported among the limit
violations, like a soft-limit violation (docs/decisions.md).
"""

from __future__ import annotations

from ....sinks.areas import DEAD, WORK, zone_check
from .controller import AREA_TYPES

KINDS = {AREA_TYPES["dead"]: DEAD, AREA_TYPES["work"]: WORK}


def setup(rt) -> None:
    """At program start: the active areas of the channel watch the recorded moves."""
    active = [(i, KINDS[a["type"]], a["axes"], a["centre"], a["extent"])
              for i, a in enumerate(rt.ctl.areas, 1) if a["active"]]
    if active:
        session = rt.session
        session.limit_checks.append(zone_check(active, rt.kernel.axis_names, session.recorder))
