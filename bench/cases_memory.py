"""Memory per million moves: a CPL loop of 1,000,000 G1 blocks without a WAIT and a flat DIN file of
1,000,000 G1 lines, each run in its own process; the case prints the process's peak resident memory and
gives it (``ncvm_peak_rss_mb``, with the child's ``ncvm_cpu_s`` and ``ncvm_wall_s``) to ``run.py --json``.
Memory per million output lines: a CPL loop of 1,000,000 PRN#(0) lines (no moves).

Without bounds the CPL run held every queued block and every recorded move (~620 MB at 1 M moves,
MemoryError at 10 M); the block buffer and the toolpath window keep it flat. The CPL screen and file table
kept every output line besides the session's bounded output (1,000,000 lines: 122 MB peak); now (47 MB) only the session keeps
its first and last 10,000. The DIN file is read a stretch at a time; past its leading stretches (what
``HOLD_BYTES`` holds) it is read again as it runs (issue 18): 81 MB when it was read again whole. The children are started by benchlib.child, so their peak is their own (forked from
the bench process they showed its peak, 162 MB each, after the in-process cases).
"""

from __future__ import annotations

import sys

from benchlib import WORK, Case, child

MOVES = 1_000_000
#: n computed G1 moves in a CPL loop, a raster of 100 moves a row (cases_process uses it too)
CPL_MOVES = """\
N1 G71 G90 G17 F6000
10 I% = 0
20 WHILE I% < {n} DO
G1 X[(I% - INT(I% / 100) * 100) * 0.5] Y[INT(I% / 100) * 0.01]
30 I% = I% + 1
40 END
M30
"""
CPL = CPL_MOVES.format(n=MOVES)
OUTPUT = f"""\
10 I% = 0
20 WHILE I% < {MOVES} DO
30 I% = I% + 1
40 PRN#(0, "LINE ", I%)
50 END
M30
"""
PROGRAMS = {"cpl": WORK / "moves_1m.cpl", "din": WORK / "moves_1m.ngc", "cpl_output": WORK / "output_1m.cpl"}
TEXTS = {"cpl": CPL, "cpl_output": OUTPUT}

MEASURE = """\
import sys
from pathlib import Path
from ncvm.api import run
from ncvm.runtime.session import RunOptions
result, _ = run(sys.argv[1], options=RunOptions(state_dir=Path(sys.argv[2])))
assert result["status"] == "ok" and result["motion"]["feed_moves"] == int(sys.argv[3]), result["error"]
"""


def write_programs() -> None:
    WORK.mkdir(exist_ok=True)
    for name, text in TEXTS.items():
        if not PROGRAMS[name].exists() or PROGRAMS[name].read_text() != text:
            PROGRAMS[name].write_text(text)
    if not PROGRAMS["din"].exists():
        lines = ["G21 G90 G17 F6000"] + [f"G1 X{(i % 100) * 0.5:.1f} Y{(i // 100) * 0.01:.2f}" for i in range(MOVES)]
        PROGRAMS["din"].write_text("\n".join(lines + ["M30"]) + "\n")


def runner(dialect: str):
    moves = 0 if dialect == "cpl_output" else MOVES

    def run_case() -> dict:
        # started by the bench's launcher (benchlib.child): a child forked from this process, grown by the cases
        # before, would count this process's memory in its peak
        used = child([sys.executable, "-c", MEASURE, str(PROGRAMS[dialect]), str(WORK / ".ncvm"), str(moves)])
        what = "output lines" if dialect == "cpl_output" else "moves"
        print(f"  {dialect}: peak RSS {used.peak_rss_mb:,.0f} MB for {MOVES:,} {what}", flush=True)
        # the child's figures, as a whole-process case gives them: run.measure puts them in the JSON document
        return {"ncvm_cpu_s": used.cpu_s, "ncvm_wall_s": used.wall_s, "ncvm_peak_rss_mb": used.peak_rss_mb}

    return run_case


def cases() -> dict[str, Case]:
    out = {f"{d}_1m_moves_memory": Case(runner(d), MOVES, "G1/s", setup=write_programs, repeat=1, in_process=False)
           for d in ("cpl", "din")}
    out["cpl_1m_output_lines_memory"] = Case(runner("cpl_output"), MOVES, "lines/s", setup=write_programs, repeat=1,
                                             in_process=False)
    return out
