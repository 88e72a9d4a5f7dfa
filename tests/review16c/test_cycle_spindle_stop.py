"""Issue 16, rule 4: "Program order kept: spindle and coolant functions where the program put them"; the
brief: "your machine crashes if the output is wrong".

DIN G86 (bore, spindle stop, rapid out) and G87 (back boring) stop the spindle *between* moves of one
block: the run's trace has dwell, spindle stop, rapid out, spindle on (G86) and spindle stop, offset,
rapid down through the bore, back to centre, spindle on (G87). The translation holds every M5 of a block
back until after "the block's move" (docs/translate.md rule 6), and a cycle block has many moves: LinuxCNC
gets the rapid out of G86 with the spindle turning (the boring bar scores the bore) and, for G87, the
offset boring bar rapids down through the bore *turning* — it sweeps the bore wall — before `M5 M3` at
the bottom. Read back with rs274, every move must have the spindle as it was in ncvm's own run.
"""

import json

from .helpers import ncvm, needs_rs274, rs274_canon, rs274_moves_with_spindle, translate

PROGRAM = """%
N10 G90 G17 G71 G54
N20 T1 M6
N30 S500 M3
N40 G0 X10 Y10 Z5
N50 G98 G86 X10 Y10 Z-10 R2 P0.5 F50
N60 G80
N70 G0 Z20
N80 G87 X30 Y10 Z-12 R2 I2 J0 K-4 F50
N85 G80
N90 M30
"""


def run_spindle_per_move(tmp_path):
    trace = tmp_path / "run.jsonl"
    r = ncvm(tmp_path, "run", str(tmp_path / "bore.din"), "--trace", str(trace))
    assert r.returncode == 0, r.stderr
    turning, states = False, []
    for line in trace.read_text().splitlines():
        rec = json.loads(line)
        if rec["call"] == "spindle":
            turning = rec["direction"] != 0
        elif rec["call"] in ("rapid", "feed", "arc"):
            states.append(turning)
    return states


@needs_rs274
def test_boring_cycles_move_with_the_spindle_as_in_the_run(tmp_path):
    rc, text, err = translate(tmp_path, PROGRAM, "bore.din")
    assert rc == 0, err
    expected = run_spindle_per_move(tmp_path)
    assert False in expected  # the cycles move with the spindle stopped in the run
    rc, canon = rs274_canon(tmp_path, text)
    assert rc == 0, canon
    got = [turning for _, turning in rs274_moves_with_spindle(canon)]
    assert len(got) == len(expected), (got, expected)
    wrong = [i for i, (a, b) in enumerate(zip(expected, got)) if a != b]
    assert not wrong, (f"moves {wrong} have the spindle {'turning' if got[wrong[0]] else 'stopped'} on LinuxCNC, "
                       f"{'turning' if expected[wrong[0]] else 'stopped'} in the run:\n{text}")
