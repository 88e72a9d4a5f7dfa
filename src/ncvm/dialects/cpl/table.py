"""The row of CPL's function table (builtins.FUNCTIONS, with chapter 4's rows from system.SYSTEM_FUNCTIONS).

A module of its own so that the system package and builtins both read it without importing each other.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable


@dataclass(frozen=True, slots=True)
class Builtin:
    impl: Callable
    min_args: int
    max_args: int
    result: str  # I R D B S, "=" first argument's type, "RD", "?" decided at run time
    section: str
    rt: bool = False
    io: bool = False  # takes the run's CplIO first (chapters 6-9)
    params: str = ""  # per argument: S string, I/N number, checked when the type is known at compile time
    refs: tuple = ()  # argument positions passed by name: a field the function fills (GETERR, MCODS)
    out: int | None = None  # the one argument the function writes back (SCS, SCSL, MCODS)
