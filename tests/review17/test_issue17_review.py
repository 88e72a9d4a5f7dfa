"""Review of issue 17 items 1-4 (batch runs, the local pool, dask clusters, reports), tried as a shop's
maintenance engineer would try them on an archive: the defects found, one failing test each.

Every test runs ``ncvm`` as a process of its own on real files, folders, symlinks and FIFOs; each names
the words of the issue (or of docs/batch.md) it holds the project to, and fails on main as reviewed.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from tests.runtime.ctrl_c import ctrl_c, wait_until

BIN = Path(sys.executable).parent

MILL = """[machine]
name = "shop mill"
[[axis]]
name = "X"
[[axis]]
name = "Y"
[[axis]]
name = "Z"
"""
#: a drilling cycle as the machine file maps G81 to it: P1 the depth; it counts the holes
CYC81 = "N1 G1 Z[P1]\nN2 G0 Z10\n10 #HOLES% = #HOLES% + 1\n"
GOOD_DIN = "N10 G90 G0 X0 Y0 Z10\nN20 G1 X20 F300\nM30\n"


def ncvm(*args: str, cwd: Path, timeout: float = 300) -> subprocess.CompletedProcess:
    return subprocess.run(
        [sys.executable, "-m", "ncvm", *args],
        cwd=cwd,
        capture_output=True,
        text=True,
        timeout=timeout,
        stdin=subprocess.DEVNULL,
    )


def write(path: Path, text: str) -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text)
    return path


def batch(folder: Path, *args: str) -> tuple[subprocess.CompletedProcess, dict]:
    """``ncvm run FOLDER --jobs 1 --report r.json`` from the folder above it: the process and the report."""
    report = folder.parent / f"{folder.name}-report.json"
    r = ncvm(
        "run",
        folder.name,
        "--jobs",
        "1",
        "--state",
        str(folder.parent / "state"),
        "--report",
        str(report),
        *args,
        cwd=folder.parent,
    )
    assert report.is_file(), r.stderr
    return r, json.loads(report.read_text())


def record(doc: dict, path: str) -> dict:
    return next(p for p in doc["programs"] if p["path"] == path)


def named(doc: dict) -> set[str]:
    return {p["path"] for p in doc["programs"]} | {s["path"] for s in doc["skipped"]}


# --- silently incomplete: a batch that never looked at programs of the archive and says nothing ------------


def test_item1_programs_in_a_symlinked_folder_are_run_or_named(tmp_path):
    """Issue 17 item 1: "`ncvm run` ... accept[s] any number of programs and folders" and files that are not
    run are "reported as skipped with the reason". A shop's archive links a machine's folder from the file
    server (`archive/lathe2 -> /nas/lathe2`): the batch never enters it, names none of its programs, and
    reports the archive healthy (exit 0) although a program there stops with an error."""
    write(tmp_path / "nas" / "lathe2" / "broken.din", "N10 G1 X1 ?\nM30\n")
    write(tmp_path / "archive" / "ok.din", GOOD_DIN)
    (tmp_path / "archive" / "lathe2").symlink_to(tmp_path / "nas" / "lathe2", target_is_directory=True)
    r, doc = batch(tmp_path / "archive")
    assert "archive/lathe2/broken.din" in named(doc), (r.stderr, doc["summary"])
    assert r.returncode == 1, r.stderr


@pytest.mark.parametrize("kind", ["fifo", "dangling symlink"])
def test_item1_a_file_with_a_program_extension_that_cannot_be_read_is_named(tmp_path, kind):
    """Issue 17 item 1: files that are not programs are "reported as skipped with the reason"; docs/batch.md:
    "every file with a program extension" below a folder is a program. A FIFO or a dangling link named
    `part7.din` (a program moved away) is neither run nor listed: the report does not know it exists."""
    write(tmp_path / "archive" / "ok.din", GOOD_DIN)
    odd = tmp_path / "archive" / "part7.din"
    if kind == "fifo":
        os.mkfifo(odd)
    else:
        odd.symlink_to(tmp_path / "moved" / "part7.din")
    r, doc = batch(tmp_path / "archive")
    assert "archive/part7.din" in named(doc), r.stderr


def test_item1_the_machine_of_a_program_does_not_depend_on_the_order_of_the_folders_named(tmp_path):
    """Issue 17 item 1: "Every program uses the machine.toml of its own folder (nearest one upwards, up to
    the folder named on the command line)". Named both, `ncvm run shop/cell shop` runs cell's programs on
    the built-in machine -- the shop's machine file with its soft limits above them is ignored, the travel
    beyond them is not reported and the batch exits 0 -- while `ncvm run shop shop/cell` uses it."""
    write(tmp_path / "shop" / "machine.toml", MILL.replace('name = "X"', 'name = "X"\nmin = -10.0\nmax = 10.0'))
    write(tmp_path / "shop" / "cell" / "long.din", GOOD_DIN)  # X20: beyond the shop's soft limit
    runs = {}
    for order in (("shop", "shop/cell"), ("shop/cell", "shop")):
        report = tmp_path / f"{order[0].replace('/', '-')}.json"
        r = ncvm("run", *order, "--state", str(tmp_path / "state"), "--report", str(report), cwd=tmp_path)
        runs[order] = (r.returncode, record(json.loads(report.read_text()), "shop/cell/long.din")["machine"])
    assert runs[("shop", "shop/cell")] == (1, "shop/machine.toml")
    assert runs[("shop/cell", "shop")] == runs[("shop", "shop/cell")], runs


def test_item1_a_long_cam_program_without_an_extension_is_run(tmp_path):
    """Issue 17 item 1: "Files without an extension are classified by content (the dialect detector already
    exists) and reported as skipped with the reason when they are not programs". A CAM program of 5 MB
    named O1234 (as such archives name them) runs alone, but a batch skips it as "larger than 4 MB: not a
    program" without looking at its content, and exits 0 with nothing run."""
    blocks = [f"N{n} G1 X{n % 400 / 10:.3f} Y{n % 313 / 10:.3f}" for n in range(3, 230_000)]
    text = "\n".join(["N1 G90 G0 X0 Y0 Z5", "N2 G1 Z-1 F500", *blocks, "N230000 M30", ""])
    assert len(text) > 4 * 2**20
    write(tmp_path / "cam" / "O1234", text)
    alone = ncvm("run", "cam/O1234", "--state", str(tmp_path / "alone"), cwd=tmp_path)
    assert alone.returncode == 0, alone.stderr
    r, doc = batch(tmp_path / "cam")
    assert [p["path"] for p in doc["programs"]] == ["cam/O1234"], doc["skipped"]


