"""What the command groups share: source places, the units of a path move's axes, the W forms' wait."""

from __future__ import annotations

import math

from ....nc.canon import Src
from ..values import fault


def source_of(tk, loc: int | Src) -> Src:
    """The source place of statement ``loc`` of the task's program; a spooled move carries its
    own, since another task's SSMS may start it (the spoolers belong to the axes, not the tasks)."""
    return loc if isinstance(loc, Src) else tk.unit.srcs[loc]


def surface(card, tk, ax: int) -> float | None:
    """Path length per degree of a rotary axis in a translational interpolation (a length PU): the arc at
    its effradius ("Mantelflächenbearbeitung", L1450); None for any other axis or PU."""
    if not card.rotary[ax] or int(tk.sysp["PU"]) not in (0, 1, 2):
        return None
    r = float(card.axes[ax].q["effradius"])
    if r <= 0.0:
        fault(256, f"effradius of rotary axis {card.axes[ax].name} must be > 0 in a translational interpolation")
    return r * math.pi / 180.0


def scale(card, tk, ax: int, f: float) -> float:
    """PU -> axis units of one axis of a path move: a rotary axis in a translational interpolation takes
    its target or travel as a length on its surface, or with MODEREG bit 10 (RotatoricUnit, L1401) in
    its own rotary unit."""
    r = surface(card, tk, ax)
    if r is None:
        return f
    return 1.0 if card.sys["MODEREG"] & 0x400 else f / r


def weight(card, tk, ax: int) -> float:
    """Path units per axis unit: a rotary axis in a translational interpolation counts with its
    surface length, so the path velocity is the velocity on the surface (effradius, L1450)."""
    r = surface(card, tk, ax)
    return 1.0 if r is None else r


def user_to_machine(card, tk, items, relative: bool, start, f: float):
    axes = tuple(ax for ax, _ in items)
    p0 = tuple(start[ax] for ax in axes)
    p1 = []
    for ax, v in items:
        a = card.axes[ax]
        k = scale(card, tk, ax, f)
        if relative:
            p1.append(a.target + v * k)
        else:
            p1.append(v * k + card.user_shift(a))
    return axes, p0, tuple(p1)


def then_wait(card, tk, axes, wait: bool):
    return card.wait_axes(tk, axes) if wait else None
