"""The card's software limits sll/slr as it enforces them (§6.3.3, L1490; EVLSS L1584-1586).

A move that would carry an axis from inside its limits across one is stopped where it gets there, with the
reaction the machine file names (``sympas.soft_limit_reaction``): SMD brakes with the axes' sdec, SMA stops
at once, TOM stops at once and turns the motor off (the position loop opens). The stop is a timed action at
the crossing; a message names the axis, the limit and the command.
"""

from __future__ import annotations

import math

from .motion import TICKS_PER_S, Chain, reach_tick

_SAMPLES = 64


def watch(card, owner) -> None:
    """Arm the stop of ``owner`` (a Move or a Chain, its times final) at its first soft-limit crossing."""
    reaction = card.cfg.soft_limit_reaction
    if reaction not in ("SMD", "TOM", "SMA"):
        return
    first = None
    for seg in (owner.segs if isinstance(owner, Chain) else (owner,)):
        for k, ax in enumerate(seg.axes):
            a = card.axes[ax]
            s = _crossing(seg, k, a.q["sll"], a.q["slr"])
            if s is not None:
                tick = reach_tick(seg, s, seg.t0)
                if first is None or tick < first[0]:
                    first = (tick, ax, seg)
    if first is None:
        return
    tick, ax, seg = first
    card.scheduler.add_timed(tick, _stop_action(card, owner, ax, seg, tick, reaction))


def _crossing(seg, k: int, lo: float, hi: float):
    """Path point s where axis k of ``seg`` first leaves [lo, hi] (it starts inside), or None."""
    L = seg.prof.length
    p0 = seg.p0[k]
    if not lo <= p0 <= hi or L <= 0.0:
        return None
    if seg.kind == "line":
        d = seg.p1[k] - p0
        if seg.p1[k] > hi:
            return L * (hi - p0) / d
        if seg.p1[k] < lo:
            return L * (lo - p0) / d
        return None
    prev = 0.0
    for i in range(1, _SAMPLES + 1):  # a circle: sample, then bisect the first piece that leaves
        s = L * i / _SAMPLES
        x = seg.point(s)[k]
        if not lo <= x <= hi:
            a, b = prev, s
            for _ in range(50):
                m = 0.5 * (a + b)
                a, b = (m, b) if lo <= seg.point(m)[k] <= hi else (a, m)
            return b
        prev = s
    return None


def _stop_action(card, owner, ax: int, seg, tick: float, reaction: str):
    def act():
        a = card.axes[ax]
        if a.move is not owner or owner.t1 <= tick:
            return
        lo, hi = a.q["sll"], a.q["slr"]
        p = card.mpos(a, tick)
        eps = 1e-6 * max(1.0, abs(p))
        if lo + eps < p < hi - eps:
            return  # re-planned since (a chain extended): armed anew by its new plan
        at_hi = p >= hi - eps
        if reaction == "SMD":
            owner.stop(tick, min(card.axes[x].q["sdec"] for x in owner.axes))
        else:
            owner.stop(tick, math.inf)
            _on_the_limit(owner, ax, hi if at_hi else lo)
        a.limit_stop = True
        fin = owner.final()
        for x in owner.axes:
            b = card.axes[x]
            b.target = fin[owner.axes.index(x)]
            b.spool.clear()
            if reaction == "TOM":
                b.closed = False
        shift = card.user_shift(a)
        limit = hi if at_hi else lo
        which = f"{'slr' if at_hi else 'sll'} = {limit - shift:g}"  # as the program reads it (A1.slr)
        if shift:
            which += f" (machine {limit:g})"
        names = ", ".join(card.names[x] for x in owner.axes)
        said = f"software limit {which} of {a.name} reached at {tick / TICKS_PER_S:.6f} s: {reaction} stops {names}"
        card.say(f"{seg.src.file}:{seg.src.line}: {said}", card.task_of(seg.src))
        # positional: a canon call takes no keywords (False: no scenario input; True: warn)
        card.canon.frozen(f"{said}: the move ends where the card stopped it, not where it was programmed", seg.src,
                          False, True)
    return act


def _on_the_limit(owner, ax: int, limit: float) -> None:
    """An immediate stop (TOM, SMA) leaves the axis on the limit itself: the stop tick is found to within
    a rounding error of the crossing, the reported end point is the crossing."""
    seg = owner.segs[-1] if isinstance(owner, Chain) else owner
    if ax in seg.axes:
        end = list(seg.final())
        end[seg.axes.index(ax)] = limit
        seg.stop_p = tuple(end)
        if isinstance(owner, Chain):
            owner.refresh()
