"""Cutter radius compensation: G41 (tool left of the contour), G42 (right), G40 (off).

The tool centre runs a tool radius beside the programmed contour, by the rules
of LinuxCNC's interpreter (the reference for ``din``), all in the plane of G17
or G18 and in machine coordinates of its two axes:

- entry: the first move after G41/G42 is a straight line from where the tool
  stands to the point a radius beside its programmed end, square to the
  programmed direction; it must be longer than the radius;
- every element is offset by the radius: a line parallel, an arc concentric
  (a tool inside an arc needs an arc radius larger than its own);
- outside (convex) corner: the tool rolls around the programmed corner on an
  arc of the tool radius (a rapid goes there straight);
- inside (concave) corner: the element before ends where the two offset
  elements meet -- two lines, a line and an arc, two arcs; an element that
  would have to run backwards to get there gouges, and the run stops;
- G40: the last element ends a radius beside its programmed end; the next
  move (a straight one) runs from there to its programmed point.

Where an element ends depends on the next one, so the last element is held
back; what the block after it sends besides moves (dwell, M functions,
spindle, coolant, messages) waits behind it, so everything leaves in program
order. A program stop or end, and G40, let it go at its offset end point.
"""

from __future__ import annotations

import math

from .canon import ArcSpec, Src

#: corners within this angle (radians) of straight count as tangent (LinuxCNC's concave-corner tolerance)
SMALL = 0.05
#: how far (mm) a shortened arc may sweep beyond its programmed sweep at an inside corner
SWEEP_SLACK = 0.0254
HALF_PI, TWO_PI = math.pi / 2.0, 2.0 * math.pi
LEFT, RIGHT = 1, -1
#: G codes that change what compensation is computed from; refused while it is on
_REFUSED_G = {53: "G53 (machine coordinates)", 54: "a zero offset change", 55: "a zero offset change",
              56: "a zero offset change", 57: "a zero offset change", 58: "a zero offset change",
              59: "a zero offset change", 92: "G92 (set position)", 92.1: "G92.1 (cancel G92)",
              10: "G10 (offset tables)", 43: "G43 (tool length)", 44: "G44 (tool length)", 49: "G49 (tool length)"}
_DEFERRED = ("message", "dwell", "spindle", "coolant", "aux", "probe", "tool_offset", "frame", "feed_per_rev")


def iso_radius(kernel, g: int, words, src: Src) -> float:
    """ISO / LinuxCNC: D names the tool whose radius counts (a whole number); without D, or with D0, the tool
    in the spindle (rs274 2.9 does so for D0); no tool in the spindle: radius 0."""
    number = kernel.tool
    if "D" in words:
        d = words["D"]
        if d != int(d) or d < 0:
            kernel.fault("NC012", f"G{g}: D{d:g} must name a tool by a whole number >= 0", src)
        number = int(d) or kernel.tool
    return kernel._tool(number, src).radius if number else 0.0


def dynamic_radius(kernel, g: float, words, src: Src) -> float:
    """LinuxCNC's G41.1/G42.1 D<diameter>: the radius is half the D word (in the program's units), no tool
    table; the L word (a lathe tool's orientation) is not modelled."""
    if "D" not in words:
        kernel.fault("NC012", f"G{g:g} needs the tool diameter as a D word (G{g:g} D10)", src)
    if words.get("L", 0.0):
        kernel.fault("NC005", f"G{g:g} L{words['L']:g}: the orientation of a lathe tool is not supported by ncvm",
                     src)
    return words["D"] * kernel.scale / 2.0


def refusal(what: str):
    """A radius source for a control whose tool data ncvm does not read for compensation yet: NC005 naming it."""
    def refuse(kernel, g: int, words, src: Src) -> float:
        kernel.fault("NC005", f"G{g}: cutter radius compensation needs {what}, which ncvm does not read yet", src)
    return refuse


