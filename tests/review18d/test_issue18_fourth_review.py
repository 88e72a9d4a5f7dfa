"""Fourth review of issue 18 (performance, bounded memory, the look-ahead planner): the defects found, one
failing test each.

Programs run through the ``ncvm`` command as a user runs them (a real process, real files, real signals).
No test here times anything: the figures checked are files left behind and the planner's entry and exit
speeds in the JSONL trace (docs/trace.md, docs/planner.md "In the trace and the summary").
"""

from __future__ import annotations

import json
import signal
import subprocess
import sys
import time
from pathlib import Path

#: a CPL program that moves for ever: 100 moves a row, one row after the other
ENDLESS = """\
N1 G71 G90 G17 F6000
10 I% = 0
20 WHILE I% >= 0 DO
G1 X[(I% - INT(I% / 100) * 100) * 0.5] Y[INT(I% / 100) * 0.01]
30 I% = I% + 1
40 END
M30
"""


def _bodies(folder: Path, name: str) -> list[Path]:
    return sorted(folder.glob(f".{name}.*.body"))


def test_run_gcode_ended_by_sigterm_leaves_no_hidden_body(tmp_path):
    """``ncvm run --gcode OUT`` writes the G-code as a hidden temporary body beside OUT (``.OUT.XXXX.body``,
    translate/output.py) and moves it into place when the run ends. Ctrl-C removes it (RUN004). SIGTERM, the
    signal a batch scheduler, ``timeout`` or ``systemctl stop`` sends to a run that takes too long, kills the
    process and leaves the body: a hidden file as large as the G-code written so far (45 MB after a few
    minutes of this program), one more at every run that is stopped so. ``ncvm translate`` ends on SIGTERM
    as on Ctrl-C ("the temporary body beside OUT removed (their default action would kill the process and
    leave it)", translate/__init__.py ``_ended_by_termination``); ``ncvm run --gcode`` does not."""
    program = tmp_path / "endless.cpl"
    program.write_text(ENDLESS)
    proc = subprocess.Popen([sys.executable, "-m", "ncvm", "run", "--state", str(tmp_path / "st"), "--gcode",
                             str(tmp_path / "out.ngc"), str(program)],
                            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    try:
        deadline = time.monotonic() + 120
        while not _bodies(tmp_path, "out.ngc") and time.monotonic() < deadline and proc.poll() is None:
            time.sleep(0.2)
        assert _bodies(tmp_path, "out.ngc"), "the G-code body never appeared"
        while _bodies(tmp_path, "out.ngc")[0].stat().st_size == 0 and time.monotonic() < deadline:
            time.sleep(0.2)  # until the run has written moves into it
        proc.send_signal(signal.SIGTERM)
        proc.communicate(timeout=60)
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.communicate()
    left = _bodies(tmp_path, "out.ngc")
    assert not left, f"left behind: {[(p.name, p.stat().st_size) for p in left]}"


def _trace_moves(tmp_path: Path, name: str, text: str, *extra: str) -> list[dict]:
    program = tmp_path / name
    program.write_text(text)
    trace = tmp_path / "t.jsonl"
    done = subprocess.run([sys.executable, "-m", "ncvm", "run", "--state", str(tmp_path / "st"), "--json",
                           "--trace", str(trace), *extra, str(program)], capture_output=True, text=True, timeout=300)
    assert json.loads(done.stdout)["status"] == "ok", done.stdout[-2000:]
    return [r for r in map(json.loads, trace.read_text().splitlines()) if r["call"] in ("feed", "rapid", "arc")]


def test_a_block_that_does_not_move_inside_a_contour_reports_the_speed_the_path_passes_it_at(tmp_path):
    """docs/planner.md: a move's ``v_entry`` and ``v_exit`` are "path speed at the move's start and end".
    ``G1 X10`` / ``G1 X10`` / ``G1 X20`` at F3000 in continuous path (G64): the planner passes X10 at
    3000 mm/min (the first move's ``v_exit`` and the third's ``v_entry`` say so, cycle time 0.45 s: 20 mm at
    50 mm/s and one ramp up and down). The block between them, which does not move, is written with
    ``v_entry`` 0 and ``v_exit`` 0 (sinks/trace.py: "no time: not planned"): read as the trace says, the tool
    stops at X10 and starts again, which it does not. A CAM post or a CNC program often repeats a point (a
    corner written twice, a block with only an F or an S word after the axis words are dropped); a user who
    plots the feed along the path from the trace sees a stop at each. The speed the path passes the point at
    is 3000 mm/min on both sides, as the neighbours' speeds say."""
    moves = _trace_moves(tmp_path, "p.ngc", "G90 G64 F3000\nG1 X10\nG1 X10\nG1 X20\nM2\n")
    assert [(m["v_entry"], m["v_exit"]) for m in moves][0::2] == [(0.0, 3000.0), (3000.0, 0.0)]
    assert (moves[1]["time"], moves[1]["v_entry"], moves[1]["v_exit"]) == (0.0, 3000.0, 3000.0)


def _cycle_time(tmp_path: Path, text: str) -> float:
    program = tmp_path / "corner.ngc"
    program.write_text(text)
    done = subprocess.run([sys.executable, "-m", "ncvm", "run", "--state", str(tmp_path / "st"), "--json", str(program)],
                          capture_output=True, text=True, timeout=300)
    result = json.loads(done.stdout)
    assert result["status"] == "ok", result["error"]
    return result["cycle_time_s"]


def test_a_bare_g64_after_g64_p_blends_as_a_bare_g64_does(tmp_path):
    """docs/planner.md: ``corner_tolerance`` (machine data, 0.02 mm) is the tolerance of continuous-path mode,
    and "a DIN program's ``G64 P..`` sets it for the run". Two 10 mm moves at a right angle at F3000 under
    ``G64`` take 0.4848 s (8.26 mm/s through the corner, tests/nc/test_planner.py). A program that selects
    ``G64 P0.001`` for a finishing pass and later a bare ``G64`` (or ``G61`` and then ``G64``) runs the same
    corner at the old P0.001 (0.4964 s): the same block ``G64`` means one tolerance or another depending on
    what came before, and no block can give the power-on tolerance back. In LinuxCNC, the anchor of DIN's
    G64 P, ``G64`` without P is a mode of its own ("keep the best speed possible"), never the last P; a
    translation of the bare G64 (kernel ``path_control`` with no tolerance) is written as ``G64`` without P
    too, so the translated program blends that corner otherwise than ncvm timed it. A bare G64 here gives
    the tolerance it gives at the start of a program."""
    corner = "G1 X10\nG1 Y10\nM2\n"
    plain = _cycle_time(tmp_path, "G90 G64 F3000\n" + corner)
    assert plain == _cycle_time(tmp_path, "G90 G64 P0.001 F3000\nG64\n" + corner)
    assert plain == _cycle_time(tmp_path, "G90 G64 P0.001 F3000\nG61\nG64\n" + corner)
