"""Batch runs of a generated archive (tests/batch/generate.py): which files run, on which machine, with the
same results as one run per program, in this process and in a local pool; the reports read back."""

from __future__ import annotations

import csv
import json
import os
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from ncvm.api import run_program
from ncvm.archive import report, run_batch
from ncvm.archive.discover import discover, machine_of
from ncvm.runtime.session import RunOptions
from tests.runtime.ctrl_c import ctrl_c

from .conftest import in_folder, stable

NCVM = [sys.executable, "-m", "ncvm"]


def by_path(doc):
    return {str(Path(r["path"])): r for r in doc["programs"]}


def test_the_archive_holds_200_programs_of_every_dialect(in_process):
    programs = in_process["programs"]
    assert len(programs) >= 200
    assert {r["dialect"] for r in programs} == {"din", "cpl", "sin800", "cl800", "sympas"}
    for dialect in ("din", "cpl", "sin800", "cl800", "sympas"):
        assert any(r["dialect"] == dialect and r["status"] == "ok" for r in programs), dialect


def test_injected_errors_stop_their_program_with_the_dialects_code(archive, in_process):
    records = by_path(in_process)
    for path, code in archive.injected.items():
        r = records[path]
        assert (r["status"], r["error"]["code"]) == ("error", code), path
        assert r["error"]["file"] == path and r["error"]["line"] in (1, 2, 6, 7)  # named as in the archive
    for path in archive.limit_violations:
        r = records[path]
        assert r["status"] == "limit_violation" and "soft limit" in r["limit_violations"][0]
    assert in_process["summary"]["failed"] == sum(r["status"] != "ok" for r in in_process["programs"])


def test_files_that_are_no_programs_and_sub_programs_are_skipped_with_the_reason(archive, in_process):
    skipped = {s["path"]: s["reason"] for s in in_process["skipped"]}
    for path in archive.not_programs:
        assert path in skipped and skipped[path].startswith("no extension"), path
    assert "binary" in skipped["injected/DUMP"]
    assert "it looks most like 'cpl'" in skipped["injected/OLDFLANGE"]
    for path in archive.subprograms:
        assert skipped[path] == f"sub-program: called by FLANGE{path.split('line')[1][0]}"
    assert skipped["examples/cpl/BOLTCIRC"] == "sub-program: not listed in examples/cpl/main.txt"
    assert skipped["injected/sin800/L81.spf"].startswith("sub-program: a SINUMERIK sub-program file")
    for path in archive.data_files:
        assert skipped[path] == "in the file root of examples/cpl/machine.toml: the controller's data, not a program"
    ran = by_path(in_process)
    assert not set(skipped) & set(ran)
    # CPL programs named as the control names them (no extension) run as CPL
    assert ran["plant/cell0/line0/FLANGE0"]["dialect"] == "cpl" and ran["plant/cell0/line0/FLANGE0"]["status"] == "ok"


def test_each_program_uses_the_nearest_machine_file_upwards(archive, in_process):
    ran = by_path(in_process)
    for path in archive.plant_programs:
        assert ran[path]["machine"] == "plant/machine.toml", path
    assert ran["plant/robots/r0/contour_0.sap"]["machine"] == "plant/robots/machine.toml"
    # the SINUMERIK example needs its folder's machine (tool D1): with it, it runs to the end
    assert ran["examples/sin800/flange.mpf"]["machine"] == "examples/sin800/machine.toml"
    assert ran["examples/sin800/flange.mpf"]["status"] == "ok"
    assert ran["regression/din/drill_plate.din"]["machine"] == "regression/din/machine.toml"
    assert in_process["summary"]["machines"]["plant/machine.toml"] == len(archive.plant_programs)
    # never above the folder named on the command line
    found = discover([str(archive.root / "plant" / "cell0")])
    assert {p.machine for p in found.programs} == {None}


def test_a_local_pool_gives_the_same_results(archive, in_process):
    pooled = in_folder(archive.root, run_batch, ["."], jobs=2)
    assert stable(pooled["programs"]) == stable(in_process["programs"])
    assert pooled["skipped"] == in_process["skipped"] and pooled["summary"]["jobs"] == 2
    assert len({r["worker"] for r in pooled["programs"]}) == 2  # two processes did the work


