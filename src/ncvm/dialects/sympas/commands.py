"""The card's axis commands (§6.6): path moves, jog and home, stops, spooler, zero points, filters.

Each ``cmd_<name>(tk, items, loc[, target])`` gets the axis numbers (form S) or
(axis, value) pairs (forms SP/SP+) and returns None, or a generator the task
runs to wait (the W variants). Values are in PU for path moves and in axis
units for jog and home commands (§6.3.1.2, L1351).
"""

from __future__ import annotations

import math
from operator import attrgetter

from ...nc.canon import Src
from . import recording
from .lookahead import retime
from .motion import TICKS_PER_S, Chain, Move, Profile
from .values import MAX_COUNTS, arc_counts, beyond_counts, fault

_GET_M = attrgetter("m")


class Commands:
    # -- helpers ------------------------------------------------------------------------------------
    def src(self, tk, loc: int | Src) -> Src:
        """The source place of statement ``loc`` of the task's program; a spooled move carries its
        own, since another task's SSMS may start it (the spoolers belong to the axes, not the tasks)."""
        return loc if isinstance(loc, Src) else tk.unit.srcs[loc]

    def others_running(self, tk) -> bool:
        for t in self.tasks:
            if t.state == "RUNNING" and t is not tk:
                return True
        return False

    def surface(self, tk, ax: int) -> float | None:
        """Path length per degree of a rotary axis in a translational interpolation (a length PU): the arc at
        its effradius ("Mantelflächenbearbeitung", L1450); None for any other axis or PU."""
        if not self.rotary[ax] or int(tk.sysp["PU"]) not in (0, 1, 2):
            return None
        r = float(self.axes[ax].q["effradius"])
        if r <= 0.0:
            fault(256, f"effradius of rotary axis {self.axes[ax].name} must be > 0 in a translational interpolation")
        return r * math.pi / 180.0

    def scale(self, tk, ax: int, f: float) -> float:
        """PU -> axis units of one axis of a path move: a rotary axis in a translational interpolation takes
        its target or travel as a length on its surface, or with MODEREG bit 10 (RotatoricUnit, L1401) in
        its own rotary unit."""
        r = self.surface(tk, ax)
        if r is None:
            return f
        return 1.0 if self.sys["MODEREG"] & 0x400 else f / r

    def weight(self, tk, ax: int) -> float:
        """Path units per axis unit: a rotary axis in a translational interpolation counts with its
        surface length, so the path velocity is the velocity on the surface (effradius, L1450)."""
        r = self.surface(tk, ax)
        return 1.0 if r is None else r

    def _user_to_machine(self, tk, items, relative: bool, start, f: float):
        axes = tuple(ax for ax, _ in items)
        p0 = tuple(start[ax] for ax in axes)
        p1 = []
        for ax, v in items:
            a = self.axes[ax]
            scale = self.scale(tk, ax, f)
            if relative:
                p1.append(a.target + v * scale)
            else:
                p1.append(v * scale + self.user_shift(a))
        return axes, p0, tuple(p1)

    def _wait(self, tk, axes, wait: bool):
        return self.wait_axes(tk, axes) if wait else None

    # -- linear interpolation (§6.6.43-46) ---------------------------------------------------------------
    def fast_line(self, tk, items, loc, relative: bool) -> bool:
        """MLAW/MLRW when nothing else can happen during the move (one task, no events, idle axes, no
        timed action before its end, mm and s, axis numbers fixed at compile time): the same profile and
        canon call as the general path, without the bookkeeping of a running move. False: not taken."""
        if self.solo is not tk or tk.enabled or self.live or self.active_zo or not tk.plain_units \
                or self.sys["MODEREG"] & 0x102:
            return False
        sysp = tk.sysp
        axes = self.axes
        acc = sysp["TRAC"]
        pos = list(map(_GET_M, axes))
        start = tuple(pos)
        c = self.counts
        l2 = 0.0
        ovr = math.inf
        for ax, val in items:
            if self.rotary[ax]:
                return False  # effradius and RotatoricUnit: the general path
            a = axes[ax]
            if a.ovr < ovr:
                ovr = a.ovr
            target = (a.target + val) if relative else (val + a.ref + a.zerooffset)
            q = target * c
            if not -MAX_COUNTS <= q <= MAX_COUNTS:
                beyond_counts(target)
            p = round(q) / c
            d = p - pos[ax]
            l2 += d * d
            pos[ax] = p
        v = sysp["TRVL"] * ovr
        if l2 == 0.0 or v <= 0 or acc <= 0:
            return False
        length = math.sqrt(l2)
        if length * acc >= v * v:
            end_t = tk.time + (length / v + v / acc) * 15625.0
        else:
            v = math.sqrt(length * acc)
            end_t = tk.time + 2.0 * length / v * 15625.0
        timed = self.timed
        if timed and timed[0][0] <= end_t:
            return False
        for ax, _ in items:
            a = axes[ax]
            a.m = a.target = pos[ax]
            if a.flags:
                a.flags &= ~self.refused_mask
        tk.time = end_t
        self.canon.feed(start, tuple(pos), v * 60.0, self.src(tk, loc))
        return True

    def _linear(self, tk, items, loc, relative: bool, wait: bool):
        axes = tuple(ax for ax, _ in items)
        start = self.prepare(tk, axes, loc)
        if start is None:
            return self._wait(tk, axes, wait)  # refused: a W form still waits for its axes (§6.5)
        f, _ = self.units(tk)
        axes, p0, p1 = self._user_to_machine(tk, items, relative, start, f)
        p1 = tuple(self.round_counts(x) for x in p1)
        nfrax = int(tk.sysp["NFRAX"])
        length = math.sqrt(sum(((b - a) * self.weight(tk, ax)) ** 2 for ax, a, b in zip(axes, p0, p1)
                               if not nfrax >> ax & 1))
        if length == 0.0:
            length = max((abs(b - a) for a, b in zip(p0, p1)), default=0.0)
        mv = Move(axes, p0, p1, "line", self.src(tk, loc), start)
        if any(nfrax >> ax & 1 or self.rotary[ax] for ax in axes) and length > 0.0:
            mv.weights = tuple(0.0 if nfrax >> ax & 1 else self.weight(tk, ax) for ax in axes)
        if not self.start_path(tk, mv, length, loc):
            return self._wait(tk, axes, wait)
        return self._wait(tk, axes, wait)

    def cmd_mla(self, tk, items, loc):
        return self._linear(tk, items, loc, False, False)

    def cmd_mlaw(self, tk, items, loc):
        return self._linear(tk, items, loc, False, True)

    def cmd_mlr(self, tk, items, loc):
        return self._linear(tk, items, loc, True, False)

    def cmd_mlrw(self, tk, items, loc):
        return self._linear(tk, items, loc, True, True)

    # -- circles and helices (§6.6.31-42) -------------------------------------------------------------------
    def _circle(self, tk, items, loc, relative: bool, wait: bool, target: bool = False):
        axes = tuple(ax for ax, _ in items)
        start = self.prepare(tk, axes, loc)
        if start is None:
            return self._wait(tk, axes, wait)
        f, _ = self.units(tk)
        p0 = tuple(start[ax] for ax in axes)
        sh = [self.user_shift(self.axes[ax]) for ax in axes]
        # the plane in path units: a rotary axis in a translational interpolation on its surface (effradius)
        w = (self.weight(tk, axes[0]), self.weight(tk, axes[1]))
        sc = (self.scale(tk, axes[0], f) * w[0], self.scale(tk, axes[1], f) * w[1])
        q0 = (p0[0] * w[0], p0[1] * w[1])
        qs = (sh[0] * w[0], sh[1] * w[1])
        vals = (items[0][1] * sc[0], items[1][1] * sc[1])
        phi_deg = tk.sysp["PHI"]
        if target:
            # target-point mode: the circle items give the end point, DTCA1/2 the centre (digest)
            rel_center = relative or bool(self.cfg["dtca_always_relative"])
            d1, d2 = tk.sysp["DTCA1"] * sc[0], tk.sysp["DTCA2"] * sc[1]
            c = (q0[0] + d1, q0[1] + d2) if rel_center else (d1 + qs[0], d2 + qs[1])
            e = (q0[0] + vals[0], q0[1] + vals[1]) if relative else (vals[0] + qs[0], vals[1] + qs[1])
            r0 = math.hypot(q0[0] - c[0], q0[1] - c[1])
            r1 = math.hypot(e[0] - c[0], e[1] - c[1])
            if r0 == 0 or abs(r1 - r0) > 1e-3 * r0 + 1e-9:
                for ax in axes:
                    self.axes[ax].flags |= 1 << self.cfg["axst_bits"]["refused"]
                return self._wait(tk, axes, wait)
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
            val = items[k][1] * self.scale(tk, axes[k], f)
            p1.append(p0[k] + val if relative else val + sh[k])
        p1 = tuple(self.round_counts(x) for x in p1)
        nfrax = int(tk.sysp["NFRAX"])
        lin2 = sum(((p1[k] - p0[k]) * self.weight(tk, axes[k])) ** 2 for k in range(2, len(axes))
                   if not nfrax >> axes[k] & 1)
        length = math.sqrt(arc_counts(radius, phi, phi_deg) ** 2 + lin2)
        mv = Move(axes, p0, p1, "arc", self.src(tk, loc), start)
        mv.center, mv.radius, mv.a0, mv.phi, mv.plane = c, radius, a0, phi, (0, 1)
        if w != (1.0, 1.0):
            mv.plane_w = w
        if w != (1.0, 1.0) or any(nfrax >> ax & 1 or self.rotary[ax] for ax in axes[2:]):
            mv.weights = w + tuple(0.0 if nfrax >> ax & 1 else self.weight(tk, ax) for ax in axes[2:])
        if not self.start_path(tk, mv, length, loc):
            return self._wait(tk, axes, wait)
        return self._wait(tk, axes, wait)

    def cmd_mca(self, tk, items, loc, target=False):
        return self._circle(tk, items, loc, False, False, target)

    def cmd_mcaw(self, tk, items, loc, target=False):
        return self._circle(tk, items, loc, False, True, target)

    def cmd_mcr(self, tk, items, loc, target=False):
        return self._circle(tk, items, loc, True, False, target)

    def cmd_mcrw(self, tk, items, loc, target=False):
        return self._circle(tk, items, loc, True, True, target)

    cmd_mha, cmd_mhaw, cmd_mhr, cmd_mhrw = cmd_mca, cmd_mcaw, cmd_mcr, cmd_mcrw

    def _circle3d(self, tk, items, loc, relative: bool, wait: bool, target: bool = False):
        axes = tuple(ax for ax, _ in items)
        start = self.prepare(tk, axes, loc)
        if start is None:
            return self._wait(tk, axes, wait)
        f, _ = self.units(tk)
        p0 = tuple(start[ax] for ax in axes)
        sh = [self.user_shift(self.axes[ax]) for ax in axes]
        vals = [v * f for _, v in items]
        n = (tk.sysp["PN1"], tk.sysp["PN2"], tk.sysp["PN3"])
        nl = math.sqrt(sum(x * x for x in n))
        if nl == 0:
            for ax in axes:
                self.axes[ax].flags |= 1 << self.cfg["axst_bits"]["refused"]
            return self._wait(tk, axes, wait)
        n = tuple(x / nl for x in n)
        c = tuple(p0[k] + vals[k] if relative else vals[k] + sh[k] for k in range(3))
        # the centre is projected into the plane through p0 (digest §10.5: parallel plane through p0)
        off = sum((p0[k] - c[k]) * n[k] for k in range(3))
        c = tuple(c[k] + off * n[k] for k in range(3))
        phi = math.radians(tk.sysp["PHI"])
        radius = math.sqrt(sum((p0[k] - c[k]) ** 2 for k in range(3)))
        from .motion import rotate
        p1 = tuple(self.round_counts(x) for x in rotate(p0, c, n, phi))
        mv = Move(axes, p0, p1, "arc3d", self.src(tk, loc), start)
        mv.center, mv.radius, mv.phi, mv.normal = c, radius, phi, n
        if not self.start_path(tk, mv, arc_counts(radius, phi, tk.sysp["PHI"]), loc):
            return self._wait(tk, axes, wait)
        return self._wait(tk, axes, wait)

    def cmd_mca3d(self, tk, items, loc, target=False):
        return self._circle3d(tk, items, loc, False, False)

    def cmd_mca3dw(self, tk, items, loc, target=False):
        return self._circle3d(tk, items, loc, False, True)

    def cmd_mcr3d(self, tk, items, loc, target=False):
        return self._circle3d(tk, items, loc, True, False)

    def cmd_mcr3dw(self, tk, items, loc, target=False):
        return self._circle3d(tk, items, loc, True, True)

    # -- spooled moves (SMLA ... SMHR, SSF, SSMS) ----------------------------------------------------------------
    def _spool(self, tk, items, loc, kind: str, target: bool = False):
        axes = tuple(ax for ax, _ in items)
        for ax in axes:
            self.check_axis(ax)
        sysp = dict(tk.sysp)
        entry = ("move", kind, tuple(items), self.src(tk, loc), target, sysp)
        cap = int(self.cfg["spool_capacity"])
        if any(self.spool_used(ax, tk.time) >= cap for ax in axes):
            # AutoSpool (MODEREG bit 5, L1396): with the spooler full, its processing starts and further
            # profiles are entered only when memory is free again; without the bit the task blocks as well
            self.cmd_ssms(tk, axes, loc)
            g = self._wait_spool(tk, axes, cap)
            if g is not None:
                return self._enter_after(tk, g, axes, entry, cap, loc)
        self._enter(tk, axes, entry, cap, loc)
        return None

    def _enter(self, tk, axes, entry, cap: int, loc) -> None:
        for ax in axes:
            self.axes[ax].spool.append(entry)
        if any(self.spool_used(ax, tk.time) >= cap for ax in axes):
            self.cmd_ssms(tk, axes, loc)  # the spooler is full now: AutoSpool starts it

    def _enter_after(self, tk, wait, axes, entry, cap: int, loc):
        yield from wait
        self._enter(tk, axes, entry, cap, loc)

    def chain_pending(self, ax: int, t: float) -> int:
        """Segments of axis ``ax``'s running chain not finished at ``t``: they still hold spooler memory."""
        mv = self.axes[ax].move
        if not isinstance(mv, Chain) or mv.jog or mv.t1 <= t:
            return 0
        return sum(1 for m in mv.segs if m.t1 > t and ax in m.axes)

    def spool_used(self, ax: int, t: float) -> int:
        """Spooler entries of axis ``ax`` at ``t``: the queued ones and the running chain's unfinished segments."""
        return len(self.axes[ax].spool) + self.chain_pending(ax, t)

    def _spool_free_at(self, axes, cap: int, t: float):
        """The tick from which every axis of ``axes`` has a free spooler entry (its oldest segments done);
        None when the running chains cannot free one (the rest waits behind a halt)."""
        until = t
        for ax in axes:
            over = self.spool_used(ax, t) - cap + 1
            if over <= 0:
                continue
            mv = self.axes[ax].move
            ends = [m.t1 for m in mv.segs if m.t1 > t and ax in m.axes] if isinstance(mv, Chain) else []
            if over > len(ends):
                return None
            until = max(until, ends[over - 1])
        return until

    def _wait_spool(self, tk, axes, cap: int):
        until = self._spool_free_at(axes, cap, tk.time)
        if until is None or until <= tk.time:
            return None
        if until < math.inf and tk.fast_wait(until):
            return None
        return self._waiting_spool(tk, axes, cap)

    def _waiting_spool(self, tk, axes, cap: int):
        try:
            while True:
                until = self._spool_free_at(axes, cap, tk.time)
                if until is None or until <= tk.time:
                    return
                yield from tk.wait_until(self.wake_time(tk, until), ends=until)  # inf: held by TROVR = 0, as a W-wait
        finally:
            tk.held = None
            tk.leaves_wait()

    def cmd_smla(self, tk, items, loc):
        return self._spool(tk, items, loc, "mla")

    def cmd_smlr(self, tk, items, loc):
        return self._spool(tk, items, loc, "mlr")

    def cmd_smca(self, tk, items, loc, target=False):
        return self._spool(tk, items, loc, "mca", target)

    def cmd_smcr(self, tk, items, loc, target=False):
        return self._spool(tk, items, loc, "mcr", target)

    def cmd_smha(self, tk, items, loc, target=False):
        return self._spool(tk, items, loc, "mha", target)

    def cmd_smhr(self, tk, items, loc, target=False):
        return self._spool(tk, items, loc, "mhr", target)

    def cmd_smca3d(self, tk, items, loc, target=False):
        return self._spool(tk, items, loc, "mca3d", target)

    def cmd_smcr3d(self, tk, items, loc, target=False):
        return self._spool(tk, items, loc, "mcr3d", target)

    def cmd_ssf(self, tk, items, loc):
        code = int(tk.sysp["SSFP"])
        entry = ("ssf", code, tuple(items), loc)
        for ax, _ in items:
            self.check_axis(ax).spool.append(entry)
        return None

    def _ssf_action(self, code: int, items):
        codes = self.cfg["ssf_codes"]

        def act():
            for ax, v in items:
                if code == codes["write_ci"]:
                    self.ci[int(self.cfg["ssf_ci_index"])] = int(v)
                elif code == codes["set_output"]:
                    bit = int(v)
                    if 1 <= bit <= 32:
                        self.axes[ax].digo |= 1 << (bit - 1)
        return act

    def cmd_ssms(self, tk, axes, loc):
        for ax in axes:
            self.check_axis(ax).spool_halted = False
        self._chain(tk, axes, loc)
        return None

    def cmd_ssmsw(self, tk, axes, loc):
        self.cmd_ssms(tk, axes, loc)
        return self.wait_axes(tk, axes)

    def _chain(self, tk, axes, loc):
        """Spooled segments run back to back; consecutive path segments join at their target
        velocity (lookahead.py) and run as one :class:`Chain` without stopping in between."""
        codes = self.cfg["ssf_codes"]
        saved_sysp, saved_t = tk.sysp, tk.time
        self.planning_chain = True  # under a feed hold the chain is planned at 100 % and held as a whole
        t = tk.time
        join = self._running_chain(axes, t)
        if join is not None:  # planned from its end, then joined to it (_join); meanwhile its axes rest there
            t = join.t1
            for ax, p in zip(join.axes, join.final()):
                self.axes[ax].move = None
                self.axes[ax].m = p
        for ax in axes:
            mv = self.axes[ax].move
            if mv is not None:
                t = max(t, mv.t1)
        busy = self.cfg["busy_move"]
        self.cfg["busy_move"] = "override"
        segs, targets, ssf_after, full0 = [], [], [], None
        try:
            while True:
                e = None
                for ax in axes:
                    sp = self.axes[ax].spool
                    if sp and not self.axes[ax].spool_halted:
                        e = sp[0]
                        break
                if e is None:
                    break
                e_axes = [ax for ax, _ in e[2]]
                for ax in e_axes:
                    sp = self.axes[ax].spool
                    if e in sp:
                        sp.remove(e)
                if e[0] == "ssf":
                    if e[1] == codes["spool_halt"]:
                        for ax in e_axes:
                            self.axes[ax].spool_halted = True
                    elif not segs and join is None:
                        self._ssf_action(e[1], e[2])()  # at the spooler head now: runs at once
                    else:
                        ssf_after.append((len(segs), self._ssf_action(e[1], e[2])))
                    continue
                _, kind, items, eloc, target, sysp = e
                tk.sysp = sysp
                tk.time = t
                if full0 is None:
                    full0 = self.all_positions(t)
                for ax in e_axes:
                    a = self.axes[ax]
                    if a.move is not None and a.move.t1 <= t:
                        self._finish(a.move)
                fn = getattr(self, "cmd_" + kind)
                before = self.axes[e_axes[0]].move
                if kind[:2] in ("mc", "mh"):
                    fn(tk, items, eloc, target)
                else:
                    fn(tk, items, eloc)
                mv = self.axes[e_axes[0]].move
                if mv is not None and mv is not before:
                    f, ts = self.units(tk)
                    mv.retired = True  # reported by the chain when it retires, not when the next one starts
                    segs.append(mv)
                    targets.append(max(0.0, sysp["TRTVL"] * f / ts * mv.ovr0))
                    t = mv.t1
        finally:
            self.cfg["busy_move"] = busy
            tk.sysp, tk.time = saved_sysp, saved_t
            self.planning_chain = False
            if join is not None:
                for ax in join.axes:
                    self.axes[ax].move = join
        mode = self.sys["MODEREG"]
        for m in segs:
            m.retired = False
            self.live.discard(m)
        if join is not None:
            self._join(tk, join, segs, targets, mode, ssf_after)
            return
        if not segs:
            return
        retime(self.axes, segs, targets, [mode] * len(segs))
        chain = Chain(segs, full0, targets, [mode] * len(segs))
        if self.path_override(chain.axes) <= 0.0:
            chain.override(chain.t0, 0.0, 0.0)
        self.live.add(chain)
        for ax in chain.axes:
            a = self.axes[ax]
            a.move = chain
        for k, act in ssf_after:
            self._arm_ssf(chain, segs[k - 1], act)

    def _running_chain(self, axes, t: float):
        """The spooled chain these axes are running at ``t`` that new segments can join (the spooler
        goes on with them without stopping), or None: then they start after whatever runs."""
        moves = {id(a.move): a.move for a in (self.axes[ax] for ax in axes) if a.move is not None and a.move.t1 > t}
        if len(moves) != 1:
            return None
        mv = next(iter(moves.values()))
        return mv if isinstance(mv, Chain) and not mv.jog and mv.joinable(t) else None

    def _join(self, tk, chain, segs: list, targets: list, mode: int, ssf_after: list) -> None:
        """Segments spooled and started while ``chain`` runs continue it: its segments not begun yet, and
        the running one if it has not begun its final ramp (Profile.replannable), are planned anew with
        the new ones by the look-ahead, so the axes do not stop at the old end (digest §10.5, L1391)."""
        now = tk.time
        chain.prune(now - self.slice - self.servo, self.canon, len(self.axes))  # other tasks lag by a slice at most
        old = len(chain.segs)
        if not segs:
            for _, act in ssf_after:
                self._arm_ssf(chain, chain.segs[old - 1], act)
            for ax in chain.axes:
                self.axes[ax].move = chain
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
            retime(self.axes, part, chain.targets[first:], chain.moderegs[first:], v_start, resume,
                   [x.steady_rate(now) for x in part])
        chain.refresh()
        for ax in chain.axes:
            self.axes[ax].move = chain
        for entry in list(chain.ssf):  # SSF entries between re-planned segments act at their new ends
            seg, act, armed = entry
            if armed[0] and seg in part:
                armed[0] = False
                chain.ssf.remove(entry)
                self._arm_ssf(chain, seg, act)
        for j, act in ssf_after:
            self._arm_ssf(chain, chain.segs[old + j - 1], act)

    def _arm_ssf(self, chain, seg, act) -> None:
        armed = [True]
        chain.ssf.append((seg, act, armed))
        self._ssf_at_end(chain, seg, act, seg.t1, armed)

    def _ssf_at_end(self, chain, seg, act, tick: float, armed: list) -> None:
        """An SSF between chained segments acts when the segment before it ends, even if UTROVR moved
        that end; not at all when a stop cut the chain before it (or a re-plan armed it anew)."""
        if tick == math.inf:  # held by TROVR = 0: armed again when UTROVR lets the chain go on
            chain.parked.append(lambda: self._ssf_at_end(chain, seg, act, seg.t1, armed))
            return

        def fire():
            if not armed[0] or seg not in chain.segs or (seg.stop_s is not None and seg.stop_s < seg.prof.length):
                return
            if seg.t1 > tick:
                self._ssf_at_end(chain, seg, act, seg.t1, armed)
                return
            armed[0] = False
            act()
        self.add_timed(tick, fire)

    # -- jog and home (§6.6.16-28), axis units ---------------------------------------------------------------------------
    def _jogging(self, a, t: float) -> bool:
        mv = a.move
        return mv is not None and mv.t1 > t and mv.jog and not mv.homing

    def _jog(self, tk, items, loc, relative: bool, wait: bool):
        """JA/JR: each axis jogs to its target with jac, jvl * jovr and the end velocity jtv. A new JA/JR
        on a jogging axis re-targets it on the fly (digest §10.5): it goes on from where it is with the
        velocity it has, brakes with jac and turns back when the new target lies behind its braking
        distance, and slows down with jac to a lowered jvl."""
        t = tk.time
        axes = tuple(ax for ax, _ in items)
        for ax in axes:
            self.check_axis(ax)
        self.settle(axes, t)
        moving = {ax: self.axis_velocity(self.axes[ax], t) for ax in axes if self._jogging(self.axes[ax], t)}
        start = self.prepare(tk, axes, loc, set(moving))
        if start is None:
            return self._wait(tk, axes, wait)
        src = self.src(tk, loc)
        for ax, v in items:
            a = self.axes[ax]
            if ax in moving:
                self._retire(a, t)  # cut where it is now; the new profile goes on with its velocity
            p0 = start[ax]
            if not relative and self.rotary[ax] and self.sys["MODEREG"] & 0x200:
                # ShortestRotatoricDistance (L1400): the shorter way round to the target angle
                here = p0 - self.user_shift(a)
                v = here + ((v - here + 180.0) % 360.0 - 180.0)
            p1 = self.round_counts(a.target + v if relative else v + self.user_shift(a))
            a.target = p1
            vel = a.q["jvl"] * a.q["jovr"]
            acc = a.q["jac"]
            if vel <= 0 or acc <= 0 or (p1 == p0 and not moving.get(ax)):
                continue
            jerk = self.jerk((ax,))
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
            if v1 > 0.0:  # arrive with the jog target velocity and keep moving (digest §10.5, A-60)
                self.add_timed(owner.t1, self._drift_action(a, owner, v1, 1.0 if p1 >= segs[-1].p0[0] else -1.0, src))
            a.move = owner
            self.live.add(owner)
        return self._wait(tk, axes, wait)

    def _run_on(self, a, t: float, v: float, src) -> None:
        """From ``t`` the axis runs on at the signed velocity ``v`` until a stop (JS, MS, RA) or the end of the
        run; at profile end for the W-waits (a drift)."""
        p = self.mpos(a, t)
        far = abs(v) * 1.0e6
        d = Move((a.number,), (p,), (p + math.copysign(far, v),), "line", src, self.all_positions(t))
        d.jog = True
        d.drift = True
        d.prof = Profile(far, abs(v), float(a.q["jac"]) or 1.0, abs(v), abs(v))
        d.t0, d.t1, d.feed, d.vmax = t, t + d.prof.duration * TICKS_PER_S, abs(v) * 60.0, abs(v)
        a.move = d
        self.live.add(d)

    def _drift_action(self, a, mv, v: float, sign: float, src):
        """At the jog target with jtv != 0: profile end and SAF, and the axis runs on at jtv until a stop;
        MODEREG bit 28 (JSatSAF) stops all axes with sdec, bit 11 (ForbidTargetVel) executes RS."""
        due = mv.t1

        def act():
            if a.move is not mv or mv.t1 != due:
                return  # stopped or replaced before it got there
            t = mv.t1
            self._finish(mv)
            bits = self.cfg["axst_bits"]
            a.flags |= 1 << bits["saf"]
            self._run_on(a, t, sign * v, src)
            mode = self.sys["MODEREG"]
            if mode & (1 << 11):
                self.sys["ERRORREG"] |= 1 << 1
                self.reset_system(t)
            elif mode & (1 << 28):
                self.sys["ERRORREG"] |= 1 << 19
                for b in self.axes:
                    m = b.move
                    if m is not None and m.t1 > t:
                        m.stop(t, min(self.axes[x].q["sdec"] for x in m.axes))
        return act

    def cmd_ja(self, tk, items, loc):
        return self._jog(tk, items, loc, False, False)

    def cmd_jaw(self, tk, items, loc):
        return self._jog(tk, items, loc, False, True)

    def cmd_jr(self, tk, items, loc):
        return self._jog(tk, items, loc, True, False)

    def cmd_jrw(self, tk, items, loc):
        return self._jog(tk, items, loc, True, True)

    def _home(self, tk, axes, loc, direction: int, wait: bool, limits=None):
        """JHL/JHR/JHI: search toward the REF switch (or the next index mark) at hvl; the axis is homed, and
        REF becomes its zero, when it reaches it (digest §10.5). A REF search latches lp there and brakes
        with hac, so the axis stops hvl^2 / (2 hac) behind REF; an index search stops on the mark.
        JHL/JHR/JHI only start the search (a JS before REF leaves the axis unhomed); the W forms wait."""
        t = tk.time
        start = self.prepare(tk, axes, loc)
        if start is None:
            return self._wait(tk, axes, wait)
        src = self.src(tk, loc)
        refs = self.cfg["ref_positions"]
        failed = 1 << self.cfg["axst_bits"]["home_failed"]
        for k, ax in enumerate(axes):
            a = self.axes[ax]
            p0 = start[ax]
            overrun = 0.0
            if limits is None:
                ref = float(refs.get(a.name, 0.0))
                ok = (ref - p0) * direction >= 0
                if ok and a.q["hac"] > 0:
                    overrun = direction * a.q["hvl"] ** 2 / (2.0 * a.q["hac"])
            else:
                period = float(self.cfg["index_period"])
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
                self._homed(a, ref, latch)
                continue
            mv = Move((ax,), (p0,), (end,), "line", src, start)
            mv.jog = mv.homing = True
            mv.start(t, abs(end - p0), a.q["hvl"], a.q["hac"], self.jerk((ax,)))
            a.move = mv
            self.live.add(mv)
            a.target = end
            if ok:
                self._latch_at(a, mv, abs(ref - p0), ref, latch)
            else:
                a.flags |= failed  # no index mark within the search range
        return self._wait(tk, axes, wait)

    @staticmethod
    def _homed(a, ref: float, latch: str) -> None:
        a.homed = True
        a.zerooffset = 0.0
        a.ref = ref
        a.q[latch] = 0.0

    def _latch_at(self, a, mv, dist: float, ref: float, latch: str) -> None:
        """Home axis ``a`` when its search move ``mv`` has run ``dist`` (reaches REF); not if it stops short."""

        def when_there(tick: float) -> None:
            if a.move is not mv and not mv.retired and mv.stop_s is None:
                return  # replaced by another command before REF
            if mv.s_at(tick) >= dist - 1e-9:
                self._homed(a, ref, latch)
            elif mv.t1 == math.inf or mv.s_at(mv.t1) >= dist - 1e-9:
                later = _reach_tick(mv, dist, tick)  # held or slowed by the override: look again then
                self.add_timed(later, lambda: when_there(later))

        first = _reach_tick(mv, dist, mv.t0)
        self.add_timed(first, lambda: when_there(first))

    def cmd_jhl(self, tk, axes, loc):
        return self._home(tk, axes, loc, -1, False)

    def cmd_jhlw(self, tk, axes, loc):
        return self._home(tk, axes, loc, -1, True)

    def cmd_jhr(self, tk, axes, loc):
        return self._home(tk, axes, loc, 1, False)

    def cmd_jhrw(self, tk, axes, loc):
        return self._home(tk, axes, loc, 1, True)

    def cmd_jhi(self, tk, items, loc):
        return self._home(tk, tuple(ax for ax, _ in items), loc, 1, False, [v for _, v in items])

    def cmd_jhiw(self, tk, items, loc):
        return self._home(tk, tuple(ax for ax, _ in items), loc, 1, True, [v for _, v in items])

    # -- stops ---------------------------------------------------------------------------------------------------------------
    def _stop(self, tk, axes, wait: bool, path: bool):
        t = tk.time
        for ax in axes:
            a = self.check_axis(ax)
            mv = a.move
            if mv is not None and mv.t1 > t:
                if path and self.sys["MODEREG"] & 0x8000:
                    f, ts = self.units(tk)
                    dec = tk.sysp["TRAC"] * f / (ts * ts)
                else:
                    dec = min(self.axes[x].q["sdec"] for x in mv.axes)
                mv.stop(t, dec)
                for x in mv.axes:
                    self.axes[x].target = mv.final()[mv.axes.index(x)]
            a.spool.clear()
        return self._wait(tk, axes, wait)

    def cmd_js(self, tk, axes, loc):
        return self._stop(tk, axes, False, False)

    def cmd_jsw(self, tk, axes, loc):
        return self._stop(tk, axes, True, False)

    def cmd_ms(self, tk, axes, loc):
        return self._stop(tk, axes, False, True)

    def cmd_msw(self, tk, axes, loc):
        return self._stop(tk, axes, True, True)

    # -- loop, reset, positions (§6.6.8-9, 49, 51, 55, 57, 70-71) ----------------------------------------------------------------
    def cmd_cl(self, tk, axes, loc):
        for ax in axes:
            a = self.check_axis(ax)
            a.closed = True
            a.poserr = 0.0  # bumpless: dp := rp
        return None

    def cmd_clv(self, tk, axes, loc):
        """CLV closes the loop like CL but keeps the axes' velocity (digest 6.6.9, A-51; the manual's example
        follows it with JS "then stop the axes immediately"): a running profile gives way to a run at the
        velocity the axis has, until a stop. A path cannot go on for part of its axes: all axes of a path
        move or chain run on at their share of the path velocity."""
        t = tk.time
        self.cmd_cl(tk, axes, loc)
        self.settle(axes, t)
        src = self.src(tk, loc)
        for ax in axes:
            a = self.axes[ax]
            mv = a.move
            if mv is None or mv.t1 <= t or mv.drift:
                continue
            velocities = [(self.axes[x], self.axis_velocity(self.axes[x], t)) for x in mv.axes]
            self._retire(a, t)
            for b, v in velocities:
                if v != 0.0:
                    self._run_on(b, t, v, src)
        return None

    def cmd_ol(self, tk, axes, loc):
        for ax in axes:
            a = self.check_axis(ax)
            self._retire(a, tk.time)
            a.target = a.m
            a.closed = False
        return None

    def cmd_ra(self, tk, axes, loc):
        for ax in axes:
            a = self.check_axis(ax)
            self._retire(a, tk.time)
            a.target = a.m
            a.spool.clear()
            a.flags = 0
            a.digi = a.digi
            a.ifs = 0
            a.closed = False
        return None

    def cmd_rptodp(self, tk, axes, loc):
        for ax in axes:
            a = self.check_axis(ax)
            if self.busy(a, tk.time):
                fault(256, f"RPTODP: axis {a.name} is in a profile")
            a.m = a.target = a.m - a.poserr
            a.poserr = 0.0
        return None

    def cmd_shp(self, tk, items, loc):
        for ax, v in items:
            a = self.check_axis(ax)
            self.settle((ax,), tk.time)
            m = self.mpos(a, tk.time)
            a.ref = m - v - a.zerooffset - (self.user_shift(a) - a.ref - a.zerooffset)
            a.homed = True
        return None

    def cmd_szpa(self, tk, items, loc):
        for ax, v in items:
            a = self.check_axis(ax)
            if self.sys["MODEREG"] & (1 << 27):
                a.ref += v - a.zerooffset
                a.zerooffset = 0.0
            else:
                a.zerooffset = v
        return None

    def cmd_szpr(self, tk, items, loc):
        for ax, v in items:
            a = self.check_axis(ax)
            if self.sys["MODEREG"] & (1 << 27):
                a.ref += v
            else:
                a.zerooffset += v
        return None

    def cmd_uf(self, tk, axes, loc):
        for ax in axes:
            a = self.check_axis(ax)
            a.active = dict(a.staged)
        return None

    def cmd_utrovr(self, tk, axes, loc):
        """TROVR becomes the path override of these axes ("reduzierte Bahngeschwindigkeit für Achsen A1
        und A2", L2189): their running path moves reach it linearly over TROVRST seconds (digest §10.5),
        and their later path moves, from any task, are planned with it. A group runs with the smallest
        override of its axes; 0 holds it (feed hold)."""
        ovr = max(0.0, float(tk.sysp["TROVR"]))
        ramp = max(0.0, float(tk.sysp["TROVRST"])) * 15625.0
        for ax in axes:
            self.check_axis(ax).ovr = ovr
        done = set()
        for ax in axes:
            mv = self.axes[ax].move
            if mv is not None and not mv.jog and id(mv) not in done and mv.t1 > tk.time:
                done.add(id(mv))
                group = self.path_override(mv.axes)
                if isinstance(mv, Chain):
                    mv.override(tk.time, group, ramp)
                else:
                    mv.override(tk.time, group / mv.ovr0, ramp)
        return None

    def cmd_lpr(self, tk, axes, loc):
        """LPR/LPRS: start the data recording of these axes (recording.py, §6.6.29-30)."""
        for ax in axes:
            self.check_axis(ax)
        recording.start(self, tk, axes)
        return None

    cmd_lprs = cmd_lpr


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


def _reach_tick(mv, dist: float, after: float) -> float:
    """The first tick (after ``after``) at which move ``mv`` has run ``dist`` along its path, by bisection of
    its monotonic s(t); a held move (no end) is looked at again 1000 ticks later."""
    hi = mv.t1
    if hi == math.inf:
        return after + 1000.0
    lo = after
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        if mv.s_at(mid) >= dist - 1e-9:
            hi = mid
        else:
            lo = mid
    return hi
