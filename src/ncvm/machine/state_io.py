"""The permanent store as a file of its own: what ``ncvm state export`` writes and ``import`` reads back.

The file is JSON: ``{"format": "ncvm-state", "version": 1, "store": {namespace: {key: value}}}``, the
store's own values unchanged, so a round trip is exact (a REAL is the binary32 value as the double
that holds it; ``json`` writes every double so that it reads back to the same bits). An import is
checked whole before anything is written: a file a control could not have written (an unknown
namespace, a wrong key, a value of another type or shape) is refused with the place and the reason,
never half imported. The namespaces are those the dialects keep (docs/batch.md, "Permanent memory").
"""

from __future__ import annotations

import json
import math
import re
import struct
from typing import Any, Callable

from ..diagnostics import UsageError

FORMAT, VERSION = "ncvm-state", 1

#: namespace -> what it holds, as ``ncvm state show`` titles it
NAMESPACES = {
    "cpl.perm": "CPL permanent variables (@1..@100, @_R(1..100), declared @NAME)",
    "cpl.zs": "CPL zero offset tables (ZS database)",
    "cpl.tc": "CPL tool compensation tables (TC)",
    "cpl.tdb": "CPL tool database (TDA records)",
    "sin800": "SINUMERIK 800 NC data (machine and setting data, tool and zero offsets, MIB, central R parameters)",
}
SIN800_AREAS = ("nc_md", "cycle_md", "plc_md", "drive_md", "nc_sd", "cycle_sd", "to", "zo", "rot", "central_r")
INT32 = (-2**31, 2**31 - 1)
_F32 = struct.Struct("f")


class StateFileError(UsageError):
    """A state file that cannot be imported (exit 2): the message names the file, the entry and why."""


def document(content: dict[str, dict[str, Any]]) -> str:
    """The export file's text."""
    return json.dumps({"format": FORMAT, "version": VERSION, "store": content}, indent=2, sort_keys=True) + "\n"


def parse(text: str, shown: str) -> dict[str, dict[str, Any]]:
    """The store content of an export file, checked whole; :class:`StateFileError` names what is wrong."""
    try:
        doc = json.loads(text)
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
        content[namespace] = {key: _checked(namespace, key, value, shown) for key, value in entries.items()}
    return content


def _checked(namespace: str, key: str, value: Any, shown: str) -> Any:
    try:
        return CHECKS[namespace](key, value)
    except _Bad as e:
        raise StateFileError(f"{shown}: {namespace} {key}: {e}") from None


class _Bad(Exception):
    """What is wrong with one entry."""


# -- values ------------------------------------------------------------------------------------
def _int(v, lo=INT32[0], hi=INT32[1]) -> int:
    if v.__class__ is not int or not lo <= v <= hi:
        raise _Bad(f"{_show(v)} is not an INTEGER in {lo}..{hi}")
    return v


def _double(v) -> float:
    if v.__class__ not in (int, float):
        raise _Bad(f"{_show(v)} is not a number")
    return float(v)


def _real(v) -> float:
    """A REAL is a binary32 value: one that binary32 does not hold exactly no control could have stored."""
    v = _double(v)
    if math.isfinite(v) and (abs(v) > 3.4028234663852886e38 or _F32.unpack(_F32.pack(v))[0] != v):
        raise _Bad(f"{_show(v)} is not a REAL (binary32) value")
    return v


def _bool(v) -> bool:
    if v.__class__ is not bool:
        raise _Bad(f"{_show(v)} is not true or false")
    return v


def _text(length: int) -> Callable[[Any], str]:
    def check(v) -> str:
        if v.__class__ is not str or len(v) > length:
            raise _Bad(f"{_show(v)} is not a string of at most {length} characters")
        return v
    return check


def _nul(check):
    return lambda v: None if v is None else check(v)


def _show(v) -> str:
    text = json.dumps(v)
    return text if len(text) <= 40 else text[:37] + "..."


def _object(v, what: str) -> dict:
    if not isinstance(v, dict):
        raise _Bad(f"must be an object of {what}")
    return v


def _list(v, n: int | None, check, what: str) -> list:
    if not isinstance(v, list) or (n is not None and len(v) != n):
        raise _Bad(f"must be a list of {n if n is not None else 'the'} {what}")
    return [check(x) for x in v]


