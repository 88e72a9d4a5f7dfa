"""Review of issue 17 item 7 (``ncvm state show/reset/export/import``), tried as a shop engineer would:
the store of real runs exported, edited, imported, and the next run started from it.

The issue: "`ncvm state export/import FILE.json`"; the README: "an import is checked whole first and a bad
file is refused with exit 2 naming the entry and why", and state_io: "a file a control could not have
written (an unknown namespace, a wrong key, a value of another type or shape) is refused with the place and
the reason, never half imported". Each test below imports a file that breaks that promise: it is taken
(exit 0), and the next ``ncvm run`` ends in "internal error ... a bug in ncvm" (exit 70) or runs on a value
no control could hold. Every test runs ``ncvm`` as a process on real files and fails on main as reviewed.
"""

from __future__ import annotations

import copy
import json
import subprocess
import sys
from pathlib import Path

import pytest

NCVM = str(Path(sys.executable).parent / "ncvm")
EXAMPLES = Path(__file__).resolve().parents[2] / "examples"

CPL_WRITE = """(W)
10 @1 = 17
20 @_R(2) = 0.1
40 @RR(1) = 0.1
70 FXC(2,54,1)=80.1
80 FXC("Z",55,1)=-3.3
90 TC(1,10,5)=2.5
100 TDA(1,1,9,1)=20000
120 TDA(2,3,8,1)="DRILL 12"
M30
"""
CPL_READ = """(R)
10 A% = @1
20 B = @_R(2)
40 D = @RR(1)
70 G = FXC(2,54,1)
90 I = TC(1,10,5)
100 J% = TDA(1,1,9)
110 K$ = TDA(2,3,8)
N120 G54 G0 X0 Y0 Z0
M30
"""
SIN_WRITE = "%MPF1\nN10 R900=0.1 R901=123.4567\nN20 @430 K1 K1 K0 K10\nN30 @430 K1 K2 K0 K-3.5\nN40 M30\n"
SIN_READ = "%MPF2\nN10 R1=R900 R2=R901\nN20 G54 G0 X0 Y0 Z0\nN30 M30\n"


def ncvm(*args, cwd, stdin=subprocess.DEVNULL):
    return subprocess.run([NCVM, *map(str, args)], cwd=cwd, capture_output=True, text=True, stdin=stdin, timeout=120)


@pytest.fixture(scope="module")
def cpl(tmp_path_factory):
    """A CPL machine folder whose store real runs filled: permanent variables, a declared REAL field, a zero
    shift, a tool compensation and two tool database records; and its export file."""
    d = tmp_path_factory.mktemp("cpl")
    (d / "files").mkdir()
    (d / "files" / "anwperm.dat").write_text("DEF REAL @RR(3)\n")
    (d / "machine.toml").write_text((EXAMPLES / "cpl" / "machine.toml").read_text()
                                    + 'tool_database = [{sector = 1, place = 1, fields = {"9" = 0}}, '
                                      '{sector = 2, place = 3, fields = {"8" = ""}}]\n')
    (d / "w.cpl").write_text(CPL_WRITE)
    (d / "r.cpl").write_text(CPL_READ)
    assert ncvm("run", "w.cpl", "--state", "s", cwd=d).returncode == 0
    assert ncvm("state", "export", "e.json", "--state", "s", cwd=d).returncode == 0
    return d, json.loads((d / "e.json").read_text())


@pytest.fixture(scope="module")
def sin(tmp_path_factory):
    """A SINUMERIK 800 folder whose store holds central R parameters and a G54 zero offset from a real run."""
    d = tmp_path_factory.mktemp("sin")
    (d / "machine.toml").write_text((EXAMPLES / "sin800" / "machine.toml").read_text())
    (d / "w.mpf").write_text(SIN_WRITE)
    (d / "r.mpf").write_text(SIN_READ)
    assert ncvm("run", "w.mpf", "--state", "s", cwd=d).returncode == 0
    assert ncvm("state", "export", "e.json", "--state", "s", cwd=d).returncode == 0
    return d, json.loads((d / "e.json").read_text())


def _import_then_run(folder: Path, doc: dict, name: str, program: str):
    """Import ``doc`` (as an edited export file) into a fresh state directory, then run ``program`` on it."""
    (folder / f"{name}.json").write_text(json.dumps(doc))
    imported = ncvm("state", "import", f"{name}.json", "--state", f"s_{name}", cwd=folder)
    run = ncvm("run", program, "--state", f"s_{name}", "--json", cwd=folder) if imported.returncode == 0 else None
    return imported, run


def _assert_refused(imported, run, entry: str):
    shown = "" if run is None else f"; the next run then gave exit {run.returncode}: {run.stderr.strip()[-300:]}"
    assert imported.returncode == 2, f"a file no control could have written was imported{shown}"
    assert entry in imported.stderr and "Traceback" not in imported.stderr


def test_the_round_trip_of_real_runs_is_exact(cpl, sin):
    """What works (kept as a guard for the failing tests below): export, import, export is the same file,
    and the next run reads the same values from the imported store, for CPL and SINUMERIK 800."""
    for (folder, doc), program in ((cpl, "r.cpl"), (sin, "r.mpf")):
        before = ncvm("run", program, "--state", "s", "--json", cwd=folder)
        imported, after = _import_then_run(folder, doc, "same", program)
        assert imported.returncode == 0, imported.stderr
        assert json.loads(after.stdout)["variables"] == json.loads(before.stdout)["variables"]
        assert ncvm("state", "export", "again.json", "--state", "s_same", cwd=folder).returncode == 0
        assert json.loads((folder / "again.json").read_text()) == doc


