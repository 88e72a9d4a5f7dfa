"""Reading translations back: the programs a test translates, a reader of the three targets' G-code, the
trace's motions, and rs274's canon output (for the tests of tests/translate)."""

from __future__ import annotations

import json
import math
import re
from pathlib import Path

from ncvm.dialects import EXTENSIONS

ROOT = Path(__file__).parents[2]
AXES = "XYZ"


def _main_programs(folder: Path) -> list[Path]:
    listing = folder / "main.txt"
    if listing.is_file():
        return [folder / name.strip() for name in listing.read_text().splitlines() if name.strip()]
    return sorted(p for p in folder.iterdir() if p.suffix.lower() in EXTENSIONS)


def programs() -> list[Path]:
    """Every example main program and every golden test program (those with an expected result)."""
    out = []
    for folder in sorted(p for p in (ROOT / "examples").iterdir() if p.is_dir() and p.name != "machines"):
        out += _main_programs(folder)
    for folder in sorted(p for p in (ROOT / "tests" / "programs").iterdir() if p.is_dir()):
        out += [p for p in sorted(folder.iterdir())
                if p.suffix.lower() in EXTENSIONS and p.with_suffix(".expected.json").is_file()]
    return out


def inputs(program: Path) -> dict:
    """The machine, scenario and key script that go with a program (as examples/run_all.py finds them)."""
    machine = program.parent / "machine.toml"
    scenario = program.with_suffix(".scenario.toml")
    keys = program.with_suffix(".keys")
    return {"machine": machine if machine.is_file() else None, "scenario": scenario if scenario.is_file() else None,
            "keys": keys if keys.is_file() else None}


def trace_moves(path: Path) -> list[tuple[str, tuple]]:
    """(kind, work end point X Y Z) of every motion of a JSONL trace; a probe move ends at its target; a home
    search is no move of the program (a translation says to home the axes instead)."""
    out, probe, homing = [], None, False
    for line in path.read_text().splitlines():
        rec = json.loads(line)
        if rec["call"] == "probe":
            probe = rec["target"]
        elif rec["call"] == "homing":
            homing = True
        elif homing and rec["call"] in ("rapid", "feed"):
            homing = False
        elif rec["call"] in ("rapid", "feed", "arc"):
            work = dict(rec["work"])
            kind = rec["call"]
            if probe is not None:
                work.update(probe)
                kind, probe = "probe", None
            out.append((kind, tuple(work.get(a, 0.0) for a in AXES)))
    return out


RS274_CALL = re.compile(r"(STRAIGHT_TRAVERSE|STRAIGHT_FEED|ARC_FEED|STRAIGHT_PROBE|SELECT_PLANE)\((.*)\)")
RS274_PLANES = {"CANON_PLANE_XY": (0, 1), "CANON_PLANE_XZ": (2, 0), "CANON_PLANE_YZ": (1, 2)}


def rs274_moves(text: str) -> list[tuple[str, tuple]]:
    """(kind, end point X Y Z) of every motion rs274 reports (its program coordinates: no offset is set)."""
    plane, out = (0, 1), []
    for line in text.splitlines():
        m = RS274_CALL.search(line)
        if not m:
            continue
        name, args = m.groups()
        if name == "SELECT_PLANE":
            plane = RS274_PLANES[args.strip()]
            continue
        nums = [float(x) for x in args.replace(" ", "").split(",")]
        if name == "ARC_FEED":
            a, b = plane
            end = [0.0] * 3
            end[a], end[b], end[3 - a - b] = nums[0], nums[1], nums[5]
            out.append(("arc", tuple(end)))
        else:
            kind = {"STRAIGHT_TRAVERSE": "rapid", "STRAIGHT_FEED": "feed", "STRAIGHT_PROBE": "probe"}[name]
            out.append((kind, tuple(nums[:3])))
    return out


WORD = re.compile(r"(MEAS=1|TURN=\d+|SUPA|[A-Z]-?\d*\.?\d+)")


def read_back(text: str, target: str, tools: dict[int, float]) -> tuple[list[tuple[str, tuple]], list[str]]:
    """Our reader of a translation: (kind, work end point X Y Z) per motion, and the words that end it.

    Comments are dropped ("( )" on LinuxCNC and ISO, "; " on the 840D); a G53 / SUPA move's machine
    coordinates become work coordinates by taking off the tool length in force (on the 840D, which keeps
    the tool length in SUPA, the translation writes D0 right before a SUPA move and the D again after it:
    the length before that D0 counts).
    """
    pos = [math.nan] * 3  # an axis no move has written yet: unknown (translations write the moving axes only)
    motion, tool_length, moves, ends = None, 0.0, [], []
    before_off, prev = 0.0, ""  # the 840D's tool length before the last D0, and the line before this one
    for raw in text.splitlines():
        line = raw.split(";")[0] if target == "sinumerik840d" else re.sub(r"\([^)]*\)", "", raw)
        if target != "sinumerik840d" and "MSG(" in raw:
            raise AssertionError(f"840D message on {target}: {raw}")
        line = re.sub(r'MSG\("[^"]*"\)', "", line).strip()
        if not line or line == "%":
            continue
        words = WORD.findall(line.replace(" ", ""))
        gs = [w for w in words if w[0] == "G"]
        machine = "G53" in gs or "SUPA" in words
        probe = "G38.2" in gs or "G38.3" in gs or "MEAS=1" in words
        for g in gs:
            if g in ("G0", "G1", "G2", "G3"):
                motion = g
            elif g == "G43":
                h = next(int(w[1:]) for w in words if w[0] == "H")
                tool_length = tools[h]
            elif g == "G49":
                tool_length = 0.0
            elif g == "G10":
                raise AssertionError(f"G10 in {target} output: {raw}")
        for w in words:
            if w[0] == "D" and target == "sinumerik840d":
                n = int(w[1:])
                before_off = tool_length if not n else before_off
                tool_length = tools[n] if n else 0.0
            if w in ("M2", "M30"):
                ends.append(w)
        prev, held = line, before_off if prev == "D0" and "SUPA" in words else tool_length
        if "G4" in gs:
            continue  # a dwell: ISO gives its seconds as X
        axes = {w[0]: float(w[1:]) for w in words if w[0] in AXES}
        alone = not axes and any(g in ("G0", "G1") for g in gs)  # a move in which nothing moves
        if not axes and not alone or motion is None and not probe:
            continue
        for a, v in axes.items():
            pos[AXES.index(a)] = v - (held if machine and a == "Z" else 0.0)
        kind = "probe" if probe else {"G0": "rapid", "G1": "feed", "G2": "arc", "G3": "arc"}[motion]
        moves.append((kind, tuple(pos)))
    return moves, ends
