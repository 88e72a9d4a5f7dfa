"""The dialect registry: id -> front end, and how a program's dialect is found.

Front ends are imported on first use, so a broken or missing one never slows
or breaks the others.
"""

from __future__ import annotations

import importlib
from pathlib import Path
from typing import TYPE_CHECKING, NamedTuple

from ..diagnostics import UsageError

if TYPE_CHECKING:  # the registry itself stays light: the CLI reads it at start-up
    from .base import Dialect


class Entry(NamedTuple):
    """One dialect as the registry knows it without importing it."""

    module: str
    title: str
    extensions: tuple[str, ...]


#: dialect id -> its entry: the one list of dialects (CLI choices and the extension map derive from it)
REGISTRY = {
    "din": Entry("ncvm.dialects.din", "plain DIN 66025 / ISO 6983", (".din", ".ngc", ".nc", ".iso")),
    "cpl": Entry("ncvm.dialects.cpl", "Bosch Rexroth CPL (Typ3 osa / PNC)", (".cpl",)),
    "cl800": Entry("ncvm.dialects.sinumerik.cl800", "Siemens CL 800 cycle language (compiled to SINUMERIK 800 @ code)",
                   (".cl8", ".cl800")),
    "sin800": Entry("ncvm.dialects.sinumerik", "SINUMERIK 800 NC: @ code and DIN part programs (%MPF/%SPF)",
                    (".mpf", ".spf")),
    "sympas": Entry("ncvm.dialects.sympas", "ADDI-DATA rw_SymPas (APCI-8001/8008)", (".pas", ".sym", ".sap")),
}

#: file extension -> dialect id
EXTENSIONS = {ext: d for d, entry in REGISTRY.items() for ext in entry.extensions}

_LOADED: dict[str, Dialect] = {}


def get_dialect(dialect_id: str) -> Dialect:
    if dialect_id not in REGISTRY:
        raise UsageError(f"unknown dialect '{dialect_id}' (known: {', '.join(REGISTRY)})")
    if dialect_id not in _LOADED:
        try:
            module = importlib.import_module(REGISTRY[dialect_id].module)
        except ModuleNotFoundError as e:
            if e.name and e.name.startswith(REGISTRY[dialect_id].module):
                raise UsageError(f"dialect '{dialect_id}' is not available in this version of ncvm") from None
            raise
        _LOADED[dialect_id] = module.DIALECT
    return _LOADED[dialect_id]


def available() -> list[str]:
    out = []
    for d in REGISTRY:
        try:
            get_dialect(d)
            out.append(d)
        except UsageError:
            pass
    return out


def dialect_of_name(path: str | Path) -> str | None:
    """The dialect a program's file name (its extension) says, or None."""
    return EXTENSIONS.get(Path(path).suffix.lower())


def detect_dialect(path: str | Path, text: str) -> str:
    """The dialect of a program: by extension, else by content when that is certain."""
    named = dialect_of_name(path)
    if named:
        return named
    scores = sorted(((get_dialect(d).sniff(text), d) for d in available()), reverse=True)
    if scores and scores[0][0] >= 60 and (len(scores) == 1 or scores[0][0] - scores[1][0] >= 30):
        return scores[0][1]
    guess = f" (it looks most like '{scores[0][1]}')" if scores and scores[0][0] > 0 else ""
    raise UsageError(f"{path}: cannot tell the dialect from the name or the content{guess}; "
                     f"pass --dialect ({', '.join(REGISTRY)})")
