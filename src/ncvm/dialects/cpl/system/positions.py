"""Positions of manual §4.2: AXO, CPOS, CPROBE, WPOS (coordinates), MPOS, PPOS, PROBE (axes), APOS, SPOS.

"Prepared" values (AXO, CPOS) come from the NC state after every block prepared so far (the runtime's
prepared kernel); "executed" values (WPOS, MPOS, APOS, SPOS) from the NC kernel, which has only run the
blocks a WAIT (or the look-ahead depth) let through: read before a WAIT they are stale (§4.1). They are
read at the program's time: inside a block still moving then, at the point its move has reached
(runtime.executed_position).
Probe values are latched by a measuring block (G75, G275, G375) from the next "probe" or "fixed_stop"
scenario event (see probe_block).
Transformations (transforms.py): CPOS is before them, WPOS after the contour shift and scaling but before
the coordinate transformation G138 (manual L1323), MPOS after all; PPOS removes the axis zero shifts, the
tool compensation and G168/G268 (L1571-1576) but none of the transformations (L1580-1583); CPROBE removes
all (L1430).
"""

from __future__ import annotations

import copy

from ....diagnostics import UsageError
from ....nc.probe import ProbeLatch, announce, programmed_end, stop_words
from ..errors import CplError, nul_used
from .axes import kernel_index, resolve, to_unit
from .context import SystemContext
from .gfuncs import program_shift


def _executed_mcs(rt: SystemContext, ax) -> float:
    i = kernel_index(rt, ax)
    return ax.position if i is None else rt.executed_position()[i]


def axis_zs(rt: SystemContext, k, i: int) -> float:
    """Axis zero shifts (G54.., external) of kernel axis i: the offset without G92, the program
    coordinate shifts G168/G268 and the tool length."""
    tool = k.tool_length if i == k.tool_axis else 0.0
    return k.offset_vec[i] - k.g92[i] - program_shift(rt, k, i) - tool


def f_axo(rt: SystemContext, sel, seltype=1):
    """AXO: the last activated G92 shift of a coordinate, at block preparation (L1388-1402)."""
    ax = resolve(rt, sel, seltype)
    k = rt.prepared_kernel()
    i = kernel_index(rt, ax)
    return 0.0 if i is None else to_unit(k, ax, k.g92[i])


def f_cpos(rt: SystemContext, sel, seltype=1):
    """CPOS: the last programmed absolute position (PCS) of a coordinate, at block preparation (L1404-1428)."""
    ax = resolve(rt, sel, seltype)
    k = rt.prepared_kernel()
    i = kernel_index(rt, ax)
    return ax.position if i is None else to_unit(k, ax, k.prog[i])


def f_wpos(rt: SystemContext, sel, seltype=1, chan=None):
    """WPOS: the interpolated command position in the WCS, at block execution (L1475-1499).

    Foreign channels are allowed; an asynchronous axis acts like SPOS."""
    ax = resolve(rt, sel, seltype, chan, own_only=False)
    i = kernel_index(rt, ax)
    k = rt.kernel
    if i is None:
        return ax.position
    t = k.transform
    if t is None:
        return to_unit(k, ax, rt.executed_position()[i] - axis_zs(rt, k, i))
    wcs = t.to_wcs([m - o for m, o in zip(rt.executed_position(), k.offset_vec)])  # G138 undone
    return to_unit(k, ax, wcs[i] + k.offset_vec[i] - axis_zs(rt, k, i))


def f_mpos(rt: SystemContext, sel, axtype=1, chan=None):
    """MPOS: the interpolated command position in the MCS, at block execution (L1539-1565)."""
    ax = resolve(rt, sel, axtype, chan, own_only=False)
    return to_unit(rt.kernel, ax, _executed_mcs(rt, ax))


def _physical(rt: SystemContext, sel):
    c = rt.ctl
    if isinstance(sel, str):
        ax = c.by_name(sel)
    elif sel.__class__ is int:
        ax = c.axes.get(sel)
    elif sel is None:
        raise nul_used()
    else:
        raise CplError("CPL032", f"axis selection {sel!r}")
    if ax is None:
        raise CplError("1938", f"physical axis {sel!r} is not configured")
    return ax


def f_spos(rt: SystemContext, sel):
    """SPOS: the axis command value of a physical axis, relative to machine zero (L1688-1714)."""
    ax = _physical(rt, sel)
    return to_unit(rt.kernel, ax, _executed_mcs(rt, ax))


def f_apos(rt: SystemContext, sel):
    """APOS: the actual (feedback) value = command value minus the configured following error (L1662-1686)."""
    ax = _physical(rt, sel)
    return to_unit(rt.kernel, ax, _executed_mcs(rt, ax) - ax.lag)


# -- measuring: G75, G275, G375 -----------------------------------------------------------------
#: the measuring G functions of §4.2: "probe input", "on-the-fly measurement", "measuring fixed stop"
PROBE_INPUT, ON_THE_FLY, FIXED_STOP = 75, 275, 375
#: the latch's code before any measuring block ran
NO_MEASUREMENT = 0
MEASURING_G = frozenset((PROBE_INPUT, ON_THE_FLY, FIXED_STOP))


