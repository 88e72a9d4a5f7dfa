"""Whole-process cases: the ``ncvm`` command run as a user runs it, side by side with rs274 on the same work.

Each run starts ``python -m ncvm run ...`` (and ``rs274 -g`` on the peer program when it is installed) as a
child process, alternating the two, and takes the child's own CPU time and peak resident memory from
``os.wait4`` (wall-clock time is noisy on a shared machine; CPU time much less). Figures per case:
``ncvm_cpu_s`` / ``rs274_cpu_s`` medians, ``speedup_vs_rs274`` (rs274 CPU over ncvm CPU, > 1: ncvm is faster),
``ncvm_peak_rss_mb`` / ``rs274_peak_rss_mb``.

- ``proc_cpl_real_loop_300k``: the peer loop_arith at 300,000 iterations, CPL with plain REAL variables;
  ``proc_cpl_double_loop_300k`` the same with DOUBLE (``!``) variables;
- ``proc_sin800_loop_300k``, ``proc_sympas_loop_300k``: the same loop in @ code and rw_SymPas;
- ``proc_startup``: one block (``M2``, bench/peers/startup_m2.ngc) through ``ncvm run`` and rs274;
  ``proc_startup_version`` / ``proc_startup_check``: ``ncvm --version`` and ``ncvm check`` of a small CPL program;
- ``proc_<dialect>_2m_moves_memory``: 2,000,000 computed G1 moves in a loop of each dialect, no plot;
- ``proc_din_flat_500k_memory``: a 500,000-line flat DIN file (bench/peers/gen_flat.py) and rs274 on it;
  ``proc_din_drill_500k_memory``: a 500,000-line DIN bolt circle (per hole a positioning, a plunge, a dwell, a
  retract: the plain runs are a few blocks long) and rs274 on it;
  ``proc_din_check_500k_memory``: ``ncvm check`` of that file;
- ``proc_sympas_2m_moves_plot_memory``: the rw_SymPas 2,000,000 moves with ``--plot`` (a PNG): the plot's
  points are thinned as the moves come and the drawing's cost is bounded by its cap of points;
- ``proc_din_drill_100k``: a 100,000-line DIN bolt circle as CAM writes it (20,000 holes: per hole a positioning,
  a plunge, a dwell, a retract; runs of four plain blocks between two exact stops) and rs274 on it;
- ``proc_sin800_drill_l81_20k``: 20,000 holes drilled by a SINUMERIK program with G81 (the manual's deep-hole
  cycle L81, examples/cl800/L81.spf: 15 moves and 11 dwells a hole) and rs274 on the flat G-code ncvm writes
  for it (``--gcode``, written once: the same moves and dwells);
- with ``run.py --large`` only: ``proc_<dialect>_10m_moves_memory`` (10,000,000 computed G1 moves),
  ``proc_sympas_10m_moves_plot_memory`` (the same with ``--plot``),
  ``proc_din_flat_10m_memory`` (a 10,000,000-line flat DIN file, 340 MB, and rs274 on it) and
  ``proc_din_check_10m_memory`` (``ncvm check`` of that file): memory bounded for a program of any length.
"""

from __future__ import annotations

import json
import math
import subprocess
import sys
from pathlib import Path

from benchlib import NCVM, PEERS, WORK, Case, child, large, rs274, rs274_argv, warm_bytecode
from cases_memory import CPL_MOVES

LOOP = 300_000
MOVES = 2_000_000
FLAT_LINES = 500_000
LARGE = 10_000_000  # moves and lines of the opt-in cases (run.py --large)
DRILL_HOLES = 20_000  # holes of the drilling cases (the DIN file: 5 lines a hole)
STATE = WORK / ".ncvm-proc"
EXAMPLES = PEERS.parent.parent / "examples"

CPL_LOOP = """\
(loop_arith - {n:,} WHILE iterations of parameter arithmetic, as peers/loop_arith.ngc, {kind} variables)
N1 G71 G90 G17
10 I% = 0 : S{s} = 0.0 : M% = 0 : ACC{s} = 1.0 : X{s} = 0.0
20 WHILE I% < {n} DO
30 X{s} = I% * 0.001
40 S{s} = S{s} + X{s} * 2.5 - 1.25
50 ACC{s} = ACC{s} * 0.999 + SIN(X{s}) * COS(X{s}) + SQRT(ABS(S{s}) + 1)
60 M% = M% + (I% - INT(I% / 7) * 7)
70 F{s} = INT(X{s} * 10) / 3
80 I% = I% + 1
90 END
M30
"""

