"""Link tables kept from one run to the next (``<program>.I``, manual §2.3 L411-428, §6.1.1 L3851).

Each run below starts with an empty in-process cache, as a new ``ncvm run`` does: what is not linked
again was read from the ``.I`` files of the state directory.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from ncvm.api import run
from ncvm.dialects.cpl import linker
from ncvm.runtime.session import RunOptions

MAIN = "10 S = 0\n20 FOR I% = 1 TO 3\n30 CALL HOLE [I% * 10]\n40 NEXT I%\nM30\n"
HOLE = "N10 G0 X[P1] Y0\nN20 G1 Z-2 F100\nN30 G0 Z2\n"


def _fresh_run(folder: Path, state: Path) -> tuple[dict, int]:
    """A run as a new process makes it: (result, programs really linked)."""
    linker._CACHE.clear()
    before = linker.LINK_STATS["linked"]
    result, _ = run(folder / "main.cpl", options=RunOptions(state_dir=state))
    return result, linker.LINK_STATS["linked"] - before


@pytest.fixture
def programs(tmp_path):
    (tmp_path / "main.cpl").write_text(MAIN)
    (tmp_path / "HOLE").write_text(HOLE)
    return tmp_path


def test_unchanged_programs_are_not_linked_again_in_the_next_run(programs):
    state = programs / ".ncvm"
    first, linked = _fresh_run(programs, state)
    assert first["status"] == "ok", first["error"] and linked == 2
    assert sorted(p.name for p in (state / "link").iterdir()) == ["HOLE.I", "main.cpl.I"]
    second, linked = _fresh_run(programs, state)
    assert linked == 0
    assert second["position"] == first["position"] == {"X": 30.0, "Y": 0.0, "Z": 2.0}
    assert second["motion"] == first["motion"] and second["cycle_time_s"] == first["cycle_time_s"]


def test_a_changed_program_is_linked_again_and_only_it(programs):
    state = programs / ".ncvm"
    _fresh_run(programs, state)
    (programs / "HOLE").write_text(HOLE.replace("Z-2", "Z-5"))
    result, linked = _fresh_run(programs, state)
    assert linked == 1
    assert result["motion"]["bounds"]["Z"][0] == -5.0


def test_a_damaged_link_table_is_made_anew(programs):
    state = programs / ".ncvm"
    _fresh_run(programs, state)
    (state / "link" / "HOLE.I").write_bytes(b"\x80\x04 not a link table")
    result, linked = _fresh_run(programs, state)
    assert result["status"] == "ok", result["error"]
    assert linked == 1
    assert _fresh_run(programs, state)[1] == 0  # and written again


def test_no_link_tables_where_a_cpl_program_could_write_them(programs):
    """A state directory inside the file root: a program could put code there, so tables are never kept."""
    axes = "".join(f'[[axis]]\nname = "{a}"\n' for a in "XYZ")
    (programs / "machine.toml").write_text(axes + '[paths]\nfile_root = "."\n')
    from ncvm.machine.config import load_machine

    machine = load_machine(programs / "machine.toml")
    linker._CACHE.clear()
    result, _ = run(programs / "main.cpl", machine=machine, options=RunOptions(state_dir=programs / ".ncvm"))
    assert result["status"] == "ok", result["error"]
    assert not (programs / ".ncvm" / "link").exists()
