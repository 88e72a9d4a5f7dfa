"""Canned cycles G73, G74, G81-G89 in `din` with LinuxCNC's semantics (interp_cycles.cc): hand-computed
cases, the errors, and a differential test against ``rs274 -g`` on generated programs (skipped without it)."""

from __future__ import annotations

import json
import random

import pytest
from rs274peer import AXES, ncvm_moves, needs_rs274, rs274, rs274_moves

from ncvm.api import run
from ncvm.machine.config import machine_from_dict
from ncvm.nc.block import Block
from ncvm.nc.canon import Canon, Src
from ncvm.nc.cycles import CannedCycles
from ncvm.nc.kernel import NcKernel
from ncvm.runtime.session import RunOptions

XYZ = {"axis": [{"name": a} for a in AXES]}
#: plane -> its (first, second, normal) axis letters
PLANE_AXES = {17: "XYZ", 18: "ZXY", 19: "YZX"}


def run_din(tmp_path, text: str, name: str = "cyc"):
    ngc = tmp_path / f"{name}.ngc"
    ngc.write_text(text)
    trace = tmp_path / f"{name}.jsonl"
    result, _ = run(ngc, machine=machine_from_dict(XYZ), options=RunOptions(state_dir=tmp_path / "st", trace=trace))
    return result, trace


def moves(tmp_path, text: str) -> list[tuple[str, tuple]]:
    result, trace = run_din(tmp_path, text)
    assert result["status"] == "ok", result["error"]
    return [(kind, end) for kind, end, _c in ncvm_moves(trace)]


def test_g81_r_plane_and_modal_repeat(tmp_path):
    """G81 from Z5 with R1 Z-2 under G99: position, down to R, drill, back to R; X5 repeats it there."""
    got = moves(tmp_path, "G21 G17 G90 F100\nG0 X1 Y0 Z5\nG81 X3 Y4 Z-2 R1\nX5\nG80\nM2\n")
    assert got == [("rapid", (1, 0, 5)), ("rapid", (3, 4, 5)), ("rapid", (3, 4, 1)), ("feed", (3, 4, -2)),
                   ("rapid", (3, 4, 1)), ("rapid", (5, 4, 1)), ("feed", (5, 4, -2)), ("rapid", (5, 4, 1))]


def test_g98_g91_with_l_repeats(tmp_path):
    """G91 G98: X steps L times; R counts from the initial level Z5 (R-1 -> 4), Z from R (Z-3 -> 1); the
    tool returns to the initial level after each hole."""
    got = moves(tmp_path, "G21 G17 G90 F100\nG0 X0 Y0 Z5\nG91 G98 G81 X5 R-1 Z-3 L2\nM2\n")
    assert got == [("rapid", (0, 0, 5)), ("rapid", (5, 0, 5)), ("rapid", (5, 0, 4)), ("feed", (5, 0, 1)),
                   ("rapid", (5, 0, 5)), ("rapid", (10, 0, 5)), ("rapid", (10, 0, 4)), ("feed", (10, 0, 1)),
                   ("rapid", (10, 0, 5))]


def test_g83_pecks_back_to_r_and_down_to_the_clearance_above_the_last_depth(tmp_path):
    """G83 Q1.5 from R1 to Z-3: pecks to -0.5 and -2, each time out to R and back to 0.254 mm above it."""
    got = moves(tmp_path, "G21 G90 F100\nG0 X0 Y0 Z1\nG83 Z-3 R1 Q1.5\nM2\n")
    zs = [e[2] for _k, e in got[1:]]
    assert zs == pytest.approx([1, -0.5, 1, -0.246, -2, 1, -1.746, -3, 1])


