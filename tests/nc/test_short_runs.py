"""Short plain runs executed block by block give the answers of executing them as columns, to the last bit.

A plain run shorter than ``block.RUN_COLUMNS_FROM`` blocks is kept as its Blocks and executed block by block
through the kernel (issue 18: a drilling program's runs of four blocks between two dwells paid numpy's fixed
cost per run, 16 times rs274's time). Each random program here runs twice: with the threshold forced to 0
(every run as columns) and to a billion (every run block by block), and the JSON summary (moves, lengths,
bounds, positions, cycle time, limit violations, steps, errors), the JSONL trace (every move's time, entry and
exit speed) and the flat G-code must be equal, not close.
"""

from __future__ import annotations

import json
import math
import random

import pytest

from ncvm.api import run
from ncvm.nc import block, plainrun
from ncvm.nc.block import PlainRun, read_din_segments
from ncvm.runtime.session import RunOptions

#: lines that end a plain run: exact stops, dwells, M functions, the spindle, modal changes, comments
BREAKS = ["G4 P0.5", "G4 P0", "M3 S1200", "M4 S800", "M5", "M8", "M9", "G61", "G64", "G64 P0.05", "G9 G1 X{x} F700",
          "M0", "(comment)", "F{f}", "G91", "G90", "G17", "G18", "G19", "S2000", "M7", "/G1 X{x}", "N77"]
#: a planes' axes and centre words
PLANES = {17: (0, 1, "IJ"), 18: (2, 0, "KI"), 19: (1, 2, "JK")}


def drilling(holes: int) -> str:
    """A DIN bolt circle as CAM writes it: per hole a positioning, a plunge, a dwell, a retract."""
    lines = ["G17 G21 G90 G94", "G0 X0 Y0 Z50", "M3 S3000"]
    for i in range(holes):
        a = math.radians(i * 360 / holes)
        lines += [f"G0 X{40 * math.cos(a):.4f} Y{40 * math.sin(a):.4f}", "G0 Z2", "G1 Z-12 F150", "G4 P0.5",
                  "G0 Z2"]
    return "\n".join(lines + ["M5", "M2"]) + "\n"


def random_program(seed: int) -> str:
    """Stretches of 1 to 6 plain blocks (and now and then 40 to 90) between breaking lines; straight moves
    at rapid and at feed, arcs and helices in every plane, G90/G91, now and then a move past a soft limit."""
    rnd = random.Random(seed)
    out = ["G21 G90 G17 G94", "G0 X0 Y0 Z10", "F800"]
    pos, absolute, plane, arc_mode = [0.0, 0.0, 10.0], True, 17, False
    while len(out) < 260:
        count = rnd.randint(40, 90) if rnd.random() < 0.1 else rnd.randint(1, 6)
        for _ in range(count):
            words = [f"N{len(out) * 10}"] if rnd.random() < 0.3 else []
            end = list(pos)
            if rnd.random() < 0.25:
                a, b, letters = PLANES[plane]
                ca, cb = pos[a] + rnd.uniform(-8, 8), pos[b] + rnd.uniform(-8, 8)
                turn, ra, rb = rnd.uniform(-3, 3), pos[a] - ca, pos[b] - cb
                end[a] = round(ca + ra * math.cos(turn) - rb * math.sin(turn), 4)
                end[b] = round(cb + ra * math.sin(turn) + rb * math.cos(turn), 4)
                if rnd.random() < 0.3:  # helix
                    end[3 - a - b] = round(pos[3 - a - b] + rnd.uniform(-2, 2), 4)
                words.append(rnd.choice(("G2", "G3")))
                arc_mode = True
                words += [f"{'XYZ'[i]}{(end[i] if absolute else end[i] - pos[i]):.4f}" for i in range(3)
                          if end[i] != pos[i] or i in (a, b)]
                words += [f"{letters[0]}{ca - pos[a]:.4f}", f"{letters[1]}{cb - pos[b]:.4f}"]
            else:
                words.append(rnd.choice(("G0", "G1", "G01", "G1") if arc_mode else ("G0", "G1", "G01", "")))
                arc_mode = False
                reach = 700.0 if rnd.random() < 0.02 else 15.0  # now and then past the X/Y soft limits
                for i in range(3):
                    if rnd.random() < 0.6:
                        end[i] = round(pos[i] + rnd.uniform(-reach, reach), 4)
                        words.append(f"{'XYZ'[i]}{(end[i] if absolute else end[i] - pos[i]):.4f}")
                if words[-1] in ("G0", "G1", "G01", ""):
                    words.append(f"Z{end[2] if absolute else 0.0:.4f}")
            if rnd.random() < 0.1:
                words.append(f"F{rnd.randint(100, 3000)}")
            pos = end
            out.append(" ".join(w for w in words if w))
        line = rnd.choice(BREAKS).format(x=round(pos[0], 4) if absolute else 0.0, f=rnd.randint(200, 2500))
        if line in ("G90", "G91"):
            absolute = line == "G90"
        elif line.startswith("G1") and len(line) == 3:
            plane = int(line[1:])
        out.append(line)
    return "\n".join(out + ["M5", "M30"]) + "\n"


