"""ncvm.batch (docs/api.md): the results of ``ncvm run FOLDER --jobs N`` as RunResult objects, in this
process, in a local pool and on a dask LocalCluster."""

from __future__ import annotations

import csv
import json
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET
from contextlib import chdir
from pathlib import Path

import pytest

import ncvm
from ncvm.diagnostics import UsageError

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def archive(tmp_path_factory):
    """examples/ with programs that fail: an error in a sub-program, a soft limit, a CPL syntax error."""
    root = tmp_path_factory.mktemp("archive")
    shutil.copytree(ROOT / "examples", root / "examples")
    bad = root / "bad"
    bad.mkdir()
    (bad / "SUB.cpl").write_text("10 A=1\n20 B=A/0\nM17\n")
    (bad / "divide.cpl").write_text("10 CALL SUB\nM30\n")
    (bad / "travel.din").write_text("G0 X9000\nM30\n")
    (bad / "syntax.cpl").write_text("10 A=\nM30\n")
    (bad / "notes.txt").write_text("not a program\n")
    (bad / "README").write_text("no program here\n")
    return root


@pytest.fixture(scope="module")
def cli_report(archive):
    """``ncvm run examples bad --jobs 2 --json`` in its own process."""
    out = subprocess.run([sys.executable, "-m", "ncvm", "run", "examples", "bad", "--jobs", "2", "--json",
                          "--state", str(archive / "cli-state")], capture_output=True, text=True, cwd=archive,
                         timeout=600)
    assert out.returncode == 1, out.stderr  # programs failed
    return json.loads(out.stdout)


@pytest.fixture(scope="module")
def in_process(archive):
    with chdir(archive):
        return ncvm.batch(["examples", "bad"], jobs=1, state=archive / "api-state")


def as_record(r: ncvm.RunResult) -> dict:
    """The fields a batch report holds, from a RunResult."""
    status = "error" if r.error else "limit_violation" if r.limit_violations else "ok"
    return {"path": r.path, "dialect": r.dialect, "machine": r.machine, "status": status,
            "error": r.to_json()["error"], "cycle_time_s": r.cycle_time_s, "steps": r.steps,
            "motion": r.motion.to_json(), "limit_violations": r.limit_violations, "output_lines": r.output,
            "position": r.position}


def test_the_results_of_ncvm_run_jobs(in_process, cli_report):
    assert isinstance(in_process, list) and all(isinstance(r, ncvm.RunResult) for r in in_process)
    expected = [{k: rec[k] for k in ("path", "dialect", "machine", "status", "error", "cycle_time_s", "steps",
                                     "motion", "limit_violations", "output_lines", "position")}
                for rec in cli_report["programs"]]
    assert [as_record(r) for r in in_process] == expected
    assert in_process.skipped == cli_report["skipped"]
    assert {k: v for k, v in in_process.summary.items() if k not in ("wall_time_s", "jobs")} == \
        {k: v for k, v in cli_report["summary"].items() if k not in ("wall_time_s", "jobs")}


def test_failures_are_typed(in_process):
    by_path = {r.path: r for r in in_process}
    divide = by_path["bad/divide.cpl"]
    assert divide.status == "error" and divide.failed
    assert (divide.error.code, divide.error.span.file, divide.error.span.line) == ("CPL028", "bad/SUB.cpl", 2)
    assert divide.error.notes == ["called from divide.cpl at bad/divide.cpl:1:4"]
    travel = by_path["bad/travel.din"]
    assert travel.status == "ok" and travel.failed and "soft limit" in travel.limit_violations[0]
    assert by_path["bad/syntax.cpl"].error.code == "CPL001"
    assert {s["path"] for s in in_process.skipped} >= {"bad/README", "bad/SUB.cpl"}
    assert "bad/notes.txt" not in {s["path"] for s in in_process.skipped}  # another extension: not looked at


def test_batch_results_hold_the_variables_a_run_gives(archive, in_process):
    flange = next(r for r in in_process if r.path == "examples/cpl/flange.cpl")
    with chdir(archive):
        alone = ncvm.run("examples/cpl/flange.cpl", state_dir=archive / "alone")
    assert flange.variables == alone.to_json()["variables"] and flange.variables
    assert flange.cycle_time_model == alone.cycle_time_model
    assert flange.session is None
    with pytest.raises(ValueError, match="moves=True"):
        _ = flange.moves


def test_a_local_pool_gives_the_same(archive, in_process):
    with chdir(archive):
        pooled = ncvm.batch(["examples", "bad"], jobs=2, state=archive / "pool-state")
    assert [r.to_json() for r in pooled] == [r.to_json() for r in in_process]
    assert pooled.summary["jobs"] == 2


def test_the_report_files(archive, in_process, tmp_path):
    in_process.write_report(tmp_path / "r.json")
    in_process.write_report(tmp_path / "r.csv")
    in_process.write_report(tmp_path / "r.xml")
    doc = json.loads((tmp_path / "r.json").read_text())
    assert [p["path"] for p in doc["programs"]] == [r.path for r in in_process]
    rows = list(csv.DictReader((tmp_path / "r.csv").open()))
    assert len(rows) == len(in_process) + len(in_process.skipped)
    suite = ET.parse(tmp_path / "r.xml").getroot()
    assert int(suite.get("failures")) == sum(r.failed for r in in_process) == in_process.summary["failed"] == 3


def test_a_single_path_and_refusals(archive):
    with chdir(archive):
        one = ncvm.batch("bad/travel.din", jobs=1, state=archive / "one")
        assert [r.path for r in one] == ["bad/travel.din"]
        with pytest.raises(UsageError, match="exclude each other"):
            ncvm.batch("bad", jobs=2, cluster="tcp://127.0.0.1:1")


def test_a_dask_local_cluster_gives_the_same(archive, in_process):
    distributed = pytest.importorskip("distributed")  # the extra ncvm[cluster], installed by make test
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1",
                                  scheduler_port=0, dashboard_address=None) as cluster, chdir(archive):
        remote = ncvm.batch(["examples", "bad"], cluster=cluster.scheduler_address, state=archive / "c-state")
    assert [r.to_json() for r in remote] == [r.to_json() for r in in_process]
    assert remote.summary["cluster"]["workers"] == 2


def test_a_batch_starts_from_a_copy_of_ncvm_as_the_command_line(tmp_path, monkeypatch):
    """The default ``state`` is ``--state``'s: .ncvm of the current directory, copied for each program."""
    monkeypatch.chdir(tmp_path)
    (tmp_path / "count.cpl").write_text("10 IF @1 = NUL THEN @1 = 0 ENDIF\n20 @1 = @1 + 1\nM30\n")
    assert ncvm.batch("count.cpl", jobs=1)[0].variables["@1"] == 1  # no .ncvm: an empty memory
    assert ncvm.run("count.cpl").variables["@1"] == 1  # kept in .ncvm
    counted = ncvm.batch("count.cpl", jobs=1)
    assert counted[0].variables["@1"] == 2 and "a copy of .ncvm" in counted.summary["state"]
    assert counted[0].to_json()["variables"] == {"@1": 2}
    assert ncvm.run("count.cpl").variables["@1"] == 2  # the batch wrote nothing back