# --- false errors: the batch fails programs that run alone ("results identical to one run per program") ----


def test_item2_a_cpl_program_using_the_machines_g81_cycle_runs_in_a_batch_as_alone(tmp_path):
    """Issue 17 item 2: "results identical to one run per program"; item 3: "the programs' text, the machine
    file and the options travel with each task". A CPL program drills with G81, which the machine file maps
    to the cycle program CYC81 ([cpl] calls, the manual's G81-G86 cycles). Alone it runs; in a batch it
    stops with CPL005 "sub-program not found: CYC81": the cycle is not shipped, because the program's text
    never names it."""
    folder = tmp_path / "cell"
    write(folder / "machine.toml", MILL + '[cpl]\ncalls = { G81 = { program = "CYC81", modal = true } }\n')
    write(folder / "main.txt", "drill.cpl\n")
    write(folder / "CYC81", CYC81)
    write(folder / "drill.cpl", "5 #HOLES% = 0\nN1 G0 X0 Y0 Z10 F500\nN2 G81 [-5]\nN3 X10\nN4 G80\nM30\n")
    alone = ncvm("run", "cell/drill.cpl", "--state", str(tmp_path / "alone"), cwd=tmp_path)
    assert alone.returncode == 0, alone.stderr
    r, doc = batch(folder)
    assert record(doc, "cell/drill.cpl")["error"] is None, r.stderr
    assert r.returncode == 0


@pytest.mark.parametrize("call", ["number", "indirect"])
def test_item2_a_sinumerik_sub_program_found_alone_is_found_in_a_batch(tmp_path, call):
    """Issue 17 item 2: "results identical to one run per program". SINUMERIK sub-programs are called by
    number: `L20` finds the file whose header is %SPF20 whatever its name, and `L=R5` calls the number in
    R5. Alone both run; in a batch both stop with RUN002 "sub-program L20 not found", because only files
    whose name the program's text mentions travel with the task."""
    folder = tmp_path / "cell"
    write(folder / "machine.toml", MILL)
    name = "slot_pass.spf" if call == "number" else "L20.spf"
    write(folder / name, "%SPF20\n(one slot pass)\nG91 G1 X10 F300\nG90\nM17\n")
    body = "N40 L20\n" if call == "number" else "N30 R5=20\nN40 L=R5\n"
    write(folder / "slot.mpf", "%MPF12\nN10 G90 G0 X0 Y0 Z0\n" + body + "N50 M30\n")
    alone = ncvm("run", "cell/slot.mpf", "--state", str(tmp_path / "alone"), cwd=tmp_path)
    assert alone.returncode == 0, alone.stderr
    r, doc = batch(folder)
    assert record(doc, "cell/slot.mpf")["error"] is None, r.stderr


