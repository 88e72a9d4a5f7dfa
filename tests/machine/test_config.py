"""Machine files: the built-in mill, the examples, and errors that name the key at fault."""

from __future__ import annotations

from pathlib import Path

import pytest

from ncvm.diagnostics import UsageError
from ncvm.machine.config import load_machine
from ncvm.machine.scenario import InterfaceBit, ProbeSwitch

EXAMPLES = Path(__file__).parents[2] / "examples" / "machines"


def write(tmp_path: Path, text: str) -> Path:
    p = tmp_path / "m.toml"
    p.write_text(text)
    return p


AXIS = '[[axis]]\nname = "X"\n'


def test_builtin_default_is_a_three_axis_mill():
    m = load_machine(None)
    assert m.axis_names == ("X", "Y", "Z")
    assert (m.axes[0].min, m.axes[0].max) == (-500.0, 500.0)
    assert m.axes[2].rapid == 8000.0 and m.axes[2].accel == 800.0
    assert m.tools[1].length == 50.0 and m.tools[2].radius == 3.0


@pytest.mark.parametrize("path", sorted(EXAMPLES.glob("*.toml")), ids=lambda p: p.name)
def test_example_machines_load(path):
    m = load_machine(path)
    assert m.axes and m.program_path[0].is_relative_to(path.parent)


def test_paths_are_relative_to_the_machine_file(tmp_path):
    m = load_machine(write(tmp_path, AXIS + '[paths]\nprogram_path = ["progs", "lib"]\nfile_root = "data"\n'))
    assert m.program_path == [tmp_path / "progs", tmp_path / "lib"]
    assert m.file_root == tmp_path / "data"


def test_offsets_start_position_and_scenario(tmp_path):
    m = load_machine(write(tmp_path, '[machine]\nstart_position = [1, 2]\n' + AXIS + '[[axis]]\nname = "Y"\n'
                           '[offsets]\nG55 = [10, -5]\n'
                           '[[scenario]]\ntime = 3\nkind = "input"\naddress = "E1.0"\nvalue = true\n'
                           '[[scenario]]\ntime = 1.5\nkind = "probe"\n'))
    assert m.start_position == [1.0, 2.0]
    assert m.offset("G55") == [10.0, -5.0] and m.offset("G56") == [0.0, 0.0]
    assert [(e.time, e.kind) for e in m.scenario] == [(1.5, "probe"), (3.0, "input")]
    assert m.scenario[1] == InterfaceBit(3.0, "E1.0", True)


# malformed files, key by key: tests/machine/test_machine_schema.py


def test_invalid_toml_and_missing_file(tmp_path):
    with pytest.raises(UsageError, match="not valid TOML"):
        load_machine(write(tmp_path, "[[axis]\nname = 'X'\n"))
    with pytest.raises(UsageError, match="cannot read machine file"):
        load_machine(tmp_path / "absent.toml")
    (tmp_path / "latin1.toml").write_bytes(b'[machine]\nname = "Fr\xe4se"\n')
    with pytest.raises(UsageError, match=r"latin1\.toml: not valid TOML: not UTF-8 text \(byte 20\)"):
        load_machine(tmp_path / "latin1.toml")


def test_scenario_file_loads_sorted_and_names_bad_keys(tmp_path):
    from ncvm.machine.config import load_scenario

    p = tmp_path / "s.toml"
    p.write_text('[[scenario]]\ntime = 4\nkind = "input"\naddress = "E1.0"\nvalue = true\n'
                 '[[scenario]]\ntime = 0.5\nkind = "probe"\nX = 12.5\n')
    events = load_scenario(p, ("X",))
    assert events == [ProbeSwitch(0.5, {"X": 12.5}), InterfaceBit(4.0, "E1.0", True)]
    p.write_text('[[scenario]]\ntime = 1\nkind = "input"\n[axis]\nname = "X"\n')
    with pytest.raises(UsageError, match="scenario file error: axis = .*: unknown key"):
        load_scenario(p)
    p.write_text('[[scenario]]\nkind = "input"\n')
    with pytest.raises(UsageError, match=r"scenario file error: scenario\[0\]\.time: is missing"):
        load_scenario(p)
