"""Moves whose time follows the spindle: threads (G33; SINUMERIK G34/G35) and feed per revolution (G95).

Under G95 the F word is a feed per revolution; each move's path feed is that feed times the spindle speed
at the move's start (feed mm/min = mm/rev x rev/min; CPL manual L2817: "in case of feed programming in
mm/rev (G95) it supplies the path feed in mm/min"). A thread moves the axes in step with the spindle: one
lead per revolution, so its time is the revolutions it takes divided by the speed. Neither runs without a
turning spindle: the control would wait for ever, ncvm stops with the block (a thread NC014, a move at
feed under G95 NC006, the feed being 0).

Two forms of the thread block, chosen by the profile:

- ISO (LinuxCNC's G33): ``G33 X.. Y.. Z.. K<lead>``, K the distance along the path per revolution, in every
  block; an F word in it is an error, as rs274 says ("F word used with a g33/g33.1").
- SINUMERIK 8xx (internal G group 0, CL 800 manual L7397: G33 constant, G34 increasing, G35 decreasing
  lead): the lead as the interpolation parameter of the axis it belongs to (I for X, J for Y, K for Z),
  modal; under G34/G35 F is the change of the lead per revolution (mm/rev^2), not the feed.

The handlers are registered by the dialects: :data:`FEED_MODES` in ``kernel.g_handlers``, the thread
moves in ``kernel.motion_modes``.
"""

from __future__ import annotations

import math

from .canon import Src

#: the interpolation parameter that carries a SINUMERIK thread's lead, per axis
LEAD_WORDS = {"X": "I", "Y": "J", "Z": "K"}


def per_rev_feed(k) -> None:
    """G95: the path feed (mm/min) of the move about to start, from F (mm/rev) and the spindle speed; 0 while
    the spindle stands, so a move at feed stops with NC006 and :func:`no_feed_message`'s words."""
    k.feed = k.feed_per_rev * abs(k.actual_speed())


def no_feed_message(k, g: int) -> str | None:
    """NC006 under G95: the feed per revolution is there, the spindle stands (None: the F word is missing)."""
    if k.feed_per_rev > 0.0 and k.actual_speed() == 0.0:
        return (f"G{g} under G95 (feed per revolution F{k.feed_per_rev / k.scale:g}) with the spindle not "
                "turning: the feed follows the spindle speed (program S and M3 or M4)")
    return None


def cleared_feed_message(k, g: int) -> str | None:
    """NC006 after a G94/G95 switch cleared the feed and no F followed: the switch is named (the user sees
    the old F a few blocks up); None when the feed is 0 for another reason."""
    if k.feed_switch is None or (k.feed_per_rev if k.per_rev else k.feed) != 0.0:
        return None
    switch, old = k.feed_switch
    if old == 0.0:
        return None  # nothing was cleared: the plain "program an F word" says it
    unit = "mm/rev" if switch == 94 else "mm/min"
    return (f"G{g} with feed rate 0: G{switch} changed the meaning of F and cleared F{old / k.scale:g} "
            f"({unit}); program F again after G{switch}")


def g94(k, g, words, src: Src) -> bool:
    """G94: F is a feed per minute again. As rs274, the feed must be programmed anew (F0 until then)."""
    if k.per_rev:
        k.feed_switch = (94, k.feed_per_rev)
        k.per_rev = False
        k.spindle_bound = k.css
        k.feed = 0.0
        k.canon.feed_per_rev(None, src)
    return False


def g95(k, g, words, src: Src) -> bool:
    """G95: F is a feed per revolution. As rs274, the feed must be programmed anew (F0 until then)."""
    if not k.per_rev:
        k.feed_switch = (95, k.feed)
        k.per_rev = k.spindle_bound = True
        k.feed_per_rev = k.feed = 0.0
        k.canon.feed_per_rev(0.0, src)
    return False


#: the feed modes as ``kernel.g_handlers`` entries
FEED_MODES = {94: g94, 95: g95}


def _turning(k, g: int, src: Src) -> float:
    """The spindle speed (rev/min) a thread follows; NC014 when it stands."""
    rpm = abs(k.actual_speed())
    if rpm <= 0.0:
        k.fault("NC014", f"G{g} (thread) with the spindle not turning: the axes follow the spindle "
                "(program S and M3 or M4 before the thread)", src)
    return rpm


def _travels(k, words) -> bool:
    """The block has an axis word: a block without one (M2, S ...) leaves the thread mode as it is."""
    return any(n in words for n in k.axis_of)


def _followable(k, g: int, start, end, length: float, feed: float, src: Src) -> None:
    """NC014 when an axis would have to run faster than its limit: the axes follow the spindle, so the
    control cannot slow the thread down (a slower axis would cut another lead)."""
    if length <= 0.0:
        return
    for name, i in k.axis_of.items():
        need = feed / 60.0 * abs(end[i] - start[i]) / length  # mm/s
        limit = k.dyn.max_feed[i]
        if need > limit * (1.0 + 1e-9):
            k.fault("NC014", f"G{g}: the thread needs axis {name} at {need * 60.0:g} mm/min, its limit is "
                    f"{limit * 60.0:g} mm/min (the axes follow the spindle: lower S or the lead)", src)


class _ThreadOut:
    """The kernel's straight move hands its canon ``feed`` call on as the canon ``thread`` call."""

    __slots__ = ("canon", "lead", "varying")

    def __init__(self, canon, lead: float, varying: bool):
        self.canon, self.lead, self.varying = canon, lead, varying

    def feed(self, start, end, feed, src) -> None:
        self.canon.thread(start, end, self.lead, self.varying, feed, src)


