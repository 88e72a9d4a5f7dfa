"""CL 800 source to the NC: the spindle reads ACSP, ACSS, AGS, PRVC compiled and run on the sin800 NC
(manual L2648-2668, L3021-3032, L4887), with values computed by hand."""

from __future__ import annotations

from pathlib import Path

import pytest

from ncvm.api import run
from ncvm.runtime.session import RunOptions

MACHINE = """
[[axis]]
name = "X"
[[axis]]
name = "Z"
[sin800]
control = "880"
gear = 2
"""

SOURCE = """\
PROGRAM 77;
CHANNEL NC 0;
PAR REAL: R10:=spindpos, R11:=spindrpm, R12:=gearstg;
PAR REAL: R13:=cutspeed, R14:=cutsp96;
BEGIN
(: S600 M3 :); LF;
(: G4 X0.25 :); LF;
STOP DEC;
spindpos = ACSP (0); spindrpm = ACSS (1);
gearstg = AGS (0); cutspeed = PRVC (0, 0);
(: G0 X50 :); LF;
(: G96 S180 :); LF;
cutsp96 = PRVC (0, 0);
END.
"""


def test_cl800_program_reads_the_simulated_spindle(tmp_path: Path):
    (tmp_path / "machine.toml").write_text(MACHINE)
    src = tmp_path / "spindle.cl8"
    src.write_text(SOURCE)
    result, _ = run(src, machine=tmp_path / "machine.toml", options=RunOptions(state_dir=tmp_path / ".ncvm"))
    assert result["status"] == "ok", result["error"]
    v = result["variables"]
    # S600 = 10 rev/s, G4 X0.25 -> 2.5 rev = 900 degrees -> 180 degrees; gear stage 2 from the machine file;
    # no G96 yet: PRVC = 0; after G96 S180: PRVC = 180 (transfer parameters keep their values after END.)
    assert (v.get("R10"), v.get("R11"), v.get("R12"), v.get("R13"), v.get("R14")) == \
        (pytest.approx(180.0), 600.0, 2.0, 0.0, 180.0)
