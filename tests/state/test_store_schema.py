"""``ncvm state import`` takes only what the control itself can hold (machine/store_schema.py): each rule of
each store kind refuses a value a run could never have written, naming the entry and why, and the store
of real runs of every dialect goes out and back in unchanged (export, import, export: the same bytes)."""

from __future__ import annotations

import copy
import json
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from ncvm.dialects.cpl.system import controller, tools, zsfile
from ncvm.dialects.sinumerik import ncdata
from ncvm.machine import sections, state_io, store_schema

NCVM = [sys.executable, "-c", "from ncvm.cli import main; main()"]
EXAMPLES = Path(__file__).resolve().parents[2] / "examples"

CPL_DECLARATIONS = "DEF REAL @RW(2)\nDEF CHAR @TXT(10)\nDEF BOOL @B\nDEF INT @N(1,2)\nDEF DOUBLE @D(2)\nDEF CHAR @CF(2,4)\n"
CPL_WRITE = """(W)
10 @1 = 17
20 @_R(2) = 0.1
30 @RW(1) = 0.1
40 @TXT$ = "HALLO"
50 @B? = TRUE
60 @N%(1,2) = -7
65 @D!(2) = 123456789.125
67 @CF$(1) = "AB"
70 FXC(2,54,1)=80.1
80 FXC("Z",55,1)=-3.3
90 TC(1,10,5)=2.5
95 TC(2,3,4)=1.5
100 TDA(1,1,9,1)=20000
120 TDA(2,3,8,1)="DRILL 12"
M30
"""
CPL_READ = "10 A% = @1\n20 B = @_R(2)\n30 C = @RW(1)\n40 D = FXC(2,54,1)\n50 E = TC(1,10,5)\n60 F% = TDA(1,1,9)\n" \
           "70 G$ = TDA(2,3,8)\nN80 G54 G0 X0 Y0 Z0\nM30\n"
#: machine data, setting data, a tool offset, settable coarse/fine, programmable, DRF and PRESET zero
#: offsets, settable and programmable rotations, the MIB and central R parameters at both ends of the range
SIN_WRITE = ("%MPF1\nN10 R900=0.1 R999=-99999999 @400 K2240 K1500 @410 K3041 K1800 @411 K5013 K111\n"
             "N20 @430 K1 K1 K0 K10 @430 K2 K2 K1 K-0.005 @432 K1 K2 K20 @434 K2 K1.5 @435 K1 K100\n"
             "N30 @420 K1 K2 K3 K20 @437 K0 K1 K1 K30 @439 K0 K2 K1 K15\nN40 R1=7.25 @212 K100 R1\nN50 M30\n")
SIN_READ = "%MPF2\nN10 R1=R900 R2=R999 @211 R3 K100\nN20 G54 G0 X0 Y0 Z0\nN30 M30\n"


def ncvm(*args, cwd) -> subprocess.CompletedProcess:
    return subprocess.run([*NCVM, *map(str, args)], capture_output=True, text=True, timeout=120, cwd=cwd,
                          stdin=subprocess.DEVNULL)


def _file(store: dict) -> str:
    return state_io.document(store)


@pytest.fixture(scope="module")
def cpl_store(tmp_path_factory) -> dict:
    """The CPL store of a real run: every kind of permanent variable, a ZS table, TC tables K4/K5, TDA."""
    d = tmp_path_factory.mktemp("cpl")
    (d / "files").mkdir()
    (d / "files" / "anwperm.dat").write_text(CPL_DECLARATIONS)
    (d / "machine.toml").write_text((EXAMPLES / "cpl" / "machine.toml").read_text()
                                    + 'tool_database = [{sector = 1, place = 1, fields = {"9" = 0}}, '
                                      '{sector = 2, place = 3, fields = {"8" = ""}}]\n')
    (d / "w.cpl").write_text(CPL_WRITE)
    assert ncvm("run", "w.cpl", "--state", "s", cwd=d).returncode == 0
    return json.loads(ncvm("state", "export", "-", "--state", "s", cwd=d).stdout)["store"]


