"""A continuous path without a tolerance (DIN's power-on G64 or a bare G64, CPL G62, SINUMERIK G64) runs at the
machine's corner tolerance; the translation writes the target's bare G64, which leaves the new control's own
corner rounding (on LinuxCNC none at all). The header says which tolerance the cycle time assumed and what the
bare G64 does there (docs/decisions.md, issue 18)."""

from __future__ import annotations

from pathlib import Path

import pytest

from ncvm import api
from ncvm.runtime.session import RunOptions
from ncvm.translate import translate

AXES = '[[axis]]\nname = "X"\n[[axis]]\nname = "Y"\n[[axis]]\nname = "Z"\n'
CONTOUR = "N10 G21 G90 G17 G54\nN20 G0 X0 Y0 Z5\nN30 G1 Z-1 F500\nN40 X50\nN50 Y50\nN60 X0\nN70 M30\n"


def _text(tmp_path: Path) -> str:
    return (tmp_path / "out").read_text()


def _header(tmp_path: Path, text: str, target: str = "linuxcnc", machine: str = AXES, name: str = "p.din",
            **options) -> tuple[str, list[str]]:
    """(the header's comments as one text, the program's lines) of ``text`` translated for ``target``."""
    (tmp_path / "machine.toml").write_text(machine)
    program = tmp_path / name
    program.write_text(text)
    out = tmp_path / "out"
    translate(program, out, target, machine=tmp_path / "machine.toml",
              options=RunOptions(state_dir=tmp_path / "st", **options))
    lines = out.read_text().splitlines()
    comment = (lambda line: line.startswith(";")) if target == "sinumerik840d" else (lambda line: line.startswith("("))
    head = []
    for line in lines:
        if not comment(line) and line != "%":
            break
        head.append(line.strip("();% "))
    return " ".join(head), [line for line in lines if line and not comment(line) and line != "%"]


def test_linuxcnc_header_names_the_tolerance_and_what_a_bare_g64_does_there(tmp_path):
    head, code = _header(tmp_path, CONTOUR)
    assert "corners blended within 0.02 mm" in head and "corner_tolerance" in head
    assert "G64 is no tolerance at all" in head and "G64 P0.02 keeps that bound" in head
    # the preamble states the mode (M2 does not reset it: a file relies on none a program before it left)
    assert code[0].endswith(" G64") and not any(line.startswith("G64") for line in code[1:]), code


def test_the_machines_own_tolerance_is_the_one_named(tmp_path):
    head, _ = _header(tmp_path, CONTOUR, machine=AXES + "[motion]\ncorner_tolerance = 0.05\n")
    assert "within 0.05 mm" in head and "G64 P0.05 keeps that bound" in head and "0.02" not in head


def test_a_corner_tolerance_of_zero_is_said_as_a_stop_at_every_corner(tmp_path):
    head, _ = _header(tmp_path, CONTOUR, machine=AXES + "[motion]\ncorner_tolerance = 0\n")
    assert "a stop at every corner" in head and "corner_tolerance 0 mm" in head and "blended within" not in head
    assert "G64 P0" not in head and "G61 stops at each" in head  # LinuxCNC's G64 P0 is no bound at all


def test_a_programmed_g64_p0_is_written_as_exact_stop(tmp_path):
    """DIN G64 P0: corners within 0 mm, a stop at each; on LinuxCNC G64 P0 is a bare G64 (no bound)."""
    head, code = _header(tmp_path, CONTOUR.replace("N40 X50", "N40 G64 P0 X50"))
    assert "G64 P0" not in code and "G61" in code, code
    assert "G64 P0: a stop at every corner, written as G61" in head or "written as G61" in _text(tmp_path)


