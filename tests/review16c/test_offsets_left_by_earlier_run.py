"""Issue 16, rule 3: "Say what was frozen: where the program's path depended on run-time input ... the output
marks the block with a comment naming the decision and its source line"; docs/sin800.md: "A run that starts
with zero offsets ... an earlier run left ... says so first ... `NC state: G58 X10 kept from an earlier run`".

The SINUMERIK programmable zero offsets G58/G59 stay in the NC (the state directory) after the program
that set them. Translated a second time in the same state directory, the same program's first move
`G0 X0 Y0 Z5` (before its own `G58`) becomes `G0 X11 Y5 Z5`, and every later position is 1 mm off too:
the path depends on what an earlier run left. `ncvm run` says so; the translation says nothing — no
FROZEN mark, no notice on stderr, only the header's generic "an added offset ... is included" that the
first translation (without the left-over offsets) had as well.
"""

from pathlib import Path

from .helpers import code_lines, translate

MACHINE = Path(__file__).parents[2] / "examples" / "sin800" / "machine.toml"

PROGRAM = """%MPF11
N10 G17 G71 G90 G54 G94
N20 T1 M6 D1
N30 S2000 M3
N40 G0 X0 Y0 Z5
N50 G58 X10 Y5
N60 G1 X20 F300
N80 G59 X1
N90 G1 X2
N100 M30
"""


def test_second_translation_says_it_uses_offsets_an_earlier_run_left(tmp_path):
    args = ("--dialect", "sin800", "--machine", str(MACHINE))
    rc, first, err = translate(tmp_path, PROGRAM, "g58.mpf", *args, out_name="first.ngc")
    assert rc == 0, err
    assert "G0 X0 Y0 Z5" in code_lines(first)
    rc, second, err = translate(tmp_path, PROGRAM, "g58.mpf", *args, out_name="second.ngc")
    assert rc == 0, err
    if code_lines(second) == code_lines(first):
        return  # the same path: nothing to say
    said = "earlier run" in second or "FROZEN" in second or "earlier run" in err
    assert said, ("the second translation moves elsewhere (offsets left by the first run) without a word:\n"
                  f"--- first\n{first}\n--- second\n{second}\n--- stderr\n{err}")
