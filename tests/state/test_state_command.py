"""``ncvm state show/reset/export/import``: the permanent store from the command line, in real processes
on real state directories (issue 17 item 7)."""

from __future__ import annotations

import json
import os
import pty
import struct
import subprocess
import sys
from pathlib import Path

import pytest

from ncvm.dialects.cpl import perm
from ncvm.dialects.sinumerik import ncdata
from ncvm.machine import state_io, store_schema
from ncvm.machine.state import StateLock

NCVM = [sys.executable, "-c", "from ncvm.cli import main; main()"]
DECLARATIONS = "DEF REAL @RW(2)\nDEF CHAR @TXT(10)\nDEF BOOL @B\nDEF INT @N(1,2)\n"
CPL = ('10 @1 = 42\n20 @_R(3) = 0.1\n30 @RW(1) = 0.1\n40 @TXT$ = "HALLO"\n50 @B? = TRUE\n'
       '60 @N%(1,2) = -7\nM30\n')
SIN = "%MPF1\nR950=R950+1.25\nM30\n"


def ncvm(*args, cwd, **kw) -> subprocess.CompletedProcess:
    return subprocess.run([*NCVM, *map(str, args)], capture_output=True, text=True, timeout=120, cwd=cwd, **kw)


@pytest.fixture
def work(tmp_path) -> Path:
    """A state directory that a CPL and a SINUMERIK run have written permanent data into."""
    (tmp_path / ".ncvm" / "files").mkdir(parents=True)
    (tmp_path / ".ncvm" / "files" / "wmhperm.dat").write_text(DECLARATIONS)
    (tmp_path / "p.cpl").write_text(CPL)
    (tmp_path / "p.mpf").write_text(SIN)
    for program in ("p.cpl", "p.mpf"):
        assert ncvm("run", program, cwd=tmp_path).returncode == 0
    return tmp_path


def exported(work: Path, name: str = "s.json") -> dict:
    out = ncvm("state", "export", name, cwd=work)
    assert out.returncode == 0, out.stderr
    return json.loads((work / name).read_text())


def test_show_lists_every_dialects_permanent_data(work):
    out = ncvm("state", "show", cwd=work)
    assert out.returncode == 0
    lines = out.stdout.splitlines()
    assert lines[0].startswith("cpl.perm: CPL permanent variables")
    for line in ("  @1 = 42", "  @_R(3) = 0.1", "  @RW REAL(2) = [null, 0.10000000149011612, null]",
                 '  @TXT CHAR(10) = "HALLO"', "  @B BOOL = true", "  @N INT(1,2) = [[null, null, null], [null, null, -7]]",
                 "  central_r:", "    950 = 1.25"):
        assert line in lines
    assert any(line.startswith("sin800: SINUMERIK 800") for line in lines)
    assert "ncvm: 7 entries in .ncvm/store.sqlite" in out.stderr


def test_export_import_round_trip_is_exact_binary32_and_strings(work):
    before = exported(work)
    real = before["store"]["cpl.perm"]["@RW"]["value"][1]
    assert real == struct.unpack("f", struct.pack("f", 0.1))[0] != 0.1  # the REAL as binary32, not 0.1
    assert ncvm("state", "reset", "--yes", cwd=work).returncode == 0
    assert exported(work, "empty.json")["store"] == {}
    out = ncvm("state", "import", "s.json", cwd=work)
    assert out.returncode == 0 and "imported 7 entries" in out.stderr
    assert (work / "s.json").read_bytes() == ncvm("state", "export", "-", cwd=work).stdout.encode()
    # a run after the import reads what the export held: @1 + 1 is 43, the REAL is still binary32
    (work / "q.cpl").write_text("10 @1 = @1 + 1\n20 @_R(4) = @RW(1)\nM30\n")
    assert ncvm("run", "q.cpl", cwd=work).returncode == 0
    after = exported(work, "after.json")["store"]["cpl.perm"]
    assert after["@1"] == 43 and after["@_R(4)"] == real and after["@TXT"]["value"] == "HALLO"


def test_show_and_export_of_a_state_directory_without_a_store_create_nothing(tmp_path):
    out = ncvm("state", "show", "--state", "none", cwd=tmp_path)
    assert out.returncode == 0 and "is empty" in out.stderr
    assert json.loads(ncvm("state", "export", "-", "--state", "none", cwd=tmp_path).stdout)["store"] == {}
    assert not (tmp_path / "none").exists()


