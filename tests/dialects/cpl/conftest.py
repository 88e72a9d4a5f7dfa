"""Machines for the chapter 4 tests: the manual's example configuration of page 4-5 (CPL manual §4.2, L1256-1337)."""

from __future__ import annotations

from pathlib import Path

import pytest

from ncvm.machine.config import machine_from_dict

#: physical axes 1..8: X Y Z on channel 1, X2 Y2 Z2 on channel 2, U_CH1 asynchronous, A (rotary) on channel 3
REFERENCE_AXES = [
    {"name": "X", "channel": 1}, {"name": "Y", "channel": 1}, {"name": "Z", "channel": 1},
    {"name": "X2", "channel": 2, "position": 12.5}, {"name": "Y2", "channel": 2, "position": -7.0},
    {"name": "Z2", "channel": 2, "position": 33.0}, {"name": "U_CH1", "channel": 0, "position": 4.0},
    {"name": "A", "channel": 3, "type": "rotary", "position": 90.0, "lag": 0.5},
]


def reference(tmp_path: Path, channel: int = 1, cpl: dict | None = None, **extra):
    """The reference configuration seen from ``channel``: the NC kernel drives that channel's axes."""
    own = [a for a in REFERENCE_AXES if a["channel"] == channel]
    axes = [{"name": a["name"], **({"kind": "rotary"} if a.get("type") == "rotary" else {})} for a in own]
    axes_cfg = []
    for a in REFERENCE_AXES:
        a = dict(a)
        if a["channel"] == channel:
            a.pop("position", None)
        axes_cfg.append(a)
    section = {"channel": channel, "axes": axes_cfg}
    section.update(cpl or {})
    data = {"axis": axes, "paths": {"program_path": ["."], "file_root": "files"}, "cpl": section}
    data.update(extra)
    return machine_from_dict(data, "<test>", tmp_path)


@pytest.fixture(name="reference")
def reference_fixture(tmp_path: Path):
    """reference(channel=1, cpl=None, **machine_tables) -> the reference machine in tmp_path."""
    return lambda channel=1, cpl=None, **extra: reference(tmp_path, channel, cpl, **extra)


@pytest.fixture
def run(run_text, reference):
    """run(text, channel=1, **machine) -> the result of the CPL program ``text`` on the reference machine."""
    return lambda text, channel=1, **kw: run_text(text, name="p.cpl", machine=reference(channel, **kw))


@pytest.fixture
def generated(tmp_path: Path):
    """generated(text) -> the Python the code generator writes for the CPL program ``text`` (checked without
    errors) on the reference machine."""
    from ncvm.dialects.cpl import codegen
    from ncvm.dialects.cpl.checker import check
    from ncvm.dialects.cpl.linker import link

    def make(text: str) -> str:
        path = tmp_path / "p.cpl"
        path.write_text(text)
        ln = link(str(path), text, reference(tmp_path)).units[str(path)]
        types, diags = check(ln)
        assert not diags
        return codegen.generate(ln, types)[0].text

    return make
