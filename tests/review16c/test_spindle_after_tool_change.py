"""Issue 16, rule 4: "spindle and coolant functions where the program put them ... feed and spindle words as
programmed"; the brief: the machine crashes if the output is wrong.

On the simulated control the spindle keeps turning through `T2 M6` (the run's trace has no spindle stop
until the end): the program cuts with T2 without a new M3. LinuxCNC stops the spindle at every M6
(rs274's canon: START_CHANGE, STOP_SPINDLE_TURNING, CHANGE_TOOL). The translation writes `T2 M6` and then
`G1 Z-1` with nothing between: on LinuxCNC tool 2 plunges into the part with the spindle standing. A
translation that keeps the run's motion must have the spindle turning on the new control wherever it
turned in the run (M3 S again after M6), or refuse.
"""

from .helpers import needs_rs274, rs274_canon, rs274_moves_with_spindle, trace_work, translate

PROGRAM = """%
N10 G90 G17 G71 G54
N20 T1 M6
N30 S1000 M3 M8
N40 G0 X10 Y10 Z5
N50 G1 Z-1 F100
N55 G0 Z50
N60 T2 M6
N70 G0 X20 Y10 Z5
N80 G1 Z-1 F100
N90 G0 Z50
N100 M30
"""


@needs_rs274
def test_spindle_turns_on_linuxcnc_for_every_cut_it_turned_in_the_run(tmp_path):
    rc, text, err = translate(tmp_path, PROGRAM, "tc.din")
    assert rc == 0, err
    moves = trace_work(tmp_path, "tc.din")
    assert [call for call, _ in moves].count("feed") == 2  # both plunges cut in the run, spindle on
    rc, canon = rs274_canon(tmp_path, text)
    assert rc == 0, canon
    cuts_standing = [line for line, turning in rs274_moves_with_spindle(canon)
                     if not turning and "STRAIGHT_TRAVERSE" not in line]
    assert not cuts_standing, ("LinuxCNC feeds with the spindle stopped (M6 stopped it, no M3 after):\n"
                               + "\n".join(cuts_standing) + "\n\n" + text)
