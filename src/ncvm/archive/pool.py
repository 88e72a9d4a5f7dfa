"""Run a batch's tasks in this process or in a pool of local processes (``--jobs N``)."""

from __future__ import annotations

import multiprocessing
import os
from concurrent.futures import ProcessPoolExecutor
from typing import Callable, Iterable

from ..dialects import get_dialect
from .runner import run_task
from .tasks import Task


def default_jobs() -> int:
    """The cores this process may use."""
    try:
        return len(os.sched_getaffinity(0)) or 1
    except (AttributeError, OSError):
        return os.cpu_count() or 1


def run_local(tasks: list[Task], jobs: int, on_record: Callable[[dict], None] | None = None) -> list[dict]:
    """The records of ``tasks`` in their order; ``jobs`` processes at most (1: this process alone).
    ``on_record`` is told of each record as it comes in."""
    for dialect in {t.dialect for t in tasks}:
        get_dialect(dialect)  # loaded once here: the pool's processes inherit it instead of loading it each
    jobs = max(1, min(jobs, len(tasks)))
    if jobs == 1:
        return _told((run_task(t) for t in tasks), on_record)
    # fork: a process starts with the loaded dialects at once (no interpreter start-up per process)
    context = multiprocessing.get_context("fork")
    chunk = max(1, min(8, len(tasks) // (jobs * 4)))
    pool = ProcessPoolExecutor(max_workers=jobs, mp_context=context)
    try:
        return _told(pool.map(run_task, tasks, chunksize=chunk), on_record)
    except BaseException:  # Ctrl-C: the programs not started are not started
        pool.shutdown(wait=False, cancel_futures=True)
        raise
    finally:
        pool.shutdown()


def _told(records: Iterable[dict], on_record: Callable[[dict], None] | None) -> list[dict]:
    """The records as a list, each told to ``on_record`` as it comes in."""
    out = []
    for record in records:
        out.append(record)
        if on_record is not None:
            on_record(record)
    return out
