"""PREP REF and INT SEC (@710, @711; manual §5.3.8.2, L4109-4254): contour elements and intersections.

PREP REF walks a contour sub-program one element per call (a cursor per input
register Rm, reset when Rm+3 = 1). INT SEC intersects one element with the
path from the current position to the destination written in the same block.
Coordinates are (V, H): V the 2nd axis of the plane, H the 1st (G17: Y, X).

The circle radius address (machine data, ``[sin800] radius_address``: B as in the manual's contour, or U)
on a circle is its radius; on a straight block followed by another straight block it rounds the corner
between them with that radius (the manual's ``N5 X400 Y50 B100``, L4216): PREP REF then hands out the
shortened line, the rounding (G2/G3, tangent to both) and the line from the rounding on, one element per
call. A radius next to a circle (a rounding the manual does not show) is refused.
"""

from __future__ import annotations

import math

from ...nc import arcs
from .errors import Cl800Error
from .reader import Word


def contour_elements(program, plane_axes: tuple[str, str], start: tuple[float, float], R,
                     radius: str = "B", axes=()) -> list[list[float]]:
    """[sv, sh, ev, eh, iv, ih, g, control] per element of the contour sub-program, with the roundings its
    radius words ask for. The other of B and U, when the machine has no such axis, is refused: it is the
    radius address of another machine."""
    other = "U" if radius == "B" else "B"
    h_name, v_name = plane_axes
    centre = {"X": "I", "Y": "J", "Z": "K"}
    ih_name, iv_name = centre.get(h_name, "I"), centre.get(v_name, "J")
    v, h = start
    g = 1.0
    absolute = True
    out: list[list[float]] = []
    rounding: list[float | None] = []  # the radius word of each element
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
            iv, ih = words.get(iv_name, 0.0), words.get(ih_name, 0.0)
            b = words.get(radius)
            if other in words and other not in axes:
                raise Cl800Error(f"contour block N{blk.n}: {other}{words[other]:g}: the circle radius address of this "
                                 f"machine is {radius} ([sin800] radius_address), and {other} is not one of its axes")
            if g in (2.0, 3.0) and b is not None:
                if iv_name not in words and ih_name not in words:  # a circle given by its radius
                    try:
                        ch, cv = arcs.center_from_radius(h, v, eh, ev, b, g == 2.0)
                    except arcs.ArcError as e:
                        raise Cl800Error(f"contour block N{blk.n}: {e}") from None
                    iv, ih = cv - v, ch - h
                b = None
            out.append([v, h, ev, eh, iv, ih, g, 1.0 if end17 else 0.0])
            rounding.append(b)
            v, h = ev, eh
        elif end17:
            out.append([v, h, v, h, 0.0, 0.0, g, 2.0])
            rounding.append(None)
        if end17:
            break
    return _rounded(out, rounding, radius)


def _rounded(elements: list[list[float]], rounding: list, radius: str) -> list[list[float]]:
    """The elements with a rounding arc after each straight element that has a radius word."""
    out: list[list[float]] = []
    for i, el in enumerate(elements):
        el = list(el)
        if out and out[-1][6] in (2.0, 3.0) and rounding[i - 1] is not None:
            el[0], el[1] = out[-1][2], out[-1][3]  # the line goes on from the rounding's end
        r = rounding[i]
        if r is None:
            out.append(el)
            continue
        nxt = elements[i + 1] if i + 1 < len(elements) and elements[i + 1][7] != 2.0 else None
        if el[6] not in (0.0, 1.0) or nxt is None or nxt[6] not in (0.0, 1.0):
            raise Cl800Error(f"{radius}{r:g}: a rounding is read between two straight contour blocks only; "
                             "next to a circle or at the end of the contour it is not supported by ncvm")
        arc = corner_arc((el[0], el[1]), (el[2], el[3]), (nxt[2], nxt[3]), r, radius)
        if arc is None:
            out.append(el)  # the lines go straight on: nothing to round
            continue
        el[2], el[3] = arc[0], arc[1]
        out += [el, arc]
    return out


def corner_arc(a, c, b, r: float, radius: str) -> list[float] | None:
    """The rounding of radius ``r`` at corner ``c`` between the lines a->c and c->b, points (v, h): the element
    [t1v, t1h, t2v, t2h, iv, ih, G2/G3, 0], or None when the lines go straight on."""
    if r <= 0.0:
        raise Cl800Error(f"{radius}{r:g}: a rounding needs a positive radius")
    (av, ah), (cv, ch), (bv, bh) = a, c, b
    l1, l2 = math.hypot(cv - av, ch - ah), math.hypot(bv - cv, bh - ch)
    if l1 < 1e-9 or l2 < 1e-9:
        raise Cl800Error(f"{radius}{r:g}: a rounding needs two lines of non-zero length")
    u1h, u1v = (ch - ah) / l1, (cv - av) / l1
    u2h, u2v = (bh - ch) / l2, (bv - cv) / l2
    cross = u1h * u2v - u1v * u2h  # > 0: the contour turns left (counter-clockwise in H-V)
    dot = u1h * u2h + u1v * u2v
    turn = math.atan2(abs(cross), dot)
    if turn < 1e-9:
        return None
    if math.pi - turn < 1e-9:
        raise Cl800Error(f"{radius}{r:g}: the contour turns back on itself; there is no rounding")
    t = r * math.tan(turn / 2.0)
    if t > l1 + 1e-9 or t > l2 + 1e-9:
        raise Cl800Error(f"{radius}{r:g}: the rounding needs {t:.4g} mm of each line, the lines are "
                         f"{l1:.4g} and {l2:.4g} mm long")
    t1h, t1v = ch - u1h * t, cv - u1v * t
    t2h, t2v = ch + u2h * t, cv + u2v * t
    side = 1.0 if cross > 0 else -1.0  # the centre lies left of the first line on a left turn
    oh, ov = t1h - side * u1v * r, t1v + side * u1h * r
    return [t1v, t1h, t2v, t2h, ov - t1v, oh - t1h, 3.0 if cross > 0 else 2.0, 0.0]


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
