"""Issue 16 item 4: "feed and spindle words as programmed". A rw_SymPas program sets its path speed with
TRVL (mm/s) and its acceleration with TRAC; a move too short to reach TRVL on the simulated card's
trapezoid is written with the peak speed the simulation reached (2 mm at TRAC 800 mm/s²: F2400 instead of
the programmed 80 mm/s = F4800). The new control has its own acceleration; the F word must be the
program's."""

from __future__ import annotations

from tests.review16e.helpers import code_lines, translate, write

MACHINE = """[machine]
name = "gantry"
[[axis]]
name = "X"
min = -10.0
max = 400.0
rapid = 12000.0
max_feed = 6000.0
accel = 1500.0
[[axis]]
name = "Y"
min = -10.0
max = 300.0
rapid = 12000.0
max_feed = 6000.0
accel = 1500.0
[[axis]]
name = "Z"
min = -120.0
max = 10.0
rapid = 6000.0
max_feed = 6000.0
accel = 1000.0
"""

PROGRAM = """program Short;
begin
  TRVL := 80.0; TRAC := 800.0;
  MLAW(A1 := 20.0, A2 := 10.0);
  MLAW(A3 := -2.0);
  MLAW(A1 := 120.0);
end.
"""


def test_short_move_keeps_the_programmed_path_speed(tmp_path):
    write(tmp_path, {"machine.toml": MACHINE, "short.sap": PROGRAM})
    rc, out, err = translate(tmp_path, "short.sap", "-m", "machine.toml")
    assert rc == 0, err
    moves = [line for line in code_lines(out) if line.startswith("G1")]
    assert moves[0] == "G1 X20 Y10 F4800", out
    assert moves[1] in ("G1 Z-2", "G1 Z-2 F4800"), out  # TRVL unchanged
    assert moves[2] in ("G1 X120", "G1 X120 F4800"), out
