"""CPL cases: the peer programs loop_arith, loop_motion and subcalls written in CPL, and rs274 on the originals;
wait_motion (a G1 block and a WAIT a pass) has no peer: rs274 has no block buffer to wait for.
cpl_prn_file (no peer) writes records to a file with PRN#, the cost of a record and of making it durable;
cpl_perm_write (no peer) writes a permanent variable a pass, the cost of a write to the permanent store.

Each CPL program does the work of its LinuxCNC peer in bench/peers: the same loop counts,
the same arithmetic (MOD written as I% - INT(I%/7)*7, CPL has no MOD), the same moves and calls.
The ``_real`` twins use plain REAL (binary32) variables where the originals use DOUBLE (``!``): most CPL
programs are written that way, and every REAL store rounds to binary32.
"""

from __future__ import annotations

from benchlib import PEERS, WORK, Case, rs274_case

from ncvm.api import run
from ncvm.runtime.session import RunOptions

LOOP_ARITH = """\
(loop_arith - 100,000 WHILE iterations of parameter arithmetic, as peers/loop_arith.ngc)
N1 G71 G90 G17
10 I% = 0 : S! = 0.0 : M% = 0 : ACC! = 1.0 : X! = 0.0
20 WHILE I% < 100000 DO
30 X! = I% * 0.001
40 S! = S! + X! * 2.5 - 1.25
50 ACC! = ACC! * 0.999 + SIN(X!) * COS(X!) + SQRT(ABS(S!) + 1)
60 M% = M% + (I% - INT(I% / 7) * 7)
70 F! = INT(X! * 10) / 3
80 I% = I% + 1
90 END
M30
"""

LOOP_MOTION = """\
(loop_motion - 100 rows x 1000 computed G1 moves, semicircle turnarounds, two full circles)
N1 G71 G90 G17 G94 G40 G80
N2 F1200
N3 G0 Z5
N4 G0 X0 Y0
N5 G1 Z-0.5
10 ROW% = 0
20 WHILE ROW% < 100 DO
30 Y0! = ROW% * 2 : Z! = -0.5 - ROW% * 0.01 : DIR% = 1 - 2 * (ROW% - INT(ROW% / 2) * 2)
40 K% = 1
50 WHILE K% <= 1000 DO
60 U! = K% * 0.1 - 50
G1 X[50 + DIR% * U!] Y[Y0! + 0.5 * SIN(K% * 3.6)] Z[Z!]
70 K% = K% + 1
80 END
90 IF ROW% < 99 THEN
100 IF DIR% > 0 THEN
G3 X100 Y[Y0! + 2] I0 J1
110 ELSE
G2 X0 Y[Y0! + 2] I0 J1
120 ENDIF
130 ENDIF
140 ROW% = ROW% + 1
150 END
G2 I5 J0
G3 I5 J0
G0 Z5
M30
"""

DRILL = """\
(DRILL - one hole with explicit moves: P1 x, P2 y, P3 depth, P4 retract, P5 feed)
10 CLEAR = P4 + 1 : BOTTOM = P3 - 0.2
N20 G0 X[P1] Y[P2]
N30 G0 Z[P4]
N40 G1 Z[BOTTOM] F[P5]
N50 G0 Z[P4]
N60 G0 Z[CLEAR]
"""

SUBCALLS = """\
(subcalls - 20,000 calls of the DRILL cycle on a 200 x 100 grid, 5 mm pitch)
N1 G71 G90 G17 G94 G40 G80
N2 F300
N3 G0 Z10
10 ROW% = 0
20 WHILE ROW% < 100 DO
30 COL% = 0
40 WHILE COL% < 200 DO
50 CALL DRILL [COL% * 5, ROW% * 5, -3, 2, 300]
60 COL% = COL% + 1
70 END
80 ROW% = ROW% + 1
90 END
M30
"""

WAIT_MOTION = """\
(wait_motion - 10,000 passes of one computed G1 block and a WAIT: the program reads the executed state each pass)
N1 G71 G90 G17 G94 F1200
10 I% = 0
20 WHILE I% < 10000 DO
G1 X[I% * 0.01] Y[0.5 * SIN(I% * 3.6)]
30 WAIT
40 I% = I% + 1
50 END
M30
"""

PRN_FILE = """\
(prn_file - 5,000 records written to a file with PRN#, as a program logs its measurements)
10 OPENW(1,"PRNLOG",130)
20 REWRITE(1)
30 FOR I%=1 TO 5000
40 PRN#(1,"P",I%," X",I%*0.5," Y",I%*0.25)
50 NEXT I%
60 CLOSE(1)
M30
"""

PERM_WRITE = """\
(perm_write - 10,000 passes, each writes the permanent variable @5, as a program counts its parts)
10 @5 = 0
20 FOR I%=1 TO 10000
30 @5 = @5 + 1
40 NEXT I%
M30
"""

FOLDER = WORK / "cpl"


def real_twin(text: str) -> str:
    """The program with REAL variables for its DOUBLE ones (X! -> X)."""
    return text.replace("!", "").replace(")\n", ", REAL variables)\n", 1)


def write_programs() -> None:
    FOLDER.mkdir(parents=True, exist_ok=True)
    for name, text in (("loop_arith.cpl", LOOP_ARITH), ("loop_motion.cpl", LOOP_MOTION), ("DRILL", DRILL),
                       ("subcalls.cpl", SUBCALLS), ("loop_arith_real.cpl", real_twin(LOOP_ARITH)),
                       ("loop_motion_real.cpl", real_twin(LOOP_MOTION)), ("wait_motion.cpl", WAIT_MOTION),
                       ("prn_file.cpl", PRN_FILE), ("perm_write.cpl", PERM_WRITE)):
        p = FOLDER / name
        if not p.exists() or p.read_text() != text:
            p.write_text(text)


def runner(name: str):
    def run_case() -> None:
        result, _ = run(FOLDER / name, options=RunOptions(state_dir=WORK / ".ncvm"))
        assert result["status"] == "ok", result["error"]

    return run_case


def cases() -> dict[str, Case]:
    return {
        "cpl_loop_arith": Case(runner("loop_arith.cpl"), 100_000, "iterations/s", setup=write_programs),
        "cpl_loop_motion": Case(runner("loop_motion.cpl"), 100_000, "G1/s", setup=write_programs),
        "cpl_loop_arith_real": Case(runner("loop_arith_real.cpl"), 100_000, "iterations/s", setup=write_programs),
        "cpl_loop_motion_real": Case(runner("loop_motion_real.cpl"), 100_000, "G1/s", setup=write_programs),
        # the file lies in the state directory's file root under bench/.work: on the disk, as a user's files do
        "cpl_prn_file": Case(runner("prn_file.cpl"), 5_000, "records/s", setup=write_programs),
        # the store lies in the state directory under bench/.work: on the disk, as a user's state directory does
        "cpl_perm_write": Case(runner("perm_write.cpl"), 10_000, "writes/s", setup=write_programs),
        "cpl_subcalls": Case(runner("subcalls.cpl"), 20_000, "calls/s", setup=write_programs),
        "cpl_wait_motion": Case(runner("wait_motion.cpl"), 10_000, "passes/s", setup=write_programs),
        "rs274_loop_arith": rs274_case(PEERS / "loop_arith.ngc", 100_000, "iterations/s"),
        "rs274_loop_motion": rs274_case(PEERS / "loop_motion.ngc", 100_000, "G1/s"),
        "rs274_subcalls": rs274_case(PEERS / "subcalls.ngc", 20_000, "calls/s"),
    }
