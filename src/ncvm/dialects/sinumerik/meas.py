"""MEAS M (@720; manual §5.3.8.3, L4355-4396): the measuring block, cut where the probe switches.

The probe inputs and where on the path a probe switches are probe.py's (and nc/probe.py's); this is the
block: its traversing axes, the measured values into R parameters, its words cut at the trigger point.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from ...nc.probe import ProbeLatch, announce
from .errors import Cl800Error
from .ncdata import whole as _i
from .rotation import angle_address, machine_frame, program_frame

if TYPE_CHECKING:
    from .runtime import Channel


def meas_m(channel: Channel, target: int, probe: float, g: tuple, words: dict, line: int) -> dict:
    """@720: the block's axes move until the probe switches; their actual values relative to machine
    zero go to R<target>... (L4357-4396). The traversing axes are those of the block as it reaches the
    interpolation: under a coordinate rotation a plane axis word moves both axes of the plane. The
    block's words come back cut at the trigger point, in the program's frame."""
    channel.run_buffer()  # the measuring block starts where the blocks before it end
    probe = _i(probe)
    k = channel.kernel
    if probe not in (1, 2):
        raise Cl800Error(f"MEAS M: probe input {probe} is not 1 or 2")
    machine = 53 in g
    turned, frame = machine_frame(channel, g, words)
    moving = sorted((n for n in turned if n in k.axis_of), key=k.axis_of.get)
    if len(moving) > 2:
        raise Cl800Error(f"MEAS M: at most 2 axes may move in the measuring block ({', '.join(moving)})")
    if next((x for x in reversed(g) if x in (0, 1, 2, 3)), k.motion) not in (0, 1):
        raise Cl800Error("MEAS M needs G00 or G01")
    scale = 25.4 if 70 in g else (1.0 if 71 in g else k.scale)
    absolute = True if 90 in g else (False if 91 in g else k.absolute)
    start = {n: k.machine_pos[k.axis_of[n]] for n in moving}
    shown = k.shown_position()  # the turned frame, as the block's words are
    end = {}
    for name in moving:
        i = k.axis_of[name]
        value = turned[name] * scale
        end[name] = value if machine else k.offset_vec[i] + (value if absolute else shown[i] + value)
    hit = channel.probe.trigger_point(channel.probe.hit(probe), start, end)
    announce(k.canon, ProbeLatch(probe, dict(hit)), channel.src(line), dict(end))
    angle = angle_address(channel) if channel.angle_used else None  # resolved into the axis words
    out = {n: v for n, v in words.items() if n not in k.axis_of and n != angle}
    cut = {}
    reg = target
    axes = channel.session.machine.axes
    for name in moving:
        i = k.axis_of[name]
        # seen by decoding only after STOP DEC; a rotary axis as position within a rotation and number
        # of rotations (L4366-4369), as ACPM
        values = [hit[name] % 360.0, float(math.floor(hit[name] / 360.0))] if axes[i].rotary \
            else [hit[name] / scale]
        for value in values:
            if reg > 999:
                raise Cl800Error(f"MEAS M: result register R{reg} does not exist")
            channel.load_r(reg, value)
            reg += 1
        prog = hit[name] - (0.0 if machine else k.offset_vec[i])
        cut[name] = prog / scale if absolute or machine else (prog - shown[i]) / scale
    out.update(cut if machine else program_frame(cut, frame))
    return out
