"""The run's bounds in the program's work frame, in every dialect: the summary line gives them by default,
labelled ``program`` (``--plot-frame machine``: the machine's, labelled ``machine``); ``--json`` has both,
``motion.bounds_program`` and the machine's ``motion.bounds``. Each program here runs in a zero offset (and a
tool length) that puts the machine elsewhere than the program's coordinates."""

from __future__ import annotations

import json
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from ncvm import api
from ncvm.cli import SUMMARY_WIDTH
from ncvm.runtime.session import RunOptions

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "examples"
MILL3 = str(EXAMPLES / "machines" / "mill3.toml")  # G54 = X200 Y150 Z-200


def ncvm_run(program: Path, *args: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "ncvm", "run", program.name, "--state", "st", *args],
                          cwd=program.parent, capture_output=True, text=True, timeout=300)


def summary(program: Path, *args: str) -> str:
    done = ncvm_run(program, *args)
    assert done.returncode == 0, done.stderr
    line = [ln for ln in done.stderr.splitlines() if ln.startswith("ncvm: ended")][-1]
    assert len(line) <= SUMMARY_WIDTH, line
    return line


def motion(program: Path, *args: str) -> dict:
    done = ncvm_run(program, "--json", *args)
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)["motion"]


def written(tmp_path: Path, name: str, text: str) -> Path:
    (tmp_path / name).write_text(text)
    return tmp_path / name


def copied(tmp_path: Path, example: str) -> Path:
    """An example in a copy of its folder (its machine file and sub-programs)."""
    src = EXAMPLES / example
    shutil.copytree(src.parent, tmp_path / "ex")
    return tmp_path / "ex" / src.name


def test_sinumerik_flange_bounds_are_the_programs_x_minus_37_to_37(tmp_path):
    """flange.mpf moves X -37..37 about the flange's centre in G54 (X 150.02, Y 99.99) with tool length 85.1;
    the machine went from its zero to X 186.98. The line says the program's, --plot-frame machine the
    machine's; --json has both."""
    program = copied(tmp_path, "sin800/flange.mpf")
    assert "program X[-36.96,36.96] Y[-36.96,36.96] Z[-12,50]" in summary(program)
    assert "machine X[0,186.98] Y[0,136.95] Z[0,135.1]" in summary(program, "--plot-frame", "machine")
    m = motion(program)
    assert m["bounds_program"]["X"] == pytest.approx([-36.955, 36.955], abs=1e-3)
    assert m["bounds_program"]["Z"] == pytest.approx([-12.0, 50.0])
    assert m["bounds"]["X"] == pytest.approx([0.0, 186.975], abs=1e-3)
    assert m["bounds"]["Z"] == pytest.approx([0.0, 135.1])


def test_din_program_in_g54(tmp_path):
    """G54 of the mill is X200 Y150 Z-200: the program's X-10..10 is the machine's X190..210 (and the machine
    began at its zero, which the program never named)."""
    program = written(tmp_path, "p.din", "N10 G90 G54 G0 X10 Y20 Z5\nN20 G1 X-10 F500\nN30 M30\n")
    assert "program X[-10,10] Y[20,20] Z[5,5]" in summary(program, "--machine", MILL3)
    assert "machine X[0,210] Y[0,170] Z[-195,0]" in summary(program, "--machine", MILL3, "--plot-frame", "machine")
    m = motion(program, "--machine", MILL3)
    assert m["bounds_program"] == {"X": [-10.0, 10.0], "Y": [20.0, 20.0], "Z": [5.0, 5.0]}
    assert m["bounds"] == {"X": [0.0, 210.0], "Y": [0.0, 170.0], "Z": [-195.0, 0.0]}


def test_din_arc_reach_counts_in_the_work_frame(tmp_path):
    """A full circle of radius 10 about the program's X0 Y0 in G54: it reaches X and Y -10..10 between its ends."""
    program = written(tmp_path, "p.din", "N10 G90 G54 G0 X10 Y0 Z5\nN20 G2 X10 Y0 I-10 J0 F500\nN30 M30\n")
    m = motion(program, "--machine", MILL3)
    assert m["bounds_program"]["X"] == pytest.approx([-10.0, 10.0])
    assert m["bounds_program"]["Y"] == pytest.approx([-10.0, 10.0])


def test_cpl_program_in_g54_and_an_additive_shift(tmp_path):
    """CPL: G54 from the machine's table, then the external (additive) shift G160 of X 40 (manual L1773, FXC):
    the zero offset is taken off, the shift stays in -- the work frame the plot draws (docs/decisions.md)."""
    program = written(tmp_path, "p.cpl", '10 FXC("X",160,0)=40\nN20 G54 G0 X10 Y20 Z5\nN30 G1 X-10 F500\n'
                                         "N40 G160 X0\nN50 G1 X5\nN60 M30\n")
    assert "program X[-10,45] Y[20,20] Z[5,5]" in summary(program, "--machine", MILL3)
    assert "machine X[0,245] Y[0,170] Z[-195,0]" in summary(program, "--machine", MILL3, "--plot-frame", "machine")
    m = motion(program, "--machine", MILL3)
    assert m["bounds_program"]["X"] == [-10.0, 45.0] and m["bounds"]["X"] == [0.0, 245.0]


