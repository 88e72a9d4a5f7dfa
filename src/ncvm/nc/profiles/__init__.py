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
#: the block dwells: handler(kernel, g, words, block_g, src) -> (seconds, alone), ``alone`` when the block is
#: the dwell and nothing else (its time word is no feed and no move), see :func:`dwell_alone`
DWELL = 2
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

    __slots__ = ("name", "manual", "rows", "addresses", "defaults", "groups", "dispatch", "by_g", "word_handlers",
                 "g_groups", "m_groups", "block_rules")

    def __init__(self, name: str, manual: str, rows: tuple, addresses: tuple = (), defaults: dict | None = None,
                 groups: dict | None = None, m_groups: dict | None = None, yielding: frozenset = frozenset(),
                 block_rules: tuple = ()):
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
        #: G number -> its modal group, for the rule "one function of a group in a block" (nc/profiles/blockrules.py);
        #: a ``yielding`` function gives way to another of its group in the block (rs274's G80) and is left out
        self.g_groups = {r.g: r.group for r in rows if r.group and r.g not in yielding}
        #: M number -> its group, for the same rule (the profiles that name M groups)
        self.m_groups = {} if m_groups is None else m_groups
        #: more rules of the control a block must keep: rule(profile, g, m, words) -> (code, message, address,
        #: value) or None (blockrules.py)
        self.block_rules = block_rules

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


#: what a din dwell block without P that also moves should say instead
ISO_DWELL_HINT = "write the time as P to dwell and then move, as rs274 reads it"
#: the words a control writes the dwell time with, in the order the kernel reads them
DWELL_TIME_WORDS = ("P", "X", "F")


def dwell_alone(kernel, g, words, block_g, src, explicit_motion: bool = False, hint: str = ""):
    """G4 with its time as X or F (P read too): the block is the dwell alone, as the controls' manuals write it
    (CL 800 ``G4 F=R27``, L5465); what :func:`lone_dwell_fault` finds in it stops the block (NC009)."""
    if len(words) == 1 and not explicit_motion:  # the usual block, its time alone: nothing to find
        for address, seconds in words.items():
            if address in DWELL_TIME_WORDS and seconds >= 0.0:
                return seconds, True
    fault = lone_dwell_fault(kernel.profile, g, words, block_g, kernel.axis_of, explicit_motion, hint)
    if fault is not None:
        kernel.fault("NC009", fault, src)
    times = [a for a in DWELL_TIME_WORDS if a in words]
    return (words[times[0]] if times else 0.0), True


def lone_dwell_fault(profile: Profile, g, words, block_g, axes, explicit_motion: bool = False,
                     hint: str = "") -> str | None:
    """Why a dwell block whose time is X or F cannot run (None: it can). A second time word, or an axis word
    beside the time, would be silently lost; ``explicit_motion``: a motion G code in the block is refused too
    (LinuxCNC reads the block's X as a move, a DIN control as the time: the block has no one meaning)."""
    times = [a for a in DWELL_TIME_WORDS if a in words]
    if len(times) > 1:
        return f"G{g:g} (dwell) with {' and '.join(times)}: one of them is the time, the block has no one meaning"
    others = [a for a in words if a in axes and a not in times]
    if explicit_motion and not others:
        others = [f"G{x:g}" for x in block_g if profile.dispatch.get(x, (None,))[0] == MOTION]
    if others:
        what = f"{times[0]}{words[times[0]]:g}" if times else "without a time"
        return (f"G{g:g} {what} is a dwell block of its own: {' '.join(others)} in it would not move "
                f"({hint or 'a dwell with a move in one block is not supported by ncvm here'})")
    if times and words[times[0]] < 0.0:
        return f"G{g:g}: the dwell time {words[times[0]]:g} is negative"
    return None