def select(kernel, g: int, words, src: Src) -> None:
    """G40, G41 or G42 in a block (before the block's move, which it applies to)."""
    comp = kernel.comp
    if g == 40:
        if comp is not None:
            comp.cancel()
        return
    if comp is not None and not comp.leaving:
        kernel.fault("NC012", f"G{g}: cutter radius compensation is on already (G40 first)", src)
    if kernel.plane not in (17, 18):
        kernel.fault("NC012", f"G{g}: cutter radius compensation works in the G17 or G18 plane, not G{kernel.plane}",
                     src)
    if kernel.plane_mirrored or kernel.plane_unknown:
        kernel.fault("NC012", f"G{g}: cutter radius compensation in a G16 plane other than G17's or G18's is "
                     "not supported by ncvm", src)
    if kernel.transform is not None:
        kernel.fault("NC005", f"G{g}: cutter radius compensation under a coordinate transformation is not "
                     "supported by ncvm", src)
    radius = (dynamic_radius if g in (41.1, 42.1) else kernel.cutter_radius)(kernel, g, words, src)
    side = LEFT if g in (41, 41.1) else RIGHT
    if radius < 0.0:  # a negative radius puts the tool on the other side
        radius, side = -radius, -side
    if comp is not None:
        comp.detach()
    if radius:
        kernel.canon.radius_compensation(g, radius, src)
    CutterComp(kernel, side, radius).g = g


def active_g(kernel) -> int:
    """The G function of the compensation group in force: 40, 41, 42, 41.1 or 42.1 (as programmed)."""
    comp = kernel.comp
    return 40 if comp is None or comp.leaving else comp.g


