"""Jog and home (§6.6.16-28), in axis units: JA/JR with re-targeting on the fly and the jog target
velocity, the REF and index searches."""

from __future__ import annotations

import math

from .. import softlimits
from ..motion import TICKS_PER_S, Chain, Move, Profile, reach_tick
from .common import source_of, then_wait


def _jogging(card, a, t: float) -> bool:
    mv = a.move
    return mv is not None and mv.t1 > t and mv.jog and not mv.homing


def _jog(card, tk, items, loc, relative: bool, wait: bool):
    """JA/JR: each axis jogs to its target with jac, jvl * jovr and the end velocity jtv. A new JA/JR
    on a jogging axis re-targets it on the fly (ncvm's reading; the rw_SymPas manual is silent): it goes on from where it is with the
    velocity it has, brakes with jac and turns back when the new target lies behind its braking
    distance, and slows down with jac to a lowered jvl."""
    t = tk.time
    axes = tuple(ax for ax, _ in items)
    for ax in axes:
        card.check_axis(ax)
    card.settle(axes, t)
    moving = {ax: card.axis_velocity(card.axes[ax], t) for ax in axes if _jogging(card, card.axes[ax], t)}
    start = card.prepare(tk, axes, loc, set(moving))
    if start is None:
        return then_wait(card, tk, axes, wait)
    src = source_of(tk, loc)
    for ax, v in items:
        a = card.axes[ax]
        if ax in moving:
            card.retire_axis(a, t)  # cut where it is now; the new profile goes on with its velocity
        p0 = start[ax]
        if not relative and card.rotary[ax] and card.sys["MODEREG"] & 0x200:
            # ShortestRotatoricDistance (L1400): the shorter way round to the target angle
            here = p0 - card.user_shift(a)
            v = here + ((v - here + 180.0) % 360.0 - 180.0)
        p1 = card.round_counts(a.target + v if relative else v + card.user_shift(a))
        a.target = p1
        vel = a.q["jvl"] * a.q["jovr"]
        acc = a.q["jac"]
        if vel <= 0 or acc <= 0 or (p1 == p0 and not moving.get(ax)):
            continue
        jerk = card.jerk((ax,))
        jtv = abs(float(a.q["jtv"]))
        segs, v1 = [], 0.0
        for q0, q1, prof in jog_plan(p0, p1, moving.get(ax, 0.0), vel, acc, jerk, jtv):
            mv = Move((ax,), (q0,), (q1,), "line", src, start)
            mv.jog = True
            mv.prof, mv.vmax, mv.feed = prof, vel, prof.v * 60.0
            mv.t0 = segs[-1].t1 if segs else t
            mv.t1 = mv.t0 + prof.duration * TICKS_PER_S
            segs.append(mv)
            v1 = prof.v1
        owner = segs[0]
        if len(segs) > 1:
            owner = Chain(segs, start, [0.0] * len(segs), [0] * len(segs))
            owner.jog = True
        if v1 > 0.0:  # arrive with the jog target velocity and keep moving (rw_SymPas manual L1733; L1404; L1414)
            sign = 1.0 if p1 >= segs[-1].p0[0] else -1.0
            card.scheduler.add_timed(owner.t1, _drift_action(card, a, owner, v1, sign, src))
        a.move = owner
        card.live.add(owner)
        softlimits.watch(card, owner)
    return then_wait(card, tk, axes, wait)


def new_override(card, tk, ax: int) -> None:
    """A new jovr of a jogging axis acts on the running jog: it goes on to its target with jvl * jovr from
    the velocity it has (re-planned as a JA to the same target)."""
    a = card.axes[ax]
    mv = a.move
    if not _jogging(card, a, tk.time) or mv.drift:
        return
    src = (mv.segs[-1] if isinstance(mv, Chain) else mv).src
    g = _jog(card, tk, ((ax, a.target - card.user_shift(a)),), src, False, False)
    assert g is None  # not a W form: it does not wait


