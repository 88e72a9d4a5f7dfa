"""The axes' spoolers (§6.6, SMLA ... SSMS): what they hold and when they have room.

Each axis queues its spooled entries (``AxisState.spool``); a running chain's unfinished segments
still hold their entries. The spooled commands (commands/spooled.py) fill and start them.
"""

from __future__ import annotations

from .motion import Chain


class Spooler:
    def __init__(self, axes: list, capacity: int):
        self.axes = axes
        self.capacity = capacity  # entries per axis (sympas.spool_capacity)
        self.planning_chain = False  # SSMS is planning a chain: no feed hold on its single segments
        self._tickets = 0

    def ticket(self) -> int:
        """The sequence number of a new spooler entry: entries run in the order they were spooled."""
        self._tickets += 1
        return self._tickets

    def chain_pending(self, ax: int, t: float) -> int:
        """Segments of axis ``ax``'s running chain not finished at ``t``: they still hold spooler memory."""
        mv = self.axes[ax].move
        if not isinstance(mv, Chain) or mv.jog or mv.t1 <= t:
            return 0
        return sum(1 for m in mv.segs if m.t1 > t and ax in m.axes)

    def used(self, ax: int, t: float) -> int:
        """Spooler entries of axis ``ax`` at ``t``: the queued ones and the running chain's unfinished segments."""
        return len(self.axes[ax].spool) + self.chain_pending(ax, t)

    def free_at(self, axes, cap: int, t: float):
        """The tick from which every axis of ``axes`` has a free spooler entry (its oldest segments done);
        None when the running chains cannot free one (the rest waits behind a halt)."""
        until = t
        for ax in axes:
            over = self.used(ax, t) - cap + 1
            if over <= 0:
                continue
            mv = self.axes[ax].move
            ends = [m.t1 for m in mv.segs if m.t1 > t and ax in m.axes] if isinstance(mv, Chain) else []
            if over > len(ends):
                return None
            until = max(until, ends[over - 1])
        return until
