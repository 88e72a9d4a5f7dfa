"""The ``[din]`` section of the machine file: the machine data of the ISO / LinuxCNC profile."""

from __future__ import annotations

from dataclasses import dataclass, replace

from ...machine.config import dialect_options
from ...nc.arcs import RS274, RadiusTolerance


@dataclass(frozen=True)
class Options:
    """The keys of ``[din]`` (machine/sections.py declares them with these defaults)."""

    arc_radius_tolerance: float = RS274.absolute
    arc_radius_tolerance_inch: float = RS274.absolute_inch
    arc_radius_relative: float = RS274.relative
    profile: str = "iso"


def options(machine) -> Options:
    return dialect_options(Options, getattr(machine, "sections", {}), "din")


def arc_tolerance(opts: Options) -> RadiusTolerance:
    """rs274's arc rule with the machine's tolerances (its cap stays 100 times the absolute tolerance)."""
    return replace(RS274, absolute=opts.arc_radius_tolerance, absolute_inch=opts.arc_radius_tolerance_inch,
                   relative=opts.arc_radius_relative)