@pytest.fixture(scope="module")
def sin_store(tmp_path_factory) -> dict:
    d = tmp_path_factory.mktemp("sin")
    (d / "machine.toml").write_text((EXAMPLES / "sin800" / "machine.toml").read_text())
    (d / "w.mpf").write_text(SIN_WRITE)
    assert ncvm("run", "w.mpf", "--state", "s", cwd=d).returncode == 0
    return json.loads(ncvm("state", "export", "-", "--state", "s", cwd=d).stdout)["store"]


def test_the_real_stores_hold_every_store_kind(cpl_store, sin_store):
    """The fixtures reach every namespace and every area the rules below break."""
    assert set(cpl_store) == {"cpl.perm", "cpl.zs", "cpl.tc", "cpl.tdb"}
    assert {"@1", "@_R(2)", "@RW", "@TXT", "@B", "@N", "@D", "@CF"} <= set(cpl_store["cpl.perm"])
    assert set(sin_store["sin800"]) == {"nc_md", "nc_sd", "to", "zo", "rot", "mib", "central_r"}
    assert state_io.parse(_file(cpl_store), "f") == cpl_store and state_io.parse(_file(sin_store), "f") == sin_store


def _break(store: dict, change) -> str:
    store = copy.deepcopy(store)
    change(store)
    return json.dumps({"format": "ncvm-state", "version": 1, "store": store})


def _zs(s):
    return s["cpl.zs"]["V1"]


CPL_BREAKS = {
    # ZS table (manual §4.3; the layout zsfile.py reads): unit, strict flag, 18 rows of one value per column
    "a ZS table in furlong": (lambda s: _zs(s).__setitem__("unit", "furlong"), 'V1.unit = "furlong": must be one of'),
    "a ZS table strict yes": (lambda s: _zs(s).__setitem__("strict", "yes"), 'V1.strict = "yes"'),
    "a ZS table strict 2": (lambda s: _zs(s).__setitem__("strict", 2), "V1.strict = 2: must be 0 to 1"),
    "a ZS table strict true": (lambda s: _zs(s).__setitem__("strict", True), "V1.strict = true"),
    "a ZS table without row G259": (lambda s: _zs(s)["rows"].pop("G259"), "V1.rows.G259: is missing"),
    "a ZS table row G60": (lambda s: _zs(s)["rows"].__setitem__("G60", [0.0] * 3), "V1.rows.G60"),
    "a ZS row of four values": (lambda s: _zs(s)["rows"]["G55"].append(1.0), "must give 3 values, one per column"),
    "a ZS column twice": (lambda s: _zs(s).__setitem__("columns", ["X", "X", "Z"]), "repeats"),
    "a ZS column in lower case": (lambda s: _zs(s).__setitem__("columns", ["x", "Y", "Z"]), "axis name in capitals"),
    "a ZS rotary axis that is no column": (lambda s: _zs(s).__setitem__("rotary", ["C"]), "is not one of the columns"),
    "a ZS table with a comment": (lambda s: _zs(s).__setitem__("comment", "x"), "V1.comment"),
    "a ZS value NaN": (lambda s: _zs(s)["rows"]["G54"].__setitem__(0, float("nan")), "finite"),
    # tool compensation (manual §4.4): a group is [H, D]
    "a TC group of one value": (lambda s: s["cpl.tc"]["K4"].__setitem__("1", [50.0]), "K4.1 = [50.0]: must have 2"),
    "a TC group of three values": (lambda s: s["cpl.tc"]["K5"]["10"].append(0.0), "must have 2 entries"),
    "a TC group 01": (lambda s: s["cpl.tc"]["K5"].__setitem__("01", [0.0, 0.0]), "a group number"),
    "a TC length of infinity": (lambda s: s["cpl.tc"]["K4"]["2"].__setitem__(0, float("inf")), "finite"),
    # tool database (manual §4.5, L1895-1966): 8 and 49 strings of at most 31, the others INTEGER
    "TDA field 49 a number": (lambda s: s["cpl.tdb"]["2,3"].__setitem__("49", 7), '"2,3".49 = 7'),
    "TDA field 9 a string": (lambda s: s["cpl.tdb"]["1,1"].__setitem__("9", "7"), "is not an INTEGER"),
    "TDA field 9 a REAL": (lambda s: s["cpl.tdb"]["1,1"].__setitem__("9", 2.0), "is not an INTEGER"),
    "TDA field 9 beyond 32 bits": (lambda s: s["cpl.tdb"]["1,1"].__setitem__("9", 2**31), "is not an INTEGER"),
    "TDA field 8 of 32 characters": (lambda s: s["cpl.tdb"]["2,3"].__setitem__("8", "D" * 32), "at most 31"),
    "TDA field 50": (lambda s: s["cpl.tdb"]["1,1"].__setitem__("50", 0), "not a tool database field 3..49"),
    "TDA field 2 (the place)": (lambda s: s["cpl.tdb"]["1,1"].__setitem__("2", 1), "not a tool database field"),
    "TDA sector 0": (lambda s: s["cpl.tdb"].__setitem__("0,1", {}), '"sector,place"'),
    # permanent variables: finite values of their type
    "@1 NaN": (lambda s: s["cpl.perm"].__setitem__("@1", float("nan")), "is not an INTEGER"),
    "@_R(2) minus infinity": (lambda s: s["cpl.perm"].__setitem__("@_R(2)", float("-inf")), "finite"),
    "@_R(2) a whole number beyond binary64": (lambda s: s["cpl.perm"].__setitem__("@_R(2)", 10**400), "finite"),
    "a DOUBLE field element 1e400": (lambda s: s["cpl.perm"]["@D"]["value"].__setitem__(1, float("inf")), "@D"),
    "a BOOL holding 1": (lambda s: s["cpl.perm"]["@B"].__setitem__("value", 1), "must be true or false"),
    "a CHAR field of a longer string": (lambda s: s["cpl.perm"]["@CF"]["value"].__setitem__(2, "ABCDE"), "at most 4"),
    "an INT field row too short": (lambda s: s["cpl.perm"]["@N"]["value"][1].pop(), "must have 3 entries"),
}


