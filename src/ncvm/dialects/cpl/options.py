"""The machine file's ``[cpl]`` section as the CPL control reads it (docs/cpl.md; its schema, with the
documentation of each key, is machine/sections.py's CPL, which checks it first)."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from ...machine.config import dialect_options


@dataclass(frozen=True)
class Options:
    """One field per key of ``[cpl]``; tables and records stay as the machine file writes them."""

    lookahead: int = 0  # NC blocks prepared ahead; 0 = the control's block buffer
    calls: dict[str, Any] = field(default_factory=dict)  # address -> sub-program, over the drilling cycles
    channel: int = 1  # the channel the program runs in
    axes: list[Any] | None = None  # physical axes 1..n (a name or a table); None: the [[axis]] list
    zs_unit: str = "mm"  # unit of new ZS tables
    zs_active: str = "V1"  # the active ZS table
    zs_tables: dict[str, dict] = field(default_factory=dict)
    tc_unit: str = "mm"  # unit of the compensation tables
    tc_tables: dict[str, dict] = field(default_factory=dict)
    tool_database: list[dict] = field(default_factory=list)
    macoda: dict[str, Any] = field(default_factory=dict)
    plc: dict[str, int] = field(default_factory=dict)
    errors: list[dict] = field(default_factory=list)  # the error log GETERR reads
    override: dict[str, int] = field(default_factory=dict)  # potentiometers; missing ones at their default
    spindle: dict[str, float] = field(default_factory=dict)  # min, max, group; missing ones at their default
    areas: list[dict] = field(default_factory=list)  # work areas and dead ranges
    language: int = 1
    date_format: str = "DD.MM"  # DATE as L2496 shows it; "DD.MM.YY" adds the year
    file_space: int = 1 << 30  # bytes the files a program writes may grow by in one run
    file_zeros: str = "suppress"  # PRN# to files drops trailing zeros (L4001); "keep" keeps them


def options(machine) -> Options:
    """The [cpl] section of the machine; an unknown key or a wrong value is a usage error."""
    return dialect_options(Options, machine.sections, "cpl", machine.axes)
