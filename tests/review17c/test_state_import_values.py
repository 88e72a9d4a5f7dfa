"""Review of ``ncvm state import`` after its schema fix (issue 17, item 7).

Issue 17 asks for "``ncvm state export/import FILE.json``" of "permanent variables, R parameters, tool and
offset tables as the store holds them". An import must refuse what no control could hold; these tests show
values the import still takes and the next run then reads. Each runs the real ``ncvm`` in a process.
"""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

NCVM = [sys.executable, "-m", "ncvm"]
EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def _ncvm(*args, cwd):
    return subprocess.run([*NCVM, *args], cwd=cwd, capture_output=True, text=True, timeout=120)


def _import(tmp_path: Path, store: dict):
    path = tmp_path / "edited.json"
    path.write_text(json.dumps({"format": "ncvm-state", "version": 1, "store": store}, ensure_ascii=False),
                    encoding="utf-8")
    return _ncvm("state", "import", "--state", "st", "edited.json", cwd=tmp_path)


def _refused(proc, entry: str):
    assert proc.returncode == 2, f"imported what the control cannot hold: {proc.stderr}"
    assert "edited.json:" in proc.stderr and entry in proc.stderr, proc.stderr


@pytest.mark.parametrize("text", ["é😀€", "a\x00\n"], ids=["non-ascii", "nul-newline"])
def test_cpl_char_variable_outside_the_controls_character_set_is_refused(tmp_path, text):
    """A CPL CHARACTER element is one byte of the ASCII set (strings compare "by ASCII code", CPL manual
    L3749-3770; [REC] 1 byte per character). An edited ``@S`` of emoji or a NUL is imported, and the next run
    prints it: a value the control could not hold, read by a later run (issue 17: the store "as the store
    holds them")."""
    (tmp_path / "machine.toml").write_text((EXAMPLES / "cpl" / "machine.toml").read_text())  # file_root = "files"
    files = tmp_path / "files"
    files.mkdir()
    (files / "anwperm.dat").write_text("DEF CHAR @S(3) ;label\n")
    (tmp_path / "show.cpl").write_text('10 PRN#(0,"L=",@S$)\nM30\n')
    proc = _import(tmp_path, {"cpl.perm": {"@S": {"type": "CHAR", "dims": [3], "value": text}}})
    if proc.returncode == 0:  # show what the next run makes of it
        run = _ncvm("run", "show.cpl", "--state", "st", cwd=tmp_path)
        pytest.fail(f"imported; the next run printed {run.stdout!r} {run.stderr!r}")
    _refused(proc, "@S")


def test_cpl_tool_database_string_field_beyond_one_byte_is_refused(tmp_path):
    """TDA string fields 8 and 49 hold at most 31 one-byte characters of the control (manual §4.5,
    L1895-1966; docs/decisions.md, "Characters a permanent string holds"): 31 euro signs are no byte each
    and no TDA field the control writes holds them."""
    _refused(_import(tmp_path, {"cpl.tdb": {"1,1": {"8": "€" * 31}}}), "1,1")


def test_sinumerik_mib_beyond_the_r_range_is_refused(tmp_path):
    """MIB(a) = x (@212, CL 800 manual L2295-2301) stores an R value, and every R value lies within
    +/-99999999 (L7077-7080); the import checks that range for central R900-R999 only and takes a MIB of
    1e308 (docs/decisions.md lets offsets, angles and machine data be any double, but names no MIB)."""
    _refused(_import(tmp_path, {"sin800": {"mib": [1e308] * 500}}), "mib")


def test_mib_beyond_the_r_range_is_not_read_by_the_next_run(tmp_path):
    """The silent case: an imported MIB value of 1e308 is read by ``@211 R1 K7`` (v := MIB[a], CL 800 manual
    L2287-2293) into R1, a value outside the R range +/-99999999 no control holds; the run reports no error
    at the read (only a later overflow stops it)."""
    machine = EXAMPLES / "sin800" / "machine.toml"
    (tmp_path / "machine.toml").write_text(machine.read_text())
    (tmp_path / "mib.mpf").write_text("%MPF1\nN10 @211 R1 K7\nN20 M30\n")
    _import(tmp_path, {"sin800": {"mib": [1e308] * 500}})
    run = _ncvm("run", "mib.mpf", "--state", "st", "--json", cwd=tmp_path)
    result = json.loads(run.stdout)
    r1 = result["variables"].get("R1")
    assert r1 is None or abs(r1) <= 99999999, f"the next run read R1 = {r1} from the imported MIB"


def test_a_key_given_twice_in_an_edited_file_is_refused_not_dropped(tmp_path):
    """Editing the export by hand, a maintenance engineer copies a line and forgets to renumber it: ``@1``
    given twice. The import keeps the last and drops the first without a word (JSON readers do), so a value
    the file holds is lost silently; an import is a restore of "permanent variables, R parameters, tool and
    offset tables" (issue 17, item 7) and must say ``file: entry: reason`` (exit 2) instead."""
    path = tmp_path / "edited.json"
    path.write_text('{"format": "ncvm-state", "version": 1, "store": {"cpl.perm": {"@1": 12, "@1": 34}}}')
    _refused(_ncvm("state", "import", "--state", "st", "edited.json", cwd=tmp_path), "@1")
