"""Values ``ncvm state import`` and the machine file refuse because no control holds them: MIB values
beyond the R range (CL 800 manual L7077-7080), CPL strings outside the control's 1-byte ASCII (CPL manual
L3749-3770), and a key a hand-edited file gives twice. Each runs the real ``ncvm`` in a process."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

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


def test_a_char_variable_of_ascii_controls_and_del_is_imported_and_one_beyond_is_refused(tmp_path):
    """Codes 1..127 are the control's ASCII set (CPL manual A.5): tab, CR, LF (CHR$(13) breaks PRN# lines)
    and DEL import; U+0080, the first code beyond it, is refused naming the entry and the character."""
    ok = _perm_char(tmp_path, "\x01\t\r\n\x1b~\x7f")
    assert ok.returncode == 0, ok.stderr
    shown = _ncvm("state", "show", "--state", "st", "--json", cwd=tmp_path)
    assert json.loads(shown.stdout)["store"]["cpl.perm"]["@S"]["value"] == "\x01\t\r\n\x1b~\x7f"
    proc = _perm_char(tmp_path, "AB\x80")
    assert proc.returncode == 2 and "edited.json: cpl.perm: \"@S\".value" in proc.stderr, proc.stderr
    assert "character 3 (U+0080)" in proc.stderr, proc.stderr


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