@pytest.mark.parametrize(("text", "words"), [
    ("{not json", "bad.json:1:2: not JSON"),
    ('{"store": {}}', "not an ncvm state file"),
    ('{"format": "ncvm-state", "version": 2, "store": {}}', "version 2"),
    ('{"format": "ncvm-state", "version": 1, "store": {"cpl.perms": {}}}', "unknown namespace 'cpl.perms'"),
    ('{"format": "ncvm-state", "version": 1, "store": {"cpl.perm": {"@101": 1}}}', "@1..@100"),
    ('{"format": "ncvm-state", "version": 1, "store": {"cpl.perm": {"@1": 2147483648}}}', "not an INTEGER"),
    ('{"format": "ncvm-state", "version": 1, "store": {"cpl.perm": {"@1": "7"}}}', "not an INTEGER"),
    ('{"format": "ncvm-state", "version": 1, "store": {"cpl.perm": {"@_R(1)": true}}}', "must be a number"),
    ('{"format": "ncvm-state", "version": 1, "store": {"cpl.perm": {"@X": {"type": "REAL", "dims": [], '
     '"value": 0.1}}}}', 'cpl.perm: "@X".value = 0.1: is not a REAL (binary32) value'),
    ('{"format": "ncvm-state", "version": 1, "store": {"cpl.perm": {"@X": {"type": "CHAR", "dims": [3], '
     '"value": "ABCD"}}}}', "at most 3 characters"),
    ('{"format": "ncvm-state", "version": 1, "store": {"cpl.perm": {"@X": {"type": "INT", "dims": [2], '
     '"value": [1, 2]}}}}', "must have 3 entries"),
    ('{"format": "ncvm-state", "version": 1, "store": {"cpl.tdb": {"1-2": {}}}}', '"sector,place"'),
    ('{"format": "ncvm-state", "version": 1, "store": {"sin800": {"r": {}}}}', "r = {}: unknown key (known: nc_md"),
    ('{"format": "ncvm-state", "version": 1, "store": {"sin800": {"central_r": {"950": "x"}}}}', "must be a number"),
])
def test_import_refuses_a_bad_file_and_leaves_the_store_as_it_was(work, text, words):
    before = ncvm("state", "export", "-", cwd=work).stdout
    (work / "bad.json").write_text(text)
    out = ncvm("state", "import", "bad.json", cwd=work)
    assert out.returncode == 2
    assert words in out.stderr and out.stderr.startswith("ncvm: error: ") and "Traceback" not in out.stderr
    assert ncvm("state", "export", "-", cwd=work).stdout == before


def test_import_of_a_file_that_is_not_utf8_or_absent_is_a_usage_error(work):
    (work / "bin.json").write_bytes(b"\xff\xfe")
    assert "not UTF-8" in ncvm("state", "import", "bin.json", cwd=work).stderr
    out = ncvm("state", "import", "missing.json", cwd=work)
    assert out.returncode == 2 and "cannot read missing.json" in out.stderr


def test_import_and_reset_hold_the_lock_as_a_run_does(work):
    (work / "empty.json").write_text(state_io.document({}))
    with StateLock(work / ".ncvm"):  # as a run holds it
        for args in (("state", "import", "empty.json"), ("state", "reset", "--yes")):
            out = ncvm(*args, cwd=work)
            assert out.returncode == 2 and "is in use by another run" in out.stderr
        assert ncvm("state", "show", cwd=work).returncode == 0  # reading needs no lock
    assert "@1" in exported(work)["store"]["cpl.perm"]


def test_reset_without_a_terminal_and_without_yes_is_refused(work):
    out = ncvm("state", "reset", cwd=work, stdin=subprocess.DEVNULL)
    assert out.returncode == 2 and "confirm it at a terminal, or give --yes" in out.stderr
    assert exported(work)["store"]["cpl.perm"]["@1"] == 42


@pytest.mark.parametrize(("answer", "code", "left"), [("n", 1, 7), ("y", 0, 0)])
def test_reset_at_a_terminal_asks_first(work, answer, code, left):
    leader, follower = pty.openpty()
    try:
        proc = subprocess.Popen([*NCVM, "state", "reset"], cwd=work, stdin=follower, stdout=subprocess.PIPE,
                                stderr=follower, text=True)
        os.write(leader, f"{answer}\n".encode())
        assert proc.wait(timeout=120) == code
        seen = os.read(leader, 4096).decode()
    finally:
        os.close(leader)
        os.close(follower)
    assert "Clear the 7 entries of the permanent store" in seen
    assert sum(map(len, exported(work)["store"].values())) == left


def test_the_namespaces_are_those_the_dialects_keep():
    assert {perm.NS, "cpl.zs", "cpl.tc", "cpl.tdb", ncdata.NAMESPACE} == set(state_io.NAMESPACES)
    assert set(store_schema.STORE) == set(state_io.NAMESPACES)
    assert {f.name for f in store_schema.SIN800.fields} == set(ncdata.PERSISTED)


def test_export_never_writes_into_the_state_directory(work):
    out = ncvm("state", "export", ".ncvm/store.sqlite", cwd=work)
    assert out.returncode == 2 and "is inside the state directory .ncvm" in out.stderr
    assert ncvm("state", "show", cwd=work).returncode == 0  # the store is intact
    assert exported(work)["store"]["cpl.perm"]["@1"] == 42