SIN800_MOVES = """\
%MPF9003
(2,000,000 computed G1 moves: a raster of 100 moves a row; R1 counter, R2 row, R3 x, R4 y)
N10 G71 G90 G17 G94 F6000 R1=0
N20 @135 R1 K{n} K30
R2=R1/100 @622 R2 R3=R2*100 R3=R1-R3 R3=R3*0.5 R4=R2*0.01
G1 X=R3 Y=R4
@620 R1 @100 K-20
N30 M30
"""

SYMPAS_MOVES = """\
{{ linear moves (MLRW): a zig-zag raster of {rows} rows x 1000 moves, the last of each row one step of A2 }}
program Moves;
var row, k: integer; dir: double;
begin
  TRVL := 100.0; TRAC := 10000.0;
  for row := 0 to {last} do
  begin
    dir := 1.0 - 2.0 * (row mod 2);
    for k := 1 to 999 do
      MLRW(A1 := dir * 0.1);
    MLRW(A1 := dir * 0.1, A2 := 0.01);
  end;
end.
"""


def drilling_din(holes: int) -> str:
    """A flat DIN bolt circle as a CAM system writes it: per hole a positioning, a plunge, a dwell, a retract."""
    lines = ["G17 G21 G90 G94", "G0 X0 Y0 Z50"]
    for i in range(holes):
        a = math.radians(i * 360 / holes)
        lines += [f"G0 X{40 * math.cos(a):.4f} Y{40 * math.sin(a):.4f}", "G0 Z2", "G1 Z-12 F150", "G4 P0.5", "G0 Z2"]
    return "\n".join(lines + ["M2"]) + "\n"


def drilling_sin800(holes: int) -> str:
    """The same bolt circle drilled with G81 (L81: the manual's deep-hole cycle, its transfer parameters R22-R28
    as tests/dialects/sinumerik/test_drilling_cycles.py sets them)."""
    lines = ["%MPF9004", "N10 G17 G90 G94 S1000 M3 F100", "N20 G0 X0 Y0 Z50",
             "N30 R22=2 R24=2 R25=5 R26=-14 R27=0.5 R28=0.25"]
    for i in range(holes):
        a = math.radians(i * 360 / holes)
        lines.append(f"{'G81 ' if i == 0 else ''}X{40 * math.cos(a):.3f} Y{40 * math.sin(a):.3f}")
    return "\n".join(lines + ["G80", "M30"]) + "\n"


def write_drilling() -> None:
    """The drilling programs, and the flat G-code of the SINUMERIK one for rs274 (written by ncvm once)."""
    write_programs()
    _write(f"drill_{DRILL_HOLES * 5 // 1000}k.ngc", drilling_din(DRILL_HOLES))
    folder = WORK / "drill_l81"
    folder.mkdir(exist_ok=True)
    _write("drill_l81/L81.spf", (EXAMPLES / "cl800" / "L81.spf").read_text())
    _write("drill_l81/drill.mpf", drilling_sin800(DRILL_HOLES))
    flat = folder / "drill_flat.ngc"
    if not flat.exists() or flat.stat().st_mtime < (folder / "drill.mpf").stat().st_mtime:
        subprocess.run(ncvm_run("drill_l81/drill.mpf", "-d", "sin800", "--gcode", str(flat)), check=True,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)


def _write(name: str, text: str) -> None:
    path = WORK / name
    if not path.exists() or path.read_text() != text:
        path.write_text(text)


