"""Issue 16 item 3: PLC inputs that steer the path are marked (or, read with no scenario, refused:
docs/translate.md "A machine input that only a scenario says ... read with no --scenario, is refused").
CPL's IC read is refused so, but CPL's `PLC(type,dm,addr,size)` (manual §4.11, L2420-2468: inputs,
markers, data words, timers, counters) steers the path silently: no mark, no refusal."""

from __future__ import annotations

import pytest

from tests.review16e.helpers import mill, translate, write


@pytest.mark.parametrize("read", ["PLC(1,,0,1)", "PLC(8,,2,1)"], ids=["input byte", "counter"])
def test_position_read_from_the_plc_is_marked_or_refused(tmp_path, read):
    program = f"10 I% = {read}\n20 IF I% = 0 THEN X = 5 ELSE X = 9 ENDIF\nN30 G90 G17 G54 G0 X[X] Y0 Z5\nN40 M30\n"
    write(tmp_path, {"machine.toml": mill('[cpl]\nplc = { "I:0" = 1, "C:2" = 3 }\n'), "plc.cpl": program})
    rc, out, err = translate(tmp_path, "plc.cpl", "-m", "machine.toml")
    if rc != 0:
        assert out == "" and "plc.cpl:1" in err and "TRN001" in err, err
        return
    marks = [line for line in out.splitlines() if line.startswith("(FROZEN:")]
    assert any("plc.cpl:1" in mark for mark in marks), out
