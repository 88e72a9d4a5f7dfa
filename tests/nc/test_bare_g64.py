"""A bare ``G64`` is continuous path at the machine's corner tolerance (docs/planner.md, machine data
``corner_tolerance``), the tolerance of the program start, whatever ``G64 P`` came before; ``G64 P`` sets
the tolerance until the next G64. The translation writes the same: ``G64 P<tol>`` where a programmed
tolerance is in force, a bare ``G64`` (the new control's own tolerance) where the machine's is."""

from __future__ import annotations

import pytest

from ncvm.machine.config import machine_from_dict
from ncvm.runtime.session import RunOptions
from ncvm.translate import translate

CORNER = "G1 X10\nG1 Y10\nM2\n"
AXES = '[[axis]]\nname = "X"\n[[axis]]\nname = "Y"\n[[axis]]\nname = "Z"\n'


def machine(tolerance: float):
    return machine_from_dict({"axis": [{"name": n} for n in "XYZ"], "motion": {"corner_tolerance": tolerance}})


@pytest.mark.parametrize("head", ["G64 P0.001 F3000\nG64", "G64 P0.001 F3000\nG61\nG64", "G64 P5 F3000\nG64"])
def test_a_bare_g64_gives_back_the_machines_corner_tolerance(run_text, head):
    at_start = run_text(f"G90 F3000\n{CORNER}", machine=machine(0.1))["cycle_time_s"]
    assert at_start != pytest.approx(run_text(f"G90 {head.split(chr(10))[0]}\n{CORNER}", machine=machine(0.1))
                                     ["cycle_time_s"], rel=1e-6)  # the P tolerance times the corner otherwise
    assert run_text(f"G90 {head}\n{CORNER}", machine=machine(0.1))["cycle_time_s"] == pytest.approx(at_start, rel=1e-12)


def test_g64_p_holds_until_the_next_g64(run_text):
    r = run_text(f"G90 G64 P0.001 F3000\nG61\nG1 X1\nG64 P0.5\n{CORNER}", machine=machine(0.1))
    exact_first = run_text(f"G90 G64 P0.5 F3000\nG61\nG1 X1\nG64 P0.5\n{CORNER}", machine=machine(0.1))
    assert r["cycle_time_s"] == pytest.approx(exact_first["cycle_time_s"], rel=1e-12)
    assert r["cycle_time_s"] != pytest.approx(run_text(f"G90 F3000\nG61\nG1 X1\nG64\n{CORNER}",
                                                       machine=machine(0.1))["cycle_time_s"], rel=1e-6)


def test_the_linuxcnc_translation_times_as_the_program(tmp_path, run_text):
    """The program and its LinuxCNC translation, run on the same machine, take the same time: ``G64 P``
    is written where the program's tolerance is in force, a bare ``G64`` where the machine's is."""
    text = "G90 G64 P0.001 F3000\nG1 X10\nG1 Y10\nG64\nG1 X20\nG1 Y20\nG64 P0.5\nG1 X30\nG1 Y30\nM2\n"
    (tmp_path / "machine.toml").write_text(AXES + "[motion]\ncorner_tolerance = 0.1\n")
    program = tmp_path / "p.ngc"
    program.write_text(text)
    out = tmp_path / "out.ngc"
    translate(program, out, "linuxcnc", machine=tmp_path / "machine.toml", options=RunOptions(state_dir=tmp_path / "st"))
    code = [line.split("(")[0].strip() for line in out.read_text().splitlines()]
    assert [line for line in code if line.startswith("G64")] == ["G64 P0.001", "G64", "G64 P0.5"], code
    timed = run_text(text, name="again.ngc", machine=tmp_path / "machine.toml")["cycle_time_s"]
    assert run_text(out.read_text(), name="translated.ngc", machine=tmp_path / "machine.toml")["cycle_time_s"] \
        == pytest.approx(timed, rel=1e-12)