def test_item2_a_sympas_include_from_a_sub_folder_travels_with_the_task(tmp_path):
    """Issue 17 item 2: "results identical to one run per program"; item 3: what a run reads travels with
    the task. rw_SymPas `{! lib/speeds.inc}` includes a file of a sub-folder: alone the program runs, in a
    batch it stops with SP007 "include file 'lib/speeds.inc' not found"."""
    folder = tmp_path / "robot"
    write(folder / "lib" / "speeds.inc", "const feed = 80.0;\n")
    write(
        folder / "move.sap",
        "program Move;\n{! lib/speeds.inc}\nbegin\n  TRVL := feed; TRAC := 800.0;\n"
        "  MLAW(A1 := 20.0, A2 := 10.0);\nend.\n",
    )
    alone = ncvm("run", "robot/move.sap", "--state", str(tmp_path / "alone"), cwd=tmp_path)
    assert alone.returncode == 0, alone.stderr
    r, doc = batch(folder)
    assert record(doc, "robot/move.sap")["error"] is None, r.stderr


# --- sub-programs and data run as main programs: false failures in the report and exit 1 --------------------


def _cycles_folder(tmp_path: Path) -> tuple[Path, str]:
    shop = tmp_path / "shop"
    write(shop / "machine.toml", MILL + '[paths]\nprogram_path = [".", "cycles"]\n')
    write(
        shop / "cycles" / "BOLTCIRC",
        (Path(__file__).resolve().parents[2] / "examples" / "cpl" / "BOLTCIRC").read_text(),
    )
    write(
        shop / "parts" / "FLANGE",
        "10 #HOLES% = 0\nN20 G90 G0 X0 Y0 Z10\n30 CALL BOLTCIRC [0, 0, 40, 6, 0, 12, 2, 150]\nM30\n",
    )
    return shop, "shop/cycles/BOLTCIRC"


def _p_address(tmp_path: Path) -> tuple[Path, str]:
    cell = tmp_path / "cell"
    write(cell / "machine.toml", MILL)
    write(cell / "SLOTCYC", "(SLOTCYC - one slot, P1 its length)\nN10 G91 G1 X[P1] F300\nN20 G90 G0 Z10\nM30\n")
    write(cell / "slot.cpl", "N10 G90 G0 X0 Y0 Z10\nN20 G1 Z-2 F200\nN30 P SLOTCYC[25]\nM30\n")
    return cell, "cell/SLOTCYC"


def _machine_cycle(tmp_path: Path) -> tuple[Path, str]:
    cell = tmp_path / "cell"
    write(cell / "machine.toml", MILL + '[cpl]\ncalls = { G81 = { program = "CYC81", modal = true } }\n')
    write(cell / "CYC81", CYC81)
    write(cell / "drill.cpl", "5 #HOLES% = 0\nN1 G0 X0 Y0 Z10 F500\nN2 G81 [-5]\nN3 X10\nN4 G80\nM30\n")
    return cell, "cell/CYC81"


def _sympas_include(tmp_path: Path) -> tuple[Path, str]:
    robot = tmp_path / "robot"
    write(robot / "common.sap", "const slow = 40.0;\n")
    write(
        robot / "move.sap",
        "program Move;\n{! common.sap}\nbegin\n  TRVL := slow; TRAC := 800.0;\n  MLAW(A1 := 20.0, A2 := 10.0);\nend.\n",
    )
    return robot, "robot/common.sap"


@pytest.mark.parametrize(
    "case",
    [_cycles_folder, _p_address, _machine_cycle, _sympas_include],
    ids=["cycles folder of the program path", "CPL P address call", "machine's G81 cycle", "SymPas include"],
)
def test_item1_a_called_sub_program_is_not_run_as_a_main_program(tmp_path, case):
    """Issue 17 item 1: "Sub-programs listed in a folder's main.txt convention (or recognised as called by
    another program) are not run as main programs". Called in ways the batch does not recognise -- from
    the shop's cycles folder of the machine's program path, by a CPL `P NAME[...]` address, as the cycle
    the machine file maps G81 to, as a rw_SymPas include -- the sub-program is run as a main program and
    fails (CPL020 NUL parameters, NC013, SP001): the archive report shows failures that are none."""
    folder, sub = case(tmp_path)
    r, doc = batch(folder)
    assert sub in {s["path"] for s in doc["skipped"]}, r.stderr
    assert sub not in {p["path"] for p in doc["programs"]}


