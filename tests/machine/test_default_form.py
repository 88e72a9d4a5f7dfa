"""The built-in machine's precomputed form (issue 18): the same machine as the file, and an edited file is
still parsed and checked."""

from __future__ import annotations

import tomllib

import pytest

from ncvm.diagnostics import UsageError
from ncvm.machine import config, default_form


def test_the_form_is_the_built_in_file_and_its_parse():
    assert default_form.TEXT == config.default_machine_text()
    assert default_form.data() == tomllib.loads(default_form.TEXT)


def test_each_call_gives_a_new_parse():
    first = default_form.data()
    first["axis"].clear()
    assert len(default_form.data()["axis"]) == 3


def test_the_built_in_machine_is_the_one_the_file_describes():
    parsed = config.machine_from_dict(tomllib.loads(default_form.TEXT), "<built-in default machine>",
                                      config.Path("."))
    assert repr(config.load_machine()) == repr(parsed)  # the simulated clock compares by identity


def test_an_edited_built_in_file_is_parsed(monkeypatch):
    edited = default_form.TEXT.replace("max = 500.0", "max = 250.0", 1)
    monkeypatch.setattr(config, "default_machine_text", lambda: edited)
    assert config.load_machine().axes[0].max == 250.0


def test_an_edited_built_in_file_is_checked(monkeypatch):
    monkeypatch.setattr(config, "default_machine_text", lambda: default_form.TEXT + "[machine\n")
    with pytest.raises(UsageError, match="<built-in default machine>: not valid TOML"):
        config.load_machine()


def test_the_form_is_a_valid_machine_file_without_dialect_sections():
    """load_machine builds the built-in machine from the form unchecked (issue 18): right only while it passes
    the machine file's schema and has no section of a dialect."""
    from ncvm.machine.sections import DIALECT_SECTIONS

    form = default_form.data()
    assert repr(config.machine_from_dict(form, "<built-in default machine>", config.Path("."))) \
        == repr(config.load_machine())
    assert {sec.name for sec in DIALECT_SECTIONS} & set(form) == set()
