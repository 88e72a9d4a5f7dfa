"""A batch run of programs and folders: find the programs, run them here, in a local pool or on a dask
cluster, and gather their report (docs/batch.md)."""

from __future__ import annotations

import time
import uuid
from contextlib import contextmanager
from pathlib import Path
from typing import Callable

from ..diagnostics import UsageError
from .discover import Found, discover
from .pool import default_jobs, run_local
from .report import document
from .runner import SETUP_ERROR
from .tasks import Settings, TaskBuilder, read_seed

#: the name (a random suffix follows) of the file a batch writes into a shared state directory
SHARE_TOKEN = "batch-token-"


def run_batch(paths, dialect: str | None = None, machine: str | Path | None = None, jobs: int | None = None,
              cluster: str | None = None, state: str | Path | None = None, shared_state: bool = False,
              max_steps: int = 100_000_000, max_memory: int | None = None, found: Found | None = None,
              on_record: Callable[[dict], None] | None = None, details: bool = False) -> dict:
    """Run every main program of ``paths`` (files and folders); the report document (:mod:`.report`).

    Each program starts from the permanent state of ``state`` (a copy; none: empty) and its writes are
    reported, unless ``shared_state``: then the runs use ``state`` itself one at a time and their writes stay.
    ``on_record`` is told of each program's record as it comes in (a progress display); ``details``: each
    record also holds the run's variables (the Python API's results, ``ncvm.batch``).
    """
    started = time.perf_counter()
    found = found or discover(paths, dialect, machine)
    if shared_state and state is None:
        raise UsageError("--shared-state needs --state DIR")
    seed_from = None if shared_state or state is None or not Path(state).is_dir() else str(state)
    settings = Settings(max_steps=max_steps, max_memory=max_memory,
                        shared_state=str(Path(state).absolute()) if shared_state else None,
                        seed=read_seed(seed_from) if seed_from else {}, seed_from=seed_from, details=details)
    with _share_token(settings):
        return _run(found, settings, jobs, cluster, started, on_record)


def _run(found: Found, settings: Settings, jobs: int | None, cluster: str | None, started: float,
         on_record: Callable[[dict], None] | None) -> dict:
    builder = TaskBuilder(settings)
    tasks, records = [], {}
    for i, program in enumerate(found.programs):
        task = builder.task(i, program)
        if isinstance(task, UsageError):
            records[i] = _setup_failed(program, str(task))
        else:
            tasks.append(task)
    how: dict = {"state": _state_words(settings)}
    if cluster:
        done, how["cluster"] = _on_cluster(tasks, cluster, on_record)
        how["jobs"] = None
    else:
        how["jobs"] = jobs or default_jobs()
        done = run_local(tasks, how["jobs"], on_record)
    records.update((t.index, r) for t, r in zip(tasks, done))
    doc = document([records[i] for i in range(len(found.programs))], found.skipped, how)
    doc["summary"]["wall_time_s"] = round(time.perf_counter() - started, 3)
    return doc


@contextmanager
def _share_token(settings: Settings):
    """With a shared state directory: a file of the batch's own in it while the batch runs, which each run
    looks for before it runs (a worker that does not see it does not share the directory)."""
    if not settings.shared_state:
        yield
        return
    state = Path(settings.shared_state)
    settings.share_token = f"{SHARE_TOKEN}{uuid.uuid4().hex}"
    try:
        state.mkdir(parents=True, exist_ok=True)
        (state / settings.share_token).write_text("ncvm batch\n")
    except OSError as e:
        raise UsageError(f"--state {state}: cannot write the shared state directory ({e.strerror})") from None
    try:
        yield
    finally:
        (state / settings.share_token).unlink(missing_ok=True)


def _on_cluster(tasks, address, on_record):
    from .cluster import run_on_cluster  # dask is an optional extra, loaded only for --cluster

    return run_on_cluster(tasks, address, on_record=on_record)


def _state_words(settings: Settings) -> str:
    if settings.shared_state:
        return f"shared: every program in turn on {settings.shared_state}, writes kept"
    start = f"a copy of {settings.seed_from}" if settings.seed_from else "an empty memory"
    return f"temporary: each program on its own from {start}, writes reported, not kept"


def _setup_failed(program, message: str) -> dict:
    error = {"code": SETUP_ERROR, "message": message, "file": None, "line": None, "column": None}
    return {"path": str(program.path), "dialect": program.dialect,
            "machine": str(program.machine) if program.machine else "built-in", "status": "error", "error": error,
            "cycle_time_s": 0.0, "steps": 0, "motion": None, "limit_violations": [], "output_lines": [],
            "position": {}, "permanent_writes": {"store": [], "files": []}, "state": None, "worker": None,
            "wall_time_s": 0.0}
