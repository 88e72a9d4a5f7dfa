"""Loop, reset, positions, zero points, filters, override and recording (§6.6.8-9, 29-30, 49, 51, 55, 57,
70-71): the commands that set an axis rather than move it."""

from __future__ import annotations

from .. import recording
from ..motion import Chain
from ..values import fault
from .common import source_of
from .jog import run_on


def cl(card, tk, axes, loc):
    for ax in axes:
        a = card.check_axis(ax)
        a.closed = True
        a.poserr = 0.0  # bumpless: dp := rp
    return None


def clv(card, tk, axes, loc):
    """CLV closes the loop like CL but keeps the axes' velocity (rw_SymPas manual §6.5-6.6, L1614-2233; L1686; the manual's example
    follows it with JS "then stop the axes immediately"): a running profile gives way to a run at the
    velocity the axis has, until a stop. A path cannot go on for part of its axes: all axes of a path
    move or chain run on at their share of the path velocity."""
    t = tk.time
    cl(card, tk, axes, loc)
    card.settle(axes, t)
    src = source_of(tk, loc)
    for ax in axes:
        a = card.axes[ax]
        mv = a.move
        if mv is None or mv.t1 <= t or mv.drift:
            continue
        velocities = [(card.axes[x], card.axis_velocity(card.axes[x], t)) for x in mv.axes]
        card.retire_axis(a, t)
        for b, v in velocities:
            if v != 0.0:
                run_on(card, b, t, v, src)
    return None


def ol(card, tk, axes, loc):
    for ax in axes:
        a = card.check_axis(ax)
        card.retire_axis(a, tk.time)
        a.target = a.m
        a.closed = False
    return None


def ra(card, tk, axes, loc):
    for ax in axes:
        a = card.check_axis(ax)
        card.retire_axis(a, tk.time)
        a.target = a.m
        a.spool.clear()
        a.flags = 0
        a.digi = a.digi
        a.ifs = 0
        a.closed = False
    return None


def rptodp(card, tk, axes, loc):
    for ax in axes:
        a = card.check_axis(ax)
        if card.busy(a, tk.time):
            fault(256, f"RPTODP: axis {a.name} is in a profile")
        a.m = a.target = a.m - a.poserr
        a.poserr = 0.0
    return None


def shp(card, tk, items, loc):
    for ax, v in items:
        a = card.check_axis(ax)
        card.settle((ax,), tk.time)
        m = card.mpos(a, tk.time)
        a.ref = m - v - a.zerooffset - (card.user_shift(a) - a.ref - a.zerooffset)
        card.zero_moved()
        a.homed = True
    return None


def szpa(card, tk, items, loc):
    for ax, v in items:
        a = card.check_axis(ax)
        if card.sys["MODEREG"] & (1 << 27):
            a.ref += v - a.zerooffset
            a.zerooffset = 0.0
        else:
            a.zerooffset = v
        card.zero_moved()
    return None


def szpr(card, tk, items, loc):
    for ax, v in items:
        a = card.check_axis(ax)
        if card.sys["MODEREG"] & (1 << 27):
            a.ref += v
        else:
            a.zerooffset += v
        card.zero_moved()
    return None


def uf(card, tk, axes, loc):
    for ax in axes:
        a = card.check_axis(ax)
        a.active = dict(a.staged)
    return None


def utrovr(card, tk, axes, loc):
    """TROVR becomes the path override of these axes ("reduzierte Bahngeschwindigkeit für Achsen A1
    und A2", L2189): their running path moves reach it linearly over TROVRST seconds (ncvm's reading; the rw_SymPas manual is silent),
    and their later path moves, from any task, are planned with it. A group runs with the smallest
    override of its axes; 0 holds it (feed hold)."""
    ovr = max(0.0, float(tk.sysp["TROVR"]))
    ramp = max(0.0, float(tk.sysp["TROVRST"])) * 15625.0
    for ax in axes:
        card.check_axis(ax).ovr = ovr
    done = set()
    for ax in axes:
        mv = card.axes[ax].move
        if mv is not None and not mv.jog and id(mv) not in done and mv.t1 > tk.time:
            done.add(id(mv))
            group = card.path_override(mv.axes)
            if isinstance(mv, Chain):
                mv.override(tk.time, group, ramp)
            else:
                mv.override(tk.time, group / mv.ovr0, ramp)
    return None


def lpr(card, tk, axes, loc):
    """LPR/LPRS: start the data recording of these axes (recording.py, §6.6.29-30)."""
    for ax in axes:
        card.check_axis(ax)
    recording.start(card, tk, axes)
    return None


lprs = lpr


#: the commands of this group by name (codegen calls them as _C_<name>)
COMMANDS = {
    "cl": cl, "clv": clv, "ol": ol, "ra": ra, "rptodp": rptodp, "shp": shp, "szpa": szpa, "szpr": szpr, "uf":
    uf, "utrovr": utrovr, "lpr": lpr, "lprs": lprs}
