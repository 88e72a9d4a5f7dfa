"""The spindle as @ code sees it: ACSP, ACSS, AGS, PRSS, PRVC (manual L2557-2668, L3021-3032, L4887).

The simulated channel has one spindle, number 1, which is the master spindle
(spindle number 0 in the @ code means the master spindle of the own channel).
Speed, direction and the angle it has turned come from the NC kernel, which
executes S, M3/M4/M5 and G96/G97; actual values read the *executed* state (the
manual asks for STOP DEC before ACSP/ACSS, L2668), programmed setpoints read
what decoding has reached (the kernel's state plus the blocks still waiting in
the decode buffer).

Gear stages (docs/decisions.md; the gearbox model is nc/spindle.py): M41-M45
select stage 1-5, M40 selects the stage automatically from the speed, using the
maximum speed of each stage in ``[sin800] gears``; ``[sin800] gear`` is the
stage at power-on.
"""

from __future__ import annotations

from ...nc.spindle import SINUMERIK_GEARS, Gearbox
from .errors import Cl800Error

MASTER_SPINDLE = 1
#: the gear M functions as the channel sees them ("M41") -> their number in the gear table (nc/spindle.py)
GEAR_M = {f"M{m}": m for m in SINUMERIK_GEARS.stages}


def _whole(v: float) -> int:
    n = int(v)
    if n != v:
        raise Cl800Error(f"{v:g} is not a whole number")
    return n


def spindle_number(v: float, top: int, what: str) -> int:
    """Spindle number 0..top of the manual's table; 0 is the master spindle. Only spindle 1 exists here."""
    n = _whole(v)
    if not 0 <= n <= top:
        raise Cl800Error(f"{what}: spindle number {n} outside 0-{top}")
    if n not in (0, MASTER_SPINDLE):
        raise Cl800Error(f"{what}: spindle {n} does not exist on this machine (only spindle {MASTER_SPINDLE})")
    return MASTER_SPINDLE


class Spindle:
    """The channel's spindle: its gear stages and its @ code reads. ``buffer``: the decoded blocks not yet
    executed (their S words and G96/G97 are the programmed setpoints)."""

    def __init__(self, kernel, data, buffer, gearbox: Gearbox):
        self.kernel = kernel
        self.data = data
        self.buffer = buffer
        self.gearbox = gearbox

    def word(self, v: float, line: int) -> str:
        """PRSS(<spindle>) = value (@442, L3318-3326): the S word of the block; spindle 0 is the master
        spindle, the only one here."""
        spindle_number(v, 1 if self.data.control in ("810", "820") else 6, "PRSS")
        return "S"

    def read(self, code: str, args: tuple) -> float:
        k = self.kernel
        wide = 6 if self.data.control == "880" else 4  # ch.6 table L4907-4912
        if code == "363":
            spindle_number(args[0], wide, "ACSP")
            return k.spindle_angle()
        if code == "364":
            spindle_number(args[0], wide, "ACSS")
            return k.actual_speed()
        if code == "3e4":
            spindle_number(args[0], 1 if self.data.control in ("810", "820") else 6, "AGS")
            return float(self.gearbox.active())
        if code == "342":
            self._programmed_channel(args[0], "PRSS")
            spindle_number(args[1], 1 if self.data.control in ("810", "820") else 6, "PRSS")
            return self._programmed()[0]
        if code == "345":
            self._programmed_channel(args[0], "PRVC")
            if _whole(args[1]) != 0:
                raise Cl800Error(f"PRVC: value 2 is {_whole(args[1])}, only 0 (G96) is defined")
            _, css, cutting = self._programmed()
            return cutting if css else 0.0
        raise Cl800Error(f"@{code} is not available")

    def _programmed_channel(self, v: float, what: str) -> None:
        """Channel numbers per the ch.6 table (L4886-4889): 880 0-16, 850 0-8; 810/820 PRSS 0-3, PRVC 1."""
        top = {"880": 16, "850": 8}.get(self.data.control, 3 if what == "PRSS" else 1)
        ch = _whole(v)
        if not 0 <= ch <= top:
            raise Cl800Error(f"{what}: channel {ch} outside 0-{top}")
        if ch not in (0, self.data.channel):
            raise Cl800Error(f"{what}: channel {ch} is not on this NC CPU")

    def _programmed(self) -> tuple[float, bool, float]:
        """(S in rev/min, G96 selected, cutting speed) as decoding has programmed them: the executed
        state, then the blocks waiting in the decode buffer in order."""
        k = self.kernel
        speed, css, cutting = k.speed, k.css, k.cutting_speed
        for blk in self.buffer:
            for g in blk.g:
                if g == 96:
                    css = True
                elif g == 97:
                    css = False
            s = blk.words.get("S")
            if s is not None:
                if css:
                    cutting = s
                else:
                    speed = s
        return speed, css, cutting
