"""Run a batch's tasks on a dask.distributed cluster (``--cluster tcp://HOST:PORT``, the extra ``ncvm[cluster]``).

Each task carries its program's text, the files it may call, its machine file and the batch's options, so
a worker needs nothing but ncvm (the same version) installed. The workers run :func:`run_task`, as the local
pool does: the results are the same.
"""

from __future__ import annotations

import logging
from pathlib import Path
from typing import Callable

from .. import __version__
from ..diagnostics import UsageError
from .runner import run_task, shares
from .tasks import Task

#: how long to wait for the scheduler to answer before the batch is refused
CONNECT_TIMEOUT_S = 20


def run_on_cluster(tasks: list[Task], address: str, timeout: float = CONNECT_TIMEOUT_S,
                   on_record: Callable[[dict], None] | None = None) -> tuple[list[dict], dict]:
    """The records of ``tasks`` in their order, and what the report says of the cluster; ``on_record`` is
    told of each record as its worker finishes it."""
    try:
        from distributed import Client
    except ImportError:
        raise UsageError("--cluster needs dask.distributed: pip install 'ncvm[cluster]'") from None
    try:
        client = Client(address, timeout=timeout, set_as_default=False)
    except (OSError, TimeoutError) as e:
        raise UsageError(f"--cluster {address}: cannot reach the dask scheduler ({e})") from None
    with client:
        try:
            versions = set(client.run(_ncvm_version).values())
        except Exception as e:  # noqa: BLE001 - whatever a worker without ncvm raises, it says so
            raise UsageError(f"--cluster {address}: the workers cannot run ncvm ({type(e).__name__}: {e}); "
                             f"install ncvm {__version__} on every worker") from None
        if versions - {__version__}:
            raise UsageError(f"--cluster {address}: the workers run ncvm {', '.join(sorted(versions))}, "
                             f"this is ncvm {__version__}; install the same version on every worker")
        workers = len(client.scheduler_info().get("workers", {}))
        if not workers:
            raise UsageError(f"--cluster {address}: the scheduler has no workers")
        _check_shared(client, address, tasks)
        futures = client.map(run_task, tasks, pure=False, key=[f"ncvm-{t.index}-{id(t):x}" for t in tasks])
        try:
            if on_record is None:
                records = client.gather(futures)
            else:  # each as it comes in, in order, as the local pool tells them
                records = []
                for future in futures:
                    records.append(future.result())
                    on_record(records[-1])
        except KeyboardInterrupt:  # Ctrl-C: the tasks are cancelled and the client closes without a word
            _quiet()
            client.cancel(futures)
            raise
    return records, {"address": address, "workers": workers}


def _check_shared(client, address: str, tasks: list[Task]) -> None:
    """Refuse ``--shared-state`` when a worker does not see the batch's state directory (the token file the
    batch wrote there): its programs' writes would stay on the worker's disk, reported kept and lost."""
    settings = tasks[0].settings if tasks else None
    if settings is None or not settings.shared_state:
        return
    sees = client.run(shares, Path(settings.shared_state), settings.share_token)
    blind = sorted(worker for worker, seen in sees.items() if not seen)
    if blind:
        raise UsageError(f"--state {settings.shared_state}: --shared-state needs a directory every worker shares, "
                         f"and {len(blind)} of {len(sees)} worker(s) do not see this one ({', '.join(blind)}); "
                         f"use a shared file system, or leave out --shared-state (each program on its own copy, "
                         f"writes reported)")


def _quiet() -> None:
    """Silence what dask and asyncio log of the tasks and connections an interrupted client leaves behind."""
    for name in ("distributed", "asyncio", "tornado"):
        logging.getLogger(name).disabled = True


def _ncvm_version() -> str:
    from ncvm import __version__ as version

    return version
