"""Review of branch g64 (a bare G64 in a translation, docs/decisions.md issue 18) as a retrofitter would use it.

Each test is one defect found: the header or the path control of a translation says or does something other
than what the simulated run did, or what the target control does with the words written. LinuxCNC facts
relied on: its interpreter passes a bare G64 to the trajectory planner as tolerance 0, and the planner reads a
tolerance of 0 as "no tolerance" (so `G64 P0` is a bare `G64`, best possible speed); M2 does not reset the path
control mode (LinuxCNC G-code manual, M2/M30: offsets, plane, distance and feed mode, cutter compensation,
spindle, motion mode, coolant only).
"""

from __future__ import annotations

import re
import shutil
from pathlib import Path

import pytest

from ncvm import api
from ncvm.runtime.session import RunOptions
from ncvm.translate import translate

ROOT = Path(__file__).resolve().parents[2]
AXES = '[[axis]]\nname = "X"\n[[axis]]\nname = "Y"\n[[axis]]\nname = "Z"\n'
CONTOUR = "N10 G90 G54 G0 X0 Y0 Z5\nN20 G1 Z-1 F500\nN30 X50\nN40 Y30\nN50 X0\nN60 Y0\nN70 G0 Z5\nN80 M30\n"
#: a drilling program: every feed move lies between two rapid positionings, which the simulation ends at rest
DRILL = "N10 G90 G0 X10 Y10 Z2\nN20 G1 Z-10 F200\nN30 G0 Z2\nN40 X30\nN50 G1 Z-10\nN60 G0 Z2\nN70 M30\n"
#: LinuxCNC: `G64 P0` (exactly zero, not G64 P0.02)
G64_P0 = re.compile(r"G64 P0(?![.\d])")


def _write(tmp_path: Path, text: str, machine: str, name: str) -> tuple[Path, Path]:
    (tmp_path / "machine.toml").write_text(machine)
    program = tmp_path / name
    program.write_text(text)
    return program, tmp_path / "machine.toml"


def _split(text: str, target: str) -> tuple[str, list[str]]:
    """(every comment of the file as one text, the code lines)."""
    lines = text.splitlines()
    mark = ";" if target == "sinumerik840d" else "("
    comments = " ".join(line.strip("();% ") for line in lines if line.startswith(mark))
    return comments, [line for line in lines if line and not line.startswith(mark) and line != "%"]


def _translated(tmp_path: Path, text: str, target: str = "linuxcnc", machine: str = AXES, name: str = "p.din",
                **options) -> tuple[str, list[str]]:
    program, machine_file = _write(tmp_path, text, machine, name)
    out = tmp_path / "out"
    translate(program, out, target, machine=machine_file, options=RunOptions(state_dir=tmp_path / "st", **options))
    return _split(out.read_text(), target)


def _cycle(program: Path, machine: Path, tmp_path: Path, **options) -> float:
    result = api.run_program(program, None, machine, RunOptions(state_dir=tmp_path / "st", **options))
    assert result.error is None, result.error
    return result.cycle_time_s


def test_corner_tolerance_zero_is_not_called_blending_nor_g64_p0_advised(tmp_path):
    """`[motion] corner_tolerance = 0` means "every corner is an exact stop" (machine file schema): the run
    times the contour exactly as rest-to-rest does (checked below). The header nevertheless says "the cycle
    time assumed corners blended within 0 mm" and advises "G64 P0 keeps corners within the simulated
    tolerance" -- on LinuxCNC `G64 P0` is the bare G64 (tolerance 0 = no tolerance, best possible speed), the
    very opposite of the exact stops the cycle time assumed. Expected: the header says the simulation stopped
    at every corner, and advises no `G64 P0` (LinuxCNC's G61 keeps that path)."""
    machine = AXES + "[motion]\ncorner_tolerance = 0\n"
    program, machine_file = _write(tmp_path, CONTOUR, machine, "p.din")
    assert _cycle(program, machine_file, tmp_path) == _cycle(program, machine_file, tmp_path,
                                                             time_model="rest-to-rest")
    head, _ = _translated(tmp_path, CONTOUR, machine=machine)
    assert "blended within 0 mm" not in head, head
    assert not G64_P0.search(head), head


def test_a_programs_g64_p0_is_not_written_as_linuxcnc_g64_p0(tmp_path):
    """A DIN `G64 P0` asks for corners within 0 mm: the simulated run stops at every corner (its cycle time
    equals the rest-to-rest one, checked below). The LinuxCNC output writes `G64 P0`, which LinuxCNC's
    trajectory planner reads as no tolerance at all: the new machine rounds every corner as far as it likes,
    silently, with no warning (the 840D and ISO targets at least warn TRN003). Expected: the exact path the
    run assumed (`G61`), or a warning; never `G64 P0` without a word."""
    text = CONTOUR.replace("N20 G1", "N20 G64 P0 G1")
    program, machine_file = _write(tmp_path, text, AXES, "p.din")
    assert _cycle(program, machine_file, tmp_path) == _cycle(program, machine_file, tmp_path,
                                                             time_model="rest-to-rest")
    _, code = _translated(tmp_path, text)
    assert not any(G64_P0.fullmatch(line) for line in code), code


#: feed moves all at a programmed G64 P0.1 (one with G09): the only move in a bare G64 is the first rapid
PROGRAMMED = "N10 G90 G0 X0 Y0 Z5\nN20 G64 P0.1 G1 Z-1 F500\nN30 X50\nN40 G09 Y30\nN50 X0\nN60 M30\n"