class CutterComp:
    """The compensation of one G41/G42 ... G40 stretch: the held moves and the geometry of the next one."""

    def __init__(self, kernel, side: int, radius: float):
        from .kernel import PLANES
        self.kernel = kernel
        self.side = side
        self.radius = radius
        self.g = 41 if side == LEFT else 42  # as programmed (select sets it)
        an, bn = PLANES[kernel.plane][:2]
        if an not in kernel.axis_of or bn not in kernel.axis_of:
            kernel.fault("NC009", f"plane G{kernel.plane} needs axes {an} and {bn}", None)
        self.a, self.b = kernel.axis_of[an], kernel.axis_of[bn]
        self.first = True  # the next move is the entry move
        self.leaving = False  # after G40: the next move must be straight, then compensation is gone
        pos = kernel.machine_pos
        self.cur = (pos[self.a], pos[self.b])  # where the tool centre will be once the held moves are out
        self.prog_pt = self.cur  # the programmed point there
        self.queue: list = []  # held moves (_Held) and canon calls (callable, args), in program order
        self.start = self.cur  # the plane position the first held move starts from (LinuxCNC's end point)
        self.start_valid = False
        self.emitted = pos  # the end of the last move that left
        self.canon = kernel.canon
        kernel.comp = self
        kernel.canon = _HeldCanon(self, self.canon)
        kernel.linear = _compensated_linear

    # -- the kernel's hooks ----------------------------------------------
    def check_block(self, block) -> None:
        """Refuse what would change the geometry compensation works on (as LinuxCNC does)."""
        k = self.kernel
        if self.leaving or 40 in block.g:  # G40 comes first in its block
            return
        for g in block.g:
            what = _REFUSED_G.get(g)
            if what is None and g in (17, 18, 19) and g != k.plane:
                what = "a plane change"
            if what is not None:
                k.fault("NC012", f"{what} is not allowed while cutter radius compensation is on (G40 first)",
                        block.src)
        if 6 in block.m:
            k.fault("NC012", "a tool change (M6) is not allowed while cutter radius compensation is on (G40 first)",
                    block.src)

    def move(self, motion: int, words, src: Src) -> None:
        k = self.kernel
        prog, moved = k._target(words, False)
        if not moved and not (motion >= 2 and any(w in words for w in "IJK")):
            return
        if self.leaving:
            if motion >= 2:
                k.fault("NC012", "the move after G40 must be straight, not an arc", src)
            self.detach()
            k._general_move(motion, words, False, src)
            return
        if self.radius == 0.0:  # no radius, nothing to compensate (as LinuxCNC)
            self.emitted = k.machine_pos
            self.kernel.comp = None
            try:
                k._general_move(motion, words, False, src)
            finally:
                self.kernel.comp = self
            return
        if motion and k.feed <= 0.0:
            k.fault("NC006", k.no_feed_message(motion), src)
        end = [p + o for p, o in zip(prog, k.offset_vec)]
        target = (end[self.a], end[self.b])
        if motion < 2:
            if self.first:
                self._entry_line(motion, target, end, src)
            else:
                self._line(motion, target, end, src)
        else:
            if self.first:
                self._entry_arc(motion == 2, target, end, words, src)
            else:
                self._arc(motion == 2, target, end, words, src)
        self.first = False
        self.prog_pt = target
        end[self.a], end[self.b] = self.cur  # the move just held ends here (its end is this list) until the next
        k.prog = prog
        k.machine_pos = tuple(end)

    def cancel(self) -> None:
        """G40: the held moves end where they are; the next move leaves the contour."""
        self.release()
        if self.first or self.radius == 0.0:
            self.detach()
        else:
            self.leaving = True

    def release(self) -> None:
        """Let every held move go at the end point it has now."""
        self._move_end_and_flush(self.cur)
        self._flush()

    def detach(self) -> None:
        """Compensation is over: the kernel's own canon and straight-move path again."""
        self.release()
        from .kernel import _transformed_linear
        k = self.kernel
        k.comp = None
        k.canon = self.canon
        k.linear = k._fast_linear if k.transform is None else _transformed_linear

    # -- the geometry --------------------------------------------------------
    def _entry_line(self, motion: int, target, end, src: Src) -> None:
        cx, cy = self.cur
        px, py = target
        r = self.radius
        if math.hypot(px - cx, py - cy) <= r:
            self.kernel.fault("NC012", f"the entry move of cutter radius compensation must be longer than the tool "
                              f"radius {r:g} mm", src)
        alpha = math.atan2(py - cy, px - cx) + self.side * HALF_PI
        self.start, self.start_valid = self.cur, True
        # the direction kept for the backwards check is the side normal (its end lies a radius that way)
        self._hold(_Held(motion, end, self.kernel.feed, src, (math.cos(alpha), math.sin(alpha))))
        self.cur = (px + r * math.cos(alpha), py + r * math.sin(alpha))

    def _entry_arc(self, cw: bool, target, end, words, src: Src) -> None:
        """The first move an arc (LinuxCNC's rule): from where the tool stands to the point a radius beside the
        programmed end, square to the arc there; the centre slides along the line from that point to the
        programmed centre until both ends lie on one circle."""
        k = self.kernel
        cx, cy = self.cur
        px, py = target
        r = self.radius
        if math.hypot(px - cx, py - cy) <= r:
            k.fault("NC012", f"the entry arc of cutter radius compensation must be longer than the tool radius "
                    f"{r:g} mm", src)
        ccx, ccy, _ = k.arc_centre(cw, cx, cy, px, py, words, src)
        inside = self._inside(not cw)
        if inside and math.hypot(ccx - cx, ccy - cy) < r:
            k.fault("NC012", f"the tool radius {r:g} mm is not less than the radius of the entry arc", src)
        gamma = math.atan2(ccy - py, ccx - px) if inside else math.atan2(py - ccy, px - ccx)
        ex, ey = px + r * math.cos(gamma), py + r * math.sin(gamma)
        towards = math.atan2(ccy - ey, ccx - ex)
        cos_a = math.cos(math.atan2(cy - ey, cx - ex) - towards)
        if abs(cos_a) < 1e-12:
            k.fault("NC012", f"the tool radius {r:g} mm does not fit the entry arc", src)
        reach = math.hypot(cx - ex, cy - ey) / 2.0 / cos_a
        centre = (ex + reach * math.cos(towards), ey + reach * math.sin(towards))
        turns = max(0, int(words.get("P", 1)) - 1)
        self.start, self.start_valid = self.cur, True
        sweep = _sweep(cx, cy, *centre, not cw, turns, ex, ey)
        self._hold(_Held(2, end, k.feed, src, None, center=centre, ccw=not cw, turns=turns, sweep=sweep))
        self.cur = (ex, ey)

    def _line(self, motion: int, target, end, src: Src) -> None:
        cx, cy = self.cur
        ox, oy = self.prog_pt
        px, py = target
        feed = self.kernel.feed
        if px == ox and py == oy:  # no motion in the plane: the tool stays beside the contour
            self._hold(_Held(motion, end, feed, src, (0.0, 0.0)))
            return
        r = self.radius
        theta = math.atan2(cy - oy, cx - ox)
        alpha = math.atan2(py - oy, px - ox)
        if self.side == LEFT:
            if theta < alpha:
                theta += TWO_PI
            beta = theta - alpha - HALF_PI
            gamma = HALF_PI
        else:
            if alpha < theta:
                alpha += TWO_PI
            beta = alpha - theta - HALF_PI
            gamma = -HALF_PI
        nx, ny = math.cos(alpha + gamma), math.sin(alpha + gamma)
        new_end = (px + r * nx, py + r * ny)
        prev = self._first_held()
        prev_arc = prev is not None and prev.center is not None
        concave = beta < -SMALL or beta > math.pi + SMALL or (
            beta > math.pi - SMALL and prev_arc and prev.ccw == (self.side == RIGHT))
        if not concave and beta > SMALL:  # outside corner: round it on the tool radius
            mid = (ox + r * nx, oy + r * ny)
            self._move_end_and_flush(self.cur, src)
            corner = self._plane_point(self.emitted, mid)
            if motion == 1:
                self._out(_Held(1, corner, feed, src, None, center=(ox, oy), ccw=self.side == RIGHT))
            else:
                self._out(_Held(0, corner, feed, src, None))
            self.start, self.start_valid = mid, True
        elif concave:
            if not prev_arc:  # line -> line: back along the last offset line to the meeting point
                half = (beta + math.pi) / 2.0
                if half == 0.0:
                    self.kernel.fault("NC012", "a zero degree inside corner cannot be compensated", src)
                back = r / math.tan(half)
                mid = (cx + back * math.cos(theta + gamma), cy + back * math.sin(theta + gamma))
            else:  # arc -> line: where the offset line meets the offset arc
                mid = self._arc_meets_line(prev, alpha, src)
            self._move_end_and_flush(mid, src)
        else:  # tangent: no corner
            self._flush()
            self.start, self.start_valid = self.cur, True
        self._hold(_Held(motion, end, feed, src, (px - ox, py - oy)))
        self.cur = new_end

    def _arc_meets_line(self, prev, base_dir: float, src: Src):
        """The point where the held (compensated) arc ``prev`` meets the offset of the new line."""
        r = self.radius
        ox, oy = self.prog_pt
        pcx, pcy = prev.center
        old = math.hypot(prev.end[self.a] - pcx, prev.end[self.b] - pcy)
        theta = base_dir + HALF_PI if prev.ccw else base_dir - HALF_PI
        phi = math.atan2(pcy - oy, pcx - ox)
        inside = self._inside(prev.ccw)
        d = (old + r if inside else old - r) * math.cos(theta - phi)
        ratio = (d - r if inside else d + r) / old
        if not -1.0 <= ratio <= 1.0:
            self.kernel.fault("NC012", "arc to straight line: the corner is too small for the tool (gouging)", src)
        turn = -math.acos(ratio) if prev.ccw == inside else math.acos(ratio)
        angle = turn + theta + math.pi
        return pcx + old * math.cos(angle), pcy + old * math.sin(angle)

    def _arc(self, cw: bool, target, end, words, src: Src) -> None:
        k = self.kernel
        ox, oy = self.prog_pt
        px, py = target
        ccx, ccy, _ = k.arc_centre(cw, ox, oy, px, py, words, src)
        turns = max(0, int(words.get("P", 1)) - 1)
        r = self.radius
        cx, cy = self.cur
        arc_radius = math.hypot(ccx - px, ccy - py)
        theta = math.atan2(cy - oy, cx - ox) - self.side * HALF_PI  # direction of the last cut at its end
        delta = math.atan2(ccy - oy, ccx - ox)
        alpha = delta + HALF_PI if cw else delta - HALF_PI  # direction of this arc at its start
        beta = theta - alpha if self.side == LEFT else alpha - theta
        if beta > 1.5 * math.pi:
            beta -= TWO_PI
        elif beta < -HALF_PI:
            beta += TWO_PI
        inside = self._inside(not cw)
        if inside:
            if arc_radius <= r:
                k.fault("NC012", f"the tool radius {r:g} mm is not less than the arc radius {arc_radius:g} mm "
                        "(the tool does not fit inside the arc)", src)
            gamma = math.atan2(ccy - py, ccx - px)
        else:
            gamma = math.atan2(py - ccy, px - ccx)
            delta += math.pi
        new_end = (px + r * math.cos(gamma), py + r * math.sin(gamma))
        sweep = _sweep(ox, oy, ccx, ccy, not cw, turns, px, py)
        held = _Held(2, end, k.feed, src, None, center=(ccx, ccy), ccw=not cw, turns=turns, sweep=sweep)
        if beta < -SMALL or beta > math.pi + SMALL or (abs(beta - math.pi) < SMALL and not inside):  # inside corner
            prev = self._first_held()
            if prev is None or prev.center is None:  # line -> arc
                rise = arc_radius * math.sin(beta - HALF_PI)
                dist = arc_radius - r if inside else arc_radius + r
                ratio = (rise + r if inside else rise - r) / dist
                if not -1.0 <= ratio <= 1.0:
                    k.fault("NC012", "straight line to arc: the corner is too small for the tool (gouging)", src)
                if inside:
                    angle = theta + math.asin(ratio) if not cw else theta - math.asin(ratio)
                else:
                    angle = theta + math.pi - math.asin(ratio) if not cw else theta + math.pi + math.asin(ratio)
                mid = (ccx + dist * math.cos(angle), ccy + dist * math.sin(angle))
            else:  # arc -> arc: where the two offset circles meet
                pcx, pcy = prev.center
                old = math.hypot(prev.end[self.a] - pcx, prev.end[self.b] - pcy)
                new = arc_radius - r if inside else arc_radius + r
                apart = math.hypot(pcx - ccx, pcy - ccy)
                if old == 0.0 or apart == 0.0:
                    k.fault("NC012", "arc to arc with the same centre cannot be compensated", src)
                cos_back = (old * old + apart * apart - new * new) / (2.0 * old * apart)
                if not -1.0 <= cos_back <= 1.0:
                    k.fault("NC012", "arc to arc: the corner is too small for the tool (gouging)", src)
                back = math.acos(cos_back)
                towards = math.atan2(ccy - pcy, ccx - pcx)
                sign = 1.0 if self._inside(prev.ccw) == (not cw) else -1.0
                angle = towards + sign * back
                mid = (pcx + old * math.cos(angle), pcy + old * math.sin(angle))
            self._move_end_and_flush(mid, src)
        elif beta > SMALL:  # outside corner: round it on the tool radius
            mid = (ox + r * math.cos(delta), oy + r * math.sin(delta))
            self._flush()
            self._out(_Held(1, self._plane_point(self.emitted, mid), k.feed, src, None, center=(ox, oy),
                            ccw=self.side == RIGHT))
            self.start, self.start_valid = mid, True
        else:  # tangent
            self._flush()
            self.start, self.start_valid = self.cur, True
        self._hold(held)
        self.cur = new_end

    def _inside(self, ccw: bool) -> bool:
        """Whether the tool runs inside an arc of this direction (left of a counter-clockwise one)."""
        return ccw == (self.side == LEFT)

    # -- the held moves ------------------------------------------------------
    def _first_held(self):
        return next((h for h in self.queue if isinstance(h, _Held)), None)

    def _hold(self, held) -> None:
        self.queue.append(held)

    def later(self, fn, args) -> None:
        """A canon call that must wait behind the held moves (at once when none is held)."""
        if self.queue:
            self.queue.append((fn, args))
        else:
            fn(*args)

    def _move_end_and_flush(self, point, src: Src | None = None) -> None:
        """Every held move now ends at ``point`` (the meeting point of an inside corner); then all leave.
        A move that would have to run backwards to get there, or an arc that would sweep further than
        programmed, gouges."""
        if not self.queue:
            return
        sx, sy = self.start
        x, y = point
        for h in self.queue:
            if not isinstance(h, _Held):
                continue
            if h.center is not None:
                if h.sweep and self.start_valid:
                    now = _sweep(sx, sy, *h.center, h.ccw, h.turns, x, y)
                    if abs(now) > abs(h.sweep) + SWEEP_SLACK:
                        self.kernel.fault("NC012", "an arc in an inside corner cannot be reached by the tool "
                                          "without gouging", src)
            elif self.start_valid and h.direction[0] * (x - sx) + h.direction[1] * (y - sy) < 0.0:
                self.kernel.fault("NC012", f"a straight {'feed' if h.motion else 'rapid'} move in an inside corner "
                                  "cannot be reached by the tool without gouging", src)
            h.end[self.a], h.end[self.b] = x, y
        self._flush()
        self.start, self.start_valid = point, True

    def _flush(self) -> None:
        """Every held move and call leaves, in program order."""
        self.start_valid = False
        queue, self.queue = self.queue, []
        for item in queue:
            if isinstance(item, _Held):
                self._out(item)
            else:
                item[0](*item[1])

    def _out(self, h) -> None:
        k = self.kernel
        start, end = self.emitted, tuple(h.end)
        if h.center is None:
            k.straight_out(h.motion, start, end, h.feed, h.src, self.canon)
        else:
            ca, cb = h.center
            radius = math.hypot(end[self.a] - ca, end[self.b] - cb)
            k.arc_out(start, end, ArcSpec(self.a, self.b, h.center, not h.ccw, radius, h.turns), h.feed, h.src,
                      self.canon)
        self.emitted = end

    def _plane_point(self, pos, point) -> list:
        out = list(pos)
        out[self.a], out[self.b] = point
        return out


