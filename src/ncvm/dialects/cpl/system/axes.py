"""Axis and coordinate selection of chapter 4 (manual §4.2 L1256-1337, L1362-1385, L1509-1531).

A selection is a name or an index. Coordinate functions look a name up as a coordinate name first, then as
an axis name, and read an index as a coordinate index (selection type 1, default) or a physical index (0).
Axis functions read an index as a logical (1, default) or physical (0) index. With no transformation the
coordinates of a channel are its logical axes. Axes of the calling channel are driven by the NC kernel;
axes of other channels hold their configured position (nothing moves them in this simulation).
"""

from __future__ import annotations

from ..errors import CplError, nul_used
from .context import SystemContext
from .controller import PhysAxis


def ctl(rt: SystemContext):
    return rt.ctl


def nul(v):
    if v is None:
        raise nul_used()
    return v


def resolve(rt: SystemContext, sel, seltype=1, chan=None, *, own_only: bool = True, physical_ok: bool = True) -> PhysAxis:
    """The physical axis behind a selection; run-time errors 1938 (not configured) and 1970 (other channel)."""
    c = rt.ctl
    sel = nul(sel)
    if seltype is None:
        seltype = 1
    if seltype not in (0, 1):
        raise CplError("CPL023", f"selection type {seltype} (0 physical, 1 logical/coordinate)")
    if chan is not None and seltype == 0:
        raise CplError("CPL040", "a physical axis cannot be given together with a channel")
    ch = c.channel if chan is None else chan
    if chan is not None and not c.channel_axes(chan):
        raise CplError("1938", f"channel {chan} has no axes")
    if isinstance(sel, str):
        up = sel.upper()
        ax = next((a for a in c.channel_axes(ch) if a.name == up), None) or c.by_name(up)
        if ax is None:
            raise CplError("1938", f"axis or coordinate {sel!r} is not configured")
    elif sel.__class__ is int:
        if seltype == 0:
            if not physical_ok:
                raise CplError("CPL040", "a physical axis index is not allowed here")
            ax = c.axes.get(sel)
            if ax is None:
                raise CplError("1938", f"physical axis {sel} is not configured")
        else:
            logical = c.channel_axes(ch)
            if not 1 <= sel <= len(logical):
                raise CplError("1938", f"channel {ch} has no axis/coordinate {sel}")
            ax = logical[sel - 1]
    else:
        raise CplError("CPL032", f"axis selection {sel!r}: a name or an INTEGER index")
    if own_only and ax.channel != c.channel:
        where = "is asynchronous" if ax.channel == 0 else f"is assigned to channel {ax.channel}"
        raise CplError("1970", f"axis {ax.name} {where}; only the own channel {c.channel} is allowed")
    if chan is not None and ax.channel != chan:
        raise CplError("1970", f"axis {ax.name} is not on channel {chan}")
    return ax


def kernel_index(rt: SystemContext, ax: PhysAxis) -> int | None:
    """The NC kernel's index of an axis of the calling channel, else None."""
    if ax.channel != rt.ctl.channel:
        return None
    return rt.kernel.axis_of.get(ax.name)


def to_unit(kernel, ax: PhysAxis, value_mm: float) -> float:
    """mm -> the calling channel's unit (G70/G71) for synchronous linear axes; degrees stay degrees;
    asynchronous linear axes always mm (L1329-1337)."""
    if ax.rotary or ax.channel == 0:
        return value_mm
    return value_mm / kernel.scale
