"""The axis qualifiers (§6.3.3): ``A1.dp``, ``A1.axst``, ``A1.digob.3`` … read and written by generated code.

Generated code calls ``_get_qual(card, tk, ax, name)`` and its siblings (codegen); ``axst`` is the status
word of an axis, with the bits the machine file names (``sympas.axst_bits``).
"""

from __future__ import annotations

import math

from .axes import AxisState
from .commands.jog import new_override
from .events import input_active
from .motion import Chain
from .values import fault

#: the software limits: read and written in the user's coordinates, kept in the machine's (rw_SymPas manual L1668-1672; L2144-2158; L1413)
LIMITS = ("sll", "slr")


def axst(card, a: AxisState, t: float) -> int:
    """The status word of axis ``a`` at ``t``: its sticky flags, motion, loop, homing, inputs and limits."""
    b = card.cfg.axst_bits
    v = a.flags
    if (not card.busy(a, t) or a.move.drift) and not a.spool:
        v |= 1 << b["profile_end"]
        if abs(a.poserr) <= a.q["ipw"]:
            v |= 1 << b["in_position"]
    mv = a.move
    if mv is not None and mv.t1 > t and not mv.jog and isinstance(mv, Chain):
        v |= 1 << b["spool_running"]  # its spooler is working off a chain
    elif a.spool_halted and any(e[0] == "move" for e in a.spool):
        v |= 1 << b["spool_halted"]  # halted by SSF 1000 with profiles waiting behind the halt
    if a.closed:
        v |= 1 << b["loop_closed"]
    if a.homed:
        v |= 1 << b["homed"]
    for inp in card.inputs:
        if inp["axis"] == a.name and input_active(a, inp):
            key = {"EO": "eo", "LSL": "lsh_left", "LSR": "lsh_right"}.get(inp.get("function"))
            if key:
                v |= 1 << b[key]
    p = card.mpos(a, t)
    if p < a.q["sll"]:
        v |= 1 << b["lss_left"]
    if p > a.q["slr"]:
        v |= 1 << b["lss_right"]
    if a.closed and abs(a.poserr) > a.q["mpe"]:
        v |= 1 << b["mpe"]
    return v


def get_qual(card, tk, ax: int, name: str):
    a = card.check_axis(ax)
    t = tk.time
    if card.scheduler.next_timed() <= t:  # a timed action due (a homing latch at profile end) acts before the read
        card.scheduler.apply_timed(t)
    if name in ("dp", "rp"):
        card.settle((ax,), t)  # a profile that has ended: its end rounded to whole counts (card.retire)
        u = card.mpos(a, t) - card.user_shift(a)
        return u - a.poserr if name == "rp" else u
    if name == "tp":
        return a.target - card.user_shift(a)
    if name in ("dv", "rv"):
        return card.axis_velocity(a, t)
    if name == "poserr":
        if card.outside and f"{a.name}.poserr" in card.outside:
            card.read_outside(f"{a.name}.poserr", a.poserr)
        return a.poserr
    if name == "zerooffset":
        return a.zerooffset
    if name == "axst":
        return axst(card, a, t)
    if name in LIMITS:
        return a.q[name] - card.user_shift(a)
    if name in ("digi", "ifs"):  # the axis' digital inputs: a run-time input (ncvm translate marks it)
        card.canon.frozen(f"digital inputs {a.name}.{name} read as {getattr(a, name):#x}", None, True)
    if name in ("digi", "digo", "ifs"):
        return getattr(a, name)
    if name in ("kp", "ki", "kd", "kpl", "kfca", "kfcv"):
        return a.staged[name]
    if name == "lsm":  # the running chain's unfinished segments still hold their entries
        return (card.spooler.capacity - card.spooler.used(ax, t)) * 64
    if name == "mcis":
        return sum(1 for e in a.spool if e[0] == "move") + card.spooler.chain_pending(ax, t)
    return a.q[name]


def set_qual(card, tk, ax: int, name: str, value) -> None:
    a = card.check_axis(ax)
    if isinstance(value, float) and not math.isfinite(value):
        # NaN or inf (a math function's "no valid return value") as a position, velocity or gain
        fault(32768, f"{a.name}.{name} := {value}: not a valid parameter value")
    if name in ("digi", "ifs"):
        setattr(a, name, 0 if name == "ifs" else a.digi)  # writing clears the latched flags (L1444)
        return
    if name == "digo":
        a.digo = value & 0xFFFFFFFF
        return
    if name == "dp":
        shift = card.user_shift(a)
        card.retire_axis(a, tk.time)
        a.m = a.target = value + shift
        return
    if name in ("kp", "ki", "kd", "kpl", "kfca", "kfcv"):
        a.staged[name] = value
        return
    if name in LIMITS:
        a.q[name] = value + card.user_shift(a)  # kept in machine coordinates: it stays put when the zero moves
        return
    a.q[name] = value
    if name == "jovr":
        new_override(card, tk, ax)  # the running jog follows its new override


def get_bit(card, tk, ax: int, squal: str, bit: int) -> bool:
    word = {"digib": "digi", "digob": "digo", "ifsb": "ifs", "axstb": "axst"}[squal]
    return bool(get_qual(card, tk, ax, word) >> (bit - 1) & 1)


def set_bit(card, ax: int, squal: str, bit: int, value: bool) -> None:
    a = card.check_axis(ax)
    mask = 1 << (bit - 1)
    a.digo = (a.digo | mask) if value else (a.digo & ~mask)
