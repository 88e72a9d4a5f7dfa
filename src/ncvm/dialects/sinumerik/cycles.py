"""The single functions machining cycles call: PREP REF, INT SEC and PREP CYC (@710, @711, @713; manual
§5.3.8.2, L4107-4282). The contour geometry is contour.py's; this is the run-time side: the cursor of each
contour, the R parameters read and written, the start point in the program's frame.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from ...diagnostics import RuntimeFault
from ...nc.block import Block
from .contour import check_window, contour_elements, intersect
from .errors import Cl800Error
from .ncdata import whole as _i
from .rotation import block_frame, program_point

if TYPE_CHECKING:
    from .runtime import Channel


class Cycles:
    """PREP REF's cursor per contour (input register Rm -> [elements, next index]) and the three functions."""

    def __init__(self, channel: Channel):
        self.channel = channel
        self.contours: dict[int, list] = {}

    def prep_cyc(self, args: tuple) -> None:
        """PREP CYC (@713): the unit factor and the diameter flag into R<v>, R<v+1>."""
        ch = self.channel
        target = args[0]
        check_window(target, 2, ((0, 98), (900, 998)), "PREP CYC output")  # L4268
        diameter = ch.data.areas["nc_md"].get("diameter_axis1", 0.0)
        ch.store(target, [1.0 if ch.kernel.scale == 1.0 else 0.03937, 2.0 if diameter else 1.0])

    def prep_ref_args(self, args: tuple) -> None:
        """PREP REF (@710) with the R numbers of its operands."""
        self.prep_ref(int(args[0]), int(args[1]))

    def prep_ref(self, rn: int, rm: int) -> None:
        """@710 Rn Rm: the next contour element of sub-program R[m] into Rn..Rn+7."""
        check_window(rm, 4, ((0, 197), (900, 997)), "PREP REF input")
        check_window(rn, 8, ((0, 192), (900, 992)), "PREP REF output")
        ch = self.channel
        R = ch.R
        cursor = self.contours.get(rm)
        if R[rm + 3] == 1.0 or cursor is None:
            number = _i(R[rm])
            unit = ch.loader(number)
            if unit is None:
                raise RuntimeFault("RUN002", f"PREP REF: contour sub-program L{number} not found")
            cursor = [contour_elements(unit.program, ch.positions.plane_axes(), (R[rm + 1], R[rm + 2]), R,
                                       ch.radius_address, ch.kernel.axis_of), 0]
            self.contours[rm] = cursor
            R[rm + 3] = 0.0
        elements, i = cursor
        if i >= len(elements):
            last = elements[-1] if elements else [R[rm + 1], R[rm + 2]] * 2 + [0.0, 0.0, 1.0, 2.0]
            ch.store(rn, last[2:4] + last[2:4] + [0.0, 0.0, last[6], 2.0])
            return
        ch.store(rn, elements[i])
        cursor[1] = i + 1

    def int_sec(self, rm: int, rn: int, g: tuple, words: dict, line: int) -> None:
        """@711 Rm Rn Rr: intersect element Rn..Rn+7 with the path to this block's destination.

        The element (PREP REF's output: the contour as programmed), the destination and the result are
        in the program's frame; so is the start point, the current position turned back by the
        block's coordinate rotation."""
        check_window(rn, 8, ((0, 192), (900, 992)), "INT SEC input")
        check_window(rm, 3, ((0, 197), (900, 997)), "INT SEC output")
        ch = self.channel
        ch.run_buffer()  # the path starts at the end point of the blocks decoded so far
        h_name, v_name = ch.positions.plane_axes()
        if h_name not in words or v_name not in words:
            raise Cl800Error(f"INT SEC needs both axes {v_name} and {h_name} of the destination in its block")
        theta = block_frame(ch, Block(tuple(g), (), words, None, None, None))[3]
        h, v = program_point(ch, h_name, v_name, theta)
        hit = intersect(ch.R[rn:rn + 8], (v, h), (words[v_name], words[h_name]))
        ch.store(rm, [0.0] if hit is None else [1.0, hit[0], hit[1]])
