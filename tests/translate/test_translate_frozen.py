"""Frozen decisions and the inputs a translation needs (docs/translate.md, "What is frozen")."""

from __future__ import annotations

from pathlib import Path

import pytest

from ncvm.runtime.session import RunOptions
from ncvm.translate import TranslationRefused, translate

EX = Path(__file__).parents[2] / "examples"


def test_a_plc_input_read_marks_the_block_it_decides(tmp_path):
    """CPL: IF IC(5,1,2) decides which way the tool goes; the translation says so at the move it leads to."""
    program = tmp_path / "branch.cpl"
    program.write_text("10 IF IC(5,1,2) THEN\nN20 G1 X10 F100\n30 ELSE\nN40 G1 X-10 F100\n50 ENDIF\nN60 M30\n")
    translate(program, tmp_path / "b.ngc", options=RunOptions(state_dir=tmp_path / "st"))
    text = (tmp_path / "b.ngc").read_text()
    assert "(FROZEN: PLC input IC" in text and "read as 0 at branch.cpl:1;" in text  # the IF that read it
    assert "G1 X-10 Y0 Z0 F100" in text and "X10 " not in text
    assert "(1 decisions of the run are frozen" in text


def test_a_scenario_event_is_marked(tmp_path):
    """rw_SymPas: the scenario's axis input that the program waits for is named at the block after it."""
    out = tmp_path / "c.ngc"
    translate(EX / "sympas" / "contour.sap", out, machine=EX / "sympas" / "machine.toml",
              options=RunOptions(state_dir=tmp_path / "st"))
    assert "(FROZEN: scenario event at 3 s: AxisInput[time=3.0, axis='A3', bit=1, value=True] at contour.sap:" \
        in out.read_text()


def test_a_probe_move_without_a_scenario_is_refused(tmp_path):
    """measlog.cpl without its scenario: the probe never switches, the run measured nothing; refused at the
    measuring block, nothing written."""
    with pytest.raises(TranslationRefused) as e:
        translate(EX / "cpl" / "measlog.cpl", tmp_path / "m.ngc", machine=EX / "cpl" / "machine.toml",
                  options=RunOptions(state_dir=tmp_path / "st"))
    d = e.value.diagnostic
    assert d.code == "TRN001" and d.span.line == 13
    assert "the run has no scenario saying where the probe switches (give it with --scenario)" in d.message
    assert list(tmp_path.iterdir()) == [tmp_path / "st"]
