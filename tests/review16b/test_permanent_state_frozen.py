"""Issue 16 rule 3 "Say what was frozen: where the program's path depended on run-time input (operator keys,
PLC inputs, scenario events, measured values, random data), the output marks the block with a comment
naming the decision and its source line".

CPL permanent variables (`@1`, kept by the control across runs, here in the state folder) are input from
outside the program just like a key press: the program below adds a deburring pass on every third part.
Three translations in the same folder give two different programs, each with "0 frozen decisions" and no
mark: the user gets whichever branch the simulated counter happened to take, silently. The translation must
either not depend on what earlier runs left behind, or mark the branch FROZEN with its source line.
"""

from .helpers import translate

EVERY_THIRD_PART = """(every third part gets a deburring pass: the count lives in a permanent variable)
10 IF @1 = NUL THEN @1 = 0 ENDIF
20 @1 = @1 + 1
N30 G90 G17 G54 G0 X0 Y0 Z5
N40 G1 Z-1 F200
N50 G1 X30
60 IF @1 >= 3 THEN
N70 G1 Y10
N80 G1 X0
90 @1 = 0
100 ENDIF
N110 G0 Z50
M30
"""


def test_a_branch_on_a_permanent_variable_is_marked_or_not_frozen_at_all(tmp_path):
    outputs = []
    for i in range(3):
        rc, text, err = translate(tmp_path, EVERY_THIRD_PART, "count.cpl", out_name=f"out{i}.ngc")
        assert rc == 0, err
        outputs.append(text)
    if len(set(outputs)) == 1:
        return  # the translation does not depend on the counter left by earlier runs
    unmarked = [i for i, text in enumerate(outputs) if "FROZEN" not in text]
    assert not unmarked, (
        f"translations {unmarked} follow the permanent variable @1 of earlier runs without a FROZEN mark; "
        f"the third one is:\n{outputs[2]}")