@pytest.mark.parametrize("what", list(CPL_BREAKS))
def test_a_cpl_store_entry_no_control_holds_is_refused(cpl_store, what):
    change, words = CPL_BREAKS[what]
    with pytest.raises(state_io.StateFileError) as e:
        state_io.parse(_break(cpl_store, change), "e.json")
    assert str(e.value).startswith("e.json: cpl.") and words in str(e.value), str(e.value)


def _sin(s):
    return s["sin800"]


SIN_BREAKS = {
    # central R parameters R900-R999 within +/-99999999 (CL 800 manual L7077-7080)
    "central R899": (lambda s: _sin(s)["central_r"].__setitem__("899", 1.0), "central_r.899"),
    "central R1000": (lambda s: _sin(s)["central_r"].__setitem__("1000", 1.0), "central_r.1000"),
    "central R written R950": (lambda s: _sin(s)["central_r"].__setitem__("R950", 1.0), "900 .. 999"),
    "central R beyond the R range": (lambda s: _sin(s)["central_r"].__setitem__("950", 1e8), "beyond the R parameter range +/-99999999"),
    "central R true": (lambda s: _sin(s)["central_r"].__setitem__("950", True), "must be a number"),
    "central R NaN": (lambda s: _sin(s)["central_r"].__setitem__("950", float("nan")), "finite"),
    # the MIB: addresses 0-499 of the 850/880
    "a MIB of 100,000 values": (lambda s: _sin(s)["mib"].extend([0.0] * 99500), "mib = [0.0, 0.0"),
    "a MIB of 499 values": (lambda s: _sin(s)["mib"].pop(), "must have 500 entries"),
    "a MIB value that is text": (lambda s: _sin(s)["mib"].__setitem__(3, "7"), "mib[3]"),
    # tool offsets P0..P15, zero offsets one value per axis, rotations of groups 1-4 / 1-2
    "a tool offset of 15 parameters": (lambda s: _sin(s)["to"]["0:1"].pop(), "must have 16 entries"),
    "a tool offset D0": (lambda s: _sin(s)["to"].__setitem__("0:0", [0.0] * 16), '"area:D"'),
    "a zero offset G58 coarse": (lambda s: _sin(s)["zo"].__setitem__("G58.coarse", [0.0] * 3), 'zo."G58.coarse"'),
    "DRF of two values, G54 of three": (lambda s: _sin(s)["zo"]["DRF"].pop(), "one value per axis"),
    "a zero offset of no values": (lambda s: _sin(s)["zo"].__setitem__("G57.fine", []), "at least one entry"),
    "a rotation of group 5": (lambda s: _sin(s)["rot"].__setitem__("settable:5", 1.0), 'rot."settable:5"'),
    "a programmable rotation 3": (lambda s: _sin(s)["rot"].__setitem__("programmable:3", 1.0), "programmable:3"),
    # machine and setting data: numbers at addresses
    "a machine data word that is a list": (lambda s: _sin(s)["nc_md"].__setitem__("2240", [1.0]), "nc_md.2240"),
    "a setting data bit pattern as text": (lambda s: _sin(s)["nc_sd"].__setitem__("5013", "00010010"),
                                           "must be a number"),
    "an area the NC has not": (lambda s: _sin(s).__setitem__("r", {}), "r = {}: unknown key"),
}


