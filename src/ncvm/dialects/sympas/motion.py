"""Motion profiles of the simulated card: one path parameter s(t) per move, trapezoidal in time
(S-shaped ramps with MODEREG bit 1).

A :class:`Move` is a straight line, a circle/helix in a plane, or a 3-D circle
over a group of axes, in machine coordinates and axis units (mm, deg), with a
rest-to-rest velocity profile (ncvm's reading; the rw_SymPas manual is silent). Positions at any
simulated time are computed from the profile, so waits, CLOCK and events see
the axes where they really are. A move is handed to the timeline (timeline.py) when
it retires (ends, is stopped, or the run ends), which reports it with what the other axes do meanwhile.
"""

from __future__ import annotations

import math

from ...nc.canon import Src

TICKS_PER_S = 15625.0
TWO_PI = 2.0 * math.pi


def ramp(tau: float, va: float, vb: float, T: float, r: float) -> tuple[float, float]:
    """Distance and velocity ``tau`` s into a velocity ramp va -> vb lasting T s.

    With S-profiles (MODEREG bit 1) the fraction ``r`` (jerkrel) of the ramp is jerk-limited: the
    acceleration rises linearly over r*T/2, holds, and falls over r*T/2 (r = 0: the plain linear
    ramp). The acceleration curve is symmetric, so the ramp covers (va + vb) / 2 * T either way;
    the second half is computed back from the end, which keeps both ends exact."""
    if T <= 0.0:
        return 0.0, vb
    A = (vb - va) / (T * (1.0 - 0.5 * r))  # the peak acceleration (signed)
    tj = 0.5 * r * T
    if tau > 0.5 * T:
        rho = T - tau
        if rho < tj:
            back, v = vb * rho - A * rho ** 3 / (6.0 * tj), vb - A * rho * rho / (2.0 * tj)
        else:
            vj, d = vb - 0.5 * A * tj, rho - tj
            back, v = vb * tj - A * tj * tj / 6.0 + vj * d - 0.5 * A * d * d, vj - A * d
        return 0.5 * (va + vb) * T - back, v
    if tau < tj:
        return va * tau + A * tau ** 3 / (6.0 * tj), va + A * tau * tau / (2.0 * tj)
    vj, d = va + 0.5 * A * tj, tau - tj
    return va * tj + A * tj * tj / 6.0 + vj * d + 0.5 * A * d * d, vj + A * d


class Profile:
    """Path parameter s(t) (t in seconds from the start): from start velocity ``v0`` up to at most ``v``,
    cruise, down to end velocity ``v1`` with acceleration ``a``; rest to rest unless chained.

    A spooled segment's ``v0 -> v1`` has been made reachable within ``length`` by the look-ahead
    (ncvm's reading; the rw_SymPas manual is silent). ``jerk`` is the S-profile's jerk-limited fraction of each ramp (0: trapezoid);
    it stretches each ramp so that the peak acceleration stays ``a``: the ramps plan with
    a * (1 - jerk / 2)."""

    __slots__ = ("length", "v", "a", "r", "v0", "v1", "t_acc", "t_cruise", "t_dec", "s_acc", "s_dec",
                 "duration")

    def __init__(self, length: float, v: float, a: float, v0: float = 0.0, v1: float = 0.0, jerk: float = 0.0):
        self.length, self.a, self.r, self.v0, self.v1 = length, a, jerk, v0, v1
        if length <= 0.0:
            self.v = v
            self.t_acc = self.t_cruise = self.t_dec = self.duration = self.s_acc = self.s_dec = 0.0
            return
        if a <= 0 or a == math.inf:
            self.v = v
            self.t_acc = self.t_dec = self.s_acc = self.s_dec = 0.0
            self.t_cruise = self.duration = length / v
            return
        ae = a * (1.0 - 0.5 * jerk)
        vp = max(min(v, math.sqrt(ae * length + 0.5 * (v0 * v0 + v1 * v1))), v0, v1)
        self.v = vp
        self.t_acc = (vp - v0) / ae
        self.s_acc = (vp * vp - v0 * v0) / (2.0 * ae)
        self.t_dec = (vp - v1) / ae
        self.s_dec = (vp * vp - v1 * v1) / (2.0 * ae)
        self.t_cruise = max(0.0, length - self.s_acc - self.s_dec) / vp if vp > 0 else 0.0
        self.duration = self.t_acc + self.t_cruise + self.t_dec

    @property
    def t_brake(self) -> float:
        """Profile time (s) at which the final ramp towards ``v1`` begins."""
        return self.t_acc + self.t_cruise

    def replannable(self, t: float) -> bool:
        """Whether the rest of the profile may be planned anew at ``t`` without a jump in velocity or
        (S-profile) acceleration: before the final ramp, and on S-ramps only while cruising."""
        if self.length <= 0.0 or t >= self.t_brake:
            return False
        return self.r == 0.0 or t >= self.t_acc

    def _at(self, t: float) -> tuple[float, float]:
        if t < self.t_acc:
            return ramp(t, self.v0, self.v, self.t_acc, self.r)
        t2 = t - self.t_acc
        if t2 < self.t_cruise:
            return self.s_acc + self.v * t2, self.v
        s, v = ramp(t2 - self.t_cruise, self.v, self.v1, self.t_dec, self.r)
        return min(self.length, self.s_acc + self.v * self.t_cruise + s), max(0.0, v)

    def s(self, t: float) -> float:
        if t >= self.duration:
            return self.length
        if t <= 0.0:
            return 0.0
        return self._at(t)[0]

    def speed(self, t: float) -> float:
        if t < 0.0 or t > self.duration:
            return 0.0
        return self._at(t)[1]