def run_on(card, a, t: float, v: float, src) -> None:
    """From ``t`` the axis runs on at the signed velocity ``v`` until a stop (JS, MS, RA) or the end of the
    run; at profile end for the W-waits (a drift)."""
    p = card.mpos(a, t)
    far = abs(v) * 1.0e6
    d = Move((a.number,), (p,), (p + math.copysign(far, v),), "line", src, card.all_positions(t))
    d.jog = True
    d.drift = True
    d.prof = Profile(far, abs(v), float(a.q["jac"]) or 1.0, abs(v), abs(v))
    d.t0, d.t1, d.feed, d.vmax = t, t + d.prof.duration * TICKS_PER_S, abs(v) * 60.0, abs(v)
    a.move = d
    card.live.add(d)


def _drift_action(card, a, mv, v: float, sign: float, src):
    """At the jog target with jtv != 0: profile end and SAF, and the axis runs on at jtv until a stop;
    MODEREG bit 28 (JSatSAF) stops all axes with sdec, bit 11 (ForbidTargetVel) executes RS."""
    due = mv.t1

    def act():
        if a.move is not mv or mv.t1 != due:
            return  # stopped or replaced before it got there
        t = mv.t1
        card.retire(mv)
        bits = card.cfg.axst_bits
        a.flags |= 1 << bits["saf"]
        run_on(card, a, t, sign * v, src)
        mode = card.sys["MODEREG"]
        if mode & (1 << 11):
            card.sys["ERRORREG"] |= 1 << 1
            card.say(f"{src.file}:{src.line}: RS: system reset by ForbidTargetVel (MODEREG bit 11): "
                     f"{a.name} reached its jog target with jtv", card.task_of(src))
            card.session.extra["ended"] = f"ended by RS (system reset) at {src.file}:{src.line}"
            card.reset_system(t)
        elif mode & (1 << 28):
            card.sys["ERRORREG"] |= 1 << 19
            for b in card.axes:
                m = b.move
                if m is not None and m.t1 > t:
                    m.stop(t, min(card.axes[x].q["sdec"] for x in m.axes))
    return act


def ja(card, tk, items, loc):
    return _jog(card, tk, items, loc, False, False)


def jaw(card, tk, items, loc):
    return _jog(card, tk, items, loc, False, True)


def jr(card, tk, items, loc):
    return _jog(card, tk, items, loc, True, False)


def jrw(card, tk, items, loc):
    return _jog(card, tk, items, loc, True, True)


def _home(card, tk, axes, loc, direction: int, wait: bool, limits=None):
    """JHL/JHR/JHI: search toward the REF switch (or the next index mark) at hvl; the axis is homed, and
    REF becomes its zero, when it reaches it (ncvm's reading; the rw_SymPas manual is silent). A REF search latches lp there and brakes
    with hac, so the axis stops hvl^2 / (2 hac) behind REF; an index search stops on the mark.
    JHL/JHR/JHI only start the search (a JS before REF leaves the axis unhomed); the W forms wait."""
    t = tk.time
    start = card.prepare(tk, axes, loc)
    if start is None:
        return then_wait(card, tk, axes, wait)
    src = source_of(tk, loc)
    refs = card.cfg.ref_positions
    failed = 1 << card.cfg.axst_bits["home_failed"]
    for k, ax in enumerate(axes):
        a = card.axes[ax]
        p0 = start[ax]
        overrun = 0.0
        if limits is None:
            ref = float(refs.get(a.name, 0.0))
            ok = (ref - p0) * direction >= 0
            if ok and a.q["hac"] > 0:
                overrun = direction * a.q["hvl"] ** 2 / (2.0 * a.q["hac"])
        else:
            period = float(card.cfg.index_period)
            d = 1 if limits[k] >= 0 else -1
            ref = (math.floor(p0 / period) + 1) * period if d > 0 else (math.ceil(p0 / period) - 1) * period
            ok = abs(ref - p0) <= abs(limits[k])
            if not ok:
                ref = p0 + limits[k]
        if not ok and limits is None:
            a.flags |= failed
            continue
        a.flags &= ~failed
        latch = "lp" if limits is None else "lpndx"
        end = ref + overrun
        if abs(ref - p0) == 0.0:  # already on REF: latched at once, nothing moves
            _homed(card, a, ref, latch)
            continue
        mv = Move((ax,), (p0,), (end,), "line", src, start)
        mv.jog = mv.homing = True
        mv.start(t, abs(end - p0), a.q["hvl"], a.q["hac"], card.jerk((ax,)))
        a.move = mv
        card.live.add(mv)
        a.target = end
        if ok:
            _latch_at(card, a, mv, abs(ref - p0), ref, latch)
        else:
            a.flags |= failed  # no index mark within the search range
    return then_wait(card, tk, axes, wait)