class _Held:
    """A compensated move waiting for the next one: a straight move, or an arc (``center`` set)."""

    __slots__ = ("motion", "end", "feed", "src", "direction", "center", "ccw", "turns", "sweep")

    def __init__(self, motion, end, feed, src, direction, center=None, ccw=False, turns=0, sweep=0.0):
        self.motion = motion
        self.end = end  # machine position, a list: an inside corner moves its plane coordinates
        self.feed = feed
        self.src = src
        self.direction = direction  # programmed direction in the plane (straight moves)
        self.center = center
        self.ccw = ccw
        self.turns = turns
        self.sweep = sweep  # the programmed sweep (radians, signed), 0 for a corner arc


def _sweep(x1: float, y1: float, cx: float, cy: float, ccw: bool, turns: int, x2: float, y2: float) -> float:
    """Signed sweep from (x1, y1) to (x2, y2) around (cx, cy): at most one turn, plus ``turns`` full ones."""
    a0 = math.atan2(y1 - cy, x1 - cx)
    a1 = math.atan2(y2 - cy, x2 - cx)
    if ccw:
        if a1 <= a0:
            a1 += TWO_PI
        return a1 - a0 + turns * TWO_PI
    if a0 <= a1:
        a0 += TWO_PI
    return a1 - a0 - turns * TWO_PI


class _HeldCanon:
    """The kernel's canon while compensation is on: calls other than moves wait behind the held moves;
    a program stop or end lets the held moves go first."""

    def __init__(self, comp: CutterComp, canon):
        self._comp = comp
        self._canon = canon

    def __getattr__(self, name: str):
        canon, comp = self._canon, self._comp
        if name in _DEFERRED:
            return lambda *args: comp.later(getattr(canon, name), args)
        if name in ("stop", "program_end"):
            def release_then(*args):
                comp.release()
                getattr(canon, name)(*args)
            return release_then
        return getattr(canon, name)


def _compensated_linear(kernel, motion: int, words, src: Src) -> None:
    """The kernel's straight move while compensation is on (a front end that kept this function past G40
    reaches the kernel's own path through it)."""
    comp = kernel.comp
    if comp is None:
        kernel.linear(kernel, motion, words, src)
    else:
        if kernel.spindle_bound:
            kernel.spindle_update(src)
        comp.move(motion, words, src)
