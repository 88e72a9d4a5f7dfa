"""The checker's axis commands (symbols.BUILTINS) and the card's command functions (commands/) are one list."""

from __future__ import annotations

from ncvm.dialects.sympas.commands import COMMANDS
from ncvm.dialects.sympas.symbols import BUILTINS


def test_every_axis_command_the_checker_accepts_has_a_function_on_the_card():
    # generated code calls _C_<name>: a command without its function would fail only when a program runs it
    axis_forms = {name.lower() for name, b in BUILTINS.items() if b.form in ("S", "SP", "SP+")}
    assert axis_forms == set(COMMANDS)
