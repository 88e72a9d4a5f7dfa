"""G80-G89 of the SINUMERIK 8xx (internal G group 9, CL 800 manual L7406): the drilling cycles L81-L89.

G81 to G89 select the drilling cycle sub-program L81 to L89, found along the program path as any
``L<n>`` call finds its sub-program; the cycle reads its data from R parameters that the program sets
before (the transfer parameters, manual L483-486; the manual's deep-hole drilling cycle PROGRAM 81,
L5404-5542, reads R22 start point, R24 degression, R25 first depth, R26 final depth, R27/R28 dwell times).
The selection is modal until G80: the block that selects the cycle and every later block with an axis
word first travels to its position (with the motion of group 0, G0 or G1) and then runs the cycle there,
as ``L8x`` written after the block would; a block that also calls a sub-program (``X20 L100``) runs the
cycle at its position before the sub-program. A block that selects a cycle without an axis word only selects
it. The cycle's own blocks do not call it again. A selected cycle whose program is missing stops the run
at the selecting block (RUN002).

The selection is decode state (the program's blocks call the cycle as they are decoded, like any L
call); the kernel hears G80-G89 too (:meth:`Drilling.executed_g`, a ``kernel.g_handlers`` entry), so
that ACG reads the group's executed function.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from ...diagnostics import Diagnostic, RuntimeFault, Span
from ...nc.axiswords import is_dwell
from ...nc.block import acts

if TYPE_CHECKING:
    from .runtime import Channel

#: the G functions of group 9
GROUP_9 = tuple(range(80, 90))


def missing_cycle(g: int) -> str:
    """The message of a selection whose cycle program L<g> is not on the program path (RUN002)."""
    return (f"G{g} calls the drilling cycle L{g}, which is not on the program path "
            f"(looked for L{g}.spf and %SPF{g} files)")


def selections(prog) -> list[tuple[int, int, int]]:
    """(G number, line, column) of each block's selection in group 9: its last G80-G89 word, as the run
    takes it (``N2 G81 X10 G80`` deselects, and the run passes it)."""
    out = []
    for blk in prog.blocks:
        last = None
        for it in blk.items:
            if getattr(it, "address", None) == "G" and it.value in GROUP_9:
                last = (int(it.value), blk.line, it.col)
        if last is not None:
            out.append(last)
    return out


def missing_cycle_warnings(prog, find, where=None) -> list[Diagnostic]:
    """``ncvm check``: a warning RUN002 at the first block that selects G81-G89 whose cycle program ``find``
    (number -> path or None) does not find: the run stops there. ``prog``: the NC program (a sin800 program,
    or the object program of a CL 800 source); ``where`` maps its (line, column) to the (line, column) to
    report (the CL 800 source's), None: as they are."""
    out, seen = [], set()
    for g, line, column in selections(prog):
        if g != 80 and g not in seen:
            seen.add(g)
            if find(g) is None:
                at = (line, column) if where is None else where(line, column)
                out.append(Diagnostic("RUN002", missing_cycle(g) + ": the run stops here",
                                      Span(prog.path, *at), severity="warning"))
    return out


class Drilling:
    """The channel's selected drilling cycle (None: G80) and its calls."""

    def __init__(self, channel: Channel):
        self.channel = channel
        self.selected: int | None = None  # as decoding has reached
        self.executed = 80  # the group's function as the kernel has executed it (ACG)
        self.busy = False  # a cycle runs: its own blocks do not call it

    @property
    def armed(self) -> int | None:
        """The cycle a block with an axis word calls now: none under G80 and none inside the cycle."""
        return None if self.busy else self.selected

    def select(self, g: int) -> None:
        """A block with G80-G89 is decoded."""
        if g == 80:
            self.selected = None
            return
        if self.channel.loader(g) is None:
            raise RuntimeFault("RUN002", missing_cycle(g))
        self.selected = g

    def call(self, line: int) -> None:
        """Run the selected cycle at the position the block just reached."""
        g = self.selected
        self.busy = True
        try:
            self.channel.call(g, 1, line)
        finally:
            self.busy = False

    def run_blocks(self, blocks: tuple, line: int) -> None:
        """A run of constant blocks while a cycle is selected: each block counted (and the step limit tested)
        before it runs, the cycle after each block that travels."""
        ch = self.channel
        axes = ch.kernel.axis_of
        counter = ch.counter
        for b in blocks:
            if counter.steps >= counter.limit:
                ch.runaway(b.src.line)
            counter.steps += 1
            if not acts(b):
                continue
            ch.execute(b)
            if ch.kernel.ended or ch.halted:
                return
            if self.armed is not None and not is_dwell(b.g) and any(a in axes for a in b.words):
                self.call(b.src.line)
                if ch.kernel.ended or ch.halted:
                    return

    def executed_g(self, kernel, g, words, src) -> bool:
        """The kernel's handler of G80-G89: the block's axis words stay its target."""
        self.executed = int(g)
        return False

    def handlers(self) -> dict:
        """The ``kernel.g_handlers`` entries of group 9."""
        return {g: self.executed_g for g in GROUP_9}