@pytest.mark.parametrize("what", list(SIN_BREAKS))
def test_a_sinumerik_store_entry_no_control_holds_is_refused(sin_store, what):
    change, words = SIN_BREAKS[what]
    with pytest.raises(state_io.StateFileError) as e:
        state_io.parse(_break(sin_store, change), "e.json")
    assert str(e.value).startswith("e.json: sin800: ") and words in str(e.value), str(e.value)


def test_a_whole_number_where_the_control_holds_a_floating_point_one_is_imported_as_one(cpl_store, sin_store):
    """An edited 5 in a DOUBLE, a ZS row, a central R parameter reads back as 5.0, as a run writes it; an
    INTEGER stays an integer."""
    def edit(s):
        s["cpl.perm"]["@_R(2)"] = 5
        _zs(s)["rows"]["G56"] = [1, 2, 3]
        s["cpl.tdb"]["1,1"]["9"] = 5
    content = state_io.parse(_break(cpl_store, edit), "e.json")
    assert content["cpl.perm"]["@_R(2)"].__class__ is float
    assert [v.__class__ for v in content["cpl.zs"]["V1"]["rows"]["G56"]] == [float] * 3
    assert content["cpl.tdb"]["1,1"]["9"].__class__ is int
    content = state_io.parse(_break(sin_store, lambda s: _sin(s)["central_r"].__setitem__("950", 2)), "e.json")
    assert content["sin800"]["central_r"]["950"].__class__ is float


def test_the_rules_agree_with_the_controls_own_limits():
    """The schema's limits are those the dialects enforce when a program writes."""
    assert store_schema.MIB_SIZE == max(ncdata.MIB_TOP.values()) + 1
    assert store_schema.R_LIMIT == ncdata.R_LIMIT
    assert tuple(map(int, store_schema.TDA_STRINGS)) == tools.STRING_FIELDS
    assert list(store_schema.TDA_FIELDS) == list(range(3, controller.TDA_FIELDS + 1))
    assert sections.ZS_ROWS == controller.ZS_ROWS
    assert store_schema.ZS_TABLE.fields[0].type.max_len == zsfile.MAX_COLUMNS
    assert {f.name for f in store_schema.SIN800.fields} == set(ncdata.PERSISTED)


def test_a_refused_file_leaves_the_store_exactly_as_it_was(tmp_path, sin_store):
    (tmp_path / "machine.toml").write_text((EXAMPLES / "sin800" / "machine.toml").read_text())
    (tmp_path / "good.json").write_text(_file(sin_store))
    assert ncvm("state", "import", "good.json", "--state", "s", cwd=tmp_path).returncode == 0
    before = (tmp_path / "s" / "store.sqlite").read_bytes()
    (tmp_path / "bad.json").write_text(_break(sin_store, lambda s: _sin(s)["mib"].extend([0.0] * 99500)))
    out = ncvm("state", "import", "bad.json", "--state", "s", cwd=tmp_path)
    assert out.returncode == 2 and out.stderr.startswith("ncvm: error: bad.json: sin800: mib = ")
    assert (tmp_path / "s" / "store.sqlite").read_bytes() == before
    assert ncvm("state", "export", "-", "--state", "s", cwd=tmp_path).stdout == _file(sin_store)