@pytest.mark.parametrize("text, message", [
    ("G81 X1 Z-1\n", "R clearance plane unspecified"),
    ("G81 X1 R1\n", "Z value (the depth) unspecified"),
    ("G81 X1 R-2 Z-1\n", "R plane below the depth"),
    ("G82 X1 R1 Z-1\n", "dwell time P word missing"),
    ("G83 X1 R1 Z-1\n", "Q word (the peck depth) missing"),
    ("G83 X1 R1 Z-1 Q-1\n", "peck depth Q must be positive"),
    ("G81 X1 R1 Z-1 L0\n", "runs at least once"),
    ("G84 X1 R1 Z-1\n", "spindle turning clockwise (M3)"),
    ("G81 X1 R1 Z-1\nG80 X2\n", "axis word X with G80"),
    ("G81 X1 R1 Z-1\nG80\nX2\n", "axis word X with G80"),
])
def test_rs274s_cycle_errors(tmp_path, text, message):
    result, _ = run_din(tmp_path, "G21 G17 G90 F100\nG0 X0 Y0 Z5\n" + text + "M2\n")
    assert result["status"] == "error" and result["error"]["code"] == "NC009"
    assert message in result["error"]["message"]


def test_g80_then_g0_runs_on_column_wise(tmp_path):
    """After G80 the plain blocks that follow a G0 run as before (the column path)."""
    got = moves(tmp_path, "G21 F100\nG0 Z5\nG81 X1 R1 Z-1\nG80\nG0 X2\nX3 Y1\nG1 X4\nM2\n")
    assert got[-3:] == [("rapid", (2, 0, 1)), ("rapid", (3, 1, 1)), ("feed", (4, 1, 1))]


def _r(v: float) -> str:
    return f"{v:.3f}"


def generate(seed: int) -> str:
    """A program of canned cycles: every cycle, the three planes, G90/G91, G98/G99, L, P, Q, G80 and moves,
    in mm or in inch."""
    rnd = random.Random(seed)
    units = 20 if seed % 4 == 3 else 21  # every fourth program in inch (the same numbers, read as inches)
    out = [f"G{units} G17 G90 G94 G40 G49 F300 S1000 M3", f"G10 L2 P1 X{_r(rnd.uniform(-20, 20))} Y{_r(rnd.uniform(-20, 20))} "
           f"Z{_r(rnd.uniform(-5, 5))}", "G54", f"G0 X{_r(rnd.uniform(-30, 30))} Y{_r(rnd.uniform(-30, 30))} "
           f"Z{_r(rnd.uniform(5, 30))}"]
    plane, spindle = 17, 1
    for _ in range(rnd.randint(5, 10)):
        cycle = rnd.choice((73, 74, 81, 82, 83, 84, 85, 86, 87, 88, 89))
        if cycle in (74, 84, 87):  # G87 is G17's only; rs274's G74/G84 in G18/G19 feed to swapped coordinates
            if plane != 17:
                plane = 17
                out.append("G17")
        elif rnd.random() < 0.4:
            plane = rnd.choice((17, 18, 19))
            out.append(f"G{plane}")
        want = -1 if cycle == 74 else 1
        if want != spindle:
            spindle = want
            out.append("M4" if want < 0 else "M3")
        a, b, n = PLANE_AXES[plane]
        absolute = rnd.random() < 0.6
        words = [f"G{rnd.choice((98, 99))}", "G90" if absolute else "G91", f"G{cycle}"]
        if absolute:
            r = rnd.uniform(-2, 10)
            words += [f"{a}{_r(rnd.uniform(-40, 40))}", f"{b}{_r(rnd.uniform(-40, 40))}", f"R{_r(r)}",
                      f"{n}{_r(r - rnd.uniform(0.5, 12))}"]
        else:
            words += [f"{a}{_r(rnd.uniform(-10, 10))}", f"{b}{_r(rnd.uniform(-10, 10))}",
                      f"R{_r(rnd.uniform(-6, 6))}", f"{n}{_r(-rnd.uniform(0.5, 12))}"]
        if cycle in (73, 83):
            words.append(f"Q{_r(rnd.uniform(0.4, 4))}")
        if cycle in (82, 86, 88, 89) or (cycle in (74, 84) and rnd.random() < 0.5):
            words.append(f"P{_r(rnd.uniform(0, 2))}")
        if cycle == 87:
            words += [f"I{_r(rnd.uniform(-3, 3))}", f"J{_r(rnd.uniform(-3, 3))}", f"K{_r(rnd.uniform(0.2, 3))}"]
            if absolute:  # K (the top of the back bore) absolute: between the bottom and R
                words[-1] = f"K{_r(r - rnd.uniform(0.1, 0.4))}"
        if rnd.random() < 0.3 and cycle != 74:  # rs274 2.9 refuses L with G74 ("L word with no ... canned cycle")
            words.append(f"L{rnd.randint(1, 3)}")
        out.append(" ".join(words))
        for _ in range(rnd.randint(0, 3)):  # modal repeats at other positions
            step = 10 if absolute else 4
            out.append(f"{a}{_r(rnd.uniform(-step, step))} {b}{_r(rnd.uniform(-step, step))}")
        if rnd.random() < 0.5:
            out.append("G80")
            out.append(f"G90 G0 X{_r(rnd.uniform(-30, 30))} Y{_r(rnd.uniform(-30, 30))} Z{_r(rnd.uniform(5, 30))}")
        elif rnd.random() < 0.3:
            out.append(f"G90 G1 {n}{_r(rnd.uniform(5, 30))}")
    out.append("M2")
    return "\n".join(out) + "\n"


