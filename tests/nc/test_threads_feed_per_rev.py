"""Threads and feed per revolution: the move's time follows the spindle (issue 14 part 3).

Feed per revolution: "in case of feed programming in mm/rev (G95) it supplies the path feed in mm/min" (CPL
manual L2817): path feed = F x S. SINUMERIK: internal G group 11 G94-G97, group 0 G33 (constant lead), G34
(increasing), G35 (decreasing) (CL 800 manual L7397, L7407). din: LinuxCNC's G33 (K = distance per
revolution) and G95 (units per revolution); rs274 checks the end points. Expected times by hand; the test
machine accelerates so fast (1e12 mm/s^2) that a move takes length / feed.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest
from rs274peer import needs_rs274, rs274

from ncvm.api import run
from ncvm.runtime.session import RunOptions

AXES = "".join(f'[[axis]]\nname = "{a}"\nrapid = 60000.0\nmax_feed = 60000.0\naccel = 1e12\n' for a in "XYZ")


def _run(tmp_path: Path, text: str, dialect: str, name: str, extra: str = ""):
    (tmp_path / "machine.toml").write_text(AXES + extra)
    (tmp_path / name).write_text(text)
    trace = tmp_path / "t.jsonl"
    result, _ = run(tmp_path / name, dialect=dialect, machine=tmp_path / "machine.toml",
                    options=RunOptions(state_dir=tmp_path / ".s", trace=trace))
    rows = [json.loads(x) for x in trace.read_text().splitlines()] if trace.exists() else []
    return result, rows


def _feed_moves(rows):
    return [(r["end"], r["feed"]) for r in rows if r["call"] == "feed"]


def test_din_g95_feed_is_f_times_the_spindle_speed(tmp_path):
    """G95 F0.1 at S1000: 100 mm/min, 10 mm take 6 s; G94 F600 again: 10 mm in 1 s."""
    r, rows = _run(tmp_path, "G21 G90\nS1000 M3\nG95 F0.1\nG1 X10\nG94 F600\nG1 X20\nM2\n", "din", "p.din")
    assert r["status"] == "ok", r["error"]
    assert [f for _e, f in _feed_moves(rows)] == pytest.approx([100.0, 600.0])
    assert r["cycle_time_s"] == pytest.approx(6.0 + 1.0)


def test_din_g95_follows_a_speed_change_and_needs_a_new_f_after_g94_as_rs274(tmp_path):
    r, rows = _run(tmp_path, "G21 G90\nS1000 M3\nG95 F0.1\nG1 X10\nS2000\nX20\nM2\n", "din", "p.din")
    assert [f for _e, f in _feed_moves(rows)] == pytest.approx([100.0, 200.0])
    r, _rows = _run(tmp_path, "G21 G90\nS1000 M3\nG95 F0.1\nG1 X10\nG94\nX20\nM2\n", "din", "p.din")
    assert r["error"]["code"] == "NC006" and r["error"]["line"] == 6


def test_din_g95_move_with_the_spindle_standing_is_an_error_naming_it(tmp_path):
    r, _rows = _run(tmp_path, "G21 G90\nS1000\nG95 F0.1\nG0 X5\nG1 X10\nM2\n", "din", "p.din")
    err = r["error"]
    assert err["code"] == "NC006" and err["line"] == 5 and "spindle not turning" in err["message"], err


def test_din_g33_takes_its_lead_k_per_revolution_along_the_path(tmp_path):
    """G33 Z-20 K1.5 from Z5 at S1000: 25 / 1.5 revolutions = 1 s; the tapered thread X5 Z-30, K2 over its
    path sqrt(25 + 100): sqrt(125) / 2 / 1000 min."""
    r, rows = _run(tmp_path, "G21 G90\nS1000 M3\nG0 X0 Z5\nG33 Z-20 K1.5\nG33 X5 Z-30 K2\nM2\n", "din", "p.din")
    assert r["status"] == "ok", r["error"]
    assert [f for _e, f in _feed_moves(rows)] == pytest.approx([1500.0, 2000.0])
    assert r["cycle_time_s"] == pytest.approx(5 / 1000 + 1.0 + math.sqrt(125) / 2000 * 60, rel=1e-6)  # rapid Z5 first


@pytest.mark.parametrize("text, code, words", [
    ("G21\nG33 Z-20 K1\nM2\n", "NC014", "spindle not turning"),
    ("G21\nS500 M3\nG33 Z-20\nM2\n", "NC009", "K word"),
    ("G21\nS500 M3\nG33 Z-20 K1 F100\nM2\n", "NC009", "F word"),
])
def test_din_g33_errors_as_rs274(tmp_path, text, code, words):
    """rs274: "Spindle not turning in G33", "K word missing with g33/g33.1", "F word used with a g33"."""
    r, _rows = _run(tmp_path, text, "din", "p.din")
    assert r["error"]["code"] == code and words in r["error"]["message"], r["error"]


def _rs274_ends(tmp_path: Path, name: str, text: str) -> list[tuple]:
    """The end point of each straight move ``rs274 -g`` reports (it stops with 0 on a program error)."""
    (tmp_path / f"{name}.ngc").write_text(text)
    proc = rs274(tmp_path / f"{name}.ngc", tmp_path / f"{name}.canon")
    assert proc.returncode == 0, proc.stderr
    out = (tmp_path / f"{name}.canon").read_text()
    return [tuple(round(float(v), 4) for v in line.split("(")[1].split(",")[:3])
            for line in out.splitlines() if "STRAIGHT_FEED(" in line or "STRAIGHT_TRAVERSE(" in line]


@needs_rs274
def test_din_thread_and_per_rev_end_points_match_rs274(tmp_path):
    text = ("G21 G90 G17\nS800 M3\nG0 X1 Y2 Z5\nG33 Z-12.5 K1.25\nG33 X4 Z-20 K2\nG0 X10\nG95 F0.2\nG1 X15 Y3\n"
            "G91 G1 X-2 Z1\nG90 G94 F300\nG1 X0 Y0\nG91 G33 Z-3 K0.5\nM2\n")
    r, rows = _run(tmp_path, text, "din", "p.din")
    assert r["status"] == "ok", r["error"]
    ours = [tuple(round(row["end"][a], 4) for a in "XYZ") for row in rows if row["call"] in ("feed", "rapid")]
    assert ours == _rs274_ends(tmp_path, "p", text) and len(ours) == 8


def test_sinumerik_g33_lead_k_and_g34_increasing_lead_f_l7397(tmp_path):
    """G33 Z-20 K2 from Z0 at S600: 10 revolutions = 1 s. G34 K2 F0.5 over 21 mm: 2n + 0.25 n^2 = 21 gives
    n = 6 revolutions (lead 2 -> 5), 0.6 s; G35 K5 F0.5 back over 21 mm: 5n - 0.25 n^2 = 21, n = 6, 0.6 s."""
    r, rows = _run(tmp_path, "%MPF1\nS600 M3\nG0 X0 Z0\nG33 Z-20 K2\nG34 Z-41 K2 F0.5\nG35 Z-62 K5 F0.5\nM30\n",
                   "sin800", "p.mpf", "[sin800]\n")
    assert r["status"] == "ok", r["error"]
    assert r["cycle_time_s"] == pytest.approx(1.0 + 0.6 + 0.6)
    assert [e["Z"] for e, _f in _feed_moves(rows)] == [-20.0, -41.0, -62.0]


def test_sinumerik_thread_without_spindle_and_g95_without_spindle_stop(tmp_path):
    r, _rows = _run(tmp_path, "%MPF1\nS600\nG33 Z-20 K2\nM30\n", "sin800", "p.mpf", "[sin800]\n")
    assert r["error"]["code"] == "NC014" and r["error"]["line"] == 3
    r, _rows = _run(tmp_path, "%MPF1\nS600 M5\nG95 G1 X10 F0.2\nM30\n", "sin800", "p.mpf", "[sin800]\n")
    assert r["error"]["code"] == "NC006" and "spindle not turning" in r["error"]["message"]


def test_sinumerik_group_11_g95_and_g96_feed_per_revolution_l7407(tmp_path):
    """G95 F0.2 at S500: 100 mm/min; G96 keeps mm/rev (constant cutting speed); ACG group 11 reads them."""
    r, rows = _run(tmp_path, "%MPF1\nS500 M3\nG95 G1 X10 F0.2\n@714 @36b R1 K0 K11\nG94 F300 X20\n"
                             "@714 @36b R2 K0 K11\nM30\n", "sin800", "p.mpf", "[sin800]\n")
    assert r["status"] == "ok", r["error"]
    assert [f for _e, f in _feed_moves(rows)] == pytest.approx([100.0, 300.0])
    assert (r["variables"]["R1"], r["variables"]["R2"]) == (95.0, 94.0)


def test_cpl_g95_path_feed_in_mm_per_min_l2817(tmp_path):
    """CPL: G95 F0.25 at S400 runs at 100 mm/min; SD(1,7,2) reports the active feed type of group 7, G95."""
    r, rows = _run(tmp_path, "N1 S400 M3\nN2 G95 G1 X10 F0.25\n10 WAIT\n20 A%=SD(1,7,2)\nM30\n", "cpl", "P1",
                   "")
    assert r["status"] == "ok", r["error"]
    assert [f for _e, f in _feed_moves(rows)] == pytest.approx([100.0])
    assert r["variables"]["A%"] == 95


def test_din_canned_cycle_under_g95_drills_at_f_times_s(tmp_path):
    """G81 under G95 F0.1 at S600: the feed down is 60 mm/min (10 mm in 10 s); without a new F after G95 the
    cycle stops with NC006 instead of moving at feed 0."""
    r, rows = _run(tmp_path, "G21 G90 G17\nS600 M3\nG0 X0 Y0 Z5\nG95 F0.1\nG81 X10 Y0 R2 Z-8\nG80\nM2\n", "din", "p.din")
    assert r["status"] == "ok", r["error"]
    assert [(e["Z"], f) for e, f in _feed_moves(rows)] == [(-8.0, pytest.approx(60.0))]
    r, _rows = _run(tmp_path, "G21 G90 G17\nS600 M3 F100\nG0 X0 Y0 Z5\nG95\nG81 X10 Y0 R2 Z-8\nM2\n", "din", "p.din")
    assert r["error"]["code"] == "NC006" and r["error"]["line"] == 5, r["error"]


def test_sinumerik_thread_whose_lead_axis_does_not_move_is_refused(tmp_path):
    """K is the lead along Z: a block moving X only cannot take it (I would be X's)."""
    r, _rows = _run(tmp_path, "%MPF1\nS600 M3\nG33 X20 K2\nM30\n", "sin800", "p.mpf", "[sin800]\n")
    assert r["error"]["code"] == "NC009" and "lead" in r["error"]["message"], r["error"]


def _random_thread_program(rnd) -> str:
    out = ["G21 G17 G90 G94 F500", f"S{rnd.choice((300, 800, 1200))} M3", "G0 X0 Y0 Z5"]
    for _ in range(rnd.randint(4, 10)):
        pick = rnd.random()
        axes = " ".join(f"{a}{rnd.uniform(-20, 20):.3f}" for a in rnd.sample("XYZ", rnd.randint(1, 3)))
        if pick < 0.3:
            out.append(f"G33 {axes} K{rnd.choice((0.5, 1, 1.25, 2.5))}")
        elif pick < 0.5:
            out.append(f"G95 G1 {axes} F{rnd.choice((0.05, 0.1, 0.2))}")
        elif pick < 0.65:
            out.append(f"G94 G1 {axes} F{rnd.randint(100, 900)}")
        elif pick < 0.8:
            out.append(f"G{rnd.choice((90, 91))} G0 {axes}")
        else:
            out.append(f"G1 {axes}")
    return "\n".join(out + ["G90 M5", "M2"]) + "\n"


@needs_rs274
def test_generated_thread_and_per_rev_programs_end_where_rs274_ends(tmp_path):
    """30 generated programs (G33 K, G95/G94 switches with F, G90/G91): every end point as rs274's."""
    rnd = __import__("random").Random(14)
    compared = 0
    for i in range(30):
        text = _random_thread_program(rnd)
        theirs = _rs274_ends(tmp_path, f"g{i}", text)
        r, rows = _run(tmp_path, text, "din", f"g{i}.din")
        ours = [tuple(round(row["end"][a], 4) for a in "XYZ") for row in rows if row["call"] in ("feed", "rapid")]
        assert ours == theirs, text
        assert r["status"] == "ok", (text, r["error"])
        compared += len(ours)
    assert compared > 150