def _run_at(tmp_path, monkeypatch, path, threshold: int, name: str, **options) -> tuple[dict, str, str]:
    """The run's JSON summary, trace and G-code with runs of ``threshold`` blocks and more as columns."""
    monkeypatch.setattr(block, "RUN_COLUMNS_FROM", threshold)
    trace, gcode = tmp_path / f"{name}.jsonl", tmp_path / f"{name}.ngc"
    result, _ = run(path, dialect="din", options=RunOptions(state_dir=tmp_path / f".{name}", trace=trace, gcode=gcode,
                                                            **options))
    return result, trace.read_text(), gcode.read_text() if gcode.exists() else None  # none after an error


def _both(tmp_path, monkeypatch, text: str, **options):
    path = tmp_path / "p.ngc"
    path.write_text(text)
    columns = _run_at(tmp_path, monkeypatch, path, 0, "columns", **options)
    blocks = _run_at(tmp_path, monkeypatch, path, 10 ** 9, "blocks", **options)
    return columns, blocks


@pytest.mark.parametrize("seed", range(10))
@pytest.mark.parametrize("model", ["lookahead", "rest-to-rest"])
def test_short_runs_block_by_block_equal_columns(tmp_path, monkeypatch, seed, model):
    text = random_program(seed)
    segments, diags = read_din_segments("p.ngc", text)
    runs = [len(s) for s in segments if isinstance(s, PlainRun)]
    assert not diags and min(runs) < block.RUN_COLUMNS_FROM <= max(runs), runs  # short runs and long ones
    (r1, trace1, gcode1), (r2, trace2, gcode2) = _both(tmp_path, monkeypatch, text, time_model=model)
    assert r1["motion"]["arc_moves"] > 10 and r1["cycle_time_s"] > 0
    assert r1 == r2
    assert trace1 == trace2
    assert gcode1 == gcode2
    moves = [t for t in map(json.loads, trace1.splitlines()) if t["call"] in ("rapid", "feed", "arc")]
    assert len(moves) > 200 and all({"time", "v_entry", "v_exit"} <= t.keys() for t in moves)
    if model == "lookahead":  # blended junctions: the speeds compared are not all zero
        assert sum(t["v_exit"] > 0.0 for t in moves) > 5


def test_drilling_program_block_by_block_equals_columns(tmp_path, monkeypatch):
    (r1, trace1, gcode1), (r2, trace2, gcode2) = _both(tmp_path, monkeypatch, drilling(60))
    assert r1["status"] == "ok" and r1["motion"]["feed_moves"] == 60
    assert (r1, trace1, gcode1) == (r2, trace2, gcode2)


def test_drilling_program_holds_no_columns(tmp_path):
    """The runs of a drilling program (four blocks between two dwells) are read as Blocks: no numpy column
    is made for them (their columns are made only when asked for)."""
    segments, _ = read_din_segments("p.ngc", drilling(100))
    runs = [s for s in segments if isinstance(s, PlainRun)]
    assert len(runs) == 102 and all(s._g is None and s.matches is not None for s in runs)


@pytest.mark.parametrize("bad, code", [("G1 X5 Y5 F0", "NC006"), ("G2 X5 Y5 I1 J0 F100", "NC002"),
                                       ("G3 X5 Y5 F100", "NC003")])
def test_fault_inside_a_short_run(tmp_path, monkeypatch, bad, code):
    """A block that faults inside a short run: the same error, line, steps and moves as the columns give."""
    text = drilling(50).replace("G0 Z2\nG1 Z-12 F150\nG4", f"G0 Z2\n{bad}\nG4", 1)
    (r1, trace1, _), (r2, trace2, _) = _both(tmp_path, monkeypatch, text)
    assert r1["status"] == "error" and r1["error"]["code"] == code and r1["error"]["line"] == 6
    assert r1 == r2 and trace1 == trace2


