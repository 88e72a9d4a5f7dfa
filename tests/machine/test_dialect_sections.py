"""The machine file has one section per dialect of the registry, and a dialect's options dataclass is its
section, checked and filled in by machine/config.py."""

from __future__ import annotations

import dataclasses
import re

import pytest

from ncvm.diagnostics import UsageError
from ncvm.dialects import REGISTRY
from ncvm.dialects.cpl.options import Options as CplOptions
from ncvm.dialects.sinumerik.cl800 import Options, options
from ncvm.dialects.sinumerik.options import Options as Sin800Options
from ncvm.dialects.sinumerik.options import options as sin800_options
from ncvm.dialects.sympas.options import Options as SympasOptions
from ncvm.dialects.sympas.options import sympas_config
from ncvm.machine.config import dialect_options
from ncvm.machine.model import Axis, Machine
from ncvm.machine.schema import NO_DEFAULT, Said
from ncvm.machine.sections import DIALECT_SECTIONS, SECTIONS
from ncvm.machine.spec import MACHINE_FILE, section_defaults


def test_one_section_per_dialect_of_the_registry():
    assert sorted(f.name for f in DIALECT_SECTIONS) == sorted(REGISTRY)
    assert set(SECTIONS) <= {f.name for f in MACHINE_FILE.fields}


def test_the_cl800_options_are_its_section():
    assert {f.name: f.default for f in dataclasses.fields(Options)} == section_defaults("cl800")
    m = Machine()
    assert options(m) == Options()
    m.sections["cl800"] = {"control": "810", "strict": True}
    assert options(m) == Options(strict=True, control="810")


@pytest.mark.parametrize("section, message", [
    ({"stict": True}, "cl800.stict = true: unknown key (known: strict, control)"),
    ({"strict": 1}, "cl800.strict = 1: must be true or false"),
    ({"control": "999"}, 'cl800.control = "999": must be one of "810", "820", "850", "880"'),
])
def test_a_bad_section_built_in_python_is_refused_as_a_machine_file_is(section, message):
    with pytest.raises(UsageError, match=re.escape("machine file error: " + message)):
        dialect_options(Options, {"cl800": section}, "cl800")


def _declared(cls) -> dict:
    """Field name -> default of an options dataclass (a default factory called)."""
    return {f.name: f.default_factory() if f.default_factory is not dataclasses.MISSING else f.default
            for f in dataclasses.fields(cls)}


@pytest.mark.parametrize("dialect, cls", [("cpl", CplOptions), ("sin800", Sin800Options), ("sympas", SympasOptions)])
def test_each_options_dataclass_is_its_section(dialect, cls):
    """One field per key, with the documented default; a default the schema says in words (``Said``) or
    leaves to the keys of a table (``NO_DEFAULT``) is the dialect's to fill in."""
    declared = _declared(cls)
    documented = section_defaults(dialect)
    assert set(declared) == set(documented)
    for key, default in documented.items():
        if not isinstance(default, Said) and default is not NO_DEFAULT:
            assert declared[key] == default, key


def test_the_sympas_options_fill_in_the_axis_names_and_the_tables():
    m = Machine()
    m.axes = [Axis("X"), Axis("Y")]
    m.sections["sympas"] = {"axst_bits": {"homed": 20}, "busy_move": "override"}
    opts = sympas_config(m)
    assert opts.axis_names == ["A1", "A2"] and opts.busy_move == "override"
    assert opts.axst_bits["homed"] == 20 and opts.axst_bits["eo"] == 4 and opts.ssf_codes["write_ci"] == 1
    m.sections["sympas"] = {"axis_names": ["P", "Q", "R"]}
    with pytest.raises(UsageError, match=re.escape('sympas.axis_names = ["P", "Q", "R"]: must give 2 values')):
        sympas_config(m)


def test_the_sin800_options_are_checked_with_the_machine_axes():
    m = Machine()
    m.axes = [Axis("X"), Axis("Y")]
    m.sections["sin800"] = {"zero_offsets": {"G54": [1.0, 2.0]}, "decode_ahead": 2}
    opts = sin800_options(m)
    assert opts.zero_offsets == {"G54": [1.0, 2.0]} and opts.decode_ahead == 2 and opts.control == "880"
    m.sections["sin800"] = {"zero_offsets": {"G54": [1.0, 2.0, 3.0]}}
    with pytest.raises(UsageError, match=re.escape("machine file error: sin800.zero_offsets.G54 = [1.0, 2.0, 3.0]: "
                                                   "must give 2 values, one per axis (X, Y)")):
        sin800_options(m)


@pytest.mark.parametrize("dialect", sorted(SECTIONS))
@pytest.mark.parametrize("axes", [(), ("X", "Y", "Z")])
def test_a_section_left_out_is_valid_so_the_options_of_a_machine_without_it_need_no_check(dialect, axes):
    """dialect_options takes the declared defaults for a machine without the dialect's section, unchecked
    (issue 18: the schema is not imported at start-up): that is right only while a section left out is valid."""
    from ncvm.machine.schema import Ctx, validate

    validate(SECTIONS[dialect], {}, Ctx(axes, tuple((-1.0, 1.0) for _ in axes)), path=dialect)


def test_the_options_of_a_machine_without_the_section_are_the_declared_defaults():
    m = Machine()
    m.axes = [Axis("X"), Axis("Y")]
    assert options(m) == Options() and sin800_options(m) == Sin800Options()
    assert dialect_options(CplOptions, {}, "cpl", m.axes) == CplOptions()
    assert dialect_options(CplOptions, {"cpl": {}}, "cpl", m.axes) == CplOptions()