# -- namespaces ----------------------------------------------------------------------------------
NAME = re.compile(r"[A-Z][A-Z0-9_]{0,15}")
ELEMENT = {"INT": _int, "REAL": _real, "DOUBLE": _double, "BOOL": _bool}


def _cpl_perm(key: str, v):
    """``@n`` INTEGER, ``@_R(i)`` DOUBLE, ``@NAME`` a declared variable's record (manual §2.4.3)."""
    if m := re.fullmatch(r"@([1-9][0-9]*)", key):
        if int(m.group(1)) > 100:
            raise _Bad("the permanent INTEGER variables are @1..@100")
        return _nul(_int)(v)
    if m := re.fullmatch(r"@_R\(([1-9][0-9]*)\)", key):
        if int(m.group(1)) > 100:
            raise _Bad("the permanent DOUBLE field is @_R(1..100)")
        return _nul(_double)(v)
    if not (key.startswith("@") and NAME.fullmatch(key[1:])):
        raise _Bad("not a permanent variable (@1..@100, @_R(1..100), or @NAME of up to 16 characters)")
    rec = _object(v, '"type", "dims" and "value"')
    if set(rec) != {"type", "dims", "value"}:
        raise _Bad('a declared variable is an object of "type", "dims" and "value"')
    typ, dims = rec["type"], rec["dims"]
    if typ not in (*ELEMENT, "CHAR"):
        raise _Bad(f"type {_show(typ)} is not INT, REAL, DOUBLE, BOOL or CHAR")
    limit = 1024 if typ == "CHAR" else 65535
    if not isinstance(dims, list) or len(dims) > 2 or any(d.__class__ is not int or not 1 <= d <= limit for d in dims):
        raise _Bad(f"dims must be a list of at most 2 sizes in 1..{limit}")
    if typ == "CHAR":  # a string of dims[-1] characters, or a field of dims[0] + 1 of them
        text = _nul(_text(dims[-1] if dims else 1))
        value = text(rec["value"]) if len(dims) <= 1 else _list(rec["value"], dims[0] + 1, text, "strings")
    else:
        element = _nul(ELEMENT[typ])
        if not dims:
            value = element(rec["value"])
        elif len(dims) == 1:
            value = _list(rec["value"], dims[0] + 1, element, f"{typ} values")
        else:
            row = lambda r: _list(r, dims[1] + 1, element, f"{typ} values")  # noqa: E731
            value = _list(rec["value"], dims[0] + 1, row, f"rows of {dims[1] + 1}")
    return {"type": typ, "dims": dims, "value": value}


def _cpl_zs(key: str, v):
    table = _object(v, "columns, unit, strict, rows")
    rows = _object(table.get("rows"), "rows")
    for row, values in rows.items():
        _list(values, None, _double, f"numbers of row {row}")
    return table


def _cpl_tc(key: str, v):
    groups = _object(v, "compensation groups")
    for group, values in groups.items():
        if not group.isdigit():
            raise _Bad(f"compensation group {group!r} is not a number")
        _list(values, None, _double, f"numbers of group {group}")
    return groups


def _cpl_tdb(key: str, v):
    if not re.fullmatch(r"[0-9]+,[0-9]+", key):
        raise _Bad('a tool database record is keyed "sector,place"')
    fields = _object(v, "fields")
    for field, value in fields.items():
        if not field.isdigit():
            raise _Bad(f"field {field!r} is not a number")
        if value.__class__ is not str:
            _int(value)
        elif len(value) > 31:
            raise _Bad(f"field {field}: at most 31 characters")
    return fields


def _sin800(key: str, v):
    if key == "mib":
        return _list(v, None, _double, "numbers")
    if key not in SIN800_AREAS:
        raise _Bad(f"not a data area of the NC ({', '.join((*SIN800_AREAS, 'mib'))})")
    for address, value in _object(v, "addresses and values").items():
        if isinstance(value, list):
            _list(value, None, _double, f"numbers at {address}")
        else:
            _double(value)
    return v


CHECKS = {"cpl.perm": _cpl_perm, "cpl.zs": _cpl_zs, "cpl.tc": _cpl_tc, "cpl.tdb": _cpl_tdb, "sin800": _sin800}