@pytest.mark.parametrize("limit", [1, 5, 6, 9, 200, 257])
def test_step_limit_inside_a_short_run(tmp_path, monkeypatch, limit):
    """--max-steps stops inside a short run as inside a long one: the same steps, moves and RUN001 line."""
    (r1, _, _), (r2, _, _) = _both(tmp_path, monkeypatch, drilling(60), max_steps=limit)
    assert r1["status"] == "error" and r1["error"]["code"] == "RUN001" and r1["steps"] == limit
    assert r1 == r2


def test_read_short_run_blocks_are_the_line_parsers(tmp_path):
    """The Blocks of a short run are those the line parser makes of its lines: G code, words (in the order
    written), N number, line."""
    from ncvm.nc.block import parse_din_line
    from ncvm.nc.canon import Src

    text = "".join(f"N{i} G1 X{i}.5 Y-{i} F{100 + i}\nG4 P1\nG0 Z.5\nN{i}7 G03 X1 Y2 I-1 J0\nM9\n" for i in range(60))
    lines = text.splitlines()
    segments, _ = read_din_segments("p.ngc", text)
    seen = 0
    for seg in segments:
        if isinstance(seg, PlainRun):
            for blk in seg.blocks():
                want = parse_din_line(lines[blk.src.line - 1], Src("p.ngc", blk.src.line))
                assert (blk.g, blk.m, list(blk.words.items()), blk.n, blk.msg, blk.src) == \
                    (want.g, want.m, list(want.words.items()), want.n, want.msg, want.src)
                seen += 1
    assert seen == 180


def test_long_block_number_is_an_error_in_a_long_program(tmp_path):
    """An N number of more than 8 digits is NC001 however long the program (a short one is read line by line,
    a long one as columns: the columns took it as a plain block and ran it)."""
    path = tmp_path / "p.ngc"
    path.write_text("G1 F100\nN1234567890123 G1 X1\n" + "".join(f"G1 X{i}\n" for i in range(300)) + "M2\n")
    result, _ = run(path, dialect="din", options=RunOptions(state_dir=tmp_path / ".n"))
    assert result["status"] == "error" and (result["error"]["code"], result["error"]["line"]) == ("NC001", 2)


CPL_HOLES = """\
N1 G71 G90 G17 F6000
10 H% = 0
20 WHILE H% < {holes} DO
30 A! = H% * 7.5
N40 G0 X[40 * COS(A!)] Y[40 * SIN(A!)]
N50 G0 Z2
N60 G1 Z-12 F150
N70 G4 F0.5
N80 G0 Z2
90 IF H% - INT(H% / 10) * 10 = 0 THEN
N100 G1 X[50 * COS(A!)] Y[50 * SIN(A!)] F900
N110 G3 X[50 * COS(A! + 5)] Y[50 * SIN(A! + 5)] I[-50 * COS(A!)] J[-50 * SIN(A!)]
N120 M8
130 WAIT
N140 M9
150 ENDIF
160 H% = H% + 1
170 END
M30
"""


@pytest.mark.parametrize("model", ["lookahead", "rest-to-rest"])
def test_cpl_short_runs_block_by_block_equal_columns(tmp_path, monkeypatch, model):
    """A CPL drilling loop (its motion queue drained at each dwell, M function and WAIT into short runs, some
    arcs): block by block as with columns, to the last bit."""
    path = tmp_path / "holes.cpl"
    path.write_text(CPL_HOLES.format(holes=40))
    got = []
    for threshold in (0, 10 ** 9):
        monkeypatch.setattr(block, "RUN_COLUMNS_FROM", threshold)
        trace = tmp_path / f"{threshold}.jsonl"
        result, _ = run(path, options=RunOptions(state_dir=tmp_path / f".{threshold}", trace=trace,
                                                 time_model=model))
        got.append((result, trace.read_text()))
    assert got[0][0]["status"] == "ok" and got[0][0]["motion"]["arc_moves"] == 4, got[0][0]["error"]
    assert got[0] == got[1]


# -- the short runs' twin of the kernel (nc/plainrun.py execute_short_run) against the kernel's general path ---------

