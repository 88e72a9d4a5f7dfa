"""A short run settles its moves in plain Python (issue 18: no numpy for a run with a few moves): the
planner's flush of fewer than ``planner.SMALL`` moves and the toolpath window of fewer than
``toolpath.SMALL`` single moves (its totals, the soft-limit check and the work bounds) give the numpy
paths' results to the last bit. Random DIN programs (rapid and feed moves, arcs and helices, G92 offsets,
exact stops, dwells and M functions between moves, soft-limit violations) run both ways: the whole result
and the trace must be equal."""

from __future__ import annotations

import math
import random
from pathlib import Path

import pytest

import ncvm.nc.planner as planner
import ncvm.sinks.toolpath as toolpath
from ncvm.api import RunOptions, run

MACHINE = """[machine]
name = "m"
[[axis]]
name = "X"
min = -40.0
max = 40.0
[[axis]]
name = "Y"
min = -30.0
max = 60.0
accel = 600.0
[[axis]]
name = "Z"
min = -20.0
max = 20.0
accel = 300.0
max_feed = 2000.0
"""


def program(rng: random.Random, moves: int) -> str:
    lines = [rng.choice(("G90 G64", "G90 G61", "G90 G64 P0.05")) + f" F{rng.uniform(100.0, 6000.0):.3f}"]
    x = y = z = 0.0
    if rng.random() < 0.4:
        x, y = round(rng.uniform(-5, 5), 3), round(rng.uniform(-5, 5), 3)  # the position, as the program sees it
        lines.append(f"G92 X{x} Y{y}")
    for _ in range(moves):
        r = rng.random()
        if r < 0.15:
            lines.append(rng.choice(("G4 P0.2", "M3 S1000", "M5", "G9 G1 X%.4f" % (x + 1.0))))
            if lines[-1].startswith("G9"):
                x += 1.0
            continue
        if r < 0.4:  # an arc (a helix when Z moves too), its end on the circle
            i, j = rng.uniform(-15, 15), rng.uniform(-15, 15)
            cx, cy, radius = x + i, y + j, math.hypot(i, j)
            phi = rng.uniform(0, 2 * math.pi)
            x, y = round(cx + radius * math.cos(phi), 6), round(cy + radius * math.sin(phi), 6)
            helix = f" Z{z + rng.uniform(-5, 5):.4f}" if rng.random() < 0.3 else ""
            lines.append(f"{rng.choice(('G2', 'G3'))} X{x} Y{y}{helix} I{i:.6f} J{j:.6f}")
            continue
        x, y = x + rng.uniform(-30, 30), y + rng.uniform(-30, 30)
        z = z + rng.choice((0.0, 0.0, rng.uniform(-10, 10)))
        lines.append(f"{rng.choice(('G0', 'G1', 'G1', 'G1'))} X{x:.4f} Y{y:.4f} Z{z:.4f}")
    return "\n".join(lines + ["M2"]) + "\n"


def run_both(tmp_path: Path, monkeypatch, text: str):
    (tmp_path / "p.ngc").write_text(text)
    (tmp_path / "m.toml").write_text(MACHINE)
    monkeypatch.chdir(tmp_path)
    out = []
    for small in (True, False):
        if not small:
            monkeypatch.setattr(planner, "SMALL", 0)
            monkeypatch.setattr(toolpath, "SMALL", 0)
        trace = tmp_path / f"t{small}.jsonl"
        result, _ = run("p.ngc", machine="m.toml", options=RunOptions(state_dir=tmp_path / "s", trace=trace))
        out.append((result, trace.read_text()))
    return out


@pytest.mark.parametrize("seed", range(30))
def test_a_short_run_settles_as_the_numpy_paths_do(tmp_path, monkeypatch, seed):
    rng = random.Random(seed)
    moves = rng.choice((1, 2, 3, 5, 7, 7, 12, 40, 70))
    (python, python_trace), (numpy, numpy_trace) = run_both(tmp_path, monkeypatch, program(rng, moves))
    assert python["status"] == "ok", python["error"]
    assert python == numpy
    assert python_trace == numpy_trace


def test_the_soft_limit_violation_of_a_short_run_names_its_move(tmp_path, monkeypatch):
    text = "G90 G1 X10 F1000\nG1 X50 Y70\nG2 X50 Y10 I0 J-30\nM2\n"
    (python, _), (numpy, _) = run_both(tmp_path, monkeypatch, text)
    assert python == numpy
    assert python["limit_violations"] == [
        "axis X reaches 50.0000, above its soft limit 40.0000 (first at p.ngc:2)",
        "axis Y reaches 70.0000, above its soft limit 60.0000 (first at p.ngc:2)"]
    assert python["motion"]["bounds"]["X"] == [0.0, 80.0]  # the arc reaches X 80 at its quadrant point
