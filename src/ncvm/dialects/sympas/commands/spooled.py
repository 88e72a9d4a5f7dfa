"""Spooled moves (SMLA ... SMCR3D), SSF and SSMS (§6.6): the axes' spoolers (spooler.py) and the chains
they run, joined at their target velocities by the look-ahead (lookahead.py)."""

from __future__ import annotations

import math

from .. import softlimits
from ..lookahead import retime
from ..motion import TICKS_PER_S, Chain
from .common import source_of
from .paths import COMMANDS as PATH_MOVES

AUTOSPOOL = 0x20  # MODEREG bit 5 (L1396)


def _spool(card, tk, items, loc, kind: str, target: bool = False):
    axes = tuple(ax for ax, _ in items)
    for ax in axes:
        card.check_axis(ax)
    sysp = dict(tk.sysp)
    entry = ("move", kind, tuple(items), source_of(tk, loc), target, sysp, card.spooler.ticket())
    cap = card.spooler.capacity
    if any(card.spooler.used(ax, tk.time) >= cap for ax in axes):
        if not card.sys["MODEREG"] & AUTOSPOOL:
            # without AutoSpool the full spooler is not started (L1396): the task waits for room, which
            # only an SSMS of another task can make (else a deadlock, RUN005)
            return _enter_after(card, tk, _wait_room(card, tk, axes, cap), axes, entry, cap, loc)
        # AutoSpool (MODEREG bit 5, L1396): with the spooler full, its processing starts and further
        # profiles are entered only when memory is free again
        ssms(card, tk, axes, loc)
        g = _wait_spool(card, tk, axes, cap)
        if g is not None:
            return _enter_after(card, tk, g, axes, entry, cap, loc)
    _enter(card, tk, axes, entry, cap, loc)
    return None


def _enter(card, tk, axes, entry, cap: int, loc) -> None:
    for ax in axes:
        card.axes[ax].spool.append(entry)
    if card.sys["MODEREG"] & AUTOSPOOL and any(card.spooler.used(ax, tk.time) >= cap for ax in axes):
        ssms(card, tk, axes, loc)  # the spooler is full now: AutoSpool starts it


def _enter_after(card, tk, wait, axes, entry, cap: int, loc):
    yield from wait
    _enter(card, tk, axes, entry, cap, loc)


def _wait_room(card, tk, axes, cap: int):
    """Wait, looking every servo cycle, until every axis of ``axes`` has a free spooler entry."""
    try:
        while any(card.spooler.used(ax, tk.time) >= cap for ax in axes):
            yield from tk.wait_until(tk.time + card.scheduler.servo)
    finally:
        tk.leaves_wait()


def _wait_spool(card, tk, axes, cap: int):
    until = card.spooler.free_at(axes, cap, tk.time)
    if until is None or until <= tk.time:
        return None
    if until < math.inf and tk.fast_wait(until):
        return None
    return _waiting_spool(card, tk, axes, cap)


def _waiting_spool(card, tk, axes, cap: int):
    try:
        while True:
            until = card.spooler.free_at(axes, cap, tk.time)
            if until is None or until <= tk.time:
                return
            # until = inf: held by TROVR = 0, as a W-wait
            yield from tk.wait_until(card.scheduler.wake_time(tk, until), ends=until)
    finally:
        tk.held = None
        tk.leaves_wait()


def smla(card, tk, items, loc):
    return _spool(card, tk, items, loc, "mla")


def smlr(card, tk, items, loc):
    return _spool(card, tk, items, loc, "mlr")


def smca(card, tk, items, loc, target=False):
    return _spool(card, tk, items, loc, "mca", target)


def smcr(card, tk, items, loc, target=False):
    return _spool(card, tk, items, loc, "mcr", target)


def smha(card, tk, items, loc, target=False):
    return _spool(card, tk, items, loc, "mha", target)


def smhr(card, tk, items, loc, target=False):
    return _spool(card, tk, items, loc, "mhr", target)


def smca3d(card, tk, items, loc, target=False):
    return _spool(card, tk, items, loc, "mca3d", target)


def smcr3d(card, tk, items, loc, target=False):
    return _spool(card, tk, items, loc, "mcr3d", target)


def ssf(card, tk, items, loc):
    code = int(tk.sysp["SSFP"])
    entry = ("ssf", code, tuple(items), loc, card.spooler.ticket())
    for ax, _ in items:
        card.check_axis(ax).spool.append(entry)
    return None


