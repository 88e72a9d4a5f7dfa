"""Run one task of a batch in this process: lay out its files, run it as ``ncvm run`` would, report it.

The same function runs a task in the batch's own process, in a local pool and on a dask worker, so the
results are the same everywhere. Each run gets a temporary copy of everything it reads: the archive is
never written. Its permanent writes (the store, the controller's files) are compared with what it started
from and reported; with a shared state directory the runs take it one at a time and their writes stay.
"""

from __future__ import annotations

import fcntl
import hashlib
import json
import os
import socket
import sqlite3
import tempfile
import threading
import time
from contextlib import contextmanager
from pathlib import Path

from .. import api
from ..diagnostics import NcvmError
from ..machine.state import STORE_NAME
from ..runtime.session import RunOptions
from .discover import own_folder_first
from .tasks import Task

#: a run owns its process's memory limit and the interpreter's signal handling: one run at a time per
#: process even where a dask worker runs several tasks in threads
_ONE_RUN = threading.Lock()
#: taken (blocking) on a shared state directory by the batch's runs; ``ncvm run`` itself is refused at once
SHARED_LOCK = "batch.lock"
#: the project's code of a program that could not be set up (docs/batch.md)
SETUP_ERROR = "RUN007"
#: what a record of the Python API's batch holds beyond the report's (ncvm.batch)
DETAILS = ("variables", "output_dropped", "cycle_time_model")


def run_task(task: Task) -> dict:
    """The report record of ``task``'s program (see :mod:`ncvm.archive.report`)."""
    with _ONE_RUN, tempfile.TemporaryDirectory(prefix="ncvm-batch-") as tmp:
        started = time.perf_counter()
        tree = Path(tmp) / "tree"
        for name, data in task.files.items():
            target = tree / name.lstrip("/")
            target.parent.mkdir(parents=True, exist_ok=True)
            target.write_bytes(data)
        inside = lambda p: tree / p.lstrip("/") if p else None  # noqa: E731
        if task.settings.shared_state:
            state = Path(task.settings.shared_state)
            with _shared(state):
                doc, writes = (_run_and_compare(task, inside, state) if shares(state, task.settings.share_token)
                               else _not_shared(task, state))
        else:
            state = Path(tmp) / "state"
            for name, data in task.settings.seed.items():
                (state / name).parent.mkdir(parents=True, exist_ok=True)
                (state / name).write_bytes(data)
            doc, writes = _run_and_compare(task, inside, state)
        prefix = str(tree)
        record = _record(task, _unmap(doc, f"{prefix}{task.base}/", prefix), writes)
        record["state"] = task.settings.shared_state or "temporary"
        record["worker"] = f"{socket.gethostname()}:{os.getpid()}"
        record["wall_time_s"] = round(time.perf_counter() - started, 6)
        return record


@contextmanager
def _shared(state: Path):
    state.mkdir(parents=True, exist_ok=True)
    fd = os.open(state / SHARED_LOCK, os.O_RDWR | os.O_CREAT | os.O_CLOEXEC, 0o666)
    try:
        fcntl.flock(fd, fcntl.LOCK_EX)
        yield
    finally:
        os.close(fd)


def shares(state: Path, token: str | None) -> bool:
    """This host sees the batch's shared state directory: the token file the batch wrote there is there."""
    return token is None or (state / token).is_file()


def _not_shared(task: Task, state: Path) -> tuple[dict, dict]:
    message = (f"--shared-state: {state} on {socket.gethostname()} is not the batch's state directory (the file "
               f"{task.settings.share_token} the batch wrote there is missing); the program is not run, as its "
               f"writes would be lost: give a directory every worker shares")
    return _setup_error(task, message), {"store": [], "files": []}


def _setup_error(task: Task, message: str) -> dict:
    error = {"code": SETUP_ERROR, "message": message, "file": None, "line": None, "column": None}
    return {"status": "error", "dialect": task.dialect, "error": error, "output": [], "position": {},
            "variables": {}, "output_dropped": 0, "cycle_time_model": "",
            "motion": None, "cycle_time_s": 0.0, "steps": 0, "limit_violations": []}


