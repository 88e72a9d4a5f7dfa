"""What a translation writes differently from the simulated run, or as the simulated machine made it, is said
on the console too (TRN003, ``file:line:col: warning``, with the source line), not only in a FROZEN comment
of the file (issue 16, "Say what was frozen"; docs/translate.md)."""

from __future__ import annotations

from tests.review16c.helpers import ncvm
from tests.review16d.helpers import machine

# SINUMERIK: M0 at N60 (line 5), on a machine whose simulated control stops there ([sin800] m0 = "stop")
from tests.review16d.test_stop_ends_run import MACHINE as STOPPING
from tests.review16d.test_stop_ends_run import PROGRAM as M0_PROGRAM

# rw_SymPas: the circle leaves A2's software limit sll = -10 (the axis minimum): the card stops it (§6.3.3)
from tests.review16d.test_sympas_limit_stop_said import MACHINE as GANTRY
from tests.review16d.test_sympas_limit_stop_said import PROGRAM as LIMIT_PROGRAM


def _translate(tmp_path, name, text, machine_text):
    (tmp_path / "mill.toml").write_text(machine_text)
    (tmp_path / name).write_text(text)
    r = ncvm(tmp_path, "translate", name, "-m", "mill.toml", "-o", "out.ngc")
    assert r.returncode == 0, r.stderr
    return r.stderr


def test_m0_the_simulated_control_stops_at_is_a_warning(tmp_path):
    err = _translate(tmp_path, "m0.mpf", M0_PROGRAM, STOPPING)
    assert 'm0.mpf:5:5: warning TRN003: the simulated control ends the run at this M0 ([sin800] m0 = "stop")' in err
    assert "\n    N60 M0\n        ^^\n" in err, err


def test_m0_the_simulated_control_passes_is_no_warning(tmp_path):
    assert "TRN003" not in _translate(tmp_path, "m0.mpf", M0_PROGRAM, machine("mill"))


def test_a_move_cut_short_at_a_software_limit_is_a_warning(tmp_path):
    err = _translate(tmp_path, "lim.sap", LIMIT_PROGRAM, GANTRY)
    assert "lim.sap:4:3: warning TRN003: software limit sll = -10 of A2 reached" in err, err
    assert "the move ends where the card stopped it" in err and "MCRW(A1 := 100.0" in err
    assert "FROZEN: software limit sll = -10 of A2" in (tmp_path / "out.ngc").read_text()
