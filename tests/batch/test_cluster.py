"""Batches on dask.distributed: a LocalCluster in this test, and a scheduler and a worker started as
processes of their own on 127.0.0.1; the results are those of the run in this process."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from ncvm.archive import run_batch
from ncvm.archive.cluster import run_on_cluster
from ncvm.diagnostics import UsageError

from .conftest import in_folder, stable

distributed = pytest.importorskip("distributed")  # the extra ncvm[cluster], installed by make test

BIN = Path(sys.executable).parent


@pytest.fixture(scope="module")
def cluster():
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1",
                                  scheduler_port=0, dashboard_address=None) as c:
        yield c


def test_a_local_cluster_gives_the_results_of_a_run_in_this_process(archive, in_process, cluster):
    on_cluster = in_folder(archive.root, run_batch, ["."], cluster=cluster.scheduler_address)
    assert stable(on_cluster["programs"]) == stable(in_process["programs"])
    assert on_cluster["skipped"] == in_process["skipped"]
    s = on_cluster["summary"]
    assert s["cluster"] == {"address": cluster.scheduler_address, "workers": 2} and s["jobs"] is None
    assert len({r["worker"] for r in on_cluster["programs"]}) == 2
    # each program on its own temporary state directory, its permanent writes reported
    assert {r["state"] for r in on_cluster["programs"]} == {"temporary"}
    partcount = next(r for r in on_cluster["programs"] if r["path"] == "examples/cpl/partcount.cpl")
    assert {w["key"] for w in partcount["permanent_writes"]["store"]} == {"@1", "@_R(1)", "@BATCHSIZE"}


def test_the_starting_state_travels_with_the_tasks(tmp_path, cluster):
    """The state directory of the command line is read once here; the workers start from a copy of it."""
    (tmp_path / "p.din").write_text("G10 L2 P1 X5\nG54 G0 X0\nM30\n")
    state = tmp_path / "state"
    run_batch([str(tmp_path / "p.din")], state=state, shared_state=True, jobs=1)  # a zero offset kept in state
    local = run_batch([str(tmp_path / "p.din")], state=state, jobs=1)
    remote = run_batch([str(tmp_path / "p.din")], state=state, cluster=cluster.scheduler_address)
    assert stable(remote["programs"]) == stable(local["programs"])
    assert remote["summary"]["state"] == local["summary"]["state"]
    assert "a copy of" in remote["summary"]["state"]


def test_workers_of_another_ncvm_version_are_refused(cluster, monkeypatch):
    from ncvm.archive import cluster as module

    monkeypatch.setattr(module, "__version__", "0.0.0")  # this side is another version than the workers
    with pytest.raises(UsageError, match=r"the workers run ncvm \d+\.\d+\.\d+, this is ncvm 0\.0\.0"):
        run_on_cluster([], cluster.scheduler_address)


def test_an_unreachable_scheduler_is_a_usage_error(free_port):
    with pytest.raises(UsageError, match="cannot reach the dask scheduler"):
        run_on_cluster([], f"tcp://127.0.0.1:{free_port}", timeout=2)


@pytest.fixture
def scheduler_and_worker(dask_processes):
    """``dask scheduler`` and ``dask worker`` as processes of their own, on 127.0.0.1 only; stopped after."""
    return dask_processes(nworkers=1)


def test_ncvm_run_on_a_scheduler_and_a_worker_of_their_own(archive, in_process, scheduler_and_worker, tmp_path):
    r = subprocess.run([BIN / "ncvm", "run", "injected", "plant", "--cluster", scheduler_and_worker,
                        "--report", str(tmp_path / "r.json")], cwd=archive.root, capture_output=True, text=True,
                       timeout=300)
    assert r.returncode == 1, r.stderr  # the injected errors
    doc = json.loads((tmp_path / "r.json").read_text())
    local = {p["path"]: p for p in in_process["programs"]}
    assert len(doc["programs"]) == 27
    assert stable(doc["programs"]) == stable([local[p["path"]] for p in doc["programs"]])
    assert doc["summary"]["cluster"] == {"address": scheduler_and_worker, "workers": 1}
    assert "injected/sin800/flange_bad0.mpf:2:4: error SIN002" in r.stderr
