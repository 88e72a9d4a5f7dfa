"""Issue 16 item 5: "a failed run leaves no output and says why". Written to a stream (a pipe, a DNC link)
the output cannot wait for the end (docs/translate.md): the blocks before the failure have gone out and a
`!!! INCOMPLETE` comment ends the stream. The message then must say so; both the stream's last comment and
the error on stderr claim "no output written", although the pipe received the program's first blocks."""

from __future__ import annotations

import subprocess
import sys

from tests.review16e.helpers import code_lines, mill, write

PROGRAM = """N10 G90 G17 G54 G0 X1 Y2 Z3
N20 G1 X5 F100
5 WAIT
10 A = SQRT(-1)
N30 X7
N40 M30
"""


def test_failed_run_on_a_stream_does_not_claim_no_output(tmp_path):
    write(tmp_path, {"machine.toml": mill(), "fail.cpl": PROGRAM})
    r = subprocess.run([sys.executable, "-m", "ncvm", "translate", "fail.cpl", "-m", "machine.toml",
                        "-o", "/dev/stdout"], cwd=tmp_path, capture_output=True, text=True, timeout=300)
    assert r.returncode == 1
    assert "INCOMPLETE" in r.stdout and "CPL029" in r.stderr
    assert "G1 X5 F100" in code_lines(r.stdout), r.stdout  # the stream did receive the moves before the fault
    assert "no output written" not in r.stdout, r.stdout
    assert "no output written" not in r.stderr, r.stderr
