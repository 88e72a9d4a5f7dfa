"""The memory guard: a run may grow the process by at most a set amount, then it stops with RUN006.

The limit is the address-space limit (``RLIMIT_AS``) of the process, set to
what the process uses when the run starts plus the allowance, and restored
when the run ends: an allocation beyond it raises MemoryError at once (one
huge field as much as a million small objects), which the run reports as
RUN006 instead of driving the machine into swap. Where the operating system
has no such limit (not Linux), runs are not guarded. The limit is the whole
process's: API users who run programs in parallel threads pass
``RunOptions(max_memory=0)`` and set one limit themselves.
"""

from __future__ import annotations

import os
import re
from contextlib import contextmanager

from ..diagnostics import Diagnostic, UsageError

try:
    import resource
except ImportError:  # pragma: no cover - Windows
    resource = None

GIB = 1 << 30
#: the default allowance: 8 GiB, or half the machine's memory when that is less
DEFAULT_MAX_MEMORY = 8 * GIB

_UNITS = {"": 1, "K": 1 << 10, "M": 1 << 20, "G": GIB, "T": 1 << 40}


def default_max_memory() -> int:
    try:
        physical = os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES")
    except (ValueError, OSError, AttributeError):
        return DEFAULT_MAX_MEMORY
    return min(DEFAULT_MAX_MEMORY, physical // 2)


def parse_size(text: str) -> int:
    """``8G``, ``512M``, ``2048K`` or bytes; 0 turns the guard off."""
    m = re.fullmatch(r"\s*(\d+(?:\.\d+)?)\s*([KMGT]?)(?:I?B)?\s*", str(text).upper())
    if not m:
        raise UsageError(f"--max-memory {text!r}: a size such as 8G, 512M or 0 (no limit)")
    return int(float(m.group(1)) * _UNITS[m.group(2)])


def describe(size: int) -> str:
    return f"{size / GIB:.1f} GiB" if size >= GIB else f"{size / (1 << 20):.0f} MiB"


def _address_space() -> int:
    """Bytes of address space the process has mapped now."""
    with open("/proc/self/statm") as f:
        return int(f.read().split()[0]) * os.sysconf("SC_PAGE_SIZE")


#: the limits a run's guard replaced, while one is set (outside_limit puts them back for a moment)
_outer: tuple[int, int] | None = None


@contextmanager
def memory_limit(allowance: int):
    """Let the code inside grow the process by at most ``allowance`` bytes (0: no limit)."""
    global _outer
    if not allowance or resource is None or not os.path.exists("/proc/self/statm"):
        yield
        return
    soft, hard = resource.getrlimit(resource.RLIMIT_AS)
    limit = _address_space() + allowance
    for bound in (soft, hard):
        if bound != resource.RLIM_INFINITY:
            limit = min(limit, bound)
    resource.setrlimit(resource.RLIMIT_AS, (limit, hard))
    _outer = (soft, hard)
    try:
        yield
    finally:
        _outer = None
        resource.setrlimit(resource.RLIMIT_AS, (soft, hard))


@contextmanager
def outside_limit():
    """Code that is not the program's: a library a run imports at its first use (ncvm.lazy) maps its shared
    objects and starts its threads without the run's limit, and the limit moves up by what that took, so
    the program keeps its whole allowance."""
    if _outer is None:
        yield
        return
    limit, hard = resource.getrlimit(resource.RLIMIT_AS)
    before = _address_space()
    resource.setrlimit(resource.RLIMIT_AS, _outer)
    try:
        yield
    finally:
        grown = max(0, _address_space() - before)
        if limit != resource.RLIM_INFINITY:
            limit += grown
            if _outer[0] != resource.RLIM_INFINITY:
                limit = min(limit, _outer[0])
        resource.setrlimit(resource.RLIMIT_AS, (limit, hard))


def out_of_memory(allowance: int) -> Diagnostic:
    """The error of a run that reached the limit (or found no memory at all)."""
    if allowance:
        text = (f"memory limit reached: the run needs more than {describe(allowance)} "
                f"(raise it with --max-memory)")
    else:
        text = "out of memory: the machine has no more memory for the run"
    return Diagnostic("RUN006", text, None)