def test_cpl_offset_written_in_the_run_moves_the_work_frame_from_there_on(tmp_path):
    """A zero offset rewritten while the program runs (FXC on the active table): the moves before keep the old
    offset, those after take the new one -- bounds per move, as the plot draws them."""
    program = written(tmp_path, "p.cpl", "N10 G54 G0 X10 Y20 Z5\n20 FXC(1,54)=250\nN30 G1 X-10 F500\nN40 M30\n")
    m = motion(program, "--machine", MILL3)
    assert m["bounds_program"]["X"] == [-10.0, 10.0], m
    assert m["bounds"]["X"] == [0.0, 260.0], m  # the axis moved with the offset written


@pytest.mark.parametrize("name, text", [
    ("p.din", "N10 G90 G54 G0 X10 Y20 Z5\nN20 G1 X-10 F500\nN30 G55 G0 X5\nN40 G92 X100\nN50 G1 X110\nN60 M30\n"),
    ("p.cpl", "N10 G90 G54 G0 X10 Y20 Z5\nN20 G1 X-10 F500\nN30 G55 G0 X5\nN40 G1 X30\nN50 M30\n"),
])
def test_zero_offset_changed_mid_program_bounds_are_the_trace_work_of_each_move(tmp_path, name, text):
    """G54 then G55 (and G92) part way: the program's bounds are the lowest and highest ``work`` coordinates
    the trace gives the moves, each with the offsets it ran with (review18e; the rw_SymPas card's SZPA/SZPR in
    tests/dialects/sympas/test_sympas_work_shift.py) -- not the machine's less the offsets at the end."""
    program = written(tmp_path, name, text)
    m = motion(program, "--machine", MILL3, "--trace", "t.jsonl")
    moves = [r for r in map(json.loads, (tmp_path / "t.jsonl").read_text().splitlines()) if "work" in r]
    for axis in "XYZ":
        work = [r["work"][axis] for r in moves]
        assert m["bounds_program"][axis] == pytest.approx([min(work), max(work)], abs=1e-6), (axis, m)
    assert m["bounds_program"]["X"][0] == -10.0 and m["bounds"]["X"][1] >= 400.0, m  # the G55 moves: machine 400+


def test_cl800_program_in_g54_with_a_tool_length(tmp_path):
    """CL 800 on the SINUMERIK 880 of the examples (G54 X 150.02 Y 99.99)."""
    shutil.copy(EXAMPLES / "sin800" / "machine.toml", tmp_path / "machine.toml")
    program = written(tmp_path, "p.cl8", "PROGRAM 90;\nCHANNEL NC 0;\nBEGIN\n"
                                         "  LF; (: G90 G54 G00 X10 Y20 Z5 :); LF;\n  (: G01 X-10 F500 :); LF;\n"
                                         "  (: M30 :); LF;\nEND.\n")
    assert "program X[-10,10] Y[20,20] Z[5,5]" in summary(program)
    assert "machine X[0,160.02] Y[0,119.99] Z[0,5]" in summary(program, "--plot-frame", "machine")
    m = motion(program)
    assert m["bounds_program"]["X"] == pytest.approx([-10.0, 10.0])


def test_sympas_bounds_program_in_motion_and_as_before(tmp_path):
    """rw_SymPas: the top-level ``bounds_program`` (kept for the scripts that read it) stands in
    ``motion.bounds_program`` too, under the program's axis names (each move less the zero point it ran with)."""
    program = copied(tmp_path, "sympas/pick_place.sap")
    assert "program A1[-0.03,290] A2[-0.03,190] A3[-60,0.01]" in summary(program)
    assert "machine A1[-5.03,285] A2[-5.03,185] A3[-55,5.01]" in summary(program, "--plot-frame", "machine")
    done = ncvm_run(program, "--json")
    doc = json.loads(done.stdout)
    assert doc["motion"]["bounds_program"] == doc["bounds_program"]
    assert doc["motion"]["bounds_program"] != doc["motion"]["bounds"]


def test_bounds_program_are_the_plots_extents(tmp_path):
    """The line says what the plot shows: the drawn points of flange.mpf (arcs sampled) span the bounds."""
    program = copied(tmp_path, "sin800/flange.mpf")
    result, session = api.run(program, None, program.parent / "machine.toml",
                              RunOptions(state_dir=tmp_path / "st", plot=True, echo=False))
    assert result["error"] is None, result["error"]
    drawn = np.concatenate(list(session.plot.drawn().values()))
    for i, axis in enumerate("XYZ"):
        lo, hi = result["motion"]["bounds_program"][axis]
        assert (np.nanmin(drawn[:, i]), np.nanmax(drawn[:, i])) == pytest.approx((lo, hi), abs=0.05), axis
