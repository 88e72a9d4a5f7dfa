"""The API's usage errors for program text, and the exit codes in the help of the command groups."""

from __future__ import annotations

import pytest
from click.testing import CliRunner

import ncvm
from ncvm.cli import cli
from ncvm.dialects import REGISTRY


@pytest.mark.parametrize("call", [ncvm.run, ncvm.check])
def test_program_text_in_an_unknown_dialect_names_the_known_ones(call):
    with pytest.raises(ncvm.UsageError) as e:
        call("G0 X10\nM30\n", dialect="cobol")
    assert "unknown dialect 'cobol'" in str(e.value)
    assert all(name in str(e.value) for name in REGISTRY)


@pytest.mark.parametrize("args", [(), ("state",)])
def test_group_help_lists_each_exit_code(args):
    out = CliRunner().invoke(cli, [*args, "--help"], terminal_width=200)
    assert out.exit_code == 0
    tail = out.output.split("Exit codes:")[1]
    for code in ("0 ", "1 ", "2 usage error", "70 internal error"):
        assert code in tail, (args, tail)
