"""The run's summary line: one number format, bounds that say their frame, and a width that does not grow
past 160 characters with the machine's axes (every figure in full stands in ``--json``)."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

from ncvm.cli import SUMMARY_WIDTH, _fitted_bounds


def run(tmp_path: Path, program: str, *args: str) -> subprocess.CompletedProcess:
    (tmp_path / "p.din").write_text(program)
    return subprocess.run([sys.executable, "-m", "ncvm", "run", "p.din", "--state", "st", *args], cwd=tmp_path,
                          capture_output=True, text=True, timeout=300)


def test_counts_and_path_write_thousands_alike(tmp_path):
    """A path of 2,000 mm and 1,001 moves: every count and length with the same thousands separator."""
    lines = "".join(f"N{i} G1 X{i % 2} F5000\n" for i in range(1, 1002))
    done = run(tmp_path, "N0 G90 G0 X0 Y0 Z0\n" + lines + "N9999 M30\n")
    assert done.returncode == 0, done.stderr
    line = done.stderr.splitlines()[-1]
    assert "1,002 moves" in line and "path 1,001.0 mm" in line, line


def test_bounds_name_their_frame_and_json_keeps_them_in_full(tmp_path):
    """The program's bounds by default (the points it reached; not the machine's zero where the run began),
    the machine's with --plot-frame machine; both in full in --json."""
    program = "N1 G90 G0 X-12.3456 Y7 Z3\nN2 G1 X20 F1000\nN3 M30\n"
    done = run(tmp_path, program)
    assert done.returncode == 0, done.stderr
    assert "program X[-12.35,20] Y[7,7] Z[3,3]" in done.stderr.splitlines()[-1]
    done = run(tmp_path, program, "--plot-frame", "machine")
    assert "machine X[-12.35,20] Y[0,7] Z[0,3]" in done.stderr.splitlines()[-1]
    done = run(tmp_path, program, "--json")
    assert json.loads(done.stdout)["motion"]["bounds"]["X"] == [-12.3456, 20.0]
    assert json.loads(done.stdout)["motion"]["bounds_program"]["Y"] == [7.0, 7.0]


def test_many_axes_are_rounded_and_then_named_as_left_to_json():
    """Rounded to whole units when 0.01 does not fit; when whole units do not fit either, the axes that fit
    and how many more ``--json`` holds -- never a line past the room it was given."""
    bounds = {a: [-123456.78, 123456.78] for a in "XYZABCUVW"}
    for room in (60, 100, SUMMARY_WIDTH):
        text = _fitted_bounds(bounds, "machine", room)
        assert len(text) <= room, text
        assert text.startswith(", machine X[-123457,123457]") and "axes in --json" in text, text
    assert _fitted_bounds({"X": [-1.234, 5]}, "machine", 80) == ", machine X[-1.23,5]"
    assert _fitted_bounds({"X": [-1.234, 5], "Y": [0, 1.5]}, "machine", 24) == ", machine X[-1,5] Y[0,2]"
