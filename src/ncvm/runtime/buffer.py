"""The block buffer: prepared blocks waiting for execution, a bounded number of them.

A control prepares (decodes) blocks ahead of the one its axes execute. CPL calls it the motion
queue, with a look-ahead depth or the block buffer (manual §4.2); the SINUMERIK 800 decodes up to
N blocks ahead (CL 800 manual L4287-4334, STOP DEC). Either way preparation puts blocks in, and when more wait than the
buffer holds the oldest execute; a WAIT, STOP DEC or the program end drains it, since what comes
next needs the executed state. Execution that stops at a block (its fault, Ctrl-C) ends the buffer: the
blocks after it never execute, also when the program's stop drains what it prepared.

The buffer is the deque of the waiting blocks itself (the oldest first), so the readers of the
prepared state (CPL's CPOS, SINUMERIK's programmed spindle speed) iterate it directly, and a put
costs an append and a length test.
"""

from __future__ import annotations

from collections import deque
from collections.abc import Callable

from . import interrupt


class BlockBuffer(deque):
    """Prepared blocks waiting for execution, the oldest first.

    ``ahead`` blocks may wait; the block prepared beyond them makes the ``spill`` oldest execute:
    one for a look-ahead (preparation waits block by block), half the buffer for a buffer emptied
    in bulk. ``execute`` is the "execute one" step; ``execute_many``, when given, executes a list of
    the oldest blocks at once (CPL runs plain rows column-wise), else they execute one by one.
    """

    __slots__ = ("ahead", "spill", "execute", "execute_many", "executed", "put")

    def __init__(self, ahead: int, execute: Callable, spill: int = 1, execute_many: Callable | None = None):
        super().__init__()
        self.ahead = ahead
        self.spill = spill
        self.execute = execute
        self.execute_many = execute_many
        self.executed = 0  # blocks taken from the buffer and executed so far
        #: put(blk) -> bool: queue a prepared block; True when the buffer overflowed and its oldest executed
        self.put: Callable[[object], bool] = self._putter()

    def _putter(self) -> Callable[[object], bool]:
        """``put`` as a closure over the buffer: generated code calls it for every block (the hot path)."""
        append, ahead, spill = self.append, self.ahead, self.spill
        overflow = self.execute_one if spill == 1 else lambda: self.execute_oldest(spill)

        def put(blk) -> bool:
            append(blk)
            if len(self) <= ahead:
                return False
            overflow()
            return True

        return put

    def execute_one(self) -> None:
        """Execute the oldest block; the blocks after it still wait while it executes."""
        blk = self.popleft()
        self.executed += 1
        try:
            self.execute(blk)
        except BaseException:
            self.clear()  # execution stopped at this block: the blocks after it never execute
            raise

    def execute_oldest(self, n: int) -> None:
        """Execute the ``n`` oldest blocks (all of them when fewer wait)."""
        run = self.execute_many
        if run is None:
            for _ in range(min(n, len(self))):
                self.execute_one()
            return
        if n >= len(self):
            blocks = list(self)
            self.clear()
        else:
            blocks = [self.popleft() for _ in range(n)]
        self.executed += len(blocks)
        try:
            with interrupt.block():  # Ctrl-C ends the run after these blocks, not amid their passes
                run(blocks)
        except BaseException:
            self.clear()  # execution stopped in these blocks: the ones still waiting never execute
            raise

    def drain(self) -> None:
        """Execute every waiting block (WAIT, STOP DEC, the program end)."""
        if self.execute_many is None:
            while self:
                self.execute_one()
        else:
            self.execute_oldest(len(self))
