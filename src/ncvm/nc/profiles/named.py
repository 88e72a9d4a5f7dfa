"""The profiles by name (a machine file's ``[din] profile`` names one), each imported when it is first named:
a DIN run reads its blocks with one of them, and each module builds its G table at import (issue 18)."""

from __future__ import annotations

from importlib import import_module

from . import Profile

#: profile name -> (module of this package, the profile's name in it), in the order docs/profiles.md shows them
WHERE = {"iso": ("iso", "ISO"), "typ3osa": ("typ3osa", "TYP3OSA"), "sinumerik8xx": ("sinumerik8xx", "SINUMERIK8XX")}


def profile(name: str) -> Profile:
    """The profile called ``name`` (KeyError for a name not in :data:`WHERE`)."""
    module, attribute = WHERE[name]
    return getattr(import_module(f".{module}", __package__), attribute)


def every_profile() -> tuple[Profile, ...]:
    return tuple(profile(name) for name in WHERE)