#: lines a drilling-like program puts between its holes: modal changes, offsets, the tool, the spindle, a skip
BETWEEN = ["G91", "G90", "G20", "G21", "G92 X{a} Y{b}", "G92.1", "G10 L2 P2 X{a} Y{b} Z-3", "G55", "G54",
           "G43 H1", "G49", "T2 M6", "M3 S1500", "M5", "G61", "G64", "G64 P0.05", "/G0 X{a} Y{b}", "M8", "M9",
           "(MSG, hole)", "F{f}", "N{n} G4 P0.2", "G4 P0", "G17", "G18", "G19", "G9 G1 X{a} F700"]


def drilling_like(seed: int, holes: int = 70) -> str:
    """A drilling program as CAM writes it, varied: per hole a positioning, an approach, a plunge at feed, a
    dwell and a retract (some without their G code, some numbered, some with a peck or an arc), and now and
    then a line from :data:`BETWEEN` (inch, G91, G92, zero offsets, tool length, exact stop, block skip)."""
    rnd = random.Random(seed)
    out = ["G17 G21 G90 G94 F250", "G0 X0 Y0 Z50", "M3 S3000"]
    for h in range(holes):
        x, y = round(rnd.uniform(-40, 40), 4), round(rnd.uniform(-30, 30), 4)
        n = f"N{h * 10} " if rnd.random() < 0.3 else ""
        out.append(f"{n}G0 X{x} Y{y}" if rnd.random() < 0.8 else f"X{x} Y{y}")
        out.append("G0 Z2" if rnd.random() < 0.9 else "Z2.5")
        depth = round(rnd.uniform(-14, -2), 3)
        if rnd.random() < 0.3:  # a peck: down, up, down again
            out += [f"G1 Z{depth / 2:.3f} F{rnd.randint(80, 400)}", "G0 Z1", f"G1 Z{depth}"]
        else:
            out.append(f"G1 Z{depth}" + (f" F{rnd.randint(80, 400)}" if rnd.random() < 0.7 else ""))
        if rnd.random() < 0.1:  # a circle at the bottom
            out += ["G17", f"G1 X{x + 2:.4f}", f"G3 X{x + 2:.4f} Y{y} I-2 J0", f"G1 X{x}"]
        if rnd.random() < 0.85:
            out.append(f"G4 P{rnd.choice((0.5, 0.25, 1))}")
        out.append("G0 Z2" if rnd.random() < 0.8 else "G00 Z5 F900")
        if rnd.random() < 0.25:
            line = rnd.choice(BETWEEN).format(a=round(rnd.uniform(-5, 5), 3), b=round(rnd.uniform(-5, 5), 3),
                                              f=rnd.randint(100, 900), n=h)
            out.append(line)
            if line == "G91":  # a few incremental holes, then back
                out += ["G0 X1.5 Y-2", "G1 Z-3 F200", "G0 Z3", "G90"]
            if line == "G20":  # a few inch holes, then back
                out += ["G0 X0.5 Y0.25", "G0 Z0.1", "G1 Z-0.2 F8", "G4 P0.5", "G0 Z0.1", "G21"]
    return "\n".join(out + ["M5", "M30"]) + "\n"


def _general_path(monkeypatch) -> None:
    """Short runs block by block through NcKernel.execute (the twin refused)."""
    monkeypatch.setattr(block, "RUN_COLUMNS_FROM", 10 ** 9)
    monkeypatch.setattr(plainrun, "plain_moves_ok", lambda k: False)


def _twin_runs(monkeypatch) -> list:
    """Short runs through the twin; the list fills with plain_moves_ok's answers."""
    seen = []
    plain_moves_ok = plainrun.plain_moves_ok

    def told(k):
        seen.append(plain_moves_ok(k))
        return seen[-1]

    monkeypatch.setattr(block, "RUN_COLUMNS_FROM", 10 ** 9)
    monkeypatch.setattr(plainrun, "plain_moves_ok", told)
    return seen


def _run_way(tmp_path, path, name: str, gcode: bool, **options):
    trace, out = tmp_path / f"{name}.jsonl", tmp_path / f"{name}.ngc"
    result, _ = run(path, dialect="din", options=RunOptions(state_dir=tmp_path / f".{name}", trace=trace,
                                                            gcode=out if gcode else None, **options))
    return result, trace.read_text(), out.read_text() if out.exists() else None