def _run_and_compare(task: Task, inside, state: Path) -> tuple[dict, dict]:
    """The run's document and what it wrote: the store and files as the run found them and as it left them,
    both seen while it holds the state directory (a run refused because another holds it wrote nothing, and
    another run's writes before or after it are not its own)."""
    file_root = inside(task.file_root)
    watched = {"state": state, "file root": file_root}
    seen: dict[str, dict] = {}

    def held(session) -> None:  # the session exists inside the run's hold, before the program runs
        seen["before"] = _snapshot(state, watched)
        session.when_closed(lambda: seen.setdefault("after", _snapshot(state, watched)))

    doc = _run(task, inside, state, held)
    if "after" not in seen:  # the run never began (refused, or its setup failed)
        seen["before"] = seen["after"] = {"store": {}, "files": {}}
    writes = _writes(seen["before"], seen["after"])
    for entry in writes["files"]:  # the files as the program's machine names them, not the copies
        folder, rel = entry.pop("where"), entry["path"]
        entry["path"] = str(Path(task.file_root) / rel) if folder == "file root" else f"<state>/files/{rel}"
    return doc, writes


def _run(task: Task, inside, state: Path, on_session=None) -> dict:
    program = inside(str(Path(task.base) / task.path))
    options = RunOptions(state_dir=state, max_steps=task.settings.max_steps, keys=inside(task.keys),
                         scenario=inside(task.scenario), on_session=on_session)
    if task.settings.max_memory is not None:
        options.max_memory = task.settings.max_memory
    try:
        machine = api.machine_for(program, inside(str(Path(task.base) / task.machine)) if task.machine else None, state)
        if task.own_folder_first:  # a machine file of a folder above: the program's own folder is searched first
            own_folder_first(machine, program)
        return api.run_program(program, task.dialect, machine, options).to_json()
    except NcvmError as e:  # the machine file, the state directory ...: as ncvm run says it, for this program
        return _setup_error(task, getattr(e, "message", None) or str(e))


def _snapshot(state: Path, watched: dict[str, Path | None]) -> dict:
    store = {}
    path = state / STORE_NAME
    if path.is_file():
        db = sqlite3.connect(f"file:{path}?mode=ro", uri=True)
        try:
            store = {(ns, key): value for ns, key, value in
                     db.execute("SELECT namespace, key, value FROM permanent")}
        except sqlite3.Error:
            store = {}
        finally:
            db.close()
    files = {}
    for where, folder in (("state", state / "files"), ("file root", watched["file root"])):
        if folder is not None and folder.is_dir():
            for p in folder.rglob("*"):
                if p.is_file():
                    files[(where, str(p.relative_to(folder)))] = hashlib.sha256(p.read_bytes()).hexdigest()
    return {"store": store, "files": files}


def _writes(before: dict, after: dict) -> dict:
    """What the run changed in its permanent memory: store entries set or removed, files written."""
    store = [{"namespace": ns, "key": key, "value": json.loads(value)}
             for (ns, key), value in sorted(after["store"].items()) if before["store"].get((ns, key)) != value]
    store += [{"namespace": ns, "key": key, "value": None, "deleted": True}
              for (ns, key) in sorted(before["store"]) if (ns, key) not in after["store"]]
    files = []
    for key in sorted(set(before["files"]) | set(after["files"])):
        old, new = before["files"].get(key), after["files"].get(key)
        if old != new:
            change = "created" if old is None else "deleted" if new is None else "changed"
            files.append({"where": key[0], "path": key[1], "change": change})
    return {"store": store, "files": files}


def _unmap(value, *prefixes: str):
    """``value`` with the temporary copy's paths back as the archive's, the batch's own relative to its base."""
    if isinstance(value, str):
        for prefix in prefixes:
            value = value.replace(prefix, "")
        return value
    if isinstance(value, list):
        return [_unmap(v, *prefixes) for v in value]
    if isinstance(value, dict):
        return {k: _unmap(v, *prefixes) for k, v in value.items()}
    return value


def _record(task: Task, doc: dict, writes: dict) -> dict:
    if doc["error"]:
        status = "error"
    elif doc["limit_violations"]:
        status = "limit_violation"
    else:
        status = "ok"
    return {"path": task.path, "dialect": doc["dialect"], "machine": task.machine or "built-in", "status": status,
            "error": doc["error"], "cycle_time_s": doc["cycle_time_s"], "steps": doc["steps"],
            "motion": doc["motion"], "limit_violations": doc["limit_violations"], "output_lines": doc["output"],
            "position": doc["position"], "permanent_writes": writes,
            **({k: doc.get(k) for k in DETAILS} if task.settings.details else {})}
