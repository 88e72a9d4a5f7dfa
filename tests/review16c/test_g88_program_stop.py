"""Issue 16, rule 4: "Program order kept ... feed and spindle words as programmed"; "Done means": "rs274 reads
each translation without an error, reaches its program end".

DIN G88 (docs/din.md: "dwell, spindle stop, program stop, the operator takes the tool to the clearance
height") makes the canon call `stop` with kind "G88", and the writer writes the kind as the line: the
translation contains a bare `G88` where the program stops. On LinuxCNC that is a canned-cycle motion code
without axes: rs274 fails ("All axes missing with motion code") with the tool at the bottom of the bore,
never reaching the program end; on a Fanuc-style control a bare G88 selects the boring cycle modally, and
the operator's next positioning runs a boring cycle. The stop must be the target's program stop (M0).
"""

from .helpers import code_lines, needs_rs274, rs274_canon, translate

PROGRAM = """%
N10 G90 G17 G71 G54
N20 T1 M6
N30 S500 M3
N40 G0 X10 Y10 Z5
N50 G98 G88 X10 Y10 Z-10 R2 P0.5 F50
N60 G80
N70 M30
"""


def test_g88_stop_is_a_program_stop_on_every_target(tmp_path):
    for target in ("linuxcnc", "sinumerik840d", "iso"):
        rc, text, err = translate(tmp_path, PROGRAM, "g88.din", "--target", target, out_name=f"out.{target}")
        assert rc == 0, err
        lines = code_lines(text)
        assert "G88" not in lines, f"{target}: the program stop is written as a bare G88:\n{text}"
        assert "M0" in lines or "M00" in lines, f"{target}: no program stop:\n{text}"


@needs_rs274
def test_g88_translation_reaches_its_end_in_rs274(tmp_path):
    rc, text, err = translate(tmp_path, PROGRAM, "g88.din")
    assert rc == 0, err
    rc, canon = rs274_canon(tmp_path, text)
    assert rc == 0 and "All axes missing" not in canon, canon[-500:]