def _ssf_action(card, code: int, items):
    codes = card.cfg.ssf_codes

    def act():
        for ax, v in items:
            if code == codes["write_ci"]:
                card.ci[int(card.cfg.ssf_ci_index)] = int(v)
            elif code == codes["set_output"]:
                bit = int(v)
                if 1 <= bit <= 32:
                    card.axes[ax].digo |= 1 << (bit - 1)
    return act


def ssms(card, tk, axes, loc):
    for ax in axes:
        card.check_axis(ax).spool_halted = False
    _chain(card, tk, axes, loc)
    return None


def ssmsw(card, tk, axes, loc):
    """SSMSW waits until all spooled profiles of the axes are done (L2101-2108): behind a spooler halt
    (SSF 1000) that means until an SSMS, from another task, has run the rest too."""
    ssms(card, tk, axes, loc)
    g = card.wait_axes(tk, axes)
    if g is None and not _spooled(card, axes):
        return None
    return _wait_spooled(card, tk, axes, g)


def _spooled(card, axes) -> bool:
    return any(e[0] == "move" for ax in axes for e in card.axes[ax].spool)


def _wait_spooled(card, tk, axes, g):
    while True:
        if g is not None:
            yield from g
        if not _spooled(card, axes):
            return
        yield from tk.wait_until(tk.time + card.scheduler.servo)  # halted: look again every servo cycle
        g = card.wait_axes(tk, axes)


def _chain(card, tk, axes, loc):
    """Spooled segments run back to back; consecutive path segments join at their target
    velocity (lookahead.py) and run as one :class:`Chain` without stopping in between."""
    codes = card.cfg.ssf_codes
    saved_sysp, saved_t = tk.sysp, tk.time
    card.spooler.planning_chain = True  # under a feed hold the chain is planned at 100 % and held as a whole
    t = tk.time
    join = _running_chain(card, axes, t)
    if join is not None:  # planned from its end, then joined to it (_join); meanwhile its axes rest there
        t = join.t1
        for ax, p in zip(join.axes, join.final()):
            card.axes[ax].move = None
            card.axes[ax].m = p
    for ax in axes:
        mv = card.axes[ax].move
        if mv is not None:
            t = max(t, mv.t1)
    busy = card.cfg.busy_move
    card.cfg.busy_move = "override"
    segs, targets, ssf_after, full0 = [], [], [], None
    try:
        while True:
            # the entries run in the order they were spooled, across the axes (a square of four SMLR
            # is a square): the oldest entry at the head of a started spooler is next
            heads = [card.axes[ax].spool[0] for ax in axes
                     if card.axes[ax].spool and not card.axes[ax].spool_halted]
            e = min(heads, key=lambda h: h[-1], default=None)
            if e is None:
                break
            e_axes = [ax for ax, _ in e[2]]
            for ax in e_axes:
                sp = card.axes[ax].spool
                if e in sp:
                    sp.remove(e)
            if e[0] == "ssf":
                if e[1] == codes["spool_halt"]:
                    for ax in e_axes:
                        card.axes[ax].spool_halted = True
                elif not segs and join is None:
                    _ssf_action(card, e[1], e[2])()  # at the spooler head now: runs at once
                else:
                    ssf_after.append((len(segs), _ssf_action(card, e[1], e[2])))
                continue
            _, kind, items, eloc, target, sysp, _ = e
            tk.sysp = sysp
            tk.time = t
            if full0 is None:
                full0 = card.all_positions(t)
            for ax in e_axes:
                a = card.axes[ax]
                if a.move is not None and a.move.t1 <= t:
                    card.retire(a.move)
            fn = PATH_MOVES[kind]
            before = card.axes[e_axes[0]].move
            if kind[:2] in ("mc", "mh"):
                fn(card, tk, items, eloc, target)
            else:
                fn(card, tk, items, eloc)
            mv = card.axes[e_axes[0]].move
            if mv is not None and mv is not before:
                f, ts = card.units(tk)
                mv.retired = True  # reported by the chain when it retires, not when the next one starts
                segs.append(mv)
                targets.append(max(0.0, sysp["TRTVL"] * f / ts * mv.ovr0))
                t = mv.t1
    finally:
        card.cfg.busy_move = busy
        tk.sysp, tk.time = saved_sysp, saved_t
        card.spooler.planning_chain = False
        if join is not None:
            for ax in join.axes:
                card.axes[ax].move = join
    mode = card.sys["MODEREG"]
    for m in segs:
        m.retired = False
        card.live.discard(m)
    if join is not None:
        _join(card, tk, join, segs, targets, mode, ssf_after)
        return
    if not segs:
        return
    retime(card.axes, segs, targets, [mode] * len(segs))
    chain = Chain(segs, full0, targets, [mode] * len(segs))
    if card.path_override(chain.axes) <= 0.0:
        chain.override(chain.t0, 0.0, 0.0)
    card.live.add(chain)
    for ax in chain.axes:
        a = card.axes[ax]
        a.move = chain
    softlimits.watch(card, chain)
    for k, act in ssf_after:
        _arm_ssf(card, chain, segs[k - 1], act)