def _one_run(program, state: Path) -> dict:
    """One run of the program on its own, as ``ncvm run`` does it, from an empty memory."""
    keys, scenario = (program.path.with_name(program.path.stem + s) for s in (".keys", ".scenario.toml"))
    options = RunOptions(state_dir=state, keys=keys if keys.is_file() else None,
                         scenario=scenario if scenario.is_file() else None)
    return run_program(program.path, program.dialect, machine_of(program), options).to_json()


def test_results_are_those_of_one_run_per_program(archive, in_process, tmp_path):
    copy = tmp_path / "archive"  # single runs write into the archive's file roots: not into the shared one
    shutil.copytree(archive.root, copy)
    cwd = os.getcwd()
    os.chdir(copy)
    try:
        found = discover(["."])
        records = by_path(in_process)
        sample = found.programs[::6] + [p for p in found.programs if str(p.path) in archive.injected]
        for i, program in enumerate(sample):
            alone = _one_run(program, tmp_path / f"state{i}")
            r = records[str(program.path)]
            assert (r["status"] == "error") == bool(alone["error"]), program.path
            assert r["error"] == alone["error"], program.path
            assert (r["steps"], r["cycle_time_s"], r["motion"], r["output_lines"], r["limit_violations"],
                    r["position"]) == (alone["steps"], alone["cycle_time_s"], alone["motion"], alone["output"],
                                       alone["limit_violations"], alone["position"]), program.path
    finally:
        os.chdir(cwd)


@pytest.mark.parametrize("path", ["examples/sin800/flange.mpf", "injected/cpl/pocket_bad1.cpl",
                                  "examples/cpl/partcount.cpl"])
def test_results_are_those_of_ncvm_run_in_its_own_process(archive, in_process, tmp_path, path):
    copy = tmp_path / "archive"  # a single run writes into its machine's file root: not into the shared archive
    shutil.copytree(archive.root / Path(path).parts[0], copy / Path(path).parts[0])
    r = subprocess.run([*NCVM, "run", path, "--json", "--state", str(tmp_path / "s")], cwd=copy,
                       capture_output=True, text=True, timeout=120)
    alone = json.loads(r.stdout)
    b = by_path(in_process)[path]
    assert (b["status"], b["error"], b["steps"], b["cycle_time_s"], b["motion"], b["output_lines"]) == \
           (alone["status"], alone["error"], alone["steps"], alone["cycle_time_s"], alone["motion"], alone["output"])


def test_permanent_writes_are_reported_and_not_kept(archive, in_process):
    """Each program starts from an empty memory; what it writes is listed and thrown away."""
    r = by_path(in_process)["examples/cpl/partcount.cpl"]
    writes = {w["key"]: w["value"] for w in r["permanent_writes"]["store"]}
    assert writes["@1"] == 1 and writes["@_R(1)"] == 30.0
    measlog = by_path(in_process)["examples/cpl/measlog.cpl"]["permanent_writes"]["files"]
    assert measlog == [{"path": str(archive.root / "examples/cpl/files/PMEASLOG"), "change": "created"}]
    assert not (archive.root / "examples/cpl/files/PMEASLOG").exists()  # the archive is never written
    assert in_process["summary"]["state"].startswith("temporary: each program on its own from an empty memory")
    assert in_process["summary"]["with_permanent_writes"] >= 2


def _partcount_folder(tmp_path: Path) -> Path:
    folder = tmp_path / "parts"
    cpl = Path(__file__).parents[2] / "examples/cpl"
    (folder / "files").mkdir(parents=True)
    shutil.copy(cpl / "files" / "anwperm.dat", folder / "files")  # the declarations of the permanent variables
    shutil.copy(cpl / "machine.toml", folder)
    text = (cpl / "partcount.cpl").read_text()
    for name in ("a.cpl", "b.cpl", "c.cpl"):
        (folder / name).write_text(text)
    return folder


def test_each_program_starts_from_a_copy_of_the_state_directory(tmp_path):
    folder = _partcount_folder(tmp_path)
    state = tmp_path / "state"
    machine = str(folder / "machine.toml")
    run_program(folder / "a.cpl", machine=machine, options=RunOptions(state_dir=state))  # a part before the batch
    doc = run_batch([str(folder)], state=state, jobs=1)
    assert [r["output_lines"][0] for r in doc["programs"]] == ["PART 2 OF 5; slot length cut so far 60.0 mm"] * 3
    assert doc["summary"]["state"] == f"temporary: each program on its own from a copy of {state}, writes " \
                                      f"reported, not kept"
    again = run_program(folder / "a.cpl", machine=machine, options=RunOptions(state_dir=state))
    assert again.output[0].startswith("PART 2 OF 5")  # the batch kept nothing