ZS_BREAKS = {
    "no columns": lambda t: t.pop("columns"),
    "columns not a list": lambda t: t.__setitem__("columns", 5),
    "no G54 row": lambda t: t["rows"].pop("G54"),
    "a row of one value for three columns": lambda t: t["rows"].__setitem__("G54", [1.0]),
}


@pytest.mark.parametrize("what", list(ZS_BREAKS))
def test_a_zero_shift_table_of_a_shape_no_control_writes_is_refused(cpl, what):
    """An edited CPL ZS table (cpl.zs V1) without its columns, without the G54 row or with a short row is
    imported (exit 0) - state_io checks only that the rows are numbers - and every CPL run on that store
    then stops with "internal error: KeyError: 'columns'" / "KeyError: 'G54'" / "IndexError" (exit 70).
    The README: "a bad file is refused with exit 2 naming the entry and why"."""
    folder, doc = cpl
    doc = copy.deepcopy(doc)
    ZS_BREAKS[what](doc["store"]["cpl.zs"]["V1"])
    imported, run = _import_then_run(folder, doc, "zs_" + what.replace(" ", "_"), "r.cpl")
    _assert_refused(imported, run, "V1")


SIN_BREAKS = {
    "a zero offset of one value for three axes": lambda s: s["zo"].__setitem__("G54.coarse", [1.0]),
    "a zero offset that is one number": lambda s: s["zo"].__setitem__("G54.coarse", 5.0),
    "a central R parameter that is a list": lambda s: s["central_r"].__setitem__("902", [1.0, 2.0]),
    "a central R parameter numbered abc": lambda s: s["central_r"].__setitem__("abc", 1.0),
}


@pytest.mark.parametrize("what", list(SIN_BREAKS))
def test_sinumerik_nc_data_of_a_shape_no_control_writes_is_refused(sin, what):
    """An edited SINUMERIK 800 store (zero offset G54 of the wrong length or not a list, a central R
    parameter that is a list or not a number) is imported, and the next run of any program on it is
    "internal error: IndexError / TypeError / ValueError ... a bug in ncvm" (exit 70)."""
    folder, doc = sin
    doc = copy.deepcopy(doc)
    SIN_BREAKS[what](doc["store"]["sin800"])
    imported, run = _import_then_run(folder, doc, "sin_" + what.replace(" ", "_"), "r.mpf")
    _assert_refused(imported, run, "sin800")


def test_central_r_parameters_are_r900_to_r999_only(sin):
    """The store's central R parameters are R900-R999 (docs/sin800.md, "The NC state"); a file naming R5
    as central is imported silently and the entry sits in the store (shown by ``state show``) although no
    control could have kept it there."""
    folder, doc = sin
    doc = copy.deepcopy(doc)
    doc["store"]["sin800"]["central_r"]["5"] = 1.0
    imported, run = _import_then_run(folder, doc, "sin_r5", "r.mpf")
    _assert_refused(imported, run, "5")


@pytest.mark.parametrize("where,value", [("@_R(2)", "NaN"), ("@RR", "Infinity")])
def test_nan_and_infinity_are_not_values_of_the_permanent_memory(cpl, where, value):
    """Python's json reads the non-JSON words NaN and Infinity, and the import takes them (``_real`` lets
    every non-finite value pass): a REAL field then reads back as ``inf`` (the run's variable D is "inf"),
    @_R(2) = NaN stops the next run with CPL042. A CPL REAL is binary32 up to +/-1e38 (the README: "a
    REAL is the binary32 value it holds"): no control holds NaN or infinity, and the file is not JSON."""
    folder, doc = cpl
    doc = copy.deepcopy(doc)
    if where == "@RR":
        doc["store"]["cpl.perm"]["@RR"]["value"][1] = 1.5
    else:
        doc["store"]["cpl.perm"][where] = 1.5
    text = json.dumps(doc).replace("1.5", value)
    (folder / f"nonfinite_{value}.json").write_text(text)
    imported = ncvm("state", "import", f"nonfinite_{value}.json", "--state", f"s_nf_{value}", cwd=folder)
    run = ncvm("run", "r.cpl", "--state", f"s_nf_{value}", "--json", cwd=folder) if imported.returncode == 0 else None
    _assert_refused(imported, run, where)


def test_a_tool_database_string_field_holding_a_number_is_refused(cpl):
    """TDA field 8 is a string (docs/cpl.md: "fields 3..49 with the manual's types (8 and 49 strings of
    <= 31 characters"); an import that puts the number 7 there is taken, and the next run silently gives
    the CHARACTER variable K$ = TDA(2,3,8) the INTEGER 7 (status ok): a wrong answer, not an error."""
    folder, doc = cpl
    doc = copy.deepcopy(doc)
    doc["store"]["cpl.tdb"]["2,3"]["8"] = 7
    imported, run = _import_then_run(folder, doc, "tdb_8", "r.cpl")
    if run is not None:
        assert json.loads(run.stdout)["variables"].get("K$") != 7, "a CHARACTER variable holds the INTEGER 7"
    _assert_refused(imported, run, "2,3")