def test_item1_a_cl800_external_list_is_skipped_not_failed(tmp_path):
    """Issue 17 item 1: files without an extension "are classified by content ... and reported as skipped
    with the reason when they are not programs". A CL 800 external list (EXTERNAL ... ENDEXTERN, the data a
    program's header names) is not a program -- `ncvm run LIST` says so as a usage error -- but a batch runs
    it as a main program and counts a failure (RUN007 "external lists are not compiled"), exit 1."""
    folder = tmp_path / "cl800"
    write(
        folder / "CENLST",
        "EXTERNAL 40;\nCHANNEL NC 0;\nID (0-CENLST-23.11.26-NCV);\nCENTRAL REAL: R900:=load_1;\nENDEXTERN\n",
    )
    write(folder / "ok.din", GOOD_DIN)
    r, doc = batch(folder)
    assert "cl800/CENLST" in {s["path"] for s in doc["skipped"]}, r.stderr
    assert r.returncode == 0, r.stderr


def test_item2_the_error_of_a_sub_program_search_reads_as_in_a_run_alone(tmp_path):
    """Issue 17 item 2: "results identical to one run per program". A program below its machine file's folder
    calls a missing sub-program: alone (`--machine shop/machine.toml`) the error names the program path
    "shop, shop/bad"; in the batch it names "shop/bad, shop, shop/bad", a folder twice."""
    shop = tmp_path / "shop"
    write(shop / "machine.toml", MILL + '[paths]\nprogram_path = [".", "bad"]\n')
    write(shop / "bad" / "call_missing.cpl", "10 CALL NOSUCH\nM30\n")
    alone = ncvm(
        "run",
        "shop/bad/call_missing.cpl",
        "--machine",
        "shop/machine.toml",
        "--json",
        "--state",
        str(tmp_path / "alone"),
        cwd=tmp_path,
    )
    message = json.loads(alone.stdout)["error"]["message"]
    assert "(program path: shop, shop/bad)" in message
    r, doc = batch(shop)
    assert record(doc, "shop/bad/call_missing.cpl")["error"]["message"] == message, r.stderr


def test_item1_a_main_program_listed_in_main_txt_but_missing_is_named(tmp_path):
    """Issue 17 item 1: "Sub-programs listed in a folder's main.txt convention ... are not run as main
    programs"; docs/batch.md: main.txt "lists its main programs". A main program listed there whose file
    is missing from the archive (deleted, renamed, a typo) is passed over in silence: the batch and its
    report say nothing of a main program the shop expects to run."""
    cell = tmp_path / "cell"
    write(cell / "main.txt", "flange.din\npocket.din\n")
    write(cell / "flange.din", GOOD_DIN)
    r, doc = batch(cell)
    assert "pocket.din" in r.stderr + json.dumps(doc), r.stderr


# --- reports ------------------------------------------------------------------------------------------------


@pytest.mark.parametrize(
    "program",
    ['10 PRN#(0,"PART READY",CHR$(7))\nM30\n', "10 A% = 1\nN20 \x01\x02QQ\nM30\n"],
    ids=["a bell in the output", "a damaged line"],
)
def test_item4_the_junit_report_is_well_formed_xml(tmp_path, program):
    """Issue 17 item 4: ".xml (JUnit: one testcase per program ...) so CI systems show archive health". A
    program that rings the operator's bell (PRN# with CHR$(7)) or a program file with a damaged line puts
    control characters into the report: the whole file is not well-formed XML, and CI tools read none of
    it."""
    write(tmp_path / "archive" / "part.cpl", program)
    write(tmp_path / "archive" / "ok.din", GOOD_DIN)
    r = ncvm("run", "archive", "--state", str(tmp_path / "state"), "--report", "r.xml", cwd=tmp_path)
    assert r.returncode in (0, 1), r.stderr
    suite = ET.parse(tmp_path / "r.xml").getroot()
    assert len(suite.findall("testcase")) == 2


def test_item4_an_error_without_a_column_is_not_located_at_column_none(tmp_path):
    """Issue 17 item 4: errors carry "file, line, column"; the project's format is `file:line:col: error CODE:
    message`. An error the control reports for a line only (NC002 radius mismatch, CL 800 E300, RUN002)
    is printed by a batch, and written into the JUnit failure, as `part.din:3:None: error NC002`: editors and
    CI problem matchers read no location from it (a run alone prints `part.din:3: error NC002`)."""
    write(tmp_path / "archive" / "part.din", "G1 X10 F100\nG2 X0 Y12 I-10 J0\nM30\n")
    write(tmp_path / "archive" / "ok.din", GOOD_DIN)
    r = ncvm("run", "archive", "--state", str(tmp_path / "state"), "--report", "r.xml", cwd=tmp_path)
    assert "error NC002" in r.stderr, r.stderr
    assert ":None:" not in r.stderr, r.stderr
    failure = ET.parse(tmp_path / "r.xml").getroot().find("testcase/failure")
    assert ":None:" not in failure.text, failure.text


