"""Control profiles as data: for each control, its modal G groups, the meaning of each G function and
address, the manual line that names it, what ncvm does with it, and the defaults at power-on/reset.

Issue 14 §1: the shared kernel speaks each control's own language through a table, not an if-chain.
:class:`Row` is one G function of a profile; ``run`` says how :meth:`ncvm.nc.kernel.NcKernel.execute`
treats it (a modal setting made at once, the block's motion, a dwell, ...) and ``handler`` is the function
that does it. A refused row's handler stops the block with NC004 (or the row's ``code``) naming the
control's meaning, so the ISO meaning of a number is never used in its place. ``docs/profiles.md`` is
generated from these tables (:mod:`ncvm.nc.profiles.doc`).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable

INCH = 25.4

# -- what ncvm does with a function (the status column of docs/profiles.md) ---------------------------
IMPLEMENTED = "implemented"
#: the manual names the function but not its behaviour: ncvm runs the meaning usual for the control family
FAMILY = "implemented: usual meaning of the control family, see decisions"
REFUSED = "refused: not supported by ncvm"
#: taken out of the block by the dialect before the kernel sees it (named in ``handler`` docs)
DIALECT = "implemented by the dialect"

# -- how the kernel runs a row (NcKernel.execute) ------------------------------------------------------
SET = 0  # handler(kernel, g, words, src) runs at once, in the block's order (modal settings)
MOTION = 1  # the block's motion mode
DWELL = 2  # the block is a dwell
POSITION = 3  # the block sets the position (G92)
MACHINE = 4  # the block's target is in machine coordinates (LinuxCNC G53)
ALONE = 5  # handler runs and the block ends there (G10 L2: a table write, no motion)
CYCLE = 6  # a canned cycle code (kernel.canned), or NC004 while the profile has none
LATE = 7  # handler runs after the block's other G codes, returns True when the axis words were its parameters


@dataclass(frozen=True, slots=True)
class Row:
    """One G function of a control."""

    g: float
    group: str  # the control's modal group ("" for a function of one block)
    meaning: str  # the control's meaning, in the manual's words where it has them
    line: str  # where the manual names it ("L2302", "§11.5 L7392"; "" where it does not)
    status: str
    run: int = SET
    handler: Callable | None = None
    code: str = ""  # the code a refused row stops the run with ("" for a row ncvm runs)


@dataclass(frozen=True, slots=True)
class Address:
    """An address letter (other than the axes and G/M/N) and what the profile does with it."""

    letter: str
    meaning: str
    line: str
    status: str
    handler: Callable | None = None  # handler(kernel, value, words, src), after the block's G functions


@dataclass(frozen=True)
class Profile:
    """A control's G table: the rows by G number, its addresses, and the power-on state per group."""

    name: str
    manual: str
    rows: tuple
    addresses: tuple = ()
    defaults: dict = field(default_factory=dict)  # group -> G number at power-on and reset
    groups: dict = field(default_factory=dict)  # group -> its name
    #: G number -> (run, handler): what the kernel looks up per G word
    dispatch: dict = field(init=False, repr=False, compare=False)
    by_g: dict = field(init=False, repr=False, compare=False)
    #: letter -> handler, for the addresses a handler reads (checked once per block when not empty)
    word_handlers: dict = field(init=False, repr=False, compare=False)

    def __post_init__(self):
        by_g = {r.g: r for r in self.rows}
        if len(by_g) != len(self.rows):
            raise ValueError(f"profile {self.name}: a G number has two rows")
        object.__setattr__(self, "by_g", by_g)
        object.__setattr__(self, "dispatch", {r.g: (r.run, r.handler) for r in self.rows})
        object.__setattr__(self, "word_handlers", {a.letter: a.handler for a in self.addresses if a.handler})

    def refused(self, g) -> Row | None:
        """The row of a G function the profile refuses (None: it runs it, or the kernel does not know it)."""
        row = self.by_g.get(g)
        return row if row is not None and row.code else None

    def group_of(self, g) -> str | None:
        row = self.by_g.get(g)
        return row.group if row is not None and row.group else None


def refusal(meaning: str, code: str = "NC004"):
    """The handler of a refused row: the block stops naming the control's meaning of the number."""
    def refuse(kernel, g, words, src):
        kernel.fault(code, f"G{g:g} ({meaning}) is not supported by ncvm", src)
    return refuse


def refused(g, group: str, meaning: str, line: str, status: str = REFUSED, code: str = "NC004") -> Row:
    """A row the kernel refuses with NC004 naming ``meaning``."""
    return Row(g, group, meaning, line, status, SET, refusal(meaning, code), code)


def unknown_g(kernel, g, src):
    """NC004 for a G number the profile does not have."""
    kernel.fault("NC004", f"G{g:g} is not a G function of the {kernel.profile.name} profile: not supported by ncvm",
                 src)


def modal_only(group: str):
    """The handler of a function whose only effect ncvm models is being the active one of its group (the
    control's reports, SD(1) and MCODS, read it from ``kernel.modal``)."""
    def remember(kernel, g, words, src):
        kernel.modal[group] = g
    return remember
