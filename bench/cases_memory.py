"""Memory per million moves: a CPL loop of 1,000,000 G1 blocks without a WAIT and a flat DIN file of
1,000,000 G1 lines, each run in its own process; the case prints the process's peak resident memory.

Without bounds the CPL run held every queued block and every recorded move (~620 MB at 1 M moves,
MemoryError at 10 M); the block buffer and the toolpath window keep it flat.
"""

from __future__ import annotations

import subprocess
import sys

from benchlib import WORK, Case

MOVES = 1_000_000
CPL = f"""\
N1 G21 G90 G17 F6000
10 I% = 0
20 WHILE I% < {MOVES} DO
G1 X[(I% - INT(I% / 100) * 100) * 0.5] Y[INT(I% / 100) * 0.01]
30 I% = I% + 1
40 END
M30
"""
PROGRAMS = {"cpl": WORK / "moves_1m.cpl", "din": WORK / "moves_1m.ngc"}

MEASURE = """\
import resource, sys
from pathlib import Path
from ncvm.api import run
from ncvm.runtime.session import RunOptions
result, _ = run(sys.argv[1], options=RunOptions(state_dir=Path(sys.argv[2])))
assert result["status"] == "ok" and result["motion"]["feed_moves"] == int(sys.argv[3]), result["error"]
print(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss)
"""


def write_programs() -> None:
    WORK.mkdir(exist_ok=True)
    if not PROGRAMS["cpl"].exists() or PROGRAMS["cpl"].read_text() != CPL:
        PROGRAMS["cpl"].write_text(CPL)
    if not PROGRAMS["din"].exists():
        lines = ["G21 G90 G17 F6000"] + [f"G1 X{(i % 100) * 0.5:.1f} Y{(i // 100) * 0.01:.2f}" for i in range(MOVES)]
        PROGRAMS["din"].write_text("\n".join(lines + ["M30"]) + "\n")


def runner(dialect: str):
    def run_case() -> None:
        out = subprocess.run([sys.executable, "-c", MEASURE, str(PROGRAMS[dialect]), str(WORK / ".ncvm"), str(MOVES)],
                             capture_output=True, text=True, check=True)
        print(f"  {dialect}: peak RSS {int(out.stdout.split()[-1]) / 1024:,.0f} MB for {MOVES:,} moves", flush=True)

    return run_case


def cases() -> dict[str, Case]:
    return {f"{d}_1m_moves_memory": Case(runner(d), MOVES, "G1/s", setup=write_programs, repeat=1) for d in PROGRAMS}