# --- the cluster ----------------------------------------------------------------------------------------------


@pytest.fixture
def scheduler_and_worker(dask_processes):
    """``dask scheduler`` and two ``dask worker`` processes on 127.0.0.1, stopped after the test."""
    return dask_processes(nworkers=2)


def test_item3_ctrl_c_stops_a_cluster_batch_without_a_traceback(tmp_path, scheduler_and_worker):
    """Issue 17 item 3 with the project's quality bar ("never a Python traceback"); docs/batch.md: "Ctrl-C
    stops the batch (RUN004, exit 1)". Interrupted while its tasks run on the cluster, `ncvm run --cluster`
    prints distributed's "Task exception was never retrieved ... Traceback ... AllExit" several times."""
    import distributed

    for i in range(6):  # each stops at --max-steps after several seconds: Ctrl-C comes while they run
        write(tmp_path / "archive" / f"loop{i}.cpl", "10 WHILE TRUE DO\n20 X% = 1\n30 END\n")
    p = subprocess.Popen(
        [
            sys.executable,
            "-m",
            "ncvm",
            "run",
            "archive",
            "--cluster",
            scheduler_and_worker,
            "--max-steps",
            "40000000",
            "--state",
            str(tmp_path / "state"),
        ],
        cwd=tmp_path,
        stderr=subprocess.PIPE,
        text=True,
        start_new_session=True,
    )
    with distributed.Client(scheduler_and_worker, timeout=60) as client:
        wait_until(lambda: any(client.processing().values()), "the tasks to run", timeout=120)
    err = ctrl_c(p, settle=0.5, group=True)[1]  # as the terminal sends it
    assert p.returncode == 1 and "interrupted by the user" in err, err
    assert "Traceback" not in err, err


def _can_hide_folders() -> bool:
    """Root in a container that allows mount namespaces: a worker can be given a disk of its own."""
    try:
        return subprocess.run(["unshare", "-m", "true"], capture_output=True, timeout=30).returncode == 0
    except (OSError, subprocess.TimeoutExpired):
        return False


@pytest.fixture
def worker_with_its_own_disk(tmp_path, dask_processes):
    """A scheduler and a worker on 127.0.0.1 whose view of ``tmp_path / "shop"`` is a disk of its own (an
    empty tmpfs in a mount namespace): a worker host that has the same path, but not the same files."""
    if not _can_hide_folders():
        pytest.skip("needs mount namespaces (unshare -m)")
    (tmp_path / "shop").mkdir()
    return dask_processes(nworkers=1, tmpfs_on=tmp_path / "shop")


def test_item3_shared_state_on_a_cluster_that_does_not_share_it_is_not_reported_kept(
    tmp_path, worker_with_its_own_disk
):
    """Issue 17 item 3: "each worker uses its own temporary state directory unless told to share one, and says
    so in the report ... document what happens to permanent data in a distributed batch (each program's
    writes are reported; they are not merged silently)". With `--shared-state --state /shop/.ncvm` on a
    worker whose /shop is its own disk, every program writes the worker's directory: the report says
    "shared: every program in turn on /shop/.ncvm, writes kept", yet the directory the batch was given
    holds nothing afterwards -- the part counter the shop relies on is silently lost."""
    state = tmp_path / "shop" / ".ncvm"
    write(
        tmp_path / "parts" / "partcount.cpl",
        '10 IF @1 = NUL THEN @1 = 0 ENDIF\n20 @1 = @1 + 1\n30 PRN#(0,"PART ",@1)\nM30\n',
    )
    r = ncvm(
        "run",
        "parts",
        "--cluster",
        worker_with_its_own_disk,
        "--shared-state",
        "--state",
        str(state),
        "--report",
        "r.json",
        cwd=tmp_path,
    )
    doc = json.loads((tmp_path / "r.json").read_text()) if (tmp_path / "r.json").is_file() else None
    if r.returncode == 0 and doc and "writes kept" in doc["summary"]["state"]:
        again = ncvm("run", "parts/partcount.cpl", "--state", str(state), cwd=tmp_path)
        assert again.stdout.split() == ["PART", "2"], (
            doc["summary"]["state"],
            again.stdout,
        )  # the batch's PART 1 was kept
    else:  # or the batch refuses a state directory its workers do not share
        assert r.returncode == 2 and "--state" in r.stderr, r.stderr
