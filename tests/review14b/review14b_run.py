"""What the review-14b tests share: a fast X/Y/Z machine, ``ncvm run`` in a real process, the moves of a trace."""

from __future__ import annotations

from pathlib import Path

from tests.review14.review14_helpers import make_runner

AXES = "".join(f'[[axis]]\nname = "{a}"\nmin = -1000.0\nmax = 1000.0\nrapid = 60000.0\nmax_feed = 60000.0\n'
               f'accel = 100000000.0\n' for a in "XYZ")

# SINUMERIK 880: D1 a shank cutter (type 20) of length P2 = 50 mm; G54 shifts X100 Y10 Z20.
SIN800_MACHINE = AXES + ('[sin800]\ncontrol = "880"\n'
                         'tool_offsets = [ { area = 0, d = 1, p = [1, 20, 50.0, 0.0, 5.0, 0.0] } ]\n'
                         'zero_offsets = { G54 = { coarse = [100.0, 10.0, 20.0], fine = [0.0, 0.0, 0.0] } }\n')


def run(tmp_path: Path, name: str, text: str, machine: str = AXES):
    """(JSON result, trace rows, stderr) of ``ncvm run --json --trace`` on a program written to tmp_path."""
    return make_runner(tmp_path)(name, text, machine=machine)


def moves(rows: list[dict]) -> list[tuple]:
    """(line, X, Y, Z) in machine coordinates of every move of a trace."""
    return [(r["line"], round(r["end"]["X"], 4), round(r["end"]["Y"], 4), round(r["end"]["Z"], 4))
            for r in rows if r["call"] in ("rapid", "feed", "arc")]
