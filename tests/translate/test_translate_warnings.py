"""What a translation writes differently from the simulated run, or as the simulated machine made it, is said
on the console too (TRN003, ``file:line:col: warning``, with the source line), not only in a FROZEN comment
of the file (issue 16, "Say what was frozen"; docs/translate.md)."""

from __future__ import annotations

from tests.review16c.helpers import ncvm
from tests.review16d.helpers import machine

M0_PROGRAM = """%MPF4
N10 G17 G71 G90 G54 G94
N40 G0 X0 Y0 Z50
N50 G1 Z5 F300
N60 M0
N70 G1 X50
N80 M30
"""

# rw_SymPas: the circle leaves A2's software limit sll = -10 (the axis minimum): the card stops it (§6.3.3)
LIMIT_PROGRAM = """program P;
begin
  TRVL := 50.0; TRAC := 500.0;
  MCRW(A1 := 100.0, A2 := 0.0, PHI := 180.0);
  MLAW(A3 := -1.0);
end.
"""


def _translate(tmp_path, name, text, machine_text):
    (tmp_path / "mill.toml").write_text(machine_text)
    (tmp_path / name).write_text(text)
    r = ncvm(tmp_path, "translate", name, "-m", "mill.toml", "-o", "out.ngc")
    assert r.returncode == 0, r.stderr
    return r.stderr


def test_m0_the_simulated_control_stops_at_is_a_warning(tmp_path):
    err = _translate(tmp_path, "m0.mpf", M0_PROGRAM, machine("mill", '[sin800]\nm0 = "stop"\n'))
    assert 'm0.mpf:5:5: warning TRN003: the simulated control ends the run at this M0 ([sin800] m0 = "stop")' in err
    assert "\n    N60 M0\n        ^^\n" in err, err


def test_m0_the_simulated_control_passes_is_no_warning(tmp_path):
    assert "TRN003" not in _translate(tmp_path, "m0.mpf", M0_PROGRAM, machine("mill"))


def test_a_move_cut_short_at_a_software_limit_is_a_warning(tmp_path):
    axes = [("X", -10.0, 400.0), ("Y", -10.0, 300.0), ("Z", -120.0, 10.0)]
    gantry = '[machine]\nname = "gantry"\n' + "".join(f'[[axis]]\nname = "{n}"\nmin = {lo}\nmax = {hi}\n'
                                                       for n, lo, hi in axes)
    err = _translate(tmp_path, "lim.sap", LIMIT_PROGRAM, gantry)
    assert "lim.sap:4:3: warning TRN003: software limit sll = -10 of A2 reached" in err, err
    assert "the move ends where the card stopped it" in err and "MCRW(A1 := 100.0" in err
    assert "FROZEN: software limit sll = -10 of A2" in (tmp_path / "out.ngc").read_text()
