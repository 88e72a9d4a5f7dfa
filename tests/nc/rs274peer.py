"""Driving LinuxCNC's standalone interpreter ``rs274`` (tests that use it skip when it is absent)."""

from __future__ import annotations

import json
import re
import shutil
import subprocess

import pytest

RS274 = shutil.which("rs274")
AXES = "XYZ"
#: plane -> (first axis, second axis, centre word of each) in rs274's ARC_FEED order
PLANES = {17: (0, 1, "I", "J"), 18: (2, 0, "K", "I"), 19: (1, 2, "J", "K")}
needs_rs274 = pytest.mark.skipif(RS274 is None, reason="rs274 not installed (Debian package linuxcnc-uspace)")


def rs274(ngc, canon) -> subprocess.CompletedProcess:
    """``rs274 -g ngc canon``; the peer itself now and then dies of a signal on this machine: try it again then
    (and skip the test when it keeps dying)."""
    for _ in range(3):
        proc = subprocess.run([RS274, "-g", str(ngc), str(canon)], stdin=subprocess.DEVNULL, capture_output=True,
                              text=True, timeout=60)
        if proc.returncode >= 0:
            return proc
    pytest.skip(f"rs274 keeps crashing (signal {-proc.returncode}); the peer is not usable here")


CALL = re.compile(r"(STRAIGHT_TRAVERSE|STRAIGHT_FEED|ARC_FEED|SET_G5X_OFFSET|SET_G92_OFFSET|SELECT_PLANE)\((.*)\)")


def rs274_moves(text: str) -> list[tuple[str, tuple, tuple | None]]:
    """(kind, machine end point, machine arc centre in plane order) for each move rs274 reports."""
    g5x, g92, plane = [0.0] * 3, [0.0] * 3, 17
    moves = []
    for line in text.splitlines():
        m = CALL.search(line)
        if not m:
            continue
        name, args = m.group(1), m.group(2)
        if name == "SELECT_PLANE":
            plane = {"CANON_PLANE_XY": 17, "CANON_PLANE_XZ": 18, "CANON_PLANE_YZ": 19}[args.strip()]
            continue
        nums = [float(x) for x in args.replace(" ", "").split(",")]
        if name == "SET_G5X_OFFSET":
            g5x = nums[1:4]
        elif name == "SET_G92_OFFSET":
            g92 = nums[0:3]
        else:
            off = [g5x[i] + g92[i] for i in range(3)]
            if name == "ARC_FEED":
                a, b, _, _ = PLANES[plane]
                n = 3 - a - b
                end = [0.0] * 3
                end[a], end[b], end[n] = nums[0], nums[1], nums[5]
                centre = (nums[2] + off[a], nums[3] + off[b])
                moves.append(("arc", tuple(end[i] + off[i] for i in range(3)), centre))
            else:
                kind = "rapid" if name == "STRAIGHT_TRAVERSE" else "feed"
                moves.append((kind, tuple(nums[i] + off[i] for i in range(3)), None))
    return moves


def ncvm_moves(trace_path) -> list[tuple[str, tuple, tuple | None]]:
    out = []
    for line in trace_path.read_text().splitlines():
        rec = json.loads(line)
        if rec["call"] in ("rapid", "feed", "arc"):
            end = tuple(rec["end"][a] for a in AXES)
            out.append((rec["call"], end, tuple(rec["center"]) if rec["call"] == "arc" else None))
    return out
