"""SINUMERIK blocks with R parameters keep their programmed axes (issue 16: "only programmed axes written" fix
of an earlier review; docs/translate.md rule 1: "The axes the block programs are written (canon
`programmed`: the block's axis words, also one whose value equals where the axis stands, e.g. the `Y0` of a
first move)").

`N30 G0 X20 Y0 Z50` is written `G0 X20 Y0 Z50`. The same block with an R parameter in it — an axis value
from R (`X=R1`) or an R assignment (`R1=5`) — is written `G0 X20 Z50`: the program's `Y0` is dropped because
the simulated Y already stood at 0. On the new control Y stays wherever it is, and every later X/Z move of
the program cuts at that Y.
"""

from __future__ import annotations

import pytest

from tests.review16c.helpers import code_lines
from tests.review16d.helpers import machine, translated

MACHINE = machine("mill")

BLOCKS = {
    "plain": "N30 G0 X20 Y0 Z50",
    "axis value from R": "N30 G0 X=R1 Y0 Z50",
    "R assignment in the block": "N30 G0 X20 Y0 Z50 R2=5",
}


@pytest.mark.parametrize("target", ["linuxcnc", "sinumerik840d", "iso"])
@pytest.mark.parametrize("kind", sorted(BLOCKS))
def test_programmed_y0_is_written(tmp_path, kind, target):
    program = f"%MPF6\nN10 G17 G71 G90 G54 G94\nN20 R1=20\n{BLOCKS[kind]}\nN40 M30\n"
    out = translated(tmp_path, MACHINE, program, "p.mpf", target)
    moves = [line for line in code_lines(out) if line.startswith("G0")]
    assert len(moves) == 1 and " Y0" in moves[0], f"{kind}: the block's Y0 is not written: {moves}"
