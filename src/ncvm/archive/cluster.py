"""Run a batch's tasks on a dask.distributed cluster (``--cluster tcp://HOST:PORT``, the extra ``ncvm[cluster]``).

Each task carries its program's text, the files it may call, its machine file and the batch's options, so
a worker needs nothing but ncvm (the same version) installed. The workers run :func:`run_task`, as the local
pool does: the results are the same.
"""

from __future__ import annotations

from typing import Callable

from .. import __version__
from ..diagnostics import UsageError
from .runner import run_task
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
        futures = client.map(run_task, tasks, pure=False, key=[f"ncvm-{t.index}-{id(t):x}" for t in tasks])
        if on_record is None:
            records = client.gather(futures)
        else:  # each as it comes in, in order, as the local pool tells them
            records = []
            for future in futures:
                records.append(future.result())
                on_record(records[-1])
    return records, {"address": address, "workers": workers}


def _ncvm_version() -> str:
    from ncvm import __version__ as version

    return version
