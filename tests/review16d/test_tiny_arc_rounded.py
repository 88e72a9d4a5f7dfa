"""An arc shorter than the written decimals becomes a full circle (issue 16: "decimals/rounding"; "makes the
same motions to the same end points ... as ncvm's own run"; "Trust first: a silently wrong answer is the
worst defect").

Positions are written to 4 decimals. A CPL arc whose end the program computes 0.0000175 mm from its start
(`G3 X[10*COS(A)] Y[10*SIN(A)] I-10 J0` with A = 0.0001 degrees) is run as that tiny arc; the translation
writes `G3 X10 Y0 I-10 J0`, whose end is its start: every G-code control cuts a full circle of radius 10 there,
63 mm the program never cut. rs274 reads it back to the same end point, so the end-point comparison cannot see
it; the sweep shows it. A move that rounds to nothing should be left out (or written as the straight move it
is), never as a circle.
"""

from __future__ import annotations

import pytest

from tests.review16c.helpers import needs_rs274, rs274_canon
from tests.review16d.helpers import full_circles, machine, rs274_sweep, translated

MACHINE = machine("mill")

PROGRAM = """10 A = 0.0001
N20 G90 G17 G54
N30 G0 X10 Y0 Z5 F300
N40 G1 Z-1
N50 G3 X[10*COS(A)] Y[10*SIN(A)] I-10 J0
N60 G0 Z5
N70 M30
"""


@pytest.mark.parametrize("target", ["linuxcnc", "sinumerik840d", "iso"])
def test_tiny_arc_is_no_full_circle(tmp_path, target):
    full = full_circles(translated(tmp_path, MACHINE, PROGRAM, "tiny.cpl", target))
    assert not full, f"{target}: a 0.0000175 mm arc written as a full circle: {full}"


@needs_rs274
def test_rs274_sweeps_no_circle(tmp_path):
    rc, canon = rs274_canon(tmp_path, translated(tmp_path, MACHINE, PROGRAM, "tiny.cpl", "linuxcnc"))
    assert rc == 0, canon
    sweep = rs274_sweep(canon)
    assert sweep < 1.0, f"rs274 turns {sweep:.1f} degrees where the run turned 0.0001"
