"""SERCOS drive parameters of manual §4.9: SCS (one value) and SCSL (a list into an ASCII file).

Each physical axis has a parameter store from [cpl] axes[].sercos ({"S-0-0030" = "...", "P-0-0004" = 7,
lists as arrays}); S-0-0051, the position feedback value, is the axis' actual position in 0.0001 mm
(degrees) units. The service channel is locked while a "sercos" scenario event with locked = true is in
force: then the result variable gets 1 and the value last read stays, or without a result variable it is
the run-time error SERCOS SERVICE CHANNEL IS LOCKED.
"""

from __future__ import annotations

from ..errors import CplError
from ..io.errors import CplRuntimeError, fail
from .axes import nul
from .context import SystemContext
from .positions import f_apos


def _locked(rt: SystemContext) -> bool:
    locked = False
    for ev in rt.machine.scenario:
        if ev.kind == "sercos" and ev.time <= rt.t_prep:  # a SercosLock (no other event has this kind)
            locked = ev.locked
    return locked


def _param(rt: SystemContext, axis, idtype, idno):
    c = rt.ctl
    ax = c.by_name(axis) if isinstance(axis, str) else c.axes.get(nul(axis))
    if ax is None:
        raise CplError("1938", f"physical axis {axis!r} is not configured")
    if idtype not in ("S", "P"):
        raise CplError("CPL023", f"SERCOS ID type {idtype!r}: \"S\" or \"P\"")
    if idno.__class__ is not int or not 0 <= idno <= 4095:
        raise CplError("CPL023", f"SERCOS ID number {idno!r}")
    key = f"{idtype}-0-{idno:04d}"
    if key == "S-0-0051":
        return ax, key, int(round(f_apos(rt, ax.index) * 10000))
    store = c.sercos.get(ax.index, {})
    if key not in store:
        raise CplError("CPL040", f"axis {ax.name} has no SERCOS parameter {key}")
    return ax, key, store[key]


def f_scs(rt: SystemContext, axis, idtype, idno, res=None):
    """SCS -> (value, result code). A list parameter cannot be read with SCS (L2137)."""
    ax, key, value = _param(rt, axis, idtype, idno)
    if isinstance(value, list):
        raise CplError("CPL040", f"{key} is a list parameter: read it with SCSL")
    last = rt.ctl.sercos_last  # what the service channel delivered last
    if _locked(rt):
        if res is None:
            raise CplError("CPL041", f"axis {ax.name} {key}")
        return last.get((ax.index, key), 0), 1
    last[(ax.index, key)] = value
    return value, 0


def f_scsl(rt: SystemContext, axis, idtype, idno, filename, res=None):
    """SCSL -> (0, result code): the list elements as records of an ASCII file (LF each, ETX LF at the end),
    written whole or not at all; a name the file root refuses is INVALID FILE NAME (result 2 with res%)."""
    ax, key, value = _param(rt, axis, idtype, idno)
    if _locked(rt):
        if res is None:
            raise CplError("CPL041", f"axis {ax.name} {key}")
        return 0, 1
    items = value if isinstance(value, list) else [value]
    files = rt.io.files
    try:  # named as OPENW names a file: in the file root, relative to the current directory
        place = files.place_of(nul(filename))
        st = files.stat_of(place)
        if files.open_for_writing(st):
            raise fail("FILE_ALREADY_OPEN", place.shown)
        files.replace_records(place, [str(v) for v in items])
    except CplRuntimeError:
        if res is None:
            raise
        return 0, 2
    except OSError as e:
        if res is None:
            raise CplError("CPL040", f"SCSL cannot write {filename!r} ({e.strerror})") from None
        return 0, 2
    return 0, 0
