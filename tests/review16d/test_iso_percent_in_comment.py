"""ISO: a `%` inside a comment ends the tape (issue 16: "plain ISO/Fanuc style (... `%` wrapper)"; "Always a
complete file: ... it always ends with the target's program end").

On a Fanuc-style control `%` is the end-of-record mark of the tape format the ISO target writes (the `%`
wrapper); the control stops reading at it, also inside a comment. The operator message `(MSG, roughing 50%
done)` is written `(roughing 50% done)`: the program read in ends there, without the cut after it and without
its `M30`. The ISO target must keep `%` out of everything between the two wrapper lines (e.g. write `pct`),
as it already keeps parentheses out of comments.
"""

from __future__ import annotations

from tests.review16c.helpers import translate

PROGRAM = """G21 G90 G94 G54
G0 X0 Y0 Z5
(MSG, roughing 50% done)
G1 X10 F100
M30
"""


def test_only_the_wrapper_lines_hold_a_percent(tmp_path):
    rc, out, err = translate(tmp_path, PROGRAM, "pct.din", "--target", "iso", out_name="out.iso")
    assert rc == 0, err
    lines = out.splitlines()
    assert lines[0] == "%" and lines[-1] == "%", out
    inside = [line for line in lines[1:-1] if "%" in line]
    assert not inside, f"a % inside the program ends the tape before M30: {inside}"
