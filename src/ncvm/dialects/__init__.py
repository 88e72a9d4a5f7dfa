"""The dialect registry: id -> front end, and how a program's dialect is found.

Front ends are imported on first use, so a broken or missing one never slows
or breaks the others.
"""

from __future__ import annotations

import importlib
from pathlib import Path

from ..diagnostics import UsageError
from .base import Dialect

#: dialect id -> module that defines DIALECT
REGISTRY = {
    "din": "ncvm.dialects.din",
    "cpl": "ncvm.dialects.cpl",
    "cl800": "ncvm.dialects.cl800",
    "sin800": "ncvm.dialects.sinumerik",
    "sympas": "ncvm.dialects.sympas",
}

#: file extension -> dialect id
EXTENSIONS = {
    ".din": "din", ".ngc": "din", ".nc": "din", ".iso": "din",
    ".cpl": "cpl",
    ".cl8": "cl800", ".cl800": "cl800",
    ".spf": "sin800", ".mpf": "sin800",
    ".pas": "sympas", ".sym": "sympas", ".sap": "sympas",
}

_LOADED: dict[str, Dialect] = {}


def get_dialect(dialect_id: str) -> Dialect:
    if dialect_id not in REGISTRY:
        raise UsageError(f"unknown dialect '{dialect_id}' (known: {', '.join(REGISTRY)})")
    if dialect_id not in _LOADED:
        try:
            module = importlib.import_module(REGISTRY[dialect_id])
        except ModuleNotFoundError as e:
            if e.name and e.name.startswith(REGISTRY[dialect_id]):
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


def detect_dialect(path: str | Path, text: str) -> str:
    """The dialect of a program: by extension, else by content when that is certain."""
    ext = Path(path).suffix.lower()
    if ext in EXTENSIONS:
        return EXTENSIONS[ext]
    scores = sorted(((get_dialect(d).sniff(text), d) for d in available()), reverse=True)
    if scores and scores[0][0] >= 60 and (len(scores) == 1 or scores[0][0] - scores[1][0] >= 30):
        return scores[0][1]
    guess = f" (it looks most like '{scores[0][1]}')" if scores and scores[0][0] > 0 else ""
    raise UsageError(f"{path}: cannot tell the dialect from the name or the content{guess}; "
                     f"pass --dialect ({', '.join(REGISTRY)})")
