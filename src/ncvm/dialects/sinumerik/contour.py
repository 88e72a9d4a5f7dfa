"""PREP REF and INT SEC (@710, @711; manual §5.3.8.2, L4109-4254): contour elements and intersections.

PREP REF walks a contour sub-program one element per call (a cursor per input
register Rm, reset when Rm+3 = 1). INT SEC intersects one element with the
path from the current position to the destination written in the same block.
Coordinates are (V, H): V the 2nd axis of the plane, H the 1st (G17: Y, X).
"""

from __future__ import annotations

import math

from .errors import Cl800Error
from .reader import Word


def contour_elements(program, plane_axes: tuple[str, str], start: tuple[float, float], R) -> list[list[float]]:
    """[sv, sh, ev, eh, iv, ih, g, control] per element of the contour sub-program."""
    h_name, v_name = plane_axes
    centre = {"X": "I", "Y": "J", "Z": "K"}
    ih_name, iv_name = centre.get(h_name, "I"), centre.get(v_name, "J")
    v, h = start
    g = 1.0
    absolute = True
    out: list[list[float]] = []
    for blk in program.blocks:
        words: dict[str, float] = {}
        ms: list[int] = []
        for it in blk.items:
            if not isinstance(it, Word):
                continue
            value = it.value if it.rref is None else it.rref[0] * R[it.rref[1]]
            if value is None:
                continue
            if it.address == "G":
                if value in (0, 1, 2, 3):
                    g = float(value)
                elif value in (90, 91):
                    absolute = value == 90
            elif it.address == "M":
                ms.append(int(value))
            else:
                words[it.address] = value
        end17 = 17 in ms or 2 in ms or 30 in ms
        if h_name in words or v_name in words:
            eh = words.get(h_name, h if absolute else 0.0) + (0.0 if absolute else h)
            ev = words.get(v_name, v if absolute else 0.0) + (0.0 if absolute else v)
            out.append([v, h, ev, eh, words.get(iv_name, 0.0), words.get(ih_name, 0.0), g, 1.0 if end17 else 0.0])
            v, h = ev, eh
        elif end17:
            out.append([v, h, v, h, 0.0, 0.0, g, 2.0])
        if end17:
            break
    return out


def intersect(element: list[float], p: tuple[float, float], d: tuple[float, float]) -> tuple[float, float] | None:
    """First point (v, h) where the path p -> d meets the element (line G0/G1, arc G2/G3)."""
    sv, sh, ev, eh, iv, ih, g = element[:7]
    if g in (2.0, 3.0):
        return _segment_arc(p, d, (sv, sh), (ev, eh), (sv + iv, sh + ih), g == 2.0)
    return _segment_segment(p, d, (sv, sh), (ev, eh))


def _segment_segment(p, d, a, b):
    rx, ry = d[0] - p[0], d[1] - p[1]
    sx, sy = b[0] - a[0], b[1] - a[1]
    den = rx * sy - ry * sx
    if abs(den) < 1e-12:
        return None
    qx, qy = a[0] - p[0], a[1] - p[1]
    t = (qx * sy - qy * sx) / den
    u = (qx * ry - qy * rx) / den
    eps = 1e-9
    if -eps <= t <= 1 + eps and -eps <= u <= 1 + eps:
        return p[0] + t * rx, p[1] + t * ry
    return None


def _segment_arc(p, d, a, b, c, cw_in_vh: bool):
    rx, ry = d[0] - p[0], d[1] - p[1]
    fx, fy = p[0] - c[0], p[1] - c[1]
    radius = math.hypot(a[0] - c[0], a[1] - c[1])
    qa = rx * rx + ry * ry
    if qa < 1e-18:
        return None
    qb = 2 * (fx * rx + fy * ry)
    qc = fx * fx + fy * fy - radius * radius
    disc = qb * qb - 4 * qa * qc
    if disc < 0:
        return None
    # (v, h) is the mirror of (h, v): G2 (clockwise in H-V) is counter-clockwise in V-H
    ccw = cw_in_vh
    a0 = math.atan2(a[1] - c[1], a[0] - c[0])
    a1 = math.atan2(b[1] - c[1], b[0] - c[0])
    span = (a1 - a0) % (2 * math.pi) if ccw else (a0 - a1) % (2 * math.pi)
    if span < 1e-12:
        span = 2 * math.pi
    for t in sorted(((-qb - math.sqrt(disc)) / (2 * qa), (-qb + math.sqrt(disc)) / (2 * qa))):
        if not -1e-9 <= t <= 1 + 1e-9:
            continue
        x, y = p[0] + t * rx, p[1] + t * ry
        ang = math.atan2(y - c[1], x - c[0])
        off = (ang - a0) % (2 * math.pi) if ccw else (a0 - ang) % (2 * math.pi)
        if off <= span + 1e-9:
            return x, y
    return None


def check_window(first: int, count: int, lo_hi: tuple[tuple[int, int], ...], what: str) -> None:
    for lo, hi in lo_hi:
        if lo <= first <= hi:
            return
    raise Cl800Error(f"{what}: R{first} outside the permitted ranges "
                     f"{', '.join(f'R{lo}-R{hi}' for lo, hi in lo_hi)} ({count} registers)")
