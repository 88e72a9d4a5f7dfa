"""Path moves (§6.6.31-46): linear interpolation, circles and helices, 3D circles.

Each ``<name>(card, tk, items, loc[, target])`` gets the (axis, value) pairs and returns None, or a
generator the task runs to wait (the W variants). Values are in PU (§6.3.1.2, L1351).
"""

from __future__ import annotations

import math
from operator import attrgetter

from ..motion import Move, rotate
from ..values import MAX_COUNTS, arc_counts, beyond_counts
from .common import scale, source_of, then_wait, user_to_machine, weight

_GET_M = attrgetter("m")


def fast_line(card, tk, items, loc, relative: bool) -> bool:
    """MLAW/MLRW when nothing else can happen during the move (one task, no events, idle axes, no
    timed action before its end, mm and s, axis numbers fixed at compile time): the same profile and
    canon call as the general path, without the bookkeeping of a running move. False: not taken."""
    if card.scheduler.solo is not tk or tk.enabled or card.live or card.active_zo or not tk.plain_units \
            or card.sys["MODEREG"] & 0x102:
        return False
    sysp = tk.sysp
    axes = card.axes
    acc = sysp["TRAC"]
    pos = list(map(_GET_M, axes))
    start = tuple(pos)
    c = card.counts
    l2 = 0.0
    ovr = math.inf
    for ax, val in items:
        if card.rotary[ax]:
            return False  # effradius and RotatoricUnit: the general path
        a = axes[ax]
        if a.ovr < ovr:
            ovr = a.ovr
        target = (a.target + val) if relative else (val + a.ref + a.zerooffset)
        q = target * c
        if not -MAX_COUNTS <= q <= MAX_COUNTS:
            beyond_counts(target)
        p = round(q) / c
        if not a.q["sll"] <= p <= a.q["slr"]:
            return False  # beyond a soft limit: the general path stops it there (softlimits.py)
        d = p - pos[ax]
        l2 += d * d
        pos[ax] = p
    v = sysp["TRVL"] * ovr
    if l2 == 0.0 or v <= 0 or acc <= 0:
        return False
    length = math.sqrt(l2)
    if length * acc >= v * v:
        end_t = tk.time + (length / v + v / acc) * 15625.0
    else:  # a triangle: the peak stays below TRVL, which is still the feed the move was programmed with
        peak = math.sqrt(length * acc)
        end_t = tk.time + 2.0 * length / peak * 15625.0
    if card.scheduler.next_timed() <= end_t or end_t == math.inf:  # a profile that never ends: refused there
        return False
    for ax, _ in items:
        a = axes[ax]
        a.m = a.target = pos[ax]
        if a.flags:
            a.flags &= ~card.refused_mask
    tk.time = end_t
    card.timeline.direct(start, tuple(pos), v * 60.0, source_of(tk, loc), end_t, length, items)
    return True


def _linear(card, tk, items, loc, relative: bool, wait: bool):
    axes = tuple(ax for ax, _ in items)
    start = card.prepare(tk, axes, loc)
    if start is None:
        return then_wait(card, tk, axes, wait)  # refused: a W form still waits for its axes (§6.5)
    f, _ = card.units(tk)
    axes, p0, p1 = user_to_machine(card, tk, items, relative, start, f)
    p1 = tuple(card.round_counts(x) for x in p1)
    nfrax = int(tk.sysp["NFRAX"])
    length = math.sqrt(sum(((b - a) * weight(card, tk, ax)) ** 2 for ax, a, b in zip(axes, p0, p1)
                           if not nfrax >> ax & 1))
    if length == 0.0:
        length = max((abs(b - a) for a, b in zip(p0, p1)), default=0.0)
    mv = Move(axes, p0, p1, "line", source_of(tk, loc), start)
    if any(nfrax >> ax & 1 or card.rotary[ax] for ax in axes) and length > 0.0:
        mv.weights = tuple(0.0 if nfrax >> ax & 1 else weight(card, tk, ax) for ax in axes)
    card.start_path(tk, mv, length, loc)  # refused or started: a W form waits for its axes either way
    return then_wait(card, tk, axes, wait)


