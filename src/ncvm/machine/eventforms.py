"""The rules across the keys of a ``[[scenario]]`` table that spec.py checks when a file is read.

Apart from the event types (scenario.py), so that reading a machine file without events does not build
them (start-up, issue 18).
"""

from __future__ import annotations

from .schema import MISSING, SchemaError, join

INPUT_FORMS = "address (CPL), byte and bit (SINUMERIK) or axis and bit (rw_SymPas)"


def _input_form(entry: dict, path: str, ctx=None) -> None:
    """An input event names its input one way: address, byte/bit or axis/bit, with the bit in that form's
    range; without address or axis it is SINUMERIK's byte/bit form."""
    with_address = "address" in entry and any(k in entry for k in ("byte", "bit", "axis"))
    if with_address or "axis" in entry and "byte" in entry:
        raise SchemaError(path, entry, f"names its input more than one way: give {INPUT_FORMS}")
    if "address" in entry:
        return
    if "axis" in entry and "bit" not in entry:
        raise SchemaError(join(path, "bit"), MISSING, "is missing: an axis input names its digital input 1-32")
    bit = entry.get("bit", 0)  # SINUMERIK: bit 0 of the byte when left out
    lo, hi = (1, 32) if "axis" in entry else (0, 7)
    if not lo <= bit <= hi:
        what = "an axis' digital input (rw_SymPas)" if "axis" in entry else "a bit of an input byte (SINUMERIK)"
        raise SchemaError(join(path, "bit"), bit, f"must be {lo} to {hi} for {what}")


def _probe_form(entry: dict, path: str, ctx=None) -> None:
    """The switch position is given once: as axis keys (CPL) or as a ``position`` table (SINUMERIK)."""
    axes = [k for k in entry if k not in ("time", "kind", "input", "position")]
    if axes and "position" in entry:
        raise SchemaError(join(path, axes[0]), entry[axes[0]],
                          "the position is given twice: axis keys here and a position table")


#: per kind, the rules across its keys that spec.py checks when the file is read
CHECKS = {"input": ("one addressing: " + INPUT_FORMS, _input_form),
          "probe": ("the position as axis keys or as a position table, not both", _probe_form)}
