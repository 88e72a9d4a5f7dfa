"""Work areas and dead ranges (manual §4.9 L2266-2275, SD group 200) checked against the motion.

The areas are machine data (`[cpl] areas`): rectangles on two axes of the channel, a centre and an
extension per axis, in machine coordinates and mm. The active ones are registered with the run's checks
as protection zones (runtime/checks.py), so a move that enters an active dead range or leaves an active
work area is reported among the limit violations, like a soft-limit violation (docs/decisions.md).
"""

from __future__ import annotations

from ....runtime.checks import DEAD, WORK, Area
from .controller import AREA_TYPES

KINDS = {AREA_TYPES["dead"]: DEAD, AREA_TYPES["work"]: WORK}


def setup(rt) -> None:
    """At program start: the active areas of the channel watch the recorded moves."""
    active = [Area(i, KINDS[a["type"]], tuple(a["axes"]), tuple(a["centre"]), tuple(a["extent"]))
              for i, a in enumerate(rt.ctl.areas, 1) if a["active"]]
    rt.session.checks.add_areas(active, rt.kernel.axis_names)