class Resumed:
    """A running profile planned anew at profile time ``tau`` (s): ``head`` up to there, then ``tail``
    from the path point ``s0`` it had reached (a spooled chain extended while it runs, lookahead.py)."""

    __slots__ = ("head", "tau", "s0", "tail", "length", "v", "a", "r", "v0", "v1", "duration")

    def __init__(self, head, tau: float, s0: float, tail: Profile):
        self.head, self.tau, self.s0, self.tail = head, tau, s0, tail
        self.length = head.length
        self.v = max(head.v, tail.v)
        self.a, self.r, self.v0, self.v1 = tail.a, tail.r, head.v0, tail.v1
        self.duration = tau + tail.duration

    @property
    def t_brake(self) -> float:
        return self.tau + self.tail.t_brake

    def replannable(self, t: float) -> bool:
        return t >= self.tau and self.tail.replannable(t - self.tau)

    def s(self, t: float) -> float:
        if t < self.tau:
            return self.head.s(t)
        return min(self.length, self.s0 + self.tail.s(t - self.tau))

    def speed(self, t: float) -> float:
        if t < 0.0 or t > self.duration:
            return 0.0
        return self.head.speed(t) if t < self.tau else self.tail.speed(t - self.tau)


class Move:
    """One profile over a group of axes (indices into the card's axes)."""

    __slots__ = ("axes", "p0", "p1", "kind", "t0", "t1", "prof", "center", "radius", "a0", "phi", "plane",
                 "normal", "lin", "src", "start_all", "feed", "stop_s", "stop_t", "stop_dec", "retired", "jog",
                 "homing", "vmax", "ovr0", "warp", "stop_v0", "stop_s0", "drift",
                 "weights", "plane_w", "braked", "dirs", "shift", "stop_p")

    def __init__(self, axes, p0, p1, kind, src: Src, start_all):
        self.axes = axes
        self.p0 = p0
        self.p1 = p1
        self.kind = kind  # "line", "arc", "arc3d"
        self.src = src
        self.start_all = start_all
        self.stop_s = None
        self.stop_p = None  # where a stop left the axes exactly (a soft limit, whole counts), when known
        self.retired = False
        self.jog = False
        self.weights = None  # path units per axis unit (effradius, NFRAX = 0); None: 1 for every axis
        self.dirs = None  # the look-ahead's unit tangents at the start and the end (lookahead.py)
        self.braked = False  # a chained segment whose end velocity was lowered for the segments after it
        self.plane_w = None  # a circle's plane in path units (a rotary axis on its surface): per axis unit
        self.homing = False  # a home search (JHL, JHR, JHI): a jog that a new JA/JR does not re-target
        self.drift = False  # a jog running on at jtv past its target (profile end already reported)
        self.ovr0 = 1.0  # the override the profile was planned with
        self.warp = None  # (t_w, tau_w, r_a, r_b, T): rate of profile time ramps r_a -> r_b over T ticks (TROVRST)

    def start(self, t0_ticks: float, length: float, v: float, a: float, jerk: float = 0.0) -> None:
        self.vmax = v
        self.prof = Profile(length, v, a, jerk=jerk)
        self.t0 = t0_ticks
        self.t1 = t0_ticks + self.prof.duration * TICKS_PER_S
        self.feed = v * 60.0  # the path speed programmed (TRVL), not the peak a short move's profile reaches

    # -- geometry -------------------------------------------------------------------------
    def point(self, s: float) -> tuple:
        L = self.prof.length
        f = s / L if L > 0 else 1.0
        if self.kind == "line":
            if f >= 1.0:
                return self.p1
            return tuple(a + (b - a) * f for a, b in zip(self.p0, self.p1))
        if self.kind == "arc":
            i, j = self.plane
            ang = self.a0 + self.phi * f
            out = [a + (b - a) * f for a, b in zip(self.p0, self.p1)]
            if f >= 1.0:
                out = list(self.p1)
            else:
                wi, wj = self.plane_w or (1.0, 1.0)
                out[i] = (self.center[0] + self.radius * math.cos(ang)) / wi
                out[j] = (self.center[1] + self.radius * math.sin(ang)) / wj
            return tuple(out)
        # 3-D circle: rotate (p0 - c) about the unit normal by phi*f (Rodrigues)
        if f >= 1.0:
            return self.p1
        return rotate(self.p0, self.center, self.normal, self.phi * f)

    def tau(self, t_ticks: float) -> float:
        """Profile time in ticks at wall time ``t_ticks``: the override (UTROVR) scales ds/dt."""
        w = self.warp
        if w is None:
            return t_ticks - self.t0
        tw, tauw, ra, rb, T = w
        dt = t_ticks - tw
        if dt <= 0.0:
            return tauw + ra * dt
        if dt < T:
            return tauw + ra * dt + (rb - ra) * dt * dt / (2.0 * T)
        return tauw + ra * T + 0.5 * (rb - ra) * T + rb * (dt - T)

    def rate(self, t_ticks: float) -> float:
        w = self.warp
        if w is None:
            return 1.0
        tw, _, ra, rb, T = w
        dt = t_ticks - tw
        return rb if dt >= T else ra + (rb - ra) * max(0.0, dt) / T

    def override(self, t_ticks: float, r_b: float, ramp_ticks: float) -> None:
        """From ``t_ticks`` the profile time rate ramps linearly to ``r_b`` over ``ramp_ticks`` (TROVRST)."""
        if t_ticks >= self.t1 or self.stop_s is not None:
            return
        r_b = max(r_b, 0.0)  # 0: feed hold, the path stands once the ramp is down (t1 = inf)
        tau_now = max(0.0, self.tau(t_ticks))
        r_a = self.rate(t_ticks) if t_ticks > self.t0 else self.rate(self.t0)
        if t_ticks < self.t0:  # not begun yet (a later chain segment): the ramp goes on from its start
            ramp_ticks = max(0.0, ramp_ticks - (self.t0 - t_ticks))
            t_ticks, tau_now = self.t0, 0.0
        self.warp = (t_ticks, tau_now, r_a, r_b, ramp_ticks)
        self.t1 = t_ticks + self._wall(self.prof.duration * TICKS_PER_S - tau_now, r_a, r_b, ramp_ticks)

    @staticmethod
    def _wall(rest: float, ra: float, rb: float, T: float) -> float:
        """Wall ticks to cover ``rest`` profile ticks while the rate ramps ra -> rb over T
        (infinite when a feed hold, rb = 0, stops the path before)."""
        ramp = ra * T + 0.5 * (rb - ra) * T
        if T > 0.0 and rest <= ramp:
            k = (rb - ra) / (2.0 * T)
            if abs(k) < 1e-15:
                return rest / ra if ra > 0.0 else (0.0 if rest <= 0.0 else math.inf)
            return (-ra + math.sqrt(max(0.0, ra * ra + 4.0 * k * rest))) / (2.0 * k)
        if rb <= 0.0:
            return math.inf if rest > ramp else T
        return T + (rest - ramp) / rb

    def steady_rate(self, t_ticks: float):
        """The constant rate of profile time from ``t_ticks`` on (from the start when it has not begun yet);
        None while an override ramp (TROVRST) still runs then, or under a feed hold."""
        w = self.warp
        if w is None:
            return 1.0
        tw, _, ra, rb, T = w
        if (max(t_ticks, self.t0) >= tw + T or ra == rb) and rb > 0.0:
            return rb
        return None

    def standstill(self) -> float:
        """The tick from which a feed hold (TROVR = 0) keeps this move standing; inf when not held."""
        w = self.warp
        if self.t1 < math.inf or w is None or w[3] > 0.0:
            return math.inf
        return w[0] + w[4]

    def _braking(self) -> float:
        """Seconds a stop (JS, MS) takes from stop_v0 with stop_dec, S-shaped like the profile's ramps."""
        return self.stop_v0 / (self.stop_dec * (1.0 - 0.5 * self.prof.r))

    def s_at(self, t_ticks: float) -> float:
        if self.stop_s is not None and t_ticks >= self.stop_t:
            d = self.stop_dec
            tt = (t_ticks - self.stop_t) / TICKS_PER_S
            if d <= 0 or d == math.inf:
                return self.stop_s
            T = self._braking()
            if tt >= T:
                return self.stop_s
            return self.stop_s0 + ramp(tt, self.stop_v0, 0.0, T, self.prof.r)[0]
        if self.warp is None:
            return self.prof.s((t_ticks - self.t0) / TICKS_PER_S)
        return self.prof.s(self.tau(t_ticks) / TICKS_PER_S)

    def pos(self, t_ticks: float) -> tuple:
        if t_ticks >= self.t1:
            return self.final()
        return self.point(self.s_at(t_ticks))

    def speed_at(self, t_ticks: float) -> float:
        if t_ticks >= self.t1:
            return 0.0
        if self.stop_s is not None and t_ticks >= self.stop_t:
            tt = (t_ticks - self.stop_t) / TICKS_PER_S
            T = self._braking()
            return 0.0 if tt >= T else max(0.0, ramp(tt, self.stop_v0, 0.0, T, self.prof.r)[1])
        if self.warp is None:
            return self.prof.speed((t_ticks - self.t0) / TICKS_PER_S)
        return self.prof.speed(self.tau(t_ticks) / TICKS_PER_S) * self.rate(t_ticks)

    def velocity(self, t_ticks: float, ax: int) -> float:
        """Axis ``ax``'s share of the path velocity at ``t_ticks`` (axis units/s, signed)."""
        v = self.speed_at(t_ticks)
        p0, p1 = self.pos(t_ticks), self.pos(t_ticks + 1.0)
        w = self.weights or (1.0,) * len(p0)
        d = math.sqrt(sum(((y - x) * wk) ** 2 for x, y, wk in zip(p0, p1, w)))
        if d <= 0.0:
            d = math.sqrt(sum((y - x) ** 2 for x, y in zip(p0, p1)))
        k = self.axes.index(ax)
        return v * (p1[k] - p0[k]) / d if d > 0 else 0.0

    def stop(self, t_ticks: float, dec: float) -> None:
        """Decelerate along the path with ``dec`` from ``t_ticks`` (JS, MS)."""
        if t_ticks >= self.t1:
            return
        s0 = self.s_at(t_ticks)
        v0 = self.speed_at(t_ticks)
        self.stop_s0, self.stop_v0 = s0, v0
        self.drift = False  # braking now: waits (JSW) end when it stands
        if dec <= 0 or dec == math.inf:
            self.stop_s, self.stop_t, self.stop_dec = s0, t_ticks, math.inf
            self.t1 = t_ticks
            return
        if v0 <= 0.0:  # at rest (a chained segment not begun yet): stops where it is
            self.stop_s, self.stop_t, self.stop_dec = s0, t_ticks, math.inf
            self.t1 = t_ticks
            return
        self.stop_t = t_ticks
        self.stop_dec = dec
        T = self._braking()
        self.stop_s = min(self.prof.length, s0 + 0.5 * v0 * T)
        self.t1 = t_ticks + T * TICKS_PER_S

    def final(self) -> tuple:
        if self.stop_p is not None:
            return self.stop_p
        return self.point(self.stop_s if self.stop_s is not None else self.prof.length)

    # -- reporting ----------------------------------------------------------------------------
    def emit(self, timeline) -> None:
        """Hand this move, final now, to the timeline that reports it (called once, when it retires)."""
        if self.retired:
            return
        self.retired = True
        timeline.add(self)