def test_a_shared_state_directory_carries_the_writes_from_program_to_program(tmp_path):
    folder = _partcount_folder(tmp_path)
    state = tmp_path / "state"
    doc = run_batch([str(folder)], state=state, shared_state=True, jobs=2)
    assert sorted(r["output_lines"][0][:11] for r in doc["programs"]) == ["PART 1 OF 5", "PART 2 OF 5", "PART 3 OF 5"]
    assert {r["state"] for r in doc["programs"]} == {str(state.absolute())}
    assert all(r["permanent_writes"]["store"] for r in doc["programs"])
    assert doc["summary"]["state"].startswith("shared: every program in turn on")


# --- the command line and the reports ---------------------------------------------------------------------

def ncvm(*args, cwd):
    return subprocess.run([*NCVM, *args], cwd=cwd, capture_output=True, text=True, timeout=300)


@pytest.fixture(scope="module")
def reports(archive, tmp_path_factory):
    """The report of the archive's injected folder and the examples as ``ncvm run`` writes it, and the same
    document as CSV and JUnit XML (the command writes them as ``--report`` names them)."""
    out = tmp_path_factory.mktemp("reports")
    r = ncvm("run", "injected", "examples", "-j", "2", "--report", str(out / "r.json"), cwd=archive.root)
    doc = json.loads((out / "r.json").read_text())
    for suffix in ("csv", "xml"):
        report.write(doc, out / f"r.{suffix}")
    return r, out


def test_the_command_line_runs_a_batch_and_exits_1_when_a_program_failed(reports):
    r, _ = reports
    assert r.returncode == 1, r.stderr
    assert "injected/din/face_and_circle_bad0.din:2:10: error NC001: cannot read '?'" in r.stderr
    assert "injected/README: skipped: no extension" in r.stderr
    assert "ncvm: 3 program(s) on machine file examples/sympas/machine.toml" in r.stderr
    assert "ncvm: 23 program(s) run, 10 with errors, 1 with limit violations, 12 ok" in r.stderr


def test_the_json_report(reports):
    doc = json.loads((reports[1] / "r.json").read_text())
    assert len(doc["programs"]) == 23 and doc["summary"]["failed"] == 11
    r = next(p for p in doc["programs"] if p["path"] == "injected/sympas/contour_bad0.sap")
    assert set(r) >= {"path", "dialect", "machine", "status", "error", "cycle_time_s", "steps", "motion",
                      "limit_violations", "output_lines"}
    assert r["error"] == {"code": "3", "message": "'undeclaredvar' is not declared (or used before its declaration)",
                          "file": "injected/sympas/contour_bad0.sap", "line": 7, "column": 3}
    assert r["machine"] == "injected/sympas/machine.toml"


def test_the_csv_report_has_a_row_per_program(reports):
    rows = list(csv.DictReader((reports[1] / "r.csv").open()))
    doc = json.loads((reports[1] / "r.json").read_text())
    programs = [r for r in rows if r["status"] != "skipped"]
    assert [r["path"] for r in programs] == [p["path"] for p in doc["programs"]]
    flange = next(r for r in rows if r["path"] == "examples/sin800/flange.mpf")
    assert (flange["status"], flange["error_code"], int(flange["steps"]), float(flange["cycle_time_s"])) == \
           ("ok", "", 130, pytest.approx(100.8360192))  # arcs ramp at an axis's own acceleration
    bad = next(r for r in rows if r["path"] == "injected/sin800/flange_bad0.mpf")
    assert (bad["error_code"], bad["error_line"], bad["error_column"]) == ("SIN002", "2", "4")
    assert {r["path"] for r in rows if r["status"] == "skipped"} >= {"injected/DUMP", "examples/cpl/BOLTCIRC"}


def test_the_junit_report_fails_the_programs_with_errors_or_limit_violations(reports):
    suite = ET.parse(reports[1] / "r.xml").getroot()
    assert suite.tag == "testsuite" and suite.get("failures") == "11"
    cases = {c.get("name"): c for c in suite.iter("testcase")}
    failure = cases["injected/cl800/deep_hole_bad0.cl8"].find("failure")
    assert failure.get("type") == "E061" and "injected/cl800/deep_hole_bad0.cl8:6:3" in failure.text
    assert cases["injected/travel.din"].find("failure").get("type") == "limit_violation"
    assert cases["examples/cpl/flange.cpl"].find("failure") is None
    assert cases["injected/EMPTY"].find("skipped") is not None
    assert int(suite.get("tests")) == len(cases)