def probe_block(rt, blk):
    """A measuring block; it travels like G1 and is executed before preparation goes on, so SD(9) and
    the measured values can be read in the next CPL block (L1451).

    G75: if a "probe" scenario event is left, the probe switches at the event's axis positions (MCS), the
    move stops there and the latch holds them. G275 measures only its one programmed axis (L1591): the
    event's position of that axis is latched and the move goes on to its end point. G375 travels its one
    axis towards a fixed stop: a "fixed_stop" event stops it at the event's position, which the latch
    holds. Without an event the end point is reached, nothing is latched and SD(9) gives 1. The canon
    ``probe`` call announces the move (nc/probe.py)."""
    codes = [g for g in blk.g if g in MEASURING_G]
    if len(codes) > 1:
        raise CplError("CPL040", f"G{codes[0]:g} and G{codes[1]:g} cannot stand in one block")
    code = int(codes[0])
    c, k = rt.ctl, rt.prepared_kernel()
    words = dict(blk.words)
    target = programmed_end(k, words) if code == PROBE_INPUT else None
    latch = c.probe = ProbeLatch(code)
    if code == PROBE_INPUT:
        trigger = _next_event(c, "probe")
        if trigger is not None:
            latch.position = {name: v for name, v in trigger.items() if name in k.axis_of}
            stop_words(k, words, latch.position)
    else:
        name = _measured_axis(k, words, code)
        event = _next_event(c, "probe" if code == ON_THE_FLY else "fixed_stop")
        if event is not None and name in event:
            latch.position = {name: event[name]}
            if code == FIXED_STOP:
                stop_words(k, words, latch.position)
    announce(rt.kernel.canon, latch, blk.src, target)
    out = copy.copy(blk)
    out.g, out.words = tuple(1 if x in MEASURING_G else x for x in blk.g), words
    return out


def check_probe_events(events) -> None:
    """CPL has one probe input: a probe event for another one would never switch (refused before the run)."""
    for ev in events:
        if ev.kind == "probe" and ev.input != 1:
            raise UsageError(f"scenario probe event at {ev.time:g} s: input = {ev.input}: the CPL control has "
                             f"one probe input (1)")


def _next_event(c, kind: str) -> dict | None:
    """The next unused scenario event of ``kind`` ("probe", "fixed_stop") as axis name -> MCS position; one
    per measuring block."""
    ev = c.probe_events.take(lambda e: e.kind == kind)
    return None if ev is None else ev.position


def _measured_axis(k, words, code: int) -> str:
    """G275 and G375 act on a single axis (L1449: "only one single axis is ever measured")."""
    named = [n for n in words if n in k.axis_of]
    if len(named) != 1:
        what = "on-the-fly measurement" if code == ON_THE_FLY else "measuring fixed stop"
        raise CplError("CPL040", f"G{code} ({what}) programs exactly one axis, not {len(named)}")
    return named[0]


def probe_latch(rt) -> dict | None:
    """The axis positions (MCS) measured by the last measuring block, None if nothing was measured."""
    return rt.ctl.probe.position


def _latched(rt, ax) -> float:
    if not ax.probe:
        raise CplError("CPL040", f"axis {ax.name}: MACODA 1003 00012 'probe can be activated' is not set")
    latch = probe_latch(rt)
    if latch is None:
        raise CplError("CPL040", "the probe has not switched (check SD(9) first)")
    if ax.name not in latch:
        code = rt.ctl.probe.code
        if code != PROBE_INPUT:
            raise CplError("CPL040", f"axis {ax.name} was not measured: G{code} measures only its programmed axis")
        return _executed_mcs(rt, ax)
    return latch[ax.name]


def f_probe(rt, sel, axtype=1):
    """PROBE: the probe switch point in MCS axis values (L1619-1648)."""
    ax = resolve(rt, sel, axtype)
    return to_unit(rt.kernel, ax, _latched(rt, ax))


def f_ppos(rt, sel, axtype=1):
    """PPOS: the switch point with the compensations of L1571-1576 removed: axis zero shifts, tool
    compensation and the program coordinate shifts G168/G268; G92 and the transformations stay in."""
    ax = resolve(rt, sel, axtype)
    mcs = _latched(rt, ax)
    k = rt.kernel
    i = kernel_index(rt, ax)
    if i is None:
        return mcs
    tool = k.tool_length if i == k.tool_axis else 0.0
    return to_unit(k, ax, mcs - axis_zs(rt, k, i) - tool - program_shift(rt, k, i))


def f_cprobe(rt, sel, seltype=1):
    """CPROBE: the switch point at the coordinate level (PCS): every shift, G92 included (L1430-1473). The
    probe must be enabled (MACODA 1003 00012) for every axis of the channel, not only the one read (L1441)."""
    ax = resolve(rt, sel, seltype)
    c = rt.ctl
    code = c.probe.code
    if code not in (NO_MEASUREMENT, PROBE_INPUT):
        raise CplError("CPL040", f"CPROBE cannot read a G{code} measurement: it measures a single axis (L1449)")
    blocked = [a.name for a in c.channel_axes(c.channel) if not a.probe]
    if blocked:
        raise CplError("CPL040", f"CPROBE: MACODA 1003 00012 'probe can be activated' is not set for "
                                 f"{', '.join(blocked)} (every axis of the channel needs it)")
    mcs = _latched(rt, ax)
    k = rt.kernel
    i = kernel_index(rt, ax)
    if i is None:
        return mcs
    latch = probe_latch(rt)
    switch = [latch.get(name, p) for name, p in zip(k.axis_names, rt.executed_position())]
    return to_unit(k, ax, k.program_position(switch)[i])


def probe_switched(rt) -> int:
    """SD(9) (L2229-2230): 1 = a measurement is active and the probe has not switched (G375: the fixed stop
    is not yet reached); 0 = it switched, or no measuring block has run ("G75 not active")."""
    latch = rt.ctl.probe
    return 0 if latch.position is not None or latch.code == NO_MEASUREMENT else 1
