"""Frozen decisions and the inputs a translation needs (docs/translate.md, "What is frozen")."""

from __future__ import annotations

from pathlib import Path

import pytest

from ncvm.runtime.session import RunOptions
from ncvm.translate import TranslationRefused, translate

EX = Path(__file__).parents[2] / "examples"


#: a scenario whose one event comes after the run: the inputs stand at their rest values, as the user said
LATE_SCENARIO = '[[scenario]]\ntime = 1000\nkind = "input"\naddress = "IC(1,1,1)"\nvalue = true\n'


def late_scenario(tmp_path: Path) -> Path:
    path = tmp_path / "late.scenario.toml"
    path.write_text(LATE_SCENARIO)
    return path


def test_a_plc_input_read_marks_the_block_it_decides(tmp_path):
    """CPL: IF IC(5,1,2) decides which way the tool goes; the translation says so at the move it leads to."""
    program = tmp_path / "branch.cpl"
    program.write_text("10 IF IC(5,1,2) THEN\nN20 G1 X10 F100\n30 ELSE\nN40 G1 X-10 F100\n50 ENDIF\nN60 M30\n")
    translate(program, tmp_path / "b.ngc", options=RunOptions(state_dir=tmp_path / "st",
                                                              scenario=late_scenario(tmp_path)))
    text = (tmp_path / "b.ngc").read_text()
    assert "(FROZEN: PLC input IC" in text and "read as 0 at branch.cpl:1;" in text  # the IF that read it
    assert "G1 X-10 F100" in text and "X10 " not in text  # the programmed axis alone
    assert "(1 decisions of the run are frozen" in text


def test_a_scenario_event_the_program_never_reads_marks_nothing(tmp_path):
    """rw_SymPas: the example scenario sets input A3.1 at 3 s, which contour.sap never reads (no digi,
    ifs or input event): its path does not depend on it, so nothing is marked frozen."""
    out = tmp_path / "c.ngc"
    translate(EX / "sympas" / "contour.sap", out, machine=EX / "sympas" / "machine.toml",
              options=RunOptions(state_dir=tmp_path / "st"))
    assert "FROZEN" not in out.read_text()


SCENARIO_CI = """
[[scenario]]
time = 0.5
kind = "ci"
index = 3
value = 7
"""


def test_a_read_of_what_a_scenario_event_set_is_marked(tmp_path):
    """rw_SymPas: a common integer a scenario event set decides the branch: marked at the block after the
    read, naming the value and the event; the digital inputs the program reads are marked as well."""
    program = tmp_path / "ci.sap"
    program.write_text("program P;\nbegin\n  WT(15625);\n  if CI3 = 7 then\n    MLAW(A1 := 10.0)\n"
                       "  else\n    MLAW(A1 := -10.0);\n  if A3.digi = 0 then MLAW(A2 := 5.0);\nend.\n")
    machine = tmp_path / "machine.toml"
    machine.write_text((EX / "sympas" / "machine.toml").read_text().split("[[scenario]]")[0] + SCENARIO_CI)
    out = tmp_path / "ci.ngc"
    translate(program, out, machine=machine, options=RunOptions(state_dir=tmp_path / "st"))
    text = out.read_text()
    assert "(FROZEN: CI3 read as 7 [set by the scenario event at 0.5 s]" in text
    assert "(FROZEN: digital inputs A3.digi read as 0x0" in text
    assert "X10" in text and "X-10" not in text


def test_a_plc_input_read_without_a_scenario_is_refused(tmp_path):
    """CPL: IF IC(5,1,2) with no scenario: nothing said what the input is, the run took its rest value;
    refused at the IF that read it, nothing written (issue 16 rule 3)."""
    program = tmp_path / "branch.cpl"
    program.write_text("10 IF IC(5,1,2) THEN\nN20 G1 X10 F100\n30 ELSE\nN40 G1 X-10 F100\n50 ENDIF\nN60 M30\n")
    with pytest.raises(TranslationRefused) as e:
        translate(program, tmp_path / "b.ngc", options=RunOptions(state_dir=tmp_path / "st"))
    d = e.value.diagnostic
    assert d.code == "TRN001" and d.span.line == 1 and "--scenario" in d.message
    assert not (tmp_path / "b.ngc").exists()


def test_a_probe_move_without_a_scenario_is_refused(tmp_path):
    """measlog.cpl without its scenario: the probe never switches, the run measured nothing; refused at the
    measuring block, nothing written."""
    with pytest.raises(TranslationRefused) as e:
        translate(EX / "cpl" / "measlog.cpl", tmp_path / "m.ngc", machine=EX / "cpl" / "machine.toml",
                  options=RunOptions(state_dir=tmp_path / "st"))
    d = e.value.diagnostic
    assert d.code == "TRN001" and d.span.line == 13
    assert "the run has no scenario saying where the probe switches (give it with --scenario)" in d.message
    assert list(tmp_path.iterdir()) == []  # no output, and no state directory: a translation creates none


def test_a_scenario_event_is_said_in_the_users_words(tmp_path):
    """SINUMERIK: the input a scenario event sets is named as the user wrote it (external input 1.3 = 1),
    not as the record the run keeps (``ExternalInput(time=0.0, byte=1, ...)``)."""
    machine = tmp_path / "machine.toml"
    machine.write_text('[machine]\nname = "880"\n' + "".join(f'[[axis]]\nname = "{a}"\n' for a in "XYZ")
                       + '[sin800]\ncontrol = "880"\n'
                       + '[[scenario]]\ntime = 0.0\nkind = "input"\nbyte = 1\nbit = 3\nvalue = 1\n')
    program = tmp_path / "in.mpf"
    program.write_text("%MPF1\nN10 G17 G71 G90 G54 G0 X0 Y0 Z0\nN20 @187 K1 K3 K40\nN30 G0 X10\n"
                       "N40 G0 X20\nN50 M30\n")
    translate(program, tmp_path / "in.ngc", machine=machine, options=RunOptions(state_dir=tmp_path / "st"))
    text = (tmp_path / "in.ngc").read_text()
    assert "(FROZEN: scenario event at 0 s: external input 1.3 = 1 at in.mpf:" in text, text
    assert "ExternalInput" not in text