def _running_chain(card, axes, t: float):
    """The spooled chain these axes are running at ``t`` that new segments can join (the spooler
    goes on with them without stopping), or None: then they start after whatever runs."""
    moves = {id(a.move): a.move for a in (card.axes[ax] for ax in axes) if a.move is not None and a.move.t1 > t}
    if len(moves) != 1:
        return None
    mv = next(iter(moves.values()))
    return mv if isinstance(mv, Chain) and not mv.jog and mv.joinable(t) else None


def _join(card, tk, chain, segs: list, targets: list, mode: int, ssf_after: list) -> None:
    """Segments spooled and started while ``chain`` runs continue it: its segments not begun yet, and
    the running one if it has not begun its final ramp (Profile.replannable), are planned anew with
    the new ones by the look-ahead, so the axes do not stop at the old end (rw_SymPas manual L1391)."""
    now = tk.time
    sched = card.scheduler  # other tasks lag by a slice at most
    chain.prune(now - sched.slice - sched.servo, card.timeline)
    old = len(chain.segs)
    if not segs:
        for _, act in ssf_after:
            _arm_ssf(card, chain, chain.segs[old - 1], act)
        for ax in chain.axes:
            card.axes[ax].move = chain
        return
    k = next(i for i, m in enumerate(chain.segs) if now < m.t1)
    m = chain.segs[k]
    rate = m.steady_rate(now)  # an override (UTROVR) that has settled goes on as it is
    tau = m.tau(now) / TICKS_PER_S
    resume, v_start, first = None, 0.0, k + 1
    if m.prof.replannable(tau):
        resume, first = (tau, m.prof.s(tau), m.prof.speed(tau) * rate, now), k
    else:
        v_start = m.prof.v1 * rate
    j = old - 1  # segments before the last joint that was not braked for the old end keep their plan
    while j > first and chain.segs[j - 1].braked:
        j -= 1
    if j > first:
        before = chain.segs[j - 1]
        resume, v_start, first = None, before.prof.v1 * before.steady_rate(now), j
    chain.extend(segs, targets, [mode] * len(segs))
    part = chain.segs[first:]
    if part:  # (a first segment not begun yet starts at m.t1 already)
        retime(card.axes, part, chain.targets[first:], chain.moderegs[first:], v_start, resume,
               [x.steady_rate(now) for x in part])
    chain.refresh()
    for ax in chain.axes:
        card.axes[ax].move = chain
    softlimits.watch(card, chain)
    for entry in list(chain.ssf):  # SSF entries between re-planned segments act at their new ends
        seg, act, armed = entry
        if armed[0] and seg in part:
            armed[0] = False
            chain.ssf.remove(entry)
            _arm_ssf(card, chain, seg, act)
    for j, act in ssf_after:
        _arm_ssf(card, chain, chain.segs[old + j - 1], act)


def _arm_ssf(card, chain, seg, act) -> None:
    armed = [True]
    chain.ssf.append((seg, act, armed))
    _ssf_at_end(card, chain, seg, act, seg.t1, armed)


def _ssf_at_end(card, chain, seg, act, tick: float, armed: list) -> None:
    """An SSF between chained segments acts when the segment before it ends, even if UTROVR moved
    that end; not at all when a stop cut the chain before it (or a re-plan armed it anew)."""
    if tick == math.inf:  # held by TROVR = 0: armed again when UTROVR lets the chain go on
        chain.parked.append(lambda: _ssf_at_end(card, chain, seg, act, seg.t1, armed))
        return

    def fire():
        if not armed[0] or seg not in chain.segs or (seg.stop_s is not None and seg.stop_s < seg.prof.length):
            return
        if seg.t1 > tick:
            _ssf_at_end(card, chain, seg, act, seg.t1, armed)
            return
        armed[0] = False
        act()
    card.scheduler.add_timed(tick, fire)


#: the commands of this group by name (codegen calls them as _C_<name>)
COMMANDS = {
    "smla": smla, "smlr": smlr, "smca": smca, "smcr": smcr, "smha": smha, "smhr": smhr, "smca3d": smca3d,
    "smcr3d": smcr3d, "ssf": ssf, "ssms": ssms, "ssmsw": ssmsw}