def write_programs() -> None:
    WORK.mkdir(exist_ok=True)
    warm_bytecode()
    _write("real_loop_300k.cpl", CPL_LOOP.format(n=LOOP, kind="REAL", s=""))
    _write("double_loop_300k.cpl", CPL_LOOP.format(n=LOOP, kind="DOUBLE", s="!"))
    _write("loop_arith_300k.ngc", (PEERS / "loop_arith.ngc").read_text().replace("100000", str(LOOP))
           .replace("100,000", f"{LOOP:,}"))
    # the sum R2 grows with the square of the passes: x 2.0 instead of 2.5 (the same work) keeps it within the
    # R parameter range (+/-99,999,999, error CL800) at 300,000 passes
    _write("loop_arith_300k.mpf", (PEERS.parent / "sin800" / "loop_arith.mpf").read_text()
           .replace("K100000", f"K{LOOP}").replace("100,000", f"{LOOP:,}").replace("R90=R6*2.5", "R90=R6*2.0"))
    _write("loop_arith_300k.sap", (PEERS.parent / "sympas" / "loop_arith.sap").read_text()
           .replace("100000", str(LOOP)).replace("100,000", f"{LOOP:,}"))
    _write("moves_2m.cpl", CPL_MOVES.format(n=MOVES))
    _write("moves_2m.mpf", SIN800_MOVES.format(n=MOVES))
    _write("moves_2m.sap", SYMPAS_MOVES.format(rows=MOVES // 1000, last=MOVES // 1000 - 1))
    _write("small.cpl", CPL_LOOP.format(n=10, kind="REAL", s=""))
    _flat(WORK / "flat_500k.ngc", FLAT_LINES)
    _write("drill_500k.ngc", drilling(FLAT_LINES // 5))


def drilling(holes: int) -> str:
    """A DIN bolt circle of ``holes`` holes as CAM output writes it, five lines a hole: ``G0 X.. Y..``,
    ``G0 Z2``, ``G1 Z-12 F150``, ``G4 P0.5``, ``G0 Z2``."""
    lines = ["G17 G21 G90 G94", "G0 X0 Y0 Z50"]
    for i in range(holes):
        a = math.radians(i * 360 / holes)
        lines += [f"G0 X{40 * math.cos(a):.4f} Y{40 * math.sin(a):.4f}", "G0 Z2", "G1 Z-12 F150", "G4 P0.5", "G0 Z2"]
    return "\n".join(lines + ["M2"]) + "\n"


def _flat(path: Path, lines: int) -> None:
    if not path.exists():
        subprocess.run([sys.executable, str(PEERS / "gen_flat.py"), "-n", str(lines), "-o", str(path)], check=True)


def write_large_programs() -> None:
    write_programs()
    _write("moves_10m.cpl", CPL_MOVES.format(n=LARGE))
    _write("moves_10m.mpf", SIN800_MOVES.format(n=LARGE))
    _write("moves_10m.sap", SYMPAS_MOVES.format(rows=LARGE // 1000, last=LARGE // 1000 - 1))
    _flat(WORK / "flat_10m.ngc", LARGE)


def ncvm_run(program: str, *extra: str) -> list[str]:
    return NCVM + ["run", "--state", str(STATE), *extra, str(WORK / program)]


def paired(ncvm_argv: list[str], peer: Path | None, *, expect_moves: int | None = None):
    """One run: ncvm and (when installed) rs274 on ``peer``, in alternating order from run to run."""
    turn = [0]

    def run_case() -> dict:
        figures = {}
        order = ["ncvm", "rs274"] if turn[0] % 2 == 0 else ["rs274", "ncvm"]
        turn[0] += 1
        for who in order:
            if who == "rs274":
                if peer is None or rs274() is None:
                    continue
                used = child(rs274_argv(peer))
            elif expect_moves is None:
                used = child(ncvm_argv)
            else:  # the JSON result says how many moves ran (and the plot asked for was drawn)
                at = ncvm_argv.index("run") + 1
                out = WORK / "proc_result.json"
                plot = Path(ncvm_argv[ncvm_argv.index("--plot") + 1]) if "--plot" in ncvm_argv else None
                if plot is not None:
                    plot.unlink(missing_ok=True)
                used = child(ncvm_argv[:at] + ["--json"] + ncvm_argv[at:], stdout=out)
                moves = json.loads(out.read_text())["motion"]["feed_moves"]
                assert moves == expect_moves, f"{moves} feed moves, expected {expect_moves}"
                assert plot is None or plot.stat().st_size > 0, f"no plot drawn in {plot}"
            figures[f"{who}_cpu_s"] = used.cpu_s
            figures[f"{who}_wall_s"] = used.wall_s
            figures[f"{who}_peak_rss_mb"] = used.peak_rss_mb
        return figures

    return run_case


def cases() -> dict[str, Case]:
    def case(run, count, unit, repeat=0):
        return Case(run, count, unit, setup=write_programs, repeat=repeat)

    def large_case(run, unit):
        return Case(run, LARGE, unit, setup=write_large_programs, repeat=1, available=large,
                    why_unavailable="10,000,000 moves: bench/run.py --large")

    return {
        "proc_cpl_real_loop_300k": case(paired(ncvm_run("real_loop_300k.cpl"), WORK / "loop_arith_300k.ngc"),
                                        LOOP, "iterations/s"),
        "proc_cpl_double_loop_300k": case(paired(ncvm_run("double_loop_300k.cpl"), WORK / "loop_arith_300k.ngc"),
                                          LOOP, "iterations/s"),
        "proc_sin800_loop_300k": case(paired(ncvm_run("loop_arith_300k.mpf", "-d", "sin800"),
                                             WORK / "loop_arith_300k.ngc"), LOOP, "iterations/s"),
        "proc_sympas_loop_300k": case(paired(ncvm_run("loop_arith_300k.sap", "-d", "sympas"),
                                             WORK / "loop_arith_300k.ngc"), LOOP, "iterations/s"),
        "proc_startup": case(paired(NCVM + ["run", "--state", str(STATE), str(PEERS / "startup_m2.ngc")],
                                    PEERS / "startup_m2.ngc"), 1, "runs/s", repeat=11),
        "proc_startup_version": case(paired(NCVM + ["--version"], None), 1, "runs/s", repeat=11),
        "proc_startup_check": case(paired(NCVM + ["check", str(WORK / "small.cpl")], None), 1, "runs/s",
                                   repeat=11),
        **{f"proc_{d}_2m_moves_memory": case(paired(ncvm_run(f"moves_2m.{ext}", "-d", d), None,
                                                    expect_moves=MOVES), MOVES, "G1/s", repeat=1)
           for d, ext in (("cpl", "cpl"), ("sin800", "mpf"), ("sympas", "sap"))},
        "proc_sympas_2m_moves_plot_memory": case(paired(ncvm_run("moves_2m.sap", "-d", "sympas", "--plot",
                                                                  str(WORK / "moves_2m_sap.png")), None,
                                                          expect_moves=MOVES), MOVES, "G1/s", repeat=1),
        "proc_din_flat_500k_memory": case(paired(ncvm_run("flat_500k.ngc", "-d", "din"), WORK / "flat_500k.ngc"),
                                          FLAT_LINES, "lines/s", repeat=1),
        "proc_din_drill_100k": Case(paired(ncvm_run(f"drill_{DRILL_HOLES * 5 // 1000}k.ngc", "-d", "din"),
                                           WORK / f"drill_{DRILL_HOLES * 5 // 1000}k.ngc"), DRILL_HOLES * 5, "lines/s",
                                    setup=write_drilling),
        "proc_sin800_drill_l81_20k": Case(paired(ncvm_run("drill_l81/drill.mpf", "-d", "sin800"),
                                                 WORK / "drill_l81" / "drill_flat.ngc"), DRILL_HOLES, "holes/s",
                                          setup=write_drilling),
        "proc_din_drill_500k_memory": case(paired(ncvm_run("drill_500k.ngc", "-d", "din"), WORK / "drill_500k.ngc",
                                                  expect_moves=FLAT_LINES // 5), FLAT_LINES, "lines/s", repeat=1),
        "proc_din_check_500k_memory": case(paired(NCVM + ["check", str(WORK / "flat_500k.ngc")], None), FLAT_LINES,
                                           "lines/s", repeat=1),
        **{f"proc_{d}_10m_moves_memory": large_case(paired(ncvm_run(f"moves_10m.{ext}", "-d", d), None,
                                                           expect_moves=LARGE), "G1/s")
           for d, ext in (("cpl", "cpl"), ("sin800", "mpf"), ("sympas", "sap"))},
        "proc_sympas_10m_moves_plot_memory": large_case(paired(ncvm_run("moves_10m.sap", "-d", "sympas", "--plot",
                                                                         str(WORK / "moves_10m_sap.png")), None,
                                                                 expect_moves=LARGE), "G1/s"),
        "proc_din_flat_10m_memory": large_case(paired(ncvm_run("flat_10m.ngc", "-d", "din"), WORK / "flat_10m.ngc"),
                                               "lines/s"),
        "proc_din_check_10m_memory": large_case(paired(NCVM + ["check", str(WORK / "flat_10m.ngc")], None), "lines/s"),
    }
