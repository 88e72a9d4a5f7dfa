"""The channel's axes and plane as @ code sees them: axis numbers, G16, and the actual-value reads ACPW,
ACPM/ACP, ACAS and ACG (planning guide ch.10, L6549-6556).

Positions and the G state are the kernel's *executed* state (the manual asks for STOP DEC before
reading them in the own channel, L2618-2734).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from ...nc import cutter
from ...nc.kernel import PLANES
from ...nc.profiles.sinumerik8xx import SINUMERIK8XX
from .errors import Cl800Error
from .feeds import active_group_11
from .ncdata import in_range as _rng
from .spindle import MASTER_SPINDLE

if TYPE_CHECKING:
    from .runtime import Channel

#: G group -> its G functions in the order of the table (ACG, @36b; nc/profiles/sinumerik8xx.py)
ACG_GROUPS: dict[int, tuple] = {}
for _row in SINUMERIK8XX.rows:
    if _row.group:
        ACG_GROUPS[int(_row.group)] = ACG_GROUPS.get(int(_row.group), ()) + (_row.g,)


def axis_index(kernel, v: float) -> int:
    """Axis number 1..n (manual: 1-24 on the 880) -> axis index."""
    return _rng("axis number", v, 1, kernel.n_axes) - 1


#: the axis numbers (1st, 2nd) of the planes G17-G19
_PLANE_OF_AXES = {(1, 2): 17, (3, 1): 18, (2, 3): 19}


class Positions:
    """The plane G16 selects and the reads of positions and G functions."""

    def __init__(self, channel: Channel):
        self.channel = channel
        self.kernel = channel.kernel
        self.g16_plane: tuple[int, int, int] | None = None  # axis numbers of the G16 plane
        self.g16_minus = (False, False, False)  # G16 with a minus sign before the axis

    def axis_name(self, v: float, line: int) -> str:
        return self.kernel.axis_names[axis_index(self.kernel, v)]

    def centre_name(self, v: float, line: int) -> str:
        name = self.axis_name(v, line)
        centre = {"X": "I", "Y": "J", "Z": "K"}.get(name)
        if centre is None:
            raise Cl800Error(f"PRIP: axis {name} has no interpolation parameter")
        return centre

    def g16(self, letters: list, line: int) -> None:
        self.channel.run_buffer()
        axes = []
        minus = []
        for name, neg in letters:
            if name not in self.kernel.axis_of:
                raise Cl800Error(f"G16: {name} is not an axis")
            axes.append(self.kernel.axis_of[name] + 1)
            minus.append(neg)
        if len(axes) < 2:
            raise Cl800Error("G16 needs at least two axes")
        while len(axes) < 3:
            axes.append(0)
        while len(minus) < 3:
            minus.append(False)
        self.g16_plane = tuple(axes[:3])
        self.g16_minus = tuple(minus[:3])
        self._select_plane(axes[0], axes[1], [name for name, _ in letters[:2]])

    def _select_plane(self, h: int, v: int, names: list[str]) -> None:
        """The plane of G16's 1st (horizontal) and 2nd (vertical) axis (L2679-2680, L4146-4147): that of
        G17-G19 with the same axes, seen mirrored where they come in the other order (G16 X Z is G18's Z-X
        plane: its G2 turns as G18's G3); a plane of other axes has no circles in ncvm (refused at the arc)."""
        k = self.kernel
        plane = _PLANE_OF_AXES.get((h, v)) or _PLANE_OF_AXES.get((v, h))
        k.plane_mirrored = plane is not None and (h, v) not in _PLANE_OF_AXES
        k.plane_unknown = None if plane else "G16 " + " ".join(names)
        if plane:
            k.plane = plane

    def plane_axes(self) -> tuple[str, str]:
        """The first and second axis of the active plane (G16 or G17-G19)."""
        k = self.kernel
        if self.g16_plane:
            h, v = self.g16_plane[0], self.g16_plane[1]
            return k.axis_names[h - 1], k.axis_names[v - 1]
        a, b = PLANES[k.plane][:2]
        return a, b

    def acpw(self, code: str, args: tuple) -> float:
        """ACPW (@360): the actual position in the workpiece system."""
        k = self.kernel
        return k.workpiece_position()[k.axis_names[axis_index(k, args[0])]]

    def acp(self, code: str, args: tuple):
        """ACPM / ACP (@361/@362): the machine position; of a rotary axis the angle and the turns."""
        i = axis_index(self.kernel, args[0])
        pos = self.kernel.machine_pos[i] / self.kernel.scale
        if self.channel.session.machine.axes[i].rotary:
            return [pos % 360.0, float(math.floor(pos / 360.0))]
        return pos

    def acas(self, code: str, args: tuple) -> list[float]:
        """ACAS (@367): the axes of the plane (G16) and the master spindle."""
        self.channel.memory.own_channel(args[0])
        plane = self.g16_plane or {17: (1, 2, 3), 18: (3, 1, 2), 19: (2, 3, 1)}[self.kernel.plane]
        out = [float(a + (128 if m else 0)) for a, m in zip(plane, self.g16_minus)]
        return out + [0.0, float(MASTER_SPINDLE)]

    def acg(self, code: str, args: tuple) -> float:
        """ACG (@36b): the active G function of a group."""
        self.channel.memory.own_channel(args[0])
        group = _rng("G group", args[1], 0, 23)
        k = self.kernel
        state = {0: k.motion, 2: k.plane, 5: int(k.work_offset[1:]) if k.work_offset else 0,
                 3: cutter.active_g(k), 8: 70 if k.scale != 1.0 else 71, 10: 90 if k.absolute else 91,
                 9: self.channel.drilling.executed, 11: active_group_11(k)}
        if group in state:
            return float(state[group])
        power_on = SINUMERIK8XX.defaults.get(str(group))  # the groups ncvm keeps no state of: their power-on G
        return float(power_on if power_on is not None else ACG_GROUPS.get(group, (0,))[0])
