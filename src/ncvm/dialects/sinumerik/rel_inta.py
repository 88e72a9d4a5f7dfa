"""Program influence by external inputs: REL and INTA (@730, @736; manual §5.3.8.4, L4398-4436).

REL holds decoding until an input changes; INTA cuts its block's path where an input reaches a level.
The inputs come from the scenario (``ExternalInput`` events of machine/scenario.py); the path INTA cuts
is inta_path.py's.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from ...machine.scenario import ExternalInput
from ...nc.dynamics import trapezoid_distance, trapezoid_time
from .errors import Cl800Error
from .inta_path import arc_path, straight_path
from .ncdata import in_range as _rng
from .ncdata import whole as _i
from .rotation import angle_address, machine_frame, program_frame

if TYPE_CHECKING:
    from .runtime import Channel


class RelInta:
    """REL and INTA blocks; ``until``: when the input of the last INTA block fired (None: it did not)."""

    def __init__(self, channel: Channel):
        self.channel = channel
        self.kernel = channel.kernel
        self.clock = channel.session.machine.clock
        self.until: float | None = None

    def read_in_inhibit(self, byte: float, bit: float, line: int) -> None:
        """@730 REL: once its block has reached its position, decoding waits for input byte.bit to become 1
        (a 0->1 change; no wait when it is 1 already). Every block decoded so far executes first."""
        self.channel.run_buffer()
        self.channel.wait_input(_i(byte), _i(bit), True, "REL")

    def inta(self, axis: float, byte: float, bit: float, g: tuple, words: dict, line: int) -> dict:
        """@736 INTA: the block's words, cut where the motion stops when input byte.bit reaches the level
        (bit >= 0: 1, bit < 0: 0); unchanged when the position is reached first. Axis 0 = all axes of the
        block; the axes interpolating with the named one stop with it, which here are all of them (both
        plane axes of a circle). The path is cut on the traversing axes (under a rotation both plane
        axes), a circle as an arc with the same centre and a shorter sweep, and handed back in the
        program's frame."""
        ch = self.channel
        ch.run_buffer()  # the block starts where the blocks before it end
        k = self.kernel
        ax = _rng("INTA axis number", axis, 0, 24)
        b, n = _i(byte), _i(bit)
        level = n >= 0 and not (n == 0 and math.copysign(1.0, bit) < 0)
        n = abs(n)
        ch.ext_input(b, n)  # checks byte 1/2, bit 0-7
        if ax > k.n_axes:
            raise Cl800Error(f"INTA: axis {ax} does not exist")
        self.until = None
        turned, frame = machine_frame(ch, g, words)  # the block in the frame of the machine axes
        path = self._path(g, turned)
        if path is None or not path.axes or (ax and k.axis_names[ax - 1] not in path.axes):
            return words
        now = self.clock.now
        hit = self._input_time(b, n, level, now + trapezoid_time(path.length, path.speed, path.accel))
        self.until = hit
        if hit is None:
            return words
        travelled = trapezoid_distance(path.length, path.speed, path.accel, hit - now)
        cut = path.cut(travelled / path.length if path.length else 0.0)
        angle = angle_address(ch) if ch.angle_used else None  # resolved into the axis words
        out = {n: v for n, v in words.items() if n not in k.axis_of and n != angle and n not in path.replaces}
        out.update(cut if 53 in g else program_frame(cut, frame))
        return out

    def _path(self, g: tuple, turned: dict):
        """The INTA block's path as the kernel will run it; None for a block the kernel rejects (it then
        reports the fault when the block executes)."""
        k = self.kernel
        motion = next((x for x in reversed(g) if x in (0, 1, 2, 3)), k.motion)
        scale = 25.4 if 70 in g else (1.0 if 71 in g else k.scale)
        machine = 53 in g
        relative = not machine and (False if 90 in g else (True if 91 in g else not k.absolute))
        prog = k.shown_position()  # the turned frame, as the block's words are
        start = [(k.machine_pos[i] if machine else prog[i]) / scale for i in range(k.n_axes)]
        feed = turned["F"] * scale if "F" in turned else k.feed  # mm/min
        if motion < 2:
            return straight_path(k, motion == 0, turned, start, scale, relative, feed)
        plane = next((x for x in reversed(g) if x in (17, 18, 19)), k.plane)
        return arc_path(k, motion == 2, plane, turned, start, scale, relative, feed)

    def inta_done(self) -> None:
        """After an INTA block: simulated time has reached the moment the input fired."""
        clock = self.clock
        if self.until is not None and clock.now < self.until:
            clock.advance(self.until - clock.now)
        self.until = None

    def _input_time(self, byte: int, bit: int, level: bool, until: float) -> float | None:
        """When external input byte.bit first has ``level``, from now to ``until``; None if not before."""
        now = self.clock.now
        if self.channel.ext_input(byte, bit) == level:
            return now
        for ev in self.channel.scenario:
            if ev.time > until:
                break
            if ev.__class__ is ExternalInput and ev.byte == byte and ev.bit == bit and ev.value == level:
                return max(ev.time, now)
        return None