def mla(card, tk, items, loc):
    return _linear(card, tk, items, loc, False, False)


def mlaw(card, tk, items, loc):
    return _linear(card, tk, items, loc, False, True)


def mlr(card, tk, items, loc):
    return _linear(card, tk, items, loc, True, False)


def mlrw(card, tk, items, loc):
    return _linear(card, tk, items, loc, True, True)


def _prepared(card, tk, items, loc):
    """The axes of a circle command and the card's state at its start: (axes, start positions or None when
    the card refuses the command, unit factor, start positions of the axes, their user shifts)."""
    axes = tuple(ax for ax, _ in items)
    start = card.prepare(tk, axes, loc)
    if start is None:
        return axes, None, 0.0, (), []
    f, _ = card.units(tk)
    return axes, start, f, tuple(start[ax] for ax in axes), [card.user_shift(card.axes[ax]) for ax in axes]


def _circle(card, tk, items, loc, relative: bool, wait: bool, target: bool = False):
    axes, start, f, p0, sh = _prepared(card, tk, items, loc)
    if start is None:
        return then_wait(card, tk, axes, wait)
    # the plane in path units: a rotary axis in a translational interpolation on its surface (effradius)
    w = (weight(card, tk, axes[0]), weight(card, tk, axes[1]))
    sc = (scale(card, tk, axes[0], f) * w[0], scale(card, tk, axes[1], f) * w[1])
    q0 = (p0[0] * w[0], p0[1] * w[1])
    qs = (sh[0] * w[0], sh[1] * w[1])
    vals = (items[0][1] * sc[0], items[1][1] * sc[1])
    phi_deg = tk.sysp["PHI"]
    if target:
        # target-point mode: the circle items give the end point, DTCA1/2 the centre (rw_SymPas manual L1918; L1931; L1921)
        rel_center = relative or bool(card.cfg.dtca_always_relative)
        d1, d2 = tk.sysp["DTCA1"] * sc[0], tk.sysp["DTCA2"] * sc[1]
        c = (q0[0] + d1, q0[1] + d2) if rel_center else (d1 + qs[0], d2 + qs[1])
        e = (q0[0] + vals[0], q0[1] + vals[1]) if relative else (vals[0] + qs[0], vals[1] + qs[1])
        r0 = math.hypot(q0[0] - c[0], q0[1] - c[1])
        r1 = math.hypot(e[0] - c[0], e[1] - c[1])
        if r0 == 0 or abs(r1 - r0) > 1e-3 * r0 + 1e-9:
            card.refuse(tk, axes, "radius 0" if r0 == 0 else f"the end point is not on the circle (radius {r0:g} at "
                                  f"the start, {r1:g} at the end)", loc)
            return then_wait(card, tk, axes, wait)
        a0 = math.atan2(q0[1] - c[1], q0[0] - c[0])
        a1 = math.atan2(e[1] - c[1], e[0] - c[0])
        d = a1 - a0
        if phi_deg >= 0:
            while d <= 1e-12:
                d += 2 * math.pi
            if d > 2 * math.pi + 1e-12:
                d -= 2 * math.pi
        else:
            while d >= -1e-12:
                d -= 2 * math.pi
            if d < -2 * math.pi - 1e-12:
                d += 2 * math.pi
        phi = d
    else:
        c = (q0[0] + vals[0], q0[1] + vals[1]) if relative else (vals[0] + qs[0], vals[1] + qs[1])
        phi = math.radians(phi_deg)
        a0 = math.atan2(q0[1] - c[1], q0[0] - c[0])
        r0 = math.hypot(q0[0] - c[0], q0[1] - c[1])
    radius = r0
    a_end = a0 + phi
    p1 = [(c[0] + radius * math.cos(a_end)) / w[0], (c[1] + radius * math.sin(a_end)) / w[1]]
    for k in range(2, len(axes)):  # the helix's further axes (rotary ones as on a straight line)
        val = items[k][1] * scale(card, tk, axes[k], f)
        p1.append(p0[k] + val if relative else val + sh[k])
    p1 = tuple(card.round_counts(x) for x in p1)
    nfrax = int(tk.sysp["NFRAX"])
    lin2 = sum(((p1[k] - p0[k]) * weight(card, tk, axes[k])) ** 2 for k in range(2, len(axes))
               if not nfrax >> axes[k] & 1)
    length = math.sqrt(arc_counts(radius, phi, phi_deg) ** 2 + lin2)
    mv = Move(axes, p0, p1, "arc", source_of(tk, loc), start)
    mv.center, mv.radius, mv.a0, mv.phi, mv.plane = c, radius, a0, phi, (0, 1)
    if w != (1.0, 1.0):
        mv.plane_w = w
    if w != (1.0, 1.0) or any(nfrax >> ax & 1 or card.rotary[ax] for ax in axes[2:]):
        mv.weights = w + tuple(0.0 if nfrax >> ax & 1 else weight(card, tk, ax) for ax in axes[2:])
    card.start_path(tk, mv, length, loc)  # refused or started: a W form waits for its axes either way
    return then_wait(card, tk, axes, wait)


