"""The progress display of ``ncvm run`` on a terminal: a long single run and a batch.

A thread of its own reads plain counters about five times a second -- the moves the recorder holds, the
simulated clock, the steps the front end has counted, the programs of a batch done -- so the run itself
does nothing for it: no call, no check in the hot loop. It draws on stderr only when stderr is a
terminal, and gets out of the way while the operator is asked for a key (CPL dialogs at the terminal).
rich is loaded by the thread when it first draws: a run that ends within a second never loads it.
"""

from __future__ import annotations

import os
import sys
import threading

from . import termstyle
from .timefmt import hms

#: how often the display is redrawn (the counters are read then, never written by the display)
INTERVAL_S = 0.2


def start_delay(default: float) -> float:
    """How long a run goes on before the display shows: ``NCVM_PROGRESS_DELAY`` (seconds, 0: at once) when
    set to a number, else the caller's default (a short run never draws)."""
    try:
        return max(0.0, float(os.environ["NCVM_PROGRESS_DELAY"]))
    except (KeyError, ValueError):
        return default


class Progress:
    """``with Progress(enabled, total=N) as p:``; a single run sets ``p.session``, a batch calls :meth:`done`."""

    def __init__(self, enabled: bool, total: int | None = None, delay: float = 1.0):
        self.enabled = enabled
        self.total = total  # programs of a batch; None: a single run
        self.delay = start_delay(delay)
        self.session = None
        self.programs = self.failed = self.moves = 0
        self.cycle_s = 0.0
        self._stop = threading.Event()
        self._lock = threading.Lock()  # the display is drawn, paused and ended under it
        self._paused = False
        self._shown = None  # the rich Progress on the screen
        self._thread = None

    def __enter__(self) -> "Progress":
        if self.enabled:
            self._thread = threading.Thread(target=self._loop, name="ncvm-progress", daemon=True)
            self._thread.start()
        return self

    def __exit__(self, *exc) -> None:
        self._stop.set()
        if self._thread:
            self._thread.join()

    # -- what the run tells it ----------------------------------------------------------------
    def done(self, record: dict) -> None:
        """A program of the batch is done: count it (plain additions; the thread draws)."""
        m = record.get("motion") or {}
        self.moves += m.get("rapid_moves", 0) + m.get("feed_moves", 0) + m.get("arc_moves", 0)
        self.cycle_s += record.get("cycle_time_s") or 0.0
        self.failed += record.get("status") in ("error", "limit_violation")
        self.programs += 1

    def operator_waits(self, waiting: bool) -> None:
        """The run waits for the operator at the terminal (True) or goes on (False): the display leaves
        the screen to the prompt and comes back after it."""
        with self._lock:
            self._paused = waiting
            if waiting:
                self._hide()

    # -- drawing ----------------------------------------------------------------------------------
    def _loop(self) -> None:
        if self._stop.wait(self.delay):
            return
        while True:
            with self._lock:
                if self._stop.is_set():
                    break
                if not self._paused:
                    self._draw()
            if self._stop.wait(INTERVAL_S):
                break
        with self._lock:
            self._hide()

    def _draw(self) -> None:
        if self._shown is None:
            self._shown, self._task = self._start()
        fields = self._fields()
        self._shown.update(self._task, completed=self.programs, **fields)
        self._shown.refresh()

    def _start(self):
        from rich.console import Console
        from rich.progress import BarColumn, MofNCompleteColumn, Progress, SpinnerColumn, TextColumn

        # NO_COLOR (https://no-color.org): no ANSI styling at all, bold included (rich keeps it with no_color)
        console = Console(stderr=True, color_system="auto" if termstyle.enabled() else None)
        columns = [SpinnerColumn(), TextColumn("[bold]{task.description}")]
        if self.total is not None:
            columns += [BarColumn(), MofNCompleteColumn(), TextColumn("programs{task.fields[failed]}")]
        columns.append(TextColumn("{task.fields[moves]} {task.fields[cycle]}"))
        # operator output on the same terminal is printed above the display, never into its line; stdout
        # that goes elsewhere (a file, a pipe) is left alone
        shown = Progress(*columns, console=console, transient=True, auto_refresh=False,
                         redirect_stdout=_is_terminal(sys.stdout), redirect_stderr=False)
        shown.start()
        task = shown.add_task("batch" if self.total is not None else "running", total=self.total, **self._fields())
        return shown, task

    def _fields(self) -> dict:
        if self.total is not None:
            moves, cycle = self.moves, self.cycle_s
            failed = f", [red]{self.failed} failed[/]" if self.failed else ""
            steps = ""
        else:
            s = self.session
            moves = len(s.recorder) if s is not None and s.recorder is not None else 0
            cycle = s.machine.clock.settled if s is not None else 0.0
            # front ends that count steps in batches (CPL, DIN) report them at calls and at the end
            steps = f"{s.steps.steps:,} steps, " if s is not None and s.steps.steps else ""
            failed = ""
        return {"moves": f"{steps}{moves:,} move{'' if moves == 1 else 's'},",
                "cycle": f"{hms(round(cycle))[:-4]} simulated", "failed": failed}

    def _hide(self) -> None:
        if self._shown is not None:
            self._shown.stop()
            self._shown = None


def _is_terminal(stream) -> bool:
    try:
        return stream is not None and stream.isatty()
    except (ValueError, OSError):
        return False
