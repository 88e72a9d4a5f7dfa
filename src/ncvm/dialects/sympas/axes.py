"""One axis channel of the card (ncvm's reading; the rw_SymPas manual is silent): position, motion, flags, I/O words, qualifiers, spooler."""

from __future__ import annotations

from .motion import Move
from .options import Options


class AxisState:
    """One axis channel (ncvm's reading; the rw_SymPas manual is silent). Positions are machine coordinates in axis units."""

    def __init__(self, number: int, name: str, cfg_axis, cfg: Options):
        self.number = number
        self.name = name
        self.m = 0.0  # machine position at rest (or at the start of `move`)
        self.target = 0.0  # last programmed end (machine)
        self.move: Move | None = None
        self.ref = 0.0  # home shift: user = machine - ref - zerooffset - ZO
        self.zerooffset = 0.0
        self.closed = bool(cfg.loop_closed)
        self.homed = False
        self.flags = 0  # sticky axst flags (refused, saf, home_failed, spool_halted)
        self.digi = 0
        self.digo = 0
        self.ifs = 0
        self.poserr = 0.0
        self.ovr = 1.0  # path override (UTROVR), 0 = feed hold
        self.spool: list = []
        self.spool_halted = False
        self.limit_stop = False  # stopped at a soft limit by the soft-limit reaction (softlimits.py)
        acc = cfg_axis.accel
        self.q = {"jvl": cfg_axis.rapid / 60.0, "jac": acc, "jtv": 0.0, "jovr": 1.0, "sdec": acc,
                  "hvl": cfg_axis.max_feed / 600.0, "hac": acc, "ipw": 0.01, "mpe": 1.0,
                  "maxvel": cfg_axis.max_feed / 60.0, "maxacc": acc, "mdvel": 0.0, "jerkrel": 0.0,
                  "sll": cfg_axis.min, "slr": cfg_axis.max, "effradius": 1.0, "gf": 1.0, "gfax": 1.0,
                  "slsp": 4000.0, "dpoffset": 0.0, "dvoffset": 0.0, "aux": 0.0, "lp": 0.0, "lpndx": 0.0,
                  "gcr": 0, "mcp": 0, "sf": 0, "epc": 0, "CFLAGS": 0, "pprev": 0.0}
        self.active = {k: 0.0 for k in ("kp", "ki", "kd", "kpl", "kfca", "kfcv")}
        self.active["kp"] = 1.0
        self.staged = dict(self.active)
