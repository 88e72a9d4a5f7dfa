"""The machine file's ``[sin800]`` section as the SINUMERIK channel reads it (docs/sin800.md; its schema,
with the documentation of each key, is machine/sections.py's SIN800, which checks it first)."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from ...machine.config import dialect_options


@dataclass(frozen=True)
class Options:
    """One field per key of ``[sin800]``; tables stay as the machine file writes them."""

    control: str = "880"  # ranges of TO areas, D numbers, MIB, PLC: 810, 820, 850 or 880
    channel: int = 1  # the channel the program runs in (PPCH)
    m0: str = "continue"  # "continue" as after the operator's cycle start, or "stop"
    block_skip: bool | None = None  # None: [setting_data] block_skip
    max_call_depth: int = 8
    cycle_alarm_stop: bool = True  # ALNZ 4000-4299 stop the program
    to_area: int = 0
    r: dict[str, float] = field(default_factory=dict)  # R parameters at power-on
    nc_md: dict[str, Any] = field(default_factory=dict)
    cycle_md: dict[str, Any] = field(default_factory=dict)
    plc_md: dict[str, Any] = field(default_factory=dict)
    drive_md: dict[str, Any] = field(default_factory=dict)
    nc_sd: dict[str, Any] = field(default_factory=dict)
    cycle_sd: dict[str, Any] = field(default_factory=dict)
    mib: dict[str, float] = field(default_factory=dict)
    inputs: dict[str, Any] = field(default_factory=dict)  # external input bytes 1 and 2
    alarms: list[int] = field(default_factory=list)  # pending NC alarms
    sob: dict[str, float] = field(default_factory=dict)
    tool_offsets: list[dict] = field(default_factory=list)
    zero_offsets: dict[str, Any] = field(default_factory=dict)
    rotation: dict[str, list[float]] = field(default_factory=dict)
    plc: dict[str, dict] = field(default_factory=dict)  # PLC number -> its images and wiring
    m_functions: dict[str, dict] = field(default_factory=dict)  # M number -> R parameter -> value or PLC data
    decode_ahead: int = 0  # blocks decoded ahead of execution (0 = lockstep)
    strict_nc: bool = False  # R stores keep 8 significant digits
    gear: int = 1  # gear stage of the master spindle at power-on
    gears: list[float] = field(default_factory=list)  # maximum speed of gear stages 1..
    v24_input: str = ""  # what INP reads from the V24 port
    radius_address: str = "B"  # the circle radius address (machine data): B as the manual's contour, or U

    def area(self, name: str) -> dict[str, Any]:
        """One of the MD/SD areas by its key (ncdata.AREAS)."""
        return getattr(self, name)


def options(machine) -> Options:
    """The [sin800] section of the machine; an unknown key or a wrong value is a usage error."""
    return dialect_options(Options, machine.sections, "sin800", machine.axes)