def test_zero_offsets_kept_for_a_machine_of_other_axes_are_refused_at_the_run(tmp_path, sin_store):
    """A file of consistent zero offsets of two values is one a two-axis SINUMERIK writes; on this three-axis
    machine the run refuses it (exit 2) naming the offset, rather than shift the wrong axes or fail inside."""
    (tmp_path / "machine.toml").write_text((EXAMPLES / "sin800" / "machine.toml").read_text())
    (tmp_path / "r.mpf").write_text(SIN_READ)
    two = _break(sin_store, lambda s: _sin(s).__setitem__("zo", {k: v[:2] for k, v in _sin(s)["zo"].items()}))
    (tmp_path / "two.json").write_text(two)
    assert ncvm("state", "import", "two.json", "--state", "s", cwd=tmp_path).returncode == 0
    out = ncvm("run", "r.mpf", "--state", "s", cwd=tmp_path)
    assert out.returncode == 2 and "holds zero offset DRF with 2 values, this machine has 3 axes" in out.stderr
    assert "internal error" not in out.stderr


def _round_trip(folder: Path, programs: list[str], reader: str | None) -> None:
    """Run ``programs`` on one store, export, import into a fresh store, export again: the same bytes, and
    ``reader`` gives the same variables on both stores."""
    for program in programs:
        ncvm("run", program, "--state", "s", cwd=folder)  # programs that stop with an error keep what they wrote
    first = ncvm("state", "export", "first.json", "--state", "s", cwd=folder)
    assert first.returncode == 0, first.stderr
    imported = ncvm("state", "import", "first.json", "--state", "t", cwd=folder)
    assert imported.returncode == 0, imported.stderr
    assert ncvm("state", "export", "second.json", "--state", "t", cwd=folder).returncode == 0
    assert (folder / "first.json").read_bytes() == (folder / "second.json").read_bytes()
    if reader:
        runs = [ncvm("run", reader, "--state", s, "--json", cwd=folder) for s in ("s", "t")]
        assert runs[0].returncode == runs[1].returncode == 0, runs[1].stderr
        assert json.loads(runs[0].stdout)["variables"] == json.loads(runs[1].stdout)["variables"]


@pytest.mark.parametrize("dialect", ["cpl", "sin800", "cl800", "din", "sympas"])
def test_export_import_export_of_real_runs_is_byte_identical_in_every_dialect(tmp_path, dialect):
    """The examples of each dialect, and for CPL and SINUMERIK 800 a program that writes every store kind."""
    folder = tmp_path / dialect
    shutil.copytree(EXAMPLES / dialect, folder)
    skip = {".toml", ".txt", ".keys", ".dat"}
    programs = sorted(p.name for p in folder.iterdir() if p.is_file() and p.suffix not in skip)
    reader = None
    if dialect == "cpl":
        (folder / "files").mkdir(exist_ok=True)
        with (folder / "files" / "anwperm.dat").open("a") as f:
            f.write(CPL_DECLARATIONS)
        with (folder / "machine.toml").open("a") as f:
            f.write('tool_database = [{sector = 1, place = 1, fields = {"9" = 0}}, '
                    '{sector = 2, place = 3, fields = {"8" = ""}}]\n')
        (folder / "w.cpl").write_text(CPL_WRITE)
        (folder / "r.cpl").write_text(CPL_READ)
        programs, reader = [*programs, "w.cpl"], "r.cpl"
    if dialect == "sin800":
        (folder / "w.mpf").write_text(SIN_WRITE)
        (folder / "r.mpf").write_text(SIN_READ)
        programs, reader = [*programs, "w.mpf"], "r.mpf"
    _round_trip(folder, programs, reader)