def mca(card, tk, items, loc, target=False):
    return _circle(card, tk, items, loc, False, False, target)


def mcaw(card, tk, items, loc, target=False):
    return _circle(card, tk, items, loc, False, True, target)


def mcr(card, tk, items, loc, target=False):
    return _circle(card, tk, items, loc, True, False, target)


def mcrw(card, tk, items, loc, target=False):
    return _circle(card, tk, items, loc, True, True, target)


def _circle3d(card, tk, items, loc, relative: bool, wait: bool, target: bool = False):
    axes, start, f, p0, sh = _prepared(card, tk, items, loc)
    if start is None:
        return then_wait(card, tk, axes, wait)
    vals = [v * f for _, v in items]
    n = (tk.sysp["PN1"], tk.sysp["PN2"], tk.sysp["PN3"])
    nl = math.sqrt(sum(x * x for x in n))
    if nl == 0:
        card.refuse(tk, axes, "the plane normal PN1, PN2, PN3 is 0", loc)
        return then_wait(card, tk, axes, wait)
    n = tuple(x / nl for x in n)
    c = tuple(p0[k] + vals[k] if relative else vals[k] + sh[k] for k in range(3))
    # the centre is projected into the plane through p0 (ncvm's reading, a parallel plane through p0; the manual is silent)
    off = sum((p0[k] - c[k]) * n[k] for k in range(3))
    c = tuple(c[k] + off * n[k] for k in range(3))
    phi = math.radians(tk.sysp["PHI"])
    radius = math.sqrt(sum((p0[k] - c[k]) ** 2 for k in range(3)))
    p1 = tuple(card.round_counts(x) for x in rotate(p0, c, n, phi))
    mv = Move(axes, p0, p1, "arc3d", source_of(tk, loc), start)
    mv.center, mv.radius, mv.phi, mv.normal = c, radius, phi, n
    card.start_path(tk, mv, arc_counts(radius, phi, tk.sysp["PHI"]), loc)  # refused or started: a W form waits for its axes either way
    return then_wait(card, tk, axes, wait)


def mca3d(card, tk, items, loc, target=False):
    return _circle3d(card, tk, items, loc, False, False)


def mca3dw(card, tk, items, loc, target=False):
    return _circle3d(card, tk, items, loc, False, True)


def mcr3d(card, tk, items, loc, target=False):
    return _circle3d(card, tk, items, loc, True, False)


def mcr3dw(card, tk, items, loc, target=False):
    return _circle3d(card, tk, items, loc, True, True)


mha, mhaw, mhr, mhrw = mca, mcaw, mcr, mcrw  # helices: circles with further axes


#: the commands of this group by name (codegen calls them as _C_<name>)
COMMANDS = {
    "mla": mla, "mlaw": mlaw, "mlr": mlr, "mlrw": mlrw, "mca": mca, "mcaw": mcaw, "mcr": mcr, "mcrw": mcrw,
    "mha": mha, "mhaw": mhaw, "mhr": mhr, "mhrw": mhrw, "mca3d": mca3d, "mca3dw": mca3dw, "mcr3d": mcr3d,
    "mcr3dw": mcr3dw}
