"""The permanent store as a file of its own: what ``ncvm state export`` writes and ``import`` reads back.

The file is JSON: ``{"format": "ncvm-state", "version": 1, "store": {namespace: {key: value}}}``, the
store's own values unchanged, so a round trip is exact (a REAL is the binary32 value as the double
that holds it; ``json`` writes every double so that it reads back to the same bits). An import is
checked whole before anything is written, against what the control can hold (:mod:`.store_schema`): a
file a control could not have written (an unknown namespace, a wrong key, a value of another type or
shape, a non-finite number) is refused with the place and the reason, never half imported. The
namespaces are those the dialects keep (docs/batch.md, "Permanent memory", "What an import accepts").
"""

from __future__ import annotations

import json
from typing import Any

from ..diagnostics import UsageError
from .schema import SchemaError, validate
from .store_schema import STORE, normal

FORMAT, VERSION = "ncvm-state", 1

#: namespace -> what it holds, as ``ncvm state show`` titles it
NAMESPACES = {
    "cpl.perm": "CPL permanent variables (@1..@100, @_R(1..100), declared @NAME)",
    "cpl.zs": "CPL zero offset tables (ZS database)",
    "cpl.tc": "CPL tool compensation tables (TC)",
    "cpl.tdb": "CPL tool database (TDA records)",
    "sin800": "SINUMERIK 800 NC data (machine and setting data, tool and zero offsets, MIB, central R parameters)",
}


class StateFileError(UsageError):
    """A state file that cannot be imported (exit 2): the message names the file, the entry and why."""


def document(content: dict[str, dict[str, Any]]) -> str:
    """The export file's text."""
    return json.dumps({"format": FORMAT, "version": VERSION, "store": content}, indent=2, sort_keys=True) + "\n"


def parse(text: str, shown: str) -> dict[str, dict[str, Any]]:
    """The store content of an export file, checked whole; :class:`StateFileError` names what is wrong."""
    try:
        doc = json.loads(text, object_pairs_hook=_once)
    except _GivenTwice as e:
        raise StateFileError(f"{shown}: {json.dumps(e.key)}: key given twice in one object (a value of the "
                             f"file would be lost; keep one)") from None
    except json.JSONDecodeError as e:
        raise StateFileError(f"{shown}:{e.lineno}:{e.colno}: not JSON: {e.msg}") from None
    except RecursionError:
        raise StateFileError(f"{shown}: not a state file: nested too deeply") from None
    if not isinstance(doc, dict) or doc.get("format") != FORMAT:
        raise StateFileError(f'{shown}: not an ncvm state file (no "format": "{FORMAT}"; write one with '
                             f"ncvm state export)")
    if doc.get("version") != VERSION:
        raise StateFileError(f"{shown}: state file version {doc.get('version')!r}; this ncvm reads version {VERSION}")
    if set(doc) - {"format", "version", "store"}:
        raise StateFileError(f"{shown}: unknown key(s) {', '.join(sorted(set(doc) - {'format', 'version', 'store'}))}")
    store = doc.get("store")
    if not isinstance(store, dict):
        raise StateFileError(f'{shown}: "store" must be an object of namespaces')
    content: dict[str, dict[str, Any]] = {}
    for namespace, entries in store.items():
        if namespace not in NAMESPACES:
            raise StateFileError(f"{shown}: unknown namespace {namespace!r} (known: {', '.join(NAMESPACES)})")
        if not isinstance(entries, dict):
            raise StateFileError(f"{shown}: {namespace}: must be an object of keys and values")
        content[namespace] = _checked(namespace, entries, shown)
    return content


class _GivenTwice(Exception):
    def __init__(self, key: str):
        self.key = key


def _once(pairs: list[tuple[str, Any]]) -> dict[str, Any]:
    """An object of the file, refusing a key given twice: a JSON reader keeps the last and drops the
    first without a word, and a hand-edited file (a copied line) would lose a value silently."""
    obj: dict[str, Any] = {}
    for key, value in pairs:
        if key in obj:
            raise _GivenTwice(key)
        obj[key] = value
    return obj


def _checked(namespace: str, entries: Any, shown: str) -> dict[str, Any]:
    node = STORE[namespace]
    try:
        validate(node, entries)
    except SchemaError as e:
        raise StateFileError(f"{shown}: {namespace}: {e}") from None
    return normal(node, entries)
