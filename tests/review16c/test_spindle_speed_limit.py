"""Issue 16, rule 4: "feed and spindle words as programmed"; docs/translate.md: "G96 constant cutting speed
(written as the spindle speeds the run computed)"; the brief: "spindle speed limits (G92 S / G26), constant
surface speed G96"; the DIN profile follows rs274 (docs/din.md).

1. rs274's `G96 D2000 S200` limits the spindle to 2000 rev/min (D: the maximum spindle speed). ncvm's DIN
   run ignores the D word: the facing cut to X1 ends at 31,831 rev/min, and the translation writes
   `M3 S31830.9886` — sixteen times the speed the program allowed, for the spindle of the new control.
2. `G92 S3000` (the spindle speed limit of the SINUMERIK / DIN 66025 lathe family, written by a user who
   means it as a limit) has no axis words: rs274 stops ("All axes missing with G92"). ncvm takes S3000 as
   the new cutting speed under G96 and the translation writes `M3 S47746.4829`.
A translated spindle speed must stay within the program's limit, or the translation must refuse.
"""

import re

from .helpers import code_lines, translate


def speeds(text):
    return [float(m.group(1)) for line in code_lines(text) for m in re.finditer(r"\bS(\d+(?:\.\d*)?)", line)]


def test_g96_d_limit_bounds_the_written_spindle_speed(tmp_path):
    program = "%\nN10 G90 G71 G54\nN20 S500 M3\nN30 G0 X10 Y0 Z0\nN40 G96 D2000 S200\nN50 G1 X1 F100\nN60 M30\n"
    rc, text, err = translate(tmp_path, program, "face.din")
    if rc != 0:
        assert "D" in err and "G96" in err, err  # a clear refusal naming the unsupported limit is safe
        return
    too_fast = [s for s in speeds(text) if s > 2000.0 + 1e-6]
    assert not too_fast, f"spindle speeds above the program's G96 D2000 limit: {too_fast}\n{text}"


def test_g92_s_without_axes_is_no_new_cutting_speed(tmp_path):
    program = ("%\nN10 G90 G71 G54\nN20 S500 M3\nN30 G0 X10 Y0 Z0\nN40 G96 S200\nN50 G92 S3000\n"
               "N60 G1 X20 F100\nN70 M30\n")
    rc, text, err = translate(tmp_path, program, "limit.din")
    if rc != 0:
        assert "G92" in err, err  # refused as rs274 refuses it
        return
    too_fast = [s for s in speeds(text) if s > 3183.1]  # 200 m/min at X10, and no higher than that
    assert not too_fast, f"G92 S3000 became a cutting speed of 3000 m/min: spindle {too_fast}\n{text}"
