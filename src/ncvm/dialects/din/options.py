"""The ``[din]`` section of the machine file: the machine data of the ISO / LinuxCNC profile."""

from __future__ import annotations

from ...machine.config import dialect_options
from ...nc.arcs import RS274, RadiusTolerance
from ...records import FrozenRecord


class Options(FrozenRecord):
    """The keys of ``[din]`` (machine/sections.py declares them with these defaults)."""

    __slots__ = ("arc_radius_tolerance", "arc_radius_tolerance_inch", "arc_radius_relative", "profile")

    def __init__(self, arc_radius_tolerance: float = RS274.absolute,
                 arc_radius_tolerance_inch: float = RS274.absolute_inch,
                 arc_radius_relative: float = RS274.relative, profile: str = "iso"):
        self.arc_radius_tolerance = arc_radius_tolerance
        self.arc_radius_tolerance_inch = arc_radius_tolerance_inch
        self.arc_radius_relative = arc_radius_relative
        self.profile = profile


def options(machine) -> Options:
    return dialect_options(Options, getattr(machine, "sections", {}), "din")


def arc_tolerance(opts: Options) -> RadiusTolerance:
    """rs274's arc rule with the machine's tolerances (its cap stays 100 times the absolute tolerance)."""
    return RadiusTolerance(opts.arc_radius_tolerance, opts.arc_radius_tolerance_inch, opts.arc_radius_relative,
                           RS274.limit, RS274.reach, RS274.zero)