def _thread_move(k, g: int, words, src: Src, lead_of, varying: bool = False):
    """The common part of a thread block: target, checks, then ``lead_of(start, end)`` -> revolutions."""
    if k.comp is not None:
        k.fault("NC012", f"G{g}: no thread while cutter radius compensation is on", src)
    if k.transform is not None:
        k.fault("NC004", f"G{g}: a thread under a coordinate transformation is not supported by ncvm", src)
    prog, moved = k._target(words, False)
    if not moved:
        return
    rpm = _turning(k, g, src)
    start = k.machine_pos
    end = tuple(p + o for p, o in zip(prog, k.offset_vec))
    length = math.dist(start, end)
    revolutions = lead_of(start, end, length)
    if length > 0.0 and revolutions <= 0.0:
        k.fault("NC009", f"G{g}: the block does not move along the axis its lead belongs to (a thread along X "
                "takes its lead as I, along Y as J, along Z as K)", src)
    minutes = revolutions / rpm
    feed = length / minutes if minutes > 0.0 else 0.0  # the mean path feed (mm/min) of the thread
    _followable(k, g, start, end, length, feed, src)
    k.straight_out(1, start, end, feed, src, _ThreadOut(k.canon, length / revolutions if revolutions > 0.0 else 0.0,
                                                       varying))
    k.prog = prog
    k.machine_pos = end


def _unused(k, g: int, words, letters: str, src: Src) -> None:
    """NC009 for a word the thread block has no use for: never dropped silently (rs274 stops there too,
    "R word with no g code that uses it"; the SINUMERIK radius address B or U arrives as R)."""
    for letter in letters:
        if letter in words:
            what = "a rounding radius (R; SINUMERIK B or U)" if letter == "R" else f"the {letter} word"
            k.fault("NC009", f"G{g}: {what} has no use in a thread block", src)


def iso_g33(k, g: int, words, src: Src) -> None:
    """LinuxCNC's G33: K is the distance along the path per revolution, in every block; no F."""
    _unused(k, g, words, "RIJPQ", src)
    if not _travels(k, words):
        return
    if "F" in words:
        k.fault("NC009", "F word used with G33 (the thread's speed follows the spindle: K is its lead)", src)
    if "K" not in words:
        k.fault("NC009", "K word (the lead, distance per revolution) missing with G33", src)
    lead = words["K"] * k.scale
    if lead <= 0.0:
        k.fault("NC009", f"G33: the lead K{words['K']:g} must be positive", src)
    _thread_move(k, g, words, src, lambda start, end, length: length / lead)


#: the ISO thread as a ``kernel.motion_modes`` entry
ISO_THREADS = {33: iso_g33}


class SinumerikThreads:
    """G33/G34/G35 of the SINUMERIK 8xx: the lead (I, J or K) and its change F are modal within the thread."""

    def __init__(self):
        self.lead_axis: str | None = None
        self.programmed = 0.0  # the modal lead as the program wrote it (I, J or K)
        self.lead = 0.0  # mm per revolution at the start of the next thread block
        self.chain_end = None  # the position where the last thread block ended (the tuple itself)
        self.change = 0.0  # mm/rev per revolution (G34 +, G35 -)

    def entries(self) -> dict:
        """The ``kernel.motion_modes`` entries."""
        return {33: self.move, 34: self.move, 35: self.move}

    def move(self, k, g: int, words, src: Src) -> None:
        _unused(k, g, words, "R", src)
        if not _travels(k, words):
            return
        given = [(axis, w) for axis, w in LEAD_WORDS.items() if w in words]
        if len(given) > 1:
            k.fault("NC009", f"G{g}: one lead word (I, J or K), not {' and '.join(w for _a, w in given)}", src)
        if given:
            axis, w = given[0]
            if axis not in k.axis_of:
                k.fault("NC009", f"G{g}: lead {w} belongs to axis {axis}, which the machine lacks", src)
            self.lead_axis, self.programmed = axis, abs(words[w]) * k.scale
            self.lead = self.programmed
        elif self.chain_end is not k.machine_pos:
            # a new pass after other moves starts at the programmed lead; only a thread block that follows
            # a thread block goes on with the lead its G34/G35 reached (every move sets a new position)
            self.lead = self.programmed
        if g == 33:
            if "F" in words:
                k.fault("NC009", "G33: F has no meaning in a thread of constant lead (the lead is I, J or K)", src)
            self.change = 0.0
        elif "F" in words:
            self.change = abs(words["F"]) * k.scale * (1.0 if g == 34 else -1.0)
        if self.lead_axis is None or self.lead <= 0.0:
            k.fault("NC009", f"G{g}: the lead (I, J or K, mm per revolution) is missing", src)
        i = k.axis_of[self.lead_axis]
        _thread_move(k, g, words, src, lambda start, end, length: self._revolutions(k, g, abs(end[i] - start[i]), src),
                     self.change != 0.0)
        self.chain_end = k.machine_pos

    def _revolutions(self, k, g: int, travel: float, src: Src) -> float:
        """Revolutions to travel ``travel`` along the lead axis with the lead growing by ``change`` per
        revolution: travel = lead n + change n^2 / 2. The lead at the end is the next block's start lead."""
        lead, change = self.lead, self.change
        if change == 0.0:
            return travel / lead
        disc = lead * lead + 2.0 * change * travel
        if disc < 0.0:
            k.fault("NC009", f"G{g}: the lead decreases to 0 before the end of the thread (lead "
                    f"{lead / k.scale:g}, decrease {-change / k.scale:g} per revolution)", src)
        n = (math.sqrt(disc) - lead) / change
        self.lead = lead + change * n
        return n
