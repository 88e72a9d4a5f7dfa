"""Internal G group 11 of the SINUMERIK 8xx (CL 800 manual L7407: G94 G95 G96 G97) and the threads of
group 0 (L7397: G33 G34 G35), as ``kernel.g_handlers`` and ``kernel.motion_modes`` entries.

One group: selecting one deselects the others. G94 feed in mm/min; G95 feed in mm/rev; G96 constant
cutting speed, the feed in mm/rev; G97 ends G96, the spindle keeping its speed, the feed still in mm/rev
(the usual meaning on the 810T-880T; docs/decisions.md); G97 without G96 before it changes nothing. Leaving G96 by G94 or G95 keeps the speed as G97
does. A change between per minute and per revolution wants a new F (F0 until then, as rs274 does).
"""

from __future__ import annotations

from ...nc import threads


def _leave_css(k) -> None:
    if k.css:
        k._g97()


def g94(k, g, words, src) -> bool:
    _leave_css(k)
    return threads.g94(k, g, words, src)


def g95(k, g, words, src) -> bool:
    _leave_css(k)
    return threads.g95(k, g, words, src)


def g96(k, g, words, src) -> bool:
    threads.g95(k, g, words, src)
    k.css = k.spindle_bound = True
    return False


def g97(k, g, words, src) -> bool:
    """G97 after G96: the speed stays, the feed stays per revolution. Without G96 before it the feed mode stays
    as it is (a program's preamble ``G94 G97`` keeps mm/min)."""
    _leave_css(k)
    return False


GROUP_11 = {94: g94, 95: g95, 96: g96, 97: g97}


def active_group_11(k) -> int:
    """ACG (@36b) group 11: the selected function (G97 after G96 reads as G95, the feed mode it leaves)."""
    return 96 if k.css else 95 if k.per_rev else 94


def setup(kernel) -> None:
    """The channel's kernel learns group 11 and the threads."""
    kernel.g_handlers.update(GROUP_11)
    kernel.motion_modes.update(threads.SinumerikThreads().entries())
