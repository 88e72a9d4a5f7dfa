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


def test_ctrl_c_in_ncvm_run_raises_after_closing_the_trace(tmp_path):
    """A real SIGINT to a script that runs a long program: KeyboardInterrupt reaches the script, and the
    trace the run wrote is closed (every line is JSON)."""
    import json
    import subprocess
    import sys
    import textwrap

    from tests.runtime.ctrl_c import ctrl_c, grown_past

    (tmp_path / "long.cpl").write_text("(LONG)\n10 FOR I% = 1 TO 3000000\nN20 G1 X[I% * 0.0001] F5000\n"
                                       "30 NEXT I%\nM30\n")
    script = textwrap.dedent("""
        import ncvm
        try:
            ncvm.run("long.cpl", trace="t.jsonl")
        except KeyboardInterrupt:
            print("interrupted", flush=True)
        else:
            print("returned", flush=True)
        """)
    proc = subprocess.Popen([sys.executable, "-c", script], cwd=tmp_path, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True)
    trace = tmp_path / "t.jsonl"
    out, err = ctrl_c(proc, grown_past(trace, 50_000), "the trace to grow", timeout=60)
    assert out.strip() == "interrupted", (out, err)
    for line in trace.read_text().splitlines():
        json.loads(line)
