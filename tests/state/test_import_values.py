"""Values ``ncvm state import`` and the machine file refuse because no control holds them: MIB values
beyond the R range (CL 800 manual L7077-7080), CPL strings outside the control's one-byte characters (CPL
manual A.5, L4631; NUL is no value, L758-762), and a key a hand-edited file gives twice. Each runs the
real ``ncvm`` in a process."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

NCVM = [sys.executable, "-m", "ncvm"]
EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def _ncvm(*args, cwd):
    return subprocess.run([*NCVM, *args], cwd=cwd, capture_output=True, text=True, timeout=120,
                          stdin=subprocess.DEVNULL)


def _import_text(tmp_path: Path, text: str):
    (tmp_path / "edited.json").write_text(text, encoding="utf-8")
    return _ncvm("state", "import", "--state", "st", "edited.json", cwd=tmp_path)


def _import(tmp_path: Path, store: dict):
    return _import_text(tmp_path, json.dumps({"format": "ncvm-state", "version": 1, "store": store}))


def _sin_machine(tmp_path: Path, mib_line: str) -> None:
    text = (EXAMPLES / "sin800" / "machine.toml").read_text()
    (tmp_path / "machine.toml").write_text(text.replace("[sin800]\n", f"[sin800]\n{mib_line}\n", 1))
    (tmp_path / "mib.mpf").write_text("%MPF1\nN10 @211 R1 K7\nN20 M30\n")


def test_mib_at_the_ends_of_the_r_range_is_imported_and_read_back(tmp_path):
    """+/-99999999 are R values (L7079): a MIB holding them imports, and @211 reads them into R."""
    mib = [0.0] * 500
    mib[7], mib[8] = -99999999.0, 99999999.0
    assert _import(tmp_path, {"sin800": {"mib": mib}}).returncode == 0
    _sin_machine(tmp_path, "")
    run = _ncvm("run", "mib.mpf", "--state", "st", "--json", cwd=tmp_path)
    assert json.loads(run.stdout)["variables"]["R1"] == -99999999.0, run.stderr


def test_a_machine_file_mib_seed_beyond_the_r_range_is_refused(tmp_path):
    """The same rule holds for ``[sin800] mib`` of the machine file: 1e9 at address 7 is no R value, and
    the run stops as a usage error naming the key (exit 2) before it reads it."""
    _sin_machine(tmp_path, 'mib = {"7" = 1e9}')
    run = _ncvm("run", "mib.mpf", cwd=tmp_path)
    assert run.returncode == 2, run.stdout + run.stderr
    assert "sin800.mib.7" in run.stderr and "-99999999 to 99999999" in run.stderr, run.stderr


def _perm_char(tmp_path: Path, text: str):
    return _import(tmp_path, {"cpl.perm": {"@S": {"type": "CHAR", "dims": [8], "value": text}}})


def test_a_char_variable_of_one_byte_characters_is_imported_and_one_beyond_is_refused(tmp_path):
    """Codes 1..255 are the control's one-byte characters: the ASCII set of CPL manual A.5 (tab, CR, LF,
    DEL) and 128..255, which INKEY gives (L4631) and CHR$ makes; U+0100, the first code beyond a byte,
    and NUL (no value, L758-762) are refused naming the entry and the character."""
    ok = _perm_char(tmp_path, "\x01\t\r\n\x7f\x80\xe9\xff")
    assert ok.returncode == 0, ok.stderr
    shown = _ncvm("state", "show", "--state", "st", "--json", cwd=tmp_path)
    assert json.loads(shown.stdout)["store"]["cpl.perm"]["@S"]["value"] == "\x01\t\r\n\x7f\x80\xe9\xff"
    for text, bad in (("AB\u0100", "character 3 (U+0100)"), ("A\x00B", "character 2 (U+0000)")):
        proc = _perm_char(tmp_path, text)
        assert proc.returncode == 2 and "edited.json: cpl.perm: \"@S\".value" in proc.stderr, proc.stderr
        assert bad in proc.stderr, proc.stderr


def _cpl_folder(tmp_path: Path) -> None:
    """A CPL machine folder declaring the permanent CHAR @S(8), with one tool database record."""
    (tmp_path / "files").mkdir()
    (tmp_path / "files" / "anwperm.dat").write_text("DEF CHAR @S(8) ;label\n")
    (tmp_path / "machine.toml").write_text((EXAMPLES / "cpl" / "machine.toml").read_text()
                                           + 'tool_database = [{sector = 1, place = 1, fields = {"8" = ""}}]\n')


def test_what_a_run_writes_beyond_ascii_exports_and_imports_byte_identical(tmp_path):
    """CHR$(233) and a Latin-1 literal (the program file holds byte E9, read as the control reads it) go
    into the permanent CHAR @S$ and TDA string field 8 (L1895-1966); ``ncvm state export`` of that store
    imports into a fresh state, whose export is the same bytes, and the next run reads the same text."""
    _cpl_folder(tmp_path)
    (tmp_path / "w.cpl").write_bytes(b'10 @S$ = "F" + CHR$(233) + "\xe9"\n20 TDA(1,1,8)="Fr\xe4ser"\nM30\n')
    (tmp_path / "r.cpl").write_text("10 S$ = @S$ : T$ = TDA(1,1,8) : C% = ASC(MID$(S$,2,1))\nM30\n")
    run = _ncvm("run", "w.cpl", "--state", "st", cwd=tmp_path)
    assert run.returncode == 0, run.stderr
    assert _ncvm("state", "export", "--state", "st", "one.json", cwd=tmp_path).returncode == 0
    again = _ncvm("state", "import", "--state", "st2", "one.json", cwd=tmp_path)
    assert again.returncode == 0, again.stderr
    assert _ncvm("state", "export", "--state", "st2", "two.json", cwd=tmp_path).returncode == 0
    assert (tmp_path / "one.json").read_bytes() == (tmp_path / "two.json").read_bytes()
    read = _ncvm("run", "r.cpl", "--state", "st2", "--json", cwd=tmp_path)
    variables = json.loads(read.stdout)["variables"]
    assert (variables["S$"], variables["T$"], variables["C%"]) == ("F\xe9\xe9", "Fr\xe4ser", 233), read.stderr


@pytest.mark.parametrize("stmt,code", [('@S$ = "A" + CHR$(0)', "CPL033"), ('TDA(1,1,8) = CHR$(0) + "B"', "CPL023")])
def test_a_run_writing_chr0_into_a_permanent_string_is_refused(tmp_path, stmt, code):
    """CHR$(0) is NUL, no value (L758-762), and a permanent variable cannot be deleted (L769): a run that
    writes it into the permanent CHAR @S$ or a TDA string field stops with the error, and the store keeps
    the text it had (which ``ncvm state import`` would refuse, as above)."""
    _cpl_folder(tmp_path)
    (tmp_path / "w.cpl").write_text(f'10 @S$ = "KEPT" : TDA(1,1,8) = "KEPT"\n20 {stmt}\nM30\n')
    run = _ncvm("run", "w.cpl", "--state", "st", cwd=tmp_path)
    assert run.returncode == 1 and f"w.cpl:2:4: error {code}:" in run.stderr and "CHR$(0)" in run.stderr, run.stderr
    store = json.loads(_ncvm("state", "show", "--state", "st", "--json", cwd=tmp_path).stdout)["store"]
    assert store["cpl.perm"]["@S"]["value"] == "KEPT" and store["cpl.tdb"]["1,1"]["8"] == "KEPT", store


def test_a_key_given_twice_deep_in_a_record_or_at_the_top_is_refused(tmp_path):
    """Twice inside a TDA record (field 9) and twice at the top (two "store" objects, the first lost): each
    is refused with exit 2 naming the key, and the store stays empty (nothing half imported)."""
    record = ('{"format": "ncvm-state", "version": 1, "store": {"cpl.tdb": {"1,1": {"9": 5, "10": 1, '
              '"9": 6}}}}')
    proc = _import_text(tmp_path, record)
    assert proc.returncode == 2 and 'edited.json: "9": key given twice' in proc.stderr, proc.stderr
    top = ('{"format": "ncvm-state", "version": 1, "store": {"cpl.perm": {"@1": 1}}, '
           '"store": {"cpl.perm": {"@2": 2}}}')
    proc = _import_text(tmp_path, top)
    assert proc.returncode == 2 and 'edited.json: "store": key given twice' in proc.stderr, proc.stderr
    shown = _ncvm("state", "show", "--state", "st", "--json", cwd=tmp_path)
    assert json.loads(shown.stdout)["store"] == {}, shown.stdout
