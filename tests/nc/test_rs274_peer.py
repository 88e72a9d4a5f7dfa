"""Differential test against LinuxCNC's standalone interpreter ``rs274`` (skipped when it is absent).

Random plain programs (lines, arcs in all three planes with I/J/K and R forms, helices, G90/G91, zero
offsets set by G10 L2 and selected by G54-G59, G92 and G92.1) run through ncvm and through
``rs274 -g``; every move's end point and every arc's centre must agree to 1e-4 mm in machine
coordinates. rs274 reports positions in the active coordinate system, so its SET_G5X_OFFSET and
SET_G92_OFFSET calls are added back.
"""

from __future__ import annotations

import math
import random
import re

import pytest
from rs274peer import AXES, PLANES, RS274, ncvm_moves, rs274, rs274_moves

from ncvm.api import run
from ncvm.machine.config import machine_from_dict
from ncvm.runtime.session import RunOptions

pytestmark = pytest.mark.skipif(RS274 is None, reason="rs274 not installed (Debian package linuxcnc-uspace)")

N_PROGRAMS = 24


def _r(v: float) -> float:
    return round(v, 4)


def generate(seed: int) -> tuple[str, int]:
    """A random program and the number of moves in it. Tracks machine position to build valid arcs."""
    rnd = random.Random(seed)
    out = ["G21 G17 G90 G94 G40 G49"]
    for p in range(1, 7):
        out.append(f"G10 L2 P{p} " + " ".join(f"{a}{_r(rnd.uniform(-50, 50))}" for a in AXES))
    offsets = {54 + p - 1: None for p in range(1, 7)}
    for line in out[1:]:
        nums = [float(x) for x in re.findall(r"[XYZ](-?[\d.]+)", line)]
        offsets[53 + int(line.split()[2][1:])] = nums
    system, g92 = 54, [0.0, 0.0, 0.0]
    mpos = [0.0, 0.0, 0.0]
    absolute, plane, moves = True, 17, 0

    def prog(m):
        return [m[i] - offsets[system][i] - g92[i] for i in range(3)]

    out.append("G54 G0 X0 Y0 Z0 F500")
    mpos = list(offsets[54])
    moves += 1
    for _ in range(rnd.randint(30, 60)):
        kind = rnd.random()
        cur = prog(mpos)
        if kind < 0.08:
            system = rnd.choice(list(offsets))
            out.append(f"G{system}")
            continue
        if kind < 0.12:
            absolute = not absolute
            out.append("G90" if absolute else "G91")
            continue
        if kind < 0.15:
            axis = rnd.randrange(3)
            value = _r(rnd.uniform(-20, 20))
            g92[axis] = mpos[axis] - offsets[system][axis] - value
            out.append(f"G92 {AXES[axis]}{value}")
            continue
        if kind < 0.17:
            g92 = [0.0, 0.0, 0.0]
            out.append("G92.1")
            continue
        words = []
        if kind < 0.55:
            target = [_r(rnd.uniform(-80, 80)) if rnd.random() < 0.7 else cur[i] for i in range(3)]
            code = "G0" if rnd.random() < 0.3 else "G1"
        else:
            new_plane = rnd.choice([17, 17, 18, 19])
            if new_plane != plane:
                plane = new_plane
                out.append(f"G{plane}")
            a, b, wa, wb = PLANES[plane]
            n = 3 - a - b
            ca, cb = cur[a] + _r(rnd.uniform(-30, 30)), cur[b] + _r(rnd.uniform(-30, 30))
            radius = math.hypot(cur[a] - ca, cur[b] - cb)
            if radius < 1.0:
                continue
            ang = rnd.uniform(0, 2 * math.pi)
            target = list(cur)
            target[a], target[b] = _r(ca + radius * math.cos(ang)), _r(cb + radius * math.sin(ang))
            if rnd.random() < 0.3:
                target[n] = _r(cur[n] + rnd.uniform(-5, 5))  # helix
            cw = rnd.random() < 0.5
            code = "G2" if cw else "G3"
            if rnd.random() < 0.25 and math.hypot(target[a] - cur[a], target[b] - cur[b]) > 2.0:
                # R form: rs274 and ncvm both recompute the centre from the end point
                words.append(f"R{_r(math.hypot(target[a] - ca, target[b] - cb))}")
            else:
                words += [f"{wa}{_r(ca - cur[a])}", f"{wb}{_r(cb - cur[b])}"]
        coords = [f"{AXES[i]}{_r(target[i] if absolute else target[i] - cur[i])}" for i in range(3)]
        out.append(" ".join([code, *coords, *words]))
        mpos = [target[i] + offsets[system][i] + g92[i] for i in range(3)]
        moves += 1
    out.append("M2")
    return "\n".join(out) + "\n", moves


def run_rs274(ngc, canon) -> None:
    proc = rs274(ngc, canon)
    assert proc.returncode == 0, f"rs274 rejected {ngc.name} (exit {proc.returncode}): {proc.stderr}"


def test_generated_programs_agree_with_rs274(tmp_path):
    machine_def = {"axis": [{"name": a} for a in AXES]}
    compared = 0
    for seed in range(N_PROGRAMS):
        text, expected_moves = generate(seed)
        ngc = tmp_path / f"gen{seed}.ngc"
        ngc.write_text(text)
        canon = tmp_path / f"gen{seed}.canon"
        run_rs274(ngc, canon)
        theirs = rs274_moves(canon.read_text())
        trace = tmp_path / f"gen{seed}.jsonl"
        result, _ = run(ngc, machine=machine_from_dict(machine_def),
                        options=RunOptions(state_dir=tmp_path / "st", trace=trace))
        assert result["status"] == "ok", (seed, result["error"])
        ours = ncvm_moves(trace)
        assert len(theirs) == expected_moves, f"seed {seed}: rs274 made {len(theirs)} moves"
        assert len(ours) == len(theirs), f"seed {seed}: {len(ours)} moves against rs274's {len(theirs)}"
        for i, ((k1, e1, c1), (k2, e2, c2)) in enumerate(zip(ours, theirs)):
            where = f"seed {seed}, move {i + 1}"
            assert k1 == k2, where
            assert e1 == pytest.approx(e2, abs=1e-4), where
            if c2 is not None:
                assert c1 == pytest.approx(c2, abs=1e-4), where
            compared += 1
    assert compared > 20 * N_PROGRAMS
    print(f"compared {compared} moves of {N_PROGRAMS} programs with rs274")