def test_a_batch_of_good_programs_exits_0_and_json_goes_to_stdout(archive):
    r = ncvm("run", "examples/sympas", "examples/din/face_and_circle.din", "--json", "--report", "good.xml",
             cwd=archive.root)
    assert r.returncode == 0, r.stderr
    doc = json.loads(r.stdout)
    assert [p["path"] for p in doc["programs"]] == ["examples/sympas/contour.sap", "examples/sympas/pick_place.sap",
                                                    "examples/sympas/two_tasks.sap", "examples/din/face_and_circle.din"]
    suite = ET.parse(archive.root / "good.xml").getroot()
    assert (suite.get("tests"), suite.get("failures")) == ("4", "0")


@pytest.mark.parametrize("args, message", [
    (["run", "examples/din", "--trace", "t.jsonl"], "--trace take(s) one program"),
    (["run", "examples/din", "--report", "r.txt"], "give a .json, .csv or .xml file"),
    (["run", "examples/din", "--jobs", "2", "--cluster", "tcp://127.0.0.1:1"], "exclude each other"),
    (["run", "examples/din", "nothing"], "no such program: nothing"),
    (["run", "examples/din", "--shared-state", "--state", " "], "--state is empty"),
])
def test_batch_usage_errors_exit_2(archive, args, message):
    r = ncvm(*args, cwd=archive.root)
    assert r.returncode == 2 and message in r.stderr, r.stderr


def test_a_broken_machine_file_fails_its_programs_only(tmp_path):
    (tmp_path / "a").mkdir()
    (tmp_path / "b").mkdir()
    (tmp_path / "a" / "machine.toml").write_text("[[axis]\n")
    for folder in ("a", "b"):
        (tmp_path / folder / "p.din").write_text("G1 X1 F100\nM30\n")
    doc = run_batch([str(tmp_path)], jobs=1)
    status = {Path(r["path"]).parent.name: (r["status"], (r["error"] or {}).get("code")) for r in doc["programs"]}
    assert status == {"a": ("error", "RUN007"), "b": ("ok", None)}
    assert "machine.toml" in doc["programs"][0]["error"]["message"]


def test_check_takes_extensionless_programs_and_the_machine_file_above(tmp_path):
    (tmp_path / "cell").mkdir()
    (tmp_path / "machine.toml").write_text((Path(__file__).parents[2] / "examples/cpl/machine.toml").read_text())
    (tmp_path / "cell" / "BOLTCIRC").write_text((Path(__file__).parents[2] / "examples/cpl/BOLTCIRC").read_text())
    (tmp_path / "cell" / "main.cpl").write_text("10 CALL BOLTCIRC [0, 0, 40, 6, 0, 12, 2, 150]\nM30\n")
    (tmp_path / "cell" / "NOTES").write_text("just words\n")
    r = ncvm("check", ".", "--json", cwd=tmp_path)
    assert r.returncode == 0, r.stdout
    doc = json.loads(r.stdout)
    assert [(f["file"], f["machine"]) for f in doc["files"]] == [("cell/BOLTCIRC", "machine.toml"),
                                                                 ("cell/main.cpl", "machine.toml")]
    assert doc["skipped"][0]["file"] == "cell/NOTES"
    text = ncvm("check", ".", cwd=tmp_path).stderr
    assert "cell/NOTES: skipped: no extension" in text and "ncvm: 2 program(s) on machine file machine.toml" in text
    assert "2 program(s) checked, 0 diagnostic(s), 1 file(s) skipped" in text


def test_ctrl_c_stops_a_pooled_batch_at_once(tmp_path):
    for i in range(6):  # runaways: the batch would take minutes
        (tmp_path / f"loop{i}.cpl").write_text("10 WHILE TRUE DO\n20 X% = 1\n30 END\n")
    p = subprocess.Popen([*NCVM, "run", ".", "-j", "2"], cwd=tmp_path, stderr=subprocess.PIPE, text=True,
                         start_new_session=True)
    children = Path(f"/proc/{p.pid}/task/{p.pid}/children")
    # as the terminal sends it: to the batch and its pool
    err = ctrl_c(p, lambda: len(children.read_text().split()) >= 2, "the pool to be at work", settle=0.5,
                 group=True, timeout=60)[1]
    assert p.returncode == 1 and "interrupted by the user" in err and "Traceback" not in err, err
    assert "program(s) run" not in err  # no summary of a batch that did not end