def _homed(card, a, ref: float, latch: str) -> None:
    a.homed = True
    a.zerooffset = 0.0
    a.ref = ref
    card.zero_moved()
    a.q[latch] = 0.0


def _latch_at(card, a, mv, dist: float, ref: float, latch: str) -> None:
    """Home axis ``a`` when its search move ``mv`` has run ``dist`` (reaches REF); not if it stops short."""

    def when_there(tick: float) -> None:
        if a.move is not mv and not mv.retired and mv.stop_s is None:
            return  # replaced by another command before REF
        if mv.s_at(tick) >= dist - 1e-9:
            _homed(card, a, ref, latch)
        elif mv.t1 == math.inf or mv.s_at(mv.t1) >= dist - 1e-9:
            later = reach_tick(mv, dist, tick)  # held or slowed by the override: look again then
            card.scheduler.add_timed(later, lambda: when_there(later))

    first = reach_tick(mv, dist, mv.t0)
    card.scheduler.add_timed(first, lambda: when_there(first))


def jhl(card, tk, axes, loc):
    return _home(card, tk, axes, loc, -1, False)


def jhlw(card, tk, axes, loc):
    return _home(card, tk, axes, loc, -1, True)


def jhr(card, tk, axes, loc):
    return _home(card, tk, axes, loc, 1, False)


def jhrw(card, tk, axes, loc):
    return _home(card, tk, axes, loc, 1, True)


def jhi(card, tk, items, loc):
    return _home(card, tk, tuple(ax for ax, _ in items), loc, 1, False, [v for _, v in items])


def jhiw(card, tk, items, loc):
    return _home(card, tk, tuple(ax for ax, _ in items), loc, 1, True, [v for _, v in items])


#: the commands of this group by name (codegen calls them as _C_<name>)
COMMANDS = {
    "ja": ja, "jaw": jaw, "jr": jr, "jrw": jrw, "jhl": jhl, "jhlw": jhlw, "jhr": jhr, "jhrw": jhrw, "jhi":
    jhi, "jhiw": jhiw}


def jog_plan(p0: float, p1: float, v0: float, vel: float, acc: float, jerk: float, jtv: float) -> list:
    """Pieces ``(from, to, Profile)`` of a jog from ``p0`` (signed velocity ``v0``) to ``p1`` with velocity
    ``vel``, acceleration ``acc`` and end velocity ``jtv``: a target behind the braking distance is reached by
    braking to rest and turning back; a velocity above ``vel`` is first brought down to it."""
    ae = acc * (1.0 - 0.5 * jerk)  # S-ramps plan with acc * (1 - jerkrel / 2)
    pieces = []
    w = abs(v0)
    if w > 0.0:
        u = 1.0 if v0 > 0.0 else -1.0
        ahead = (p1 - p0) * u
        brake = w * w / (2.0 * ae)
        if ahead < brake:
            q = p0 + u * brake
            pieces.append((p0, q, Profile(brake, w, acc, w, 0.0, jerk)))
            p0, w = q, 0.0
        elif w > vel:
            d = (w * w - vel * vel) / (2.0 * ae)
            q = p0 + u * d
            pieces.append((p0, q, Profile(d, w, acc, w, vel, jerk)))
            p0, w = q, vel
    L = abs(p1 - p0)
    if L > 0.0:
        v1 = min(jtv, math.sqrt(w * w + 2.0 * ae * L)) if jtv > 0.0 else 0.0
        pieces.append((p0, p1, Profile(L, max(vel, v1), acc, w, v1, jerk)))
    return pieces
