"""The spooler's look-ahead: junction velocities of spooled path segments (rw_SymPas manual MODEREG, L1391-1398).

A segment ends with its target velocity TRTVL (L1316) and the next one starts with it, so the
axes do not stop in between. The last segment of the spooler contents ends at rest. With
LookAhead (MODEREG bit 0) the target velocity is further limited so that no axis's velocity
jumps by more than its ``mdvel`` at the joint, and a circle's path velocity to sqrt(R * maxacc).
With ChkMaxVel (bit 7) a linear segment's path velocity and acceleration are scaled so that no
axis exceeds ``maxvel`` / ``maxacc`` (NFRAX axes included). Every joint velocity is then made
reachable: a backward pass (the next segment can still brake) and a forward pass (this segment
can reach it from its start velocity). With LookAhead and NoTriangle (bit 6) a segment too short to
reach its path velocity runs on at its start velocity instead of speeding up and braking again.
"""

from __future__ import annotations

import math

from .motion import TICKS_PER_S, Profile, Resumed

LOOKAHEAD = 0x1
NOTRIANGLE = 0x40
CHKMAXVEL = 0x80


def _direction(mv, at_end: bool) -> list:
    """Axis units per path unit at the start or end of ``mv``, over all machine axes (kept on the move:
    a chain joined again and again asks for them each time)."""
    if mv.dirs is None:
        mv.dirs = (_tangent(mv, False), _tangent(mv, True))
    return mv.dirs[at_end]


def _tangent(mv, at_end: bool) -> list:
    L = mv.prof.length
    ds = L * 1e-6
    s0, s1 = (L - ds, L) if at_end else (0.0, ds)
    p0, p1 = mv.point(s0), mv.point(s1)
    u = [0.0] * len(mv.start_all)
    for k, ax in enumerate(mv.axes):
        u[ax] = (p1[k] - p0[k]) / ds
    return u


def retime(axes, segs: list, targets: list, moderegs: list, v_start: float = 0.0, resume=None,
           rates=None) -> None:
    """Give the chained moves ``segs`` (started rest to rest, back to back) their junction velocities
    and new start/end times. ``targets[k]`` is segment k's TRTVL in units/s, ``moderegs[k]`` the
    MODEREG in force when the spooler started it.

    A chain extended while it runs is planned anew from its running state: ``v_start`` is the velocity
    the first segment starts with (the end velocity of the segment before it, which keeps its plan), or
    ``resume = (tau, s, v, t)`` says that the first segment is running and is planned anew from profile
    time ``tau`` (s), where it stands at path point ``s`` with velocity ``v`` at the tick ``t``.

    ``rates[k]`` is the steady rate at which an override (UTROVR) runs segment k's profile time: the
    junctions are planned on the wall clock (velocities times the rate, accelerations times its square),
    each profile in its own time. Velocities here (``v_start``, ``targets``, resume's ``v``) are on the
    wall clock; ``targets`` are those of the segments' planning override, scaled by the rates."""
    n = len(segs)
    rates = rates or [1.0] * n
    lengths = [m.prof.length for m in segs]
    if resume is not None:
        lengths[0] -= resume[1]
        v_start = resume[2]
    vmax = []
    acc = []
    for m, mode, rate in zip(segs, moderegs, rates):
        v, a = m.vmax * rate, m.prof.a * rate * rate
        if mode & LOOKAHEAD and m.kind in ("arc", "arc3d"):
            plane = [m.axes[i] for i in m.plane] if m.kind == "arc" else list(m.axes[:3])
            w = m.plane_w or (1.0,) * len(plane)  # a rotary axis on its surface: mm per deg
            v = min(v, math.sqrt(m.radius * min(axes[ax].q["maxacc"] * wk for ax, wk in zip(plane, w))))
        if mode & CHKMAXVEL and m.kind == "line" and m.prof.length > 0:
            for k, ax in enumerate(m.axes):
                d = abs(m.p1[k] - m.p0[k]) / m.prof.length
                if d > 0:
                    v = min(v, axes[ax].q["maxvel"] / d)
                    a = min(a, axes[ax].q["maxacc"] / d)
        vmax.append(v)
        acc.append(a)
    # joint k is the end of segment k; the last one ends at rest
    vj = [0.0] * n
    for k in range(n - 1):
        v = min(targets[k] * rates[k], vmax[k], vmax[k + 1])
        if moderegs[k] & LOOKAHEAD and v > 0:
            u_out, u_in = _direction(segs[k], True), _direction(segs[k + 1], False)
            for ax, (x, y) in enumerate(zip(u_out, u_in)):
                jump = abs(y - x)
                if jump > 1e-9:
                    v = min(v, axes[ax].q["mdvel"] / jump)
        vj[k] = max(0.0, v)
    jerk = [m.prof.r for m in segs]
    ramp_acc = [a * (1.0 - 0.5 * r) for a, r in zip(acc, jerk)]  # S-ramps plan with a * (1 - jerkrel / 2)
    segs[-1].braked = True  # at rest for want of a next segment: a later join plans it anew
    for k in range(n - 2, -1, -1):  # the next segment must be able to brake to its end velocity
        brake = math.sqrt(vj[k + 1] ** 2 + 2.0 * ramp_acc[k + 1] * lengths[k + 1])
        segs[k].braked = brake < vj[k]
        vj[k] = min(vj[k], brake)
    v_in = v_start
    t = segs[0].t0
    for k, m in enumerate(segs):  # this segment must be able to reach its end velocity
        L = lengths[k]
        v_out = min(vj[k], math.sqrt(v_in * v_in + 2.0 * ramp_acc[k] * L))
        v_top = vmax[k]
        peak = math.sqrt(ramp_acc[k] * L + 0.5 * (v_in * v_in + v_out * v_out))
        if moderegs[k] & LOOKAHEAD and moderegs[k] & NOTRIANGLE and 0.0 < v_in and v_out + 1e-9 < peak < v_top:
            # NoTriangle (L1397): a segment that would speed up and brake again without reaching its path
            # velocity (a triangle) keeps its start velocity instead
            v_top = v_in
            v_out = min(v_out, v_in)
        r = rates[k]
        prof = Profile(L, v_top / r, acc[k] / (r * r), v_in / r, v_out / r, jerk[k])
        if k == 0 and resume is not None:
            m.prof = Resumed(m.prof, resume[0], resume[1], prof)  # the override goes on at its steady rate
            m.t1 = t = resume[3] + prof.duration * TICKS_PER_S / r
        else:
            m.prof = prof
            m.t0 = t
            m.warp = None if r == 1.0 else (t, 0.0, r, r, 0.0)
            m.t1 = t = t + prof.duration * TICKS_PER_S / r
        m.feed = m.vmax * 60.0  # as programmed: the joints and the card's limits are its planner's
        v_in = v_out
