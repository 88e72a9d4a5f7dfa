"""Ctrl-C at a block boundary: an interrupted run stops between blocks, never inside one.

A block executed in bulk (CPL runs plain rows column-wise) updates the position, the move counters and the
sinks (trace, plot) in passes of its own; a KeyboardInterrupt between those passes would leave a summary
that disagrees with the trace. During a run (:func:`deferring`) SIGINT inside a :func:`block` is held and
raised as the block ends; outside one it is raised at once, as Python does. Marking a bulk of blocks costs
two integer updates per bulk, nothing per step.
"""

from __future__ import annotations

import signal
import threading
from contextlib import contextmanager

_depth = 0  # blocks being executed now (nested: a bulk within a drain)
_pending = False  # a SIGINT came while a block executed


def _on_sigint(signum, frame):
    global _pending
    if _depth:
        _pending = True
    else:
        raise KeyboardInterrupt


@contextmanager
def deferring():
    """Hold Ctrl-C inside blocks while the run goes (the main thread only: signals arrive there)."""
    global _pending
    if threading.current_thread() is not threading.main_thread() or \
            signal.getsignal(signal.SIGINT) is not signal.default_int_handler:
        yield
        return
    _pending = False
    signal.signal(signal.SIGINT, _on_sigint)
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, signal.default_int_handler)


@contextmanager
def block():
    """Execute a block (or a bulk of them) whole: a Ctrl-C that comes meanwhile is raised after it."""
    global _depth, _pending
    _depth += 1
    try:
        yield
    finally:
        _depth -= 1
    if not _depth and _pending:
        _pending = False
        raise KeyboardInterrupt


#: who sends each terminating signal, as its message says
_SENDERS = {signal.SIGTERM: "sent from outside: kill, timeout, a batch system", signal.SIGHUP: "the terminal closed"}


class Terminated(BaseException):
    """The command was stopped from outside (SIGTERM: a ``kill``, a batch system, ``timeout``; SIGHUP: the
    terminal closed): it ends as after Ctrl-C, its temporary files removed; ``str()`` says so. Its error code
    is RUN009, not Ctrl-C's RUN004: a supervisor stopped it, not the user."""

    code = "RUN009"

    def __init__(self, signum: int, what: str = "run", outcome: str = ""):
        self.signum = signum
        name = signal.Signals(signum).name
        sender = _SENDERS.get(signum)
        super().__init__(f"{what} stopped by {name}" + (f" ({sender})" if sender else "")
                         + (f"; {outcome}" if outcome else ""))


_TERMINATING = (signal.SIGTERM, signal.SIGHUP)


@contextmanager
def ended_by_termination(what: str = "run", outcome: str = ""):
    """SIGTERM and SIGHUP raise :class:`Terminated` meanwhile, so that the command ends as Ctrl-C ends it,
    its temporary files removed (their default action would kill the process and leave them). Once one
    came, more are ignored until the cleanup is done. Only where nobody else took the signals (an
    embedding program's handlers stay), in the main thread."""
    if threading.current_thread() is not threading.main_thread() or \
            any(signal.getsignal(s) is not signal.SIG_DFL for s in _TERMINATING):
        yield
        return

    def stop(signum, frame):
        for s in _TERMINATING:
            signal.signal(s, signal.SIG_IGN)
        raise Terminated(signum, what, outcome)

    for s in _TERMINATING:
        signal.signal(s, stop)
    try:
        yield
    finally:
        for s in _TERMINATING:
            signal.signal(s, signal.SIG_DFL)