def rs274_dwells(text: str) -> list[float]:
    return [float(line.split("DWELL(")[1].rstrip(")")) for line in text.splitlines() if "DWELL(" in line]


def ncvm_dwells(trace) -> list[float]:
    return [rec["seconds"] for rec in map(json.loads, trace.read_text().splitlines()) if rec["call"] == "dwell"]


N_PROGRAMS = 40


@needs_rs274
def test_generated_cycle_programs_agree_with_rs274(tmp_path):
    programs = compared = 0
    for seed in range(N_PROGRAMS):
        text = generate(seed)
        ngc = tmp_path / f"cyc{seed}.ngc"
        ngc.write_text(text)
        canon = tmp_path / f"cyc{seed}.canon"
        proc = rs274(ngc, canon)
        assert proc.returncode == 0, (seed, proc.stdout[-300:], text)
        theirs = rs274_moves(canon.read_text())
        result, trace = run_din(tmp_path, text, f"cyc{seed}")
        assert result["status"] == "ok", (seed, result["error"])
        unit = 25.4 if text.startswith("G20") else 1.0  # rs274 reports positions in the program's unit
        ours = [(kind, tuple(v / unit for v in end), c) for kind, end, c in ncvm_moves(trace)]
        assert len(ours) == len(theirs), f"seed {seed}: {len(ours)} moves against rs274's {len(theirs)}"
        for i, ((k1, e1, _c1), (k2, e2, _c2)) in enumerate(zip(ours, theirs)):
            assert (k1, e1) == (k2, pytest.approx(e2, abs=1e-4)), f"seed {seed}, move {i + 1}"
        assert ncvm_dwells(trace) == pytest.approx(rs274_dwells(canon.read_text()), abs=1e-4), seed
        programs += 1
        compared += len(ours)
    assert programs == N_PROGRAMS and compared > 40 * N_PROGRAMS
    print(f"compared {compared} moves of {programs} canned-cycle programs (10 in inch) with rs274: all equal")


def test_a_fork_keeps_its_own_cycle_state():
    k = NcKernel(machine_from_dict(XYZ), Canon([]))
    k.canned = CannedCycles()
    k.execute(Block((0, 99), (), {"Z": 5.0, "F": 100.0}, None, None, Src("t", 1)))
    shadow = k.fork()
    shadow.execute(Block((98, 81), (), {"X": 1.0, "R": 2.0, "Z": -1.0}, None, None, Src("t", 2)))
    assert (k.canned.retract_to_r, k.canned.r, k.motion) == (True, 0.0, 0)
    assert (shadow.canned.retract_to_r, shadow.canned.r, shadow.motion) == (False, 2.0, 81)
