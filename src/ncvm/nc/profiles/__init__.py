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

from typing import Callable

from ...records import FrozenRecord

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
#: handler runs after the block's tool change (M6): LinuxCNC's order of execution changes the tool (step 6)
#: before it applies the tool length offset (step 14), so ``T1 M6 G43`` takes tool 1's length
AFTER_TOOL_CHANGE = 8


class Row(FrozenRecord):
    """One G function of a control."""

    __slots__ = ("g", "group", "meaning", "line", "status", "run", "handler", "code")

    def __init__(self, g: float, group: str, meaning: str, line: str, status: str, run: int = SET,
                 handler: Callable | None = None, code: str = ""):
        self.g = g
        self.group = group  # the control's modal group ("" for a function of one block)
        self.meaning = meaning  # the control's meaning, in the manual's words where it has them
        self.line = line  # where the manual names it ("L2302", "§11.5 L7392"; "" where it does not)
        self.status = status
        self.run = run
        self.handler = handler
        self.code = code  # the code a refused row stops the run with ("" for a row ncvm runs)


class Address(FrozenRecord):
    """An address letter (other than the axes and G/M/N) and what the profile does with it."""

    __slots__ = ("letter", "meaning", "line", "status", "handler")

    def __init__(self, letter: str, meaning: str, line: str, status: str, handler: Callable | None = None):
        self.letter = letter
        self.meaning = meaning
        self.line = line
        self.status = status
        self.handler = handler  # handler(kernel, value, words, src), after the block's G functions


class Profile(FrozenRecord):
    """A control's G table: the rows by G number, its addresses, and the power-on state per group.

    Row, Address and Profile are records rather than dataclasses: every run's start-up imports them
    (ncvm/records.py)."""

    __slots__ = ("name", "manual", "rows", "addresses", "defaults", "groups", "dispatch", "by_g", "word_handlers")

    def __init__(self, name: str, manual: str, rows: tuple, addresses: tuple = (), defaults: dict | None = None,
                 groups: dict | None = None):
        self.name = name
        self.manual = manual
        self.rows = rows
        self.addresses = addresses
        self.defaults = {} if defaults is None else defaults  # group -> G number at power-on and reset
        self.groups = {} if groups is None else groups  # group -> its name
        self.by_g = {r.g: r for r in rows}
        if len(self.by_g) != len(rows):
            raise ValueError(f"profile {name}: a G number has two rows")
        #: G number -> (run, handler): what the kernel looks up per G word
        self.dispatch = {r.g: (r.run, r.handler) for r in rows}
        #: letter -> handler, for the addresses a handler reads (checked once per block when not empty)
        self.word_handlers = {a.letter: a.handler for a in addresses if a.handler}

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
