"""Step counting, the runaway limit, and the debug hook for single-block stepping.

Generated code counts executed statements in a local variable, a group of
straight statements at once, and tests the limit at the head of each group,
before any of it runs: the limit is never passed and the count is the
statements that ran. A debug build of a unit calls :attr:`hook` before
every statement; the normal build has no hook calls at all.
"""

from __future__ import annotations

from collections.abc import Callable

from ..diagnostics import RuntimeFault, Span

DEFAULT_MAX_STEPS = 100_000_000

#: signature of a debug hook: (file, line, variables) -> None; may raise to stop the run
StepHook = Callable[[str, int, dict], None]


class StepCounter:
    """Counts statements and blocks executed; stops a runaway program at ``limit``."""

    __slots__ = ("steps", "limit", "hook", "breakpoints")

    def __init__(self, limit: int = DEFAULT_MAX_STEPS, hook: StepHook | None = None):
        self.steps = 0
        self.limit = limit
        self.hook = hook
        self.breakpoints: set[tuple[str, int]] = set()

    def runaway(self, file: str, line: int):
        raise RuntimeFault("RUN001", f"step limit of {self.limit:,} statements and blocks reached "
                                     f"(runaway program? raise it with --max-steps)", Span(file, line))