class Chain:
    """Spooled segments that run back to back without stopping (the spooler's look-ahead).

    It stands for all its segments on every axis they use, so positions, velocities and stops
    (JS, MS) see the segment that runs at the asked time."""

    __slots__ = ("segs", "axes", "t0", "t1", "p1", "retired", "jog", "drift", "_full0", "parked", "targets",
                 "moderegs", "ssf", "homing")

    def __init__(self, segs: list, full0: tuple, targets: list, moderegs: list):
        self.segs = segs
        self.targets, self.moderegs = targets, moderegs  # each segment's TRTVL (units/s) and MODEREG
        self._full0 = full0
        self.t0 = segs[0].t0
        self.retired = False
        self.jog = self.drift = self.homing = False
        self.parked: list = []  # timed actions waiting for a held segment's end (re-armed by UTROVR)
        self.ssf: list = []  # (segment, action, armed) of the SSF entries between segments
        self.refresh()

    def refresh(self) -> None:
        """Axes, end and end point after the segments changed (a join, a stop)."""
        self.axes = tuple(sorted({ax for m in self.segs for ax in m.axes}))
        self.t1 = self.segs[-1].t1
        self.p1 = self.final()

    def extend(self, segs: list, targets: list, moderegs: list) -> None:
        """Later spooled segments join the chain (their times are planned by the caller)."""
        self.segs.extend(segs)
        self.targets.extend(targets)
        self.moderegs.extend(moderegs)
        self.refresh()

    def prune(self, before: float, timeline) -> None:
        """Report and drop the segments that ended before ``before``, so that a chain joined again and again
        (AutoSpool) stays as short as the spooler; no one asks for times that far back any more."""
        k = 0
        while k < len(self.segs) - 1 and self.segs[k].t1 < before:
            k += 1
        if not k:
            return
        for m in self.segs[:k]:
            m.emit(timeline)
        del self.segs[:k], self.targets[:k], self.moderegs[:k]
        kept = {id(m) for m in self.segs}
        self.ssf = [e for e in self.ssf if id(e[0]) in kept]

    def joinable(self, t: float) -> bool:
        """New segments can join this chain at ``t``: it is not stopped, and its segments still to run go at
        a steady override rate (no TROVRST ramp under way, no feed hold)."""
        if self.t1 == math.inf or any(m.stop_s is not None for m in self.segs):
            return False
        return all(m.steady_rate(t) is not None for m in self.segs if m.t1 > t)

    def _seg(self, t: float):
        for m in self.segs:
            if t < m.t1:
                return m
        return self.segs[-1]

    def _full(self, m, p) -> tuple:
        full = list(m.start_all)
        for k, ax in enumerate(m.axes):
            full[ax] = p[k]
        return tuple(full[ax] for ax in self.axes)

    def pos(self, t: float) -> tuple:
        m = self._seg(t)
        return self._full(m, m.pos(t))

    def speed_at(self, t: float) -> float:
        if t >= self.t1:
            return 0.0
        return self._seg(t).speed_at(t)

    def velocity(self, t: float, ax: int) -> float:
        m = self._seg(t)
        return m.velocity(t, ax) if ax in m.axes else 0.0

    def final(self) -> tuple:
        m = self.segs[-1]
        return self._full(m, m.final())

    def stop(self, t: float, dec: float) -> None:
        if t >= self.t1:
            return
        m = self._seg(t)
        m.stop(t, dec)
        self.segs = self.segs[:self.segs.index(m) + 1]
        self.t1 = m.t1

    def override(self, t: float, ovr: float, ramp_ticks: float) -> None:
        """UTROVR on a chain: the running segment ramps, the later ones follow on at the new rate."""
        if t >= self.t1:
            return
        m = self._seg(t)
        k = self.segs.index(m)
        m.override(t, ovr / m.ovr0, ramp_ticks)
        end_ramp = t + ramp_ticks
        for prev, nxt in zip(self.segs[k:], self.segs[k + 1:]):
            nxt.t0 = nxt.t1 = prev.t1  # starts where the one before ends: never while that one is held
            if prev.t1 == math.inf:
                nxt.warp = None
                continue
            ra = prev.rate(prev.t1) * prev.ovr0 / nxt.ovr0  # segments of a joined chain may be planned apart
            nxt.warp = (nxt.t0, 0.0, ra, ra, 0.0)
            nxt.t1 = math.inf
            nxt.override(nxt.t0, ovr / nxt.ovr0, max(0.0, end_ramp - nxt.t0))
        self.t1 = self.segs[-1].t1
        parked, self.parked = self.parked, []
        for rearm in parked:
            rearm()

    def standstill(self) -> float:
        held = next((m for m in self.segs if m.t1 == math.inf), None)
        return held.standstill() if held is not None else math.inf

    def emit(self, timeline) -> None:
        if self.retired:
            return
        self.retired = True
        for m in self.segs:
            m.emit(timeline)


def rotate(p, c, n, ang):
    v = [p[k] - c[k] for k in range(3)]
    cs, sn = math.cos(ang), math.sin(ang)
    dot = n[0] * v[0] + n[1] * v[1] + n[2] * v[2]
    cross = (n[1] * v[2] - n[2] * v[1], n[2] * v[0] - n[0] * v[2], n[0] * v[1] - n[1] * v[0])
    return tuple(c[k] + v[k] * cs + cross[k] * sn + n[k] * dot * (1 - cs) for k in range(3))


def reach_tick(mv, dist: float, after: float) -> float:
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
