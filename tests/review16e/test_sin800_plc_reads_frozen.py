"""Issue 16 item 3 "Say what was frozen": where the path depended on "PLC inputs", the output marks the
block with a comment naming the decision and its source line. A SINUMERIK 8xx program reads its PLC with
@ code (CL 800 manual L2777-2936: PLCI, PLCC, PLCDF) and gets PLC data words in answer to an M function
(L4305-4326, the M94 part-number example). The translation writes the positions those reads gave (from the
simulated PLC) with no mark and no refusal."""

from __future__ import annotations

import pytest

from tests.review16e.helpers import bare_machine, translate, write

MACHINE = bare_machine("880 plc", """\
[sin800]
control = "880"
m_functions = { 94 = { R60 = "DB20.DW1" } }
[sin800.plc.1]
I = { "0" = "00000101" }
DB = { "10" = [12, 0, 65535], "20" = [0, 33] }
C = { "2" = 7 }
""")

HEAD = "%MPF108\nN10 G17 G71 G90 G54 G94 G0 X0 Y0 Z0\n"


@pytest.mark.parametrize(("read", "move"), [
    ("N20 @714 @3a5 R10 K1 K2", "N30 G0 X=R10"),          # PLCC: counter C2 of PLC 1
    ("N20 @714 @3b0 R10 K1 K10 K0 K1 K0", "N30 G0 X=R10"),  # PLCDF: DB10 DW0 of PLC 1
    ("N20 @714 @380 R10 K1 K0 K2", "N30 G0 X=R10"),       # PLCI: input I0.2 of PLC 1
    ("N20 M94", "N30 @714 G0 X=R60"),                      # the PLC's answer to M94 (DB20 DW1)
], ids=["PLCC", "PLCDF", "PLCI", "M94"])
def test_position_read_from_the_plc_is_marked_frozen(tmp_path, read, move):
    write(tmp_path, {"machine.toml": MACHINE, "plc.mpf": f"{HEAD}{read}\n{move}\nN40 M30\n"})
    rc, out, err = translate(tmp_path, "plc.mpf", "-m", "machine.toml")
    if rc != 0:  # a refusal naming the read is as good as a mark
        assert out == "" and "plc.mpf:3" in err and "TRN001" in err, err
        return
    marks = [line for line in out.splitlines() if line.startswith("(FROZEN:")]
    assert any("plc.mpf:3" in mark or "plc.mpf:4" in mark for mark in marks), out
