"""What the system functions of chapter 4 see of a run: the typed context they receive.

The language runtime (runtime.CplRuntime) is the one implementation; the system functions name only these
members, so the runtime's other state stays its own (tests/dialects/cpl/test_cpl_system_context.py checks
that every member a system module reads is named here and that the runtime has it).
"""

from __future__ import annotations

from collections import deque
from typing import TYPE_CHECKING, Protocol

if TYPE_CHECKING:
    from ....machine.model import Machine
    from ....nc.kernel import NcKernel
    from ....runtime.session import Session
    from ..io.context import CplIO
    from ..linker import LinkResult
    from .controller import Controller


class SystemContext(Protocol):
    """A CPL run as the system functions use it."""

    ctl: Controller  # the simulated controller (CPL manual §4, L1184-3343): axes, tables, PLC image, error log, NCS state
    kernel: NcKernel  # the NC state as executed (MPOS, active G functions)
    machine: Machine
    session: Session
    io: CplIO  # the run's files (ZS tables and NPV files by path, SERCOS lists)
    linked: LinkResult  # the main program (MCODS: the selected program of the own channel)
    queue: deque  # the prepared blocks not yet executed (the motion queue)
    t_prep: float  # the program's own time, s (where block preparation stands)
    block_skip: bool  # the block-skip switch (/ blocks)

    def prepared_kernel(self) -> NcKernel:
        """The NC state after every prepared block (CPOS, AXO: values at block preparation)."""

    def forget_prepared(self) -> None:
        """The prepared state is built again at the next read (offsets or tool tables changed under it)."""

    def executed_position(self) -> tuple:
        """The machine position at the program's time."""

    def moving(self) -> bool:
        """Whether a block is still moving at the program's time."""

    def executing_block(self):
        """The block the channel executes at the program's time, or None."""

    def execute_next(self) -> bool:
        """Let execution go on by one block; False when nothing is left."""

    def _apply_events(self, t: float) -> None:
        """The scenario's input events up to time ``t`` (IC reads)."""

    def frozen(self, what: str, scenario: bool = False) -> None:
        """The run read ``what`` from outside the program: marked at the running CPL line (ncvm translate)."""
