"""A rounding between two straight blocks in motion: the circle radius address on a G1 block (the manual's
``N5 X400 Y50 B100``, L4216; machine data ``[sin800] radius_address``, B or U).

The corner can only be rounded once the next block is known, so a G1 block with the radius waits (as the
control's block preparation holds it) until the next block executes. Then three moves leave: the first
line shortened to the rounding, the rounding (G2/G3, tangent to both lines, the geometry of PREP REF's
element, contour.py) and the next line from the rounding's end. A next block that itself carries a
radius waits in its turn, so a chain of rounded corners runs as the contour sub-program describes it.

Where the corner cannot be rounded as the manual shows it, the run stops (NC009, "not supported by
ncvm" where the control could but ncvm does not): the next block is not a straight G1 move in the plane,
either block moves an axis off the plane, the program ends or waits (STOP DEC) before the next block,
cutter radius compensation or a coordinate rotation is on.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from ...diagnostics import Diagnostic, RuntimeFault, Span
from ...nc.block import Block
from ...nc.kernel import PLANES
from .contour import corner_arc
from .errors import Cl800Error
from .reader import Word

if TYPE_CHECKING:
    from .runtime import Channel

#: why a rounding cannot be made, as the run and the check say it
NOT_STRAIGHT = "the next block {} is not a straight move at feed (G1)"
OFF_PLANE = "a rounding between moves that leave the plane is not supported by ncvm"
_MOTION = (0, 1, 2, 3, 33, 34, 35)

#: G functions a block that takes part in a rounding may carry besides G1
_QUIET_G = frozenset((1, 90, 91, 94, 95, 60, 64))


class CornerRounding:
    """Installed on the channel's execution path once a block with the radius word is decoded
    (:meth:`Channel.use_rounding`); holds at most one block."""

    def __init__(self, channel: Channel):
        self.channel = channel
        self.used = False
        self.held: Block | None = None
        self.inner = None  # the execution path behind this one (set by Channel.route)
        self.inner_linear = None

    def execute(self, block: Block) -> None:
        if self.held is not None:
            self._round(block)
        elif "R" in block.words and self._motion(block) == 1:
            self._check_quiet(block, block)
            self.held = block
        else:
            self.inner(block)

    def linear(self, k, motion: int, words, src) -> None:
        """The generated G0/G1 path: a plain straight block completes a waiting rounding."""
        if self.held is not None:
            self._round(Block((motion,), (), words, None, None, src))
        else:
            self.inner_linear(k, motion, words, src)

    def finish(self) -> None:
        """The program ends or decoding waits (STOP DEC) while a rounding waits for its next block."""
        if self.held is not None:
            self._refuse(self.held, "the program ends or waits (STOP DEC) before the next block")

    # -- the rounding ------------------------------------------------------
    def _motion(self, block: Block, before: int | None = None) -> int:
        """The motion of group 0 the block runs with (``before``: the mode it starts in, else the kernel's)."""
        motion = self.channel.kernel.motion if before is None else before
        for g in block.g:
            if g in _MOTION:
                motion = g
        return motion

    def _check_quiet(self, held: Block, block: Block) -> None:
        ch = self.channel
        if ch.kernel.comp is not None or ch.kernel.transform is not None or ch.angle_used:
            self._refuse(held, "with cutter radius compensation, a coordinate rotation or the programmed angle "
                               "on, a rounding in motion is not supported by ncvm")
        if any(g not in _QUIET_G and g != 0 for g in block.g) or any(m in (0, 1, 2, 30) for m in block.m):
            self._refuse(held, f"block {self._name(block)} has G or M functions a rounding does not pass")

    def _round(self, nxt: Block) -> None:
        held, self.held = self.held, None
        k = self.channel.kernel
        if self._motion(nxt, self._motion(held)) != 1:
            self._refuse(held, NOT_STRAIGHT.format(self._name(nxt)))
        self._check_quiet(held, nxt)
        if not any(w in k.axis_of for w in nxt.words):  # M8, F500 ...: not the second line of the corner
            self._refuse(held, f"block {self._name(nxt)} between the two lines does not move (a rounding joins "
                               "two consecutive straight moves; a block with M or F alone is not supported here by ncvm)")
        an, bn, _cn, iw, jw = PLANES[k.plane]
        a, b = k.axis_of.get(an), k.axis_of.get(bn)
        if a is None or b is None:
            self._refuse(held, f"the plane G{k.plane} needs axes {an} and {bn}")
        start = list(k.prog)
        shadow = k.fork()
        quiet = {w: v for w, v in held.words.items() if w != "R"}
        shadow.execute(Block(held.g, (), quiet, None, None, held.src))
        corner, after_held_absolute = list(shadow.prog), shadow.absolute
        shadow.execute(Block(nxt.g, (), {w: v for w, v in nxt.words.items() if w != "R"}, None, None, nxt.src))
        end, after_next_absolute = list(shadow.prog), shadow.absolute
        if any(i not in (a, b) and (abs(corner[i] - start[i]) > 1e-9 or abs(end[i] - corner[i]) > 1e-9)
               for i in range(k.n_axes)):
            self._refuse(held, OFF_PLANE)
        try:
            arc = corner_arc((start[b], start[a]), (corner[b], corner[a]), (end[b], end[a]), held.words["R"] * k.scale,
                              self.channel.radius_address)
        except Cl800Error as e:
            self._refuse(held, str(e))
        scale = k.scale
        if arc is None:  # the lines go straight on: nothing to round
            self.inner(Block(held.g, held.m, quiet, held.n, held.msg, held.src))
            self.execute(nxt)
            return
        t1v, t1h, t2v, t2h, iv, ih, g = arc[:7]

        def plane_words(absolute: bool, frm, to_a: float, to_b: float) -> dict:
            if absolute:
                return {an: to_a / scale, bn: to_b / scale}
            return {an: (to_a - frm[a]) / scale, bn: (to_b - frm[b]) / scale}

        first = dict(quiet, **plane_words(after_held_absolute, start, t1h, t1v))
        self.inner(Block(held.g, held.m, first, held.n, held.msg, held.src))
        after_first = list(k.prog)
        rounding = dict(plane_words(after_held_absolute, after_first, t2h, t2v), **{iw: ih / scale, jw: iv / scale})
        self.inner(Block((int(g),), (), rounding, None, None, held.src))
        after_arc = list(k.prog)
        words = dict(nxt.words, **plane_words(after_next_absolute, after_arc, end[a], end[b]))
        self.execute(Block(tuple(x for x in nxt.g if x != 1) + (1,), nxt.m, words, nxt.n, nxt.msg, nxt.src))

    @staticmethod
    def _name(block: Block) -> str:
        return f"N{block.n}" if block.n is not None else f"at line {block.src.line if block.src else '?'}"

    def _refuse(self, held: Block, why: str):
        self.held = None
        radius = self.channel.radius_address
        src = held.src
        raise RuntimeFault("NC009", f"{radius}{held.words['R'] / self.channel.kernel.scale:g} rounds the corner to the "
                                    f"next straight block: {why}", Span(src.file, src.line) if src else None)


def rounding_diagnostics(prog, radius: str, axes) -> list[Diagnostic]:
    """``ncvm check``: NC009 at a G1 block with the radius word whose rounding the run cannot make, read from
    the text in the order it is written: the next block is no G1 move, or one of the two writes an axis off
    the plane (G17 at the start, as the run's). ``radius``: the radius address (not when it is an axis)."""
    if radius in axes:
        return []
    out = []
    motion, plane, held = 0, 17, None  # held: (block, its radius word)
    for blk in prog.blocks:
        words = [it for it in blk.items if isinstance(it, Word) and (it.value is not None or it.rref is not None)]
        g = [w.value for w in words if w.address == "G" and w.value is not None]
        named = [w.address for w in words if w.address in axes]
        if not g and not named and not any(w.address == radius for w in words):
            continue
        motion = next((x for x in reversed(g) if x in _MOTION), motion)
        plane = next((x for x in reversed(g) if x in (17, 18, 19)), plane)
        off = [a for a in named if a not in PLANES[plane][:2]]
        if held is not None:
            why = NOT_STRAIGHT.format(f"at line {blk.line}") if motion != 1 else OFF_PLANE if off or held[2] else None
            if why is not None:
                out.append(Diagnostic("NC009", f"{radius} rounds the corner to the next straight block: {why}: "
                                      "the run stops here", Span(prog.path, held[0].line, held[1].col),
                                      severity="warning"))
            held = None
        word = next((w for w in words if w.address == radius), None)
        if word is not None and motion == 1:
            held = (blk, word, bool(off))
    return out