def _twin_and_general(tmp_path, monkeypatch, text: str, gcode: bool = False, **options):
    """(twin's answers, the general path's answers, how often the twin ran its own way)."""
    path = tmp_path / "p.ngc"
    path.write_text(text)
    with monkeypatch.context() as m:
        seen = _twin_runs(m)
        twin = _run_way(tmp_path, path, "twin", gcode, **options)
    with monkeypatch.context() as m:
        _general_path(m)
        general = _run_way(tmp_path, path, "general", gcode, **options)
    return twin, general, sum(seen)


@pytest.mark.parametrize("seed", range(14))
@pytest.mark.parametrize("model", ["lookahead", "rest-to-rest"])
def test_twin_equals_the_kernels_general_path(tmp_path, monkeypatch, seed, model):
    """Random drilling-like programs: the summary, every trace record (each move's time, entry and exit speed)
    and the limit violations of the twin are the general path's, bit for bit."""
    text = drilling_like(seed)
    twin, general, fast = _twin_and_general(tmp_path, monkeypatch, text, time_model=model)
    assert twin[0]["status"] == "ok", twin[0].get("error")
    assert twin == general
    assert fast > 60  # the twin ran most short runs itself
    if seed == 0:  # and the columns give the same (every run as columns)
        monkeypatch.setattr(block, "RUN_COLUMNS_FROM", 0)
        assert _run_way(tmp_path, tmp_path / "p.ngc", "columns", False, time_model=model) == twin


@pytest.mark.parametrize("seed", range(4))
def test_twin_with_a_gcode_translation_equals_the_general_path(tmp_path, monkeypatch, seed):
    """With --gcode (a sink that takes each block's axis words) the short runs go through the kernel's
    execute: the same G-code, trace and summary."""
    text = "".join(ln for ln in drilling_like(100 + seed).splitlines(True) if not ln.startswith("G10"))
    twin, general, fast = _twin_and_general(tmp_path, monkeypatch, text, gcode=True)  # G10: refused (TRN001)
    assert twin[0]["status"] == "ok", twin[0].get("error")
    assert twin[2] and twin == general and fast == 0


def test_twin_sees_limit_violations(tmp_path, monkeypatch):
    text = drilling_like(3).replace("G0 Z2\n", "G0 Z2\nG0 X700 Y20\nG0 X0\n", 2)
    twin, general, fast = _twin_and_general(tmp_path, monkeypatch, text)
    assert twin[0]["status"] == "limit_violation" or twin[0].get("limit_violations"), twin[0]
    assert twin == general and fast


@pytest.mark.parametrize("bad, code", [("G1 X5 Y5 F0", "NC006"), ("G2 X5 Y5 I1 J0 F100", "NC002"),
                                       ("G3 X5 Y5 F100", "NC003"), ("G1 X3 F-5", "NC006")])
@pytest.mark.parametrize("seed", range(5))
def test_twin_fault_at_the_same_block(tmp_path, monkeypatch, bad, code, seed):
    """A block that faults inside a short run (G1 without feed, an arc on another radius, an arc without
    centre): the same error, line, steps, and the moves before it."""
    rnd = random.Random(seed)
    lines = drilling_like(seed).splitlines()
    at = rnd.randrange(4, len(lines) - 3)
    while lines[at].startswith(("G4", "M", "(", "/", "T", "G9", "G10", "G92", "G43", "G49", "G5", "G6", "F", "N")):
        at += 1
    lines.insert(at, bad)
    twin, general, fast = _twin_and_general(tmp_path, monkeypatch, "\n".join(lines) + "\n")
    assert twin[0]["status"] == "error" and twin[0]["error"]["code"] == code, twin[0]
    assert twin[0]["error"]["line"] == at + 1
    assert twin == general and fast


def test_twin_step_limit_at_every_block(tmp_path, monkeypatch):
    """--max-steps anywhere in a drilling program (inside short runs, at their first and last block, at a
    dwell): the same steps, moves, trace and RUN001 line as the general path."""
    text = drilling_like(7, holes=12)
    (tmp_path / "p.ngc").write_text(text)
    steps = _run_way(tmp_path, tmp_path / "p.ngc", "all", False)[0]["steps"]
    assert steps > 60
    for limit in range(1, steps + 2):
        twin, general, _ = _twin_and_general(tmp_path, monkeypatch, text, max_steps=limit)
        assert twin == general, limit
        assert (twin[0]["status"] == "error") == (limit < steps), limit
