"""The path of an INTA block (@736, L4417-4436) and the block cut where its input stops it.

A path is timed exactly as the NC kernel times the block: G00/G01 as a straight move by its axis
deltas, G02/G03 by the arc's (or helix's) length at the speed and ramp no plane axis exceeds
anywhere on it (``nc.dynamics.arc_limits``, ``NcKernel.arc_out``). Cutting it after a fraction of its length gives the words that end the block
there; all coordinates are in program units and in the frame of the machine axes (under a
coordinate rotation the caller turns the words back into the program's frame).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable

from ...nc import arcs
from ...nc.dynamics import arc_limits, path_limits
from ...nc.kernel import PLANES


@dataclass(frozen=True)
class BlockPath:
    """One block's path: the axes that traverse, its length and the limits of its speed profile."""

    axes: tuple[str, ...]
    length: float  # mm
    speed: float  # path speed limit, mm/s
    accel: float  # path acceleration limit, mm/s^2
    cut: Callable[[float], dict]  # the axis (and centre) words that end the block at that fraction
    replaces: frozenset = frozenset()  # non-axis words the cut words stand in for


def _end(k, turned: dict, start: list[float], relative: bool) -> list[float]:
    end = list(start)
    for name, value in turned.items():
        i = k.axis_of.get(name)
        if i is not None:
            end[i] = start[i] + value if relative else value
    return end


def _axis_words(k, axes, point: list[float], start: list[float], relative: bool) -> dict:
    return {n: point[k.axis_of[n]] - start[k.axis_of[n]] if relative else point[k.axis_of[n]] for n in axes}


def straight_path(k, rapid: bool, turned: dict, start: list[float], scale: float, relative: bool,
                  feed: float) -> BlockPath | None:
    """G00 (rapid rate) or G01 (``feed`` mm/min) to the block's end point; None for G01 without a feed
    (the kernel reports it)."""
    axes = tuple(n for n in turned if n in k.axis_of)
    end = _end(k, turned, start, relative)
    deltas = [(e - s) * scale for s, e in zip(start, end)]
    length = math.sqrt(sum(d * d for d in deltas))
    if not rapid and feed <= 0.0:
        return None
    dyn = k.dyn
    v, a = path_limits(deltas, length, math.inf if rapid else feed / 60.0, dyn.rapid if rapid else dyn.max_feed,
                       dyn.accel)

    def cut(frac: float) -> dict:
        return _axis_words(k, axes, [s + frac * (e - s) for s, e in zip(start, end)], start, relative)

    return BlockPath(axes, length, v, a, cut)


def arc_path(k, cw: bool, plane: int, turned: dict, start: list[float], scale: float, relative: bool,
             feed: float) -> BlockPath | None:
    """G02/G03 (helical when other axes are programmed) at ``feed`` mm/min; None when the block is no
    arc the kernel would run (no feed, no plane axes, no centre, bad radius: the kernel then
    reports it)."""
    an, bn, _n, iw, jw = PLANES[plane]
    if feed <= 0.0 or an not in k.axis_of or bn not in k.axis_of:
        return None
    a, b = k.axis_of[an], k.axis_of[bn]
    end = _end(k, turned, start, relative)
    sa, sb, ea, eb = start[a], start[b], end[a], end[b]
    try:
        if "R" in turned and iw not in turned and jw not in turned:
            ca, cb = arcs.center_from_radius(sa, sb, ea, eb, turned["R"], cw)
        elif iw in turned or jw in turned:
            ca, cb = sa + turned.get(iw, 0.0), sb + turned.get(jw, 0.0)
        else:
            return None
        radius = arcs.check_radii(sa, sb, ea, eb, ca, cb)
    except arcs.ArcError:
        return None
    turns = max(0, int(turned.get("P", 1)) - 1)
    sweep = arcs.sweep(sa, sb, ea, eb, ca, cb, cw, turns)
    helix = math.sqrt(sum((e - s) ** 2 for i, (s, e) in enumerate(zip(start, end)) if i not in (a, b)))
    length = arcs.arc_length(radius, sweep, helix) * scale
    v, acc = arc_limits([(e - s) * scale for s, e in zip(start, end)], a, b, length, feed / 60.0, k.dyn.max_feed, k.dyn.accel)
    axes = tuple(dict.fromkeys((an, bn, *(n for n in turned if n in k.axis_of))))
    a0 = math.atan2(sb - cb, sa - ca)

    def cut(frac: float) -> dict:
        """A helix has a constant pitch: a fraction of its length is that fraction of the sweep and of
        the linear axes' travel. The cut arc keeps the centre (I/J/K from the start point)."""
        angle = frac * sweep
        point = [s + frac * (e - s) for s, e in zip(start, end)]
        point[a], point[b] = ca + radius * math.cos(a0 + angle), cb + radius * math.sin(a0 + angle)
        turns = abs(angle) / arcs.TWO_PI
        if math.hypot(point[a] - sa, point[b] - sb) < arcs.SAME_POINT:  # the kernel reads a full circle
            passes = round(turns)
            if not passes:
                return {}  # stopped before it moved: no motion at all
        else:
            passes = math.floor(turns) + 1
        words = _axis_words(k, axes, point, start, relative)
        words[iw], words[jw] = ca - sa, cb - sb
        if passes > 1:
            words["P"] = float(passes)
        return words

    return BlockPath(axes, length, v, acc, cut, frozenset(("R", "P", iw, jw)))
