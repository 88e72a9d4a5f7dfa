"""Batch cases on a generated archive of all five dialects (tests/batch/generate.py, about 240 programs):
one ``ncvm run`` process per program, as a shell loop would, against one ``ncvm run ARCHIVE`` in one
process (-j 1), in a local pool (default: the cores) and on a dask LocalCluster of one worker per core.
The rate is programs/s: the ratio of two rates is the speed-up."""

from __future__ import annotations

import importlib.util
import shutil
import subprocess
import sys
from pathlib import Path

from benchlib import WORK, Case

from ncvm.archive import default_jobs, run_batch
from ncvm.archive.discover import discover

REPO = Path(__file__).resolve().parents[1]
ARCHIVE = WORK / "archive"
NCVM = [sys.executable, "-m", "ncvm"]
_cluster = {}


def _make_archive() -> Path:
    if not ARCHIVE.exists():
        spec = importlib.util.spec_from_file_location("generate", REPO / "tests" / "batch" / "generate.py")
        module = importlib.util.module_from_spec(spec)
        sys.modules[spec.name] = module  # its dataclasses look their module up
        spec.loader.exec_module(module)
        WORK.mkdir(exist_ok=True)
        module.make_archive(ARCHIVE)
    return ARCHIVE


def _count() -> int:
    return len(discover([str(_make_archive())]).programs)


def one_process_per_program() -> None:
    """``ncvm run PROGRAM`` for every main program, one after the other, each on its machine file."""
    state = WORK / "batch-states"
    for i, p in enumerate(discover([str(_make_archive())]).programs):
        args = [*NCVM, "run", str(p.path), "--json", "--state", str(state / str(i))]
        if p.machine:
            args += ["--machine", str(p.machine)]
        for option, suffix in (("--keys", ".keys"), ("--scenario", ".scenario.toml")):
            side = p.path.with_name(p.path.stem + suffix)
            if side.is_file():
                args += [option, str(side)]
        subprocess.run(args, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, stdin=subprocess.DEVNULL)
    shutil.rmtree(state, ignore_errors=True)


def batch(jobs: int):
    def run() -> None:
        subprocess.run([*NCVM, "run", str(_make_archive()), "--jobs", str(jobs), "--state", str(WORK / "batch-state")],
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, stdin=subprocess.DEVNULL)
    return run


def _start_cluster() -> None:
    from distributed import LocalCluster

    _make_archive()
    if "cluster" not in _cluster:
        _cluster["cluster"] = LocalCluster(n_workers=default_jobs(), threads_per_worker=1, host="127.0.0.1",
                                           scheduler_port=0, dashboard_address=None)


def on_cluster() -> None:
    run_batch([str(_make_archive())], cluster=_cluster["cluster"].scheduler_address)


def _has_distributed() -> bool:
    return importlib.util.find_spec("distributed") is not None


def cases() -> dict[str, Case]:
    n = _count()
    cores = default_jobs()
    return {
        "batch_one_process_each": Case(one_process_per_program, n, "programs/s", repeat=1),
        "batch_one_process_j1": Case(batch(1), n, "programs/s", repeat=3),
        f"batch_pool_j{cores}": Case(batch(cores), n, "programs/s", repeat=3),
        f"batch_dask_local_{cores}w": Case(on_cluster, n, "programs/s", setup=_start_cluster, repeat=3,
                                          available=_has_distributed, why_unavailable="pip install 'ncvm[cluster]'"),
    }

