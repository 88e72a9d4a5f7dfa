"""Issue 16, target 6: "plain ISO/Fanuc style (`G43 H`, `G2/G3 I/J/K`, `%` wrapper)"; the quality bar: "a
silently wrong answer is the worst defect".

A Fanuc-style ISO control reads an axis word written without a decimal point in its least input increment
(with the usual setting, decimal point input off: `X10` is 0.010 mm, `Z5` is 0.005 mm, `G4 X2` is 2 ms);
only `X10.` is 10 mm. That is why ISO programs write every dimension with a point. The ISO translation
writes integral values the LinuxCNC way (`G0 X10 Y10 Z5`, `G2 X45 Y20 I-15 J0`, `G4 X2`): on such a
control the tool goes to the wrong place (a retract `Z50` stops 0.05 mm above the part) and the dwell is
a thousandth of the program's. The ISO target must write each dimension word and dwell with a decimal
point.
"""

import re

from .helpers import code_lines, translate

PROGRAM = """%
N10 G90 G17 G71 G54
N20 T1 M6
N30 S2500 M3
N40 G0 X45 Y20 Z50
N50 G1 Z-3 F200
N60 G2 X45 Y20 I-15 J0 F600
N70 G4 X2
N80 G0 Z50
N90 M30
"""

DIMENSION = re.compile(r"\b([XYZIJKR])(-?\d+(?:\.\d*)?)")


def test_iso_dimensions_and_dwell_have_a_decimal_point(tmp_path):
    rc, text, err = translate(tmp_path, PROGRAM, "part.din", "--target", "iso", out_name="out.nc")
    assert rc == 0, err
    words = [(line, m.group(0)) for line in code_lines(text) for m in DIMENSION.finditer(line)]
    assert words, text
    bare = [f"{word} in '{line}'" for line, word in words if "." not in word]
    assert not bare, ("ISO words without a decimal point (a Fanuc-style control reads them in its least "
                      "input increment, X10 = 0.010 mm):\n" + "\n".join(bare) + "\n\n" + text)