@pytest.mark.parametrize("text", [
    CONTOUR.replace("N30 G1 Z-1 F500\n", "N30 G1 Z-1 F500 M8\n").replace("N40 X50\nN50 Y50\nN60 X0\n", "N40 X50\n"),
    "N10 G0 X0 Y0 Z5\nN20 G1 Z-1 F200\nN30 G0 Z5\nN40 X10\nN50 G1 Z-1\nN60 G0 Z5\nN70 M30\n",  # drilling
    "N10 G0 X0 Y0 Z5\nN20 G1 X10 F200\nN30 G4 P1\nN40 X20\nN50 M30\n",  # a dwell between
    "N10 G0 X0 Y0 Z5\nN20 G1 X10 F200\nN30 G9 Y10\nN40 G64 P0.1 X0\nN50 M30\n",
])
def test_no_word_where_no_two_feed_moves_blended_at_the_machines_tolerance(tmp_path, text):
    head, _ = _header(tmp_path, text)
    assert "corners blended" not in head, head


def test_a_bare_g64_after_g64_p_is_said_too(tmp_path):
    text = CONTOUR.replace("N40 X50", "N40 G64 P0.1 X50").replace("N60 X0", "N60 G64 X0")
    head, code = _header(tmp_path, text)
    assert "G64 P0.1" in code and "G64" in code, code
    assert "within 0.02 mm" in head


@pytest.mark.parametrize("text", [
    CONTOUR.replace("N10 G21", "N10 G61 G21"),  # exact stop throughout
    CONTOUR.replace("N10 G21", "N10 G64 P0.01 G21"),  # a programmed tolerance throughout: written as such
])
def test_no_word_on_blending_where_no_move_ran_at_the_machines_tolerance(tmp_path, text):
    head, _ = _header(tmp_path, text)
    assert "corners blended" not in head and "continuous path" not in head


def test_rest_to_rest_timing_is_said(tmp_path):
    head, _ = _header(tmp_path, CONTOUR, machine=AXES + '[motion]\nmodel = "rest-to-rest"\n')
    assert "timed every move from rest to rest" in head and "corners blended within" not in head


def test_the_time_model_the_run_was_given_is_the_one_said(tmp_path):
    head, _ = _header(tmp_path, CONTOUR, time_model="rest-to-rest")
    assert "timed every move from rest to rest [the run's --time-model]" in head and "no tolerance at all" in head


@pytest.mark.parametrize(("target", "words"), [
    ("sinumerik840d", "the control's own continuous-path mode (how it slows at corners is its machine data"),
    ("iso", "the control's own corner rounding, a setting of that control"),
])
def test_other_targets_say_their_own_g64(tmp_path, target, words):
    head, _ = _header(tmp_path, CONTOUR, target)
    assert "within 0.02 mm" in head and words in head and "G64 P" not in head


def test_cpl_g62_and_sinumerik_g64_run_at_the_machines_tolerance(tmp_path):
    head, _ = _header(tmp_path, "N10 G90 G17 G54 G61 G0 X0 Y0 Z5\nN20 G1 X5 F100\nN30 G62 X9\nN35 Y9\nN40 M30\n",
                      name="p.cpl")
    assert "within 0.02 mm" in head
    machine = AXES + '[sin800]\ncontrol = "880"\n'
    program = "%MPF5\nN10 G17 G71 G90 G54 G94 G0 X0 Y0 Z5\nN20 G1 X50 F500\nN30 G64 Y50\nN35 X0\nN40 M30\n"
    head, _ = _header(tmp_path, program, machine=machine, name="p.mpf")
    assert "within 0.02 mm" in head
    head, _ = _header(tmp_path, program.replace("N30 G64 Y50", "N30 Y50"), machine=machine, name="p.mpf")
    assert "corners blended" not in head  # the 8xx's power-on exact stop throughout


def test_run_gcode_header_says_it_too(tmp_path):
    (tmp_path / "machine.toml").write_text(AXES + "[motion]\ncorner_tolerance = 0.03\n")
    program = tmp_path / "p.din"
    program.write_text(CONTOUR)
    out = tmp_path / "p.ngc"
    result = api.run_program(program, "din", tmp_path / "machine.toml",
                             RunOptions(state_dir=tmp_path / "st", gcode=out))
    assert result.error is None
    text = out.read_text()
    assert "within 0.03 mm" in text and "G64 P0.03 keeps" in text
