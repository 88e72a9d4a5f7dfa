"""Issue 16 "translation stops with a clear error naming the block"; BRIEF_COMMON: bad input gives
`file:line:col: error CODE: message` with the source line. A zero offset rewritten after moves with it is
refused (docs/translate.md rule 2); DIN's `G10 L2` refusal names its block, but the same refusal for a
CPL FXC write into the active table (manual §4.3, L1724-1779) and a SINUMERIK `@430` ZOA write
(CL 800 manual L3186-3192) names no file and no line."""

from __future__ import annotations

import re

import pytest

from tests.review16e.helpers import mill, translate, write

S880 = """[machine]
name = "880 mill"
[[axis]]
name = "X"
min = -300.0
max = 300.0
[[axis]]
name = "Y"
min = -300.0
max = 300.0
[[axis]]
name = "Z"
min = -300.0
max = 300.0
[sin800]
control = "880"
zero_offsets = { G54 = { coarse = [150.0, 100.0, 0.0], fine = [0.0, 0.0, 0.0] } }
"""

CPL = """N10 G90 G17 G54 G0 X1 Y0 Z5
15 WAIT
20 FXC(1,54) = 50
N30 G0 X2
N40 M30
"""

SIN = """%MPF104
N10 G17 G71 G90 G54 G94
N20 G0 X10 Y10 Z5
N30 @714
N40 @430 K1 K1 K0 K50
N50 G0 X20
N60 M30
"""


@pytest.mark.parametrize(("name", "program", "machine", "lines"), [
    ("fx.cpl", CPL, mill(), (3, 4)),
    ("zoa.mpf", SIN, S880, (5, 6)),
], ids=["cpl-FXC", "sin800-ZOA"])
def test_zero_offset_rewrite_refusal_names_the_block(tmp_path, name, program, machine, lines):
    write(tmp_path, {"machine.toml": machine, name: program})
    rc, out, err = translate(tmp_path, name, "-m", "machine.toml")
    assert (rc, out) == (1, "")
    assert "TRN001" in err and "rewrites zero offset G54" in err, err
    located = re.search(rf"^{re.escape(name)}:(\d+)(:\d+)?: error TRN001", err, re.M)
    assert located and int(located.group(1)) in lines, err
