"""The row of CPL's function table (builtins.FUNCTIONS, with chapter 4's rows from system.SYSTEM_FUNCTIONS).

A module of its own so that the system package and builtins both read it without importing each other.
"""

from __future__ import annotations

from typing import Callable

from ...records import FrozenRecord


class Builtin(FrozenRecord):
    """One row of the function table: the implementation, its arguments and result, where the manual has it."""

    __slots__ = ("impl", "min_args", "max_args", "result", "section", "rt", "io", "params", "refs", "out")

    def __init__(self, impl: Callable, min_args: int, max_args: int, result: str, section: str, rt: bool = False,
                 io: bool = False, params: str = "", refs: tuple = (), out: int | None = None):
        self.impl = impl
        self.min_args = min_args
        self.max_args = max_args
        self.result = result  # I R D B S, "=" first argument's type, "RD", "?" decided at run time
        self.section = section
        self.rt = rt
        self.io = io  # takes the run's CplIO first (chapters 6-9)
        self.params = params  # per argument: S string, I/N number, checked when the type is known at compile time
        self.refs = refs  # argument positions passed by name: a field the function fills (GETERR, MCODS)
        self.out = out  # the one argument the function writes back (SCS, SCSL, MCODS)
