"""LPR / LPRS: the card's data recording of a motion for mcfg's graphical system analysis (§6.6.29-30).

The manual (L1299-1300, L1845-1859): recording starts LST seconds after the call, always takes
1000 values, and lasts LET seconds rounded up to a whole multiple of 1000 * T_A (T_A = the servo
period, 1.28 ms by default). So the values are ``k * T_A`` apart with ``k = ceil(LET / (1000 T_A))``,
at least 1. PU and TU are the command's system parameters: positions are recorded in PU and
velocities in PU/TU of the calling task, as in force at the call. LPRS starts the axes together,
on one time grid. The card samples in its servo cycle, so the first value is taken in the first
servo cycle at or after call + LST. A new LPR/LPRS of an axis replaces that axis's recording.

The values come from the simulated axis state at each sample's own time: the card takes a sample
as a timed action (in time order with everything else), and after the programs end the remaining
samples are taken from the motion as it runs out. The host (mcfg's stand-in) reads the buffers:
``Card.recordings`` in Python and ``recordings`` in the run's JSON document.
"""

from __future__ import annotations

import math

from .motion import TICKS_PER_S
from .values import fault

SAMPLES = 1000
FIELDS = ("t", "dp", "rp", "dv", "rv", "poserr")


class Recording:
    """One axis's trace buffer: up to 1000 samples of (t, dp, rp, dv, rv, poserr)."""

    __slots__ = ("axis", "call_tick", "first_tick", "every", "f", "ts", "samples")

    def __init__(self, axis: int, call_tick: float, first_tick: float, every: float, f: float, ts: float):
        self.axis = axis
        self.call_tick = call_tick
        self.first_tick = first_tick
        self.every = every  # ticks between two samples
        self.f, self.ts = f, ts  # axis units per PU; seconds per TU
        self.samples: list[tuple] = []

    def tick(self, i: int) -> float:
        return self.first_tick + i * self.every

    @property
    def complete(self) -> bool:
        return len(self.samples) >= SAMPLES

    def take(self, card) -> None:
        """Take the next sample, from the axis state at its own time."""
        t = self.tick(len(self.samples))
        a = card.axes[self.axis]
        dp = (card.mpos(a, t) - card.user_shift(a)) / self.f
        dv = card.axis_velocity(a, t) / self.f * self.ts
        perr = a.poserr / self.f
        self.samples.append(((t - self.call_tick) / TICKS_PER_S, dp, dp - perr, dv, dv, perr))

    def to_json(self, name: str) -> dict:
        return {"axis": name, "interval_s": self.every / TICKS_PER_S, "fields": list(FIELDS),
                "samples": [list(s) for s in self.samples]}


def start(card, tk, axes) -> None:
    """LPR/LPRS: arm one recording per axis, all on the same time grid."""
    lst, let = float(tk.sysp["LST"]), float(tk.sysp["LET"])
    if lst < 0.0 or let < 0.0:
        fault(256, f"LST = {lst:g} s and LET = {let:g} s must not be negative")
    f, ts = card.units(tk)
    servo = card.scheduler.servo
    t_a = servo / TICKS_PER_S
    k = max(1, math.ceil(let / (SAMPLES * t_a) - 1e-9))
    call = tk.time
    first = math.ceil((call + lst * TICKS_PER_S) / servo - 1e-9) * servo
    for ax in axes:
        rec = Recording(ax, call, first, k * servo, f, ts)
        card.recordings[ax] = rec
        card.scheduler.add_timed(first, _sampler(card, rec))


def _sampler(card, rec: Recording):
    def act():
        if card.recordings.get(rec.axis) is not rec:
            return  # replaced by a later LPR of the axis
        rec.take(card)
        if not rec.complete:
            card.scheduler.add_timed(rec.tick(len(rec.samples)), act)
    return act


def run_out(card) -> None:
    """After the programs end the card goes on recording: take the samples still due."""
    for rec in card.recordings.values():
        while not rec.complete:
            rec.take(card)
