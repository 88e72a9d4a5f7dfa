"""``ncvm check`` warns (NC008) at a literal T word whose tool the machine file lacks when M6 changes to it
-- where the run stops with NC008 -- in cpl, din and sin800, and only there (nc/toolcheck.py: the kernel's
own rule). Issue 14 §5: a clean check means the run will not stop on what the machine lacks."""

from __future__ import annotations

from pathlib import Path

import pytest

from ncvm.api import check

AXES = '[[axis]]\nname = "X"\n[[axis]]\nname = "Y"\n[[axis]]\nname = "Z"\n'
TOOL2 = AXES + "[[tool]]\nnumber = 2\nlength = 10.0\nradius = 1.0\n"
BLOCKS = {  # (name, head, the T/M6 blocks formatted in, tail)
    "cpl": ("p.cpl", "", "N90 M30\n"),
    "din": ("p.ngc", "", "M2\n"),
    "sin800": ("p.mpf", "%MPF1\n", "N90 M30\n"),
}


def _codes(tmp_path: Path, dialect: str, body: str):
    name, head, tail = BLOCKS[dialect]
    (tmp_path / "machine.toml").write_text(TOOL2)
    prog = tmp_path / name
    prog.write_text(head + body + tail)
    return [(d.code, d.severity, d.span.line) for d in check(prog, dialect=dialect, machine=tmp_path / "machine.toml")]


@pytest.mark.parametrize("dialect", sorted(BLOCKS))
def test_t_word_of_a_missing_tool_changed_by_m6_is_warned_once(tmp_path, dialect):
    head = 1 if dialect == "sin800" else 0
    body = "N10 T1\nN20 M6\nN30 T1 M6\nN40 T2 M6\n"
    assert _codes(tmp_path, dialect, body) == [("NC008", "warning", head + 1)]


@pytest.mark.parametrize("dialect", sorted(BLOCKS))
def test_tools_the_machine_has_t0_and_a_t_without_m6_are_clean(tmp_path, dialect):
    assert _codes(tmp_path, dialect, "N10 T2 M6\nN20 T0 M6\nN30 T7\n") == []