@pytest.mark.parametrize("text", [DRILL, PROGRAMMED], ids=["drilling", "programmed_tolerance"])
def test_rapid_positionings_are_not_blended_corners(tmp_path, text):
    """The planner ends every rapid positioning at rest (docs/planner.md: "Exact stops (a rapid positioning,
    ...)"), so a drilling program -- each G1 between two G0 -- blends no corner at the machine's tolerance:
    its look-ahead cycle time equals the rest-to-rest one (checked below). The header still says "the cycle
    time assumed corners blended within 0.02 mm" (`Setup.blended` is set for any move in continuous path,
    rapid or not). So does a program whose feed moves all run at a programmed `G64 P0.1` (written as such):
    its only move in a bare G64 is the first G0. Expected: no word on corners blended at the machine's
    tolerance where the run blended none at it."""
    if text is DRILL:
        program, machine_file = _write(tmp_path, text, AXES, "p.din")
        assert _cycle(program, machine_file, tmp_path) == _cycle(program, machine_file, tmp_path,
                                                                 time_model="rest-to-rest")
    head, code = _translated(tmp_path, text)
    assert text is DRILL or "G64 P0.1" in code
    assert "corners blended within" not in head, head


def test_rw_sympas_header_does_not_claim_the_motion_corner_tolerance(tmp_path):
    """An rw_SymPas program is timed by the card's own velocity profiles (`cycle_time_model` "card"), not by
    the path planner: `[motion] corner_tolerance` changes nothing in its cycle time (checked below). The header
    says "the cycle time assumed corners blended within 0.02 mm (... [motion] corner_tolerance)", a figure the
    run never used. Expected: the header names the card's model (its spooled joints), not the corner
    tolerance of the DIN/CPL/SINUMERIK planner."""
    for name in ("contour.sap", "machine.toml"):
        shutil.copy(ROOT / "examples" / "sympas" / name, tmp_path / name)
    program, machine_file = tmp_path / "contour.sap", tmp_path / "machine.toml"
    result = api.run_program(program, None, machine_file, RunOptions(state_dir=tmp_path / "st"))
    assert result.error is None and result.cycle_time_model == "card"
    loose = tmp_path / "loose.toml"
    loose.write_text(machine_file.read_text() + "\n[motion]\ncorner_tolerance = 5\n")
    assert _cycle(program, loose, tmp_path) == result.cycle_time_s
    out = tmp_path / "out.ngc"
    translate(program, out, "linuxcnc", machine=machine_file, options=RunOptions(state_dir=tmp_path / "st"))
    head, _ = _split(out.read_text(), "linuxcnc")
    assert "corner_tolerance" not in head and "corners blended within" not in head, head


def test_rest_to_rest_header_still_says_what_linuxcncs_bare_g64_does(tmp_path):
    """docs/translate.md: where a move ran in continuous path the header names the tolerance "or that the run
    timed every move from rest to rest" *and* what the target's bare G64 does (LinuxCNC: no tolerance at all).
    With `model = "rest-to-rest"` the header drops the second half: the user learns the new control "blends
    corners and takes less time", not that the bare G64 written keeps no bound on the corner deviation."""
    head, code = _translated(tmp_path, CONTOUR, machine=AXES + '[motion]\nmodel = "rest-to-rest"\n')
    assert "from rest to rest" in head
    assert "no tolerance at all" in head, head


def test_run_gcode_names_the_time_model_option_not_the_machines_model(tmp_path):
    """`ncvm run --gcode out.ngc --time-model rest-to-rest` on a machine whose `[motion] model` is lookahead
    (the built-in default here): the header says the run timed every move from rest to rest "(<machine>'s
    [motion] model)". The machine file says lookahead; it was the option. Expected: the header names
    `--time-model` as the cause (decisions.md: "by the machine's model or `--time-model`")."""
    program, machine_file = _write(tmp_path, CONTOUR, AXES, "p.din")
    out = tmp_path / "p.ngc"
    result = api.run_program(program, "din", machine_file,
                             RunOptions(state_dir=tmp_path / "st", gcode=out, time_model="rest-to-rest"))
    assert result.error is None
    head, _ = _split(out.read_text(), "linuxcnc")
    assert "from rest to rest" in head
    assert "[motion] model" not in head and "time-model" in head, head


def test_linuxcnc_output_writes_the_g64_its_header_speaks_of(tmp_path):
    """The header says "continuous path (G64 without a tolerance) ... on the new control G64 is no tolerance at
    all; G64 P0.02 keeps corners within the simulated tolerance", but a program that ran in DIN's power-on G64
    gets no G64 line at all: the file relies on the LinuxCNC's path mode as it finds it, and M2 does not reset
    the path mode, so the G61 or `G64 P..` a previous program left stays in force (the preamble resets plane,
    units, distance, feed mode, compensation, canned cycle -- not this). The user told to use `G64 P0.02` finds
    no G64 to change. (The 840D target writes its G64 in the preamble.) Expected: the LinuxCNC file states the
    path mode its header describes, before the first move that ran in it. Note: the engineers' test asserts the
    opposite on purpose ("LinuxCNC powers on in G64: nothing written"): a judgement call for the integrator."""
    head, code = _translated(tmp_path, CONTOUR)
    assert "G64 without a tolerance" in head
    first_move = next(i for i, line in enumerate(code) if line.startswith(("G0 ", "G1 ")))
    assert any(re.search(r"\bG64$", line) for line in code[:first_move]), code  # the preamble's last word
