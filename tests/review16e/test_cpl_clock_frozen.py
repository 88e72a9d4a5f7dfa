"""Issue 16 item 3 "Say what was frozen": "where the program's path depended on run-time input (operator
keys, PLC inputs, scenario events, measured values, random data), the output marks the block with a
comment naming the decision and its source line". CPL's DATE and TIME (manual §4.12, L2490-2506) read the
control's calendar: a program that cuts the day or the hour into the part (a date stamp) takes its path
from the simulated clock, which is not the day the new control runs it; the translation writes the
simulated value as a fixed position with no mark."""

from __future__ import annotations

import pytest

from tests.review16e.helpers import mill, translate, write

DATED = """5 DIM D$(10)
10 D$ = {function}
20 N% = VAL(MID$(D$,1,2))
N30 G90 G17 G54 G0 X[N%] Y0 Z5
N40 G1 Z-1 F100
N50 M30
"""


@pytest.mark.parametrize("function", ["DATE", "TIME"])
def test_position_taken_from_the_clock_is_marked_frozen(tmp_path, function):
    write(tmp_path, {"machine.toml": mill(), "stamp.cpl": DATED.format(function=function)})
    rc, out, err = translate(tmp_path, "stamp.cpl", "-m", "machine.toml")
    assert rc == 0, err
    marks = [line for line in out.splitlines() if line.startswith("(FROZEN:")]
    assert any("stamp.cpl:2" in mark for mark in marks), out
