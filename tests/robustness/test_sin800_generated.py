"""Generated valid SINUMERIK 800 programs: run-time faults make sense, and CL 800 runs like its object file.

Mutation fuzzing (test_mutations.py) mostly stops at read errors. Here a small
grammar writes programs that read and compile cleanly: hand-written @ code
part programs (R words, @ codes of the table with operands of the right kind,
loops with @13x/@14x/@100, CASE, push/pop, L calls with P passes) and CL 800
sources (declarations, expressions, IF/CASE/WHILE/REPEAT/FOR, system memory
reads and writes). Each is run with a small step limit; a fault must come from
the NC's own checks, never from a Python error caught on the way, and a CL 800
source must give the same result document as its compiled object file.

The regression tests below hold the minimal programs of the bugs the
generator found.
"""

from __future__ import annotations

import pytest

from ncvm.api import compile_program, run
from ncvm.runtime.session import RunOptions


@pytest.mark.parametrize("text, message", [
    # @3b1 PLCDB with 0 data words read no word and stopped with "invalid literal for int()"
    ("@3b1 R10 K1 K10 K0 K0 K101", "number of data words 0 outside 1-3"),
    ("@3b0 R10 K1 K10 K0 K3 K1", "number of data words 3 outside 1-2"),
    # SQRT/LN/ARC SIN outside their domain stopped with "arithmetic error (math domain error)"
    ("R1=-4 @613 R2 R1", "SQRT(-4): no square root of a negative number"),
    ("@640 R2 K0", "LN(0): no logarithm of zero or a negative number"),
    ("@634 R2 K1.5", "ARC SIN(1.5): the sine must lie between -1 and 1"),
    ("@641 R2 K1000", "INV LN(1000): the result is too large"),
])
def test_fault_names_the_users_mistake(run_text, text, message):
    result = run_text(f"%MPF1\n{text}\nM30\n", name="P1.mpf", dialect="sin800")
    assert result["error"]["code"] == "CL800"
    assert result["error"]["message"] == f"CL 800 error: {message}"
    assert result["error"]["line"] == 2


# 11 locals R50-R60 and 24 temporaries R76-R99 (one per bracket level): as one @040 K35 list the push did
# not fit a block and the valid program failed with S064; now each range is pushed by its own @041.
MANY_TEMPORARIES = """PROGRAM 5;
CHANNEL NC 0;
PAR REAL: R1, R2;
LOCAL REAL: R50, R51, R52, R53, R54, R55, R56, R57, R58, R59, R60;
BEGIN
R50 = 1; R60 = 2;
R2 = (((((((((((((((((((((((R1 + 1) * 2) + 1) * 2) + 1) * 2) + 1) * 2)
+ 1) * 2) + 1) * 2) + 1) * 2) + 1) * 2) + 1) * 2) + 1) * 2) + 1) * 2)
+ 1) * R50 + R60;
END.
"""


def test_push_set_too_long_for_one_block_is_split(tmp_path):
    src = tmp_path / "p.cl8"
    src.write_text(MANY_TEMPORARIES, encoding="latin-1")
    obj = compile_program(src, tmp_path / "L5.spf").read_text(encoding="latin-1").split("\n")
    assert obj[1].startswith("@041 R50 R60 @041 R76 R99 ")
    assert obj[-2].endswith(" @043 R76 R99 @043 R50 R60 M17")  # popped in the reverse order
    by_source, _ = run(src, options=RunOptions(state_dir=tmp_path / "a"))
    by_object, _ = run(tmp_path / "L5.spf", dialect="sin800", options=RunOptions(state_dir=tmp_path / "b"))
    # R1 = 0: 11 times x -> (x + 1) * 2 gives 2**12 - 2 = 4094; (4094 + 1) * R50 + R60 = 4095 * 1 + 2
    assert by_source["error"] is None and by_source["variables"]["R2"] == 4097.0
    assert by_source["variables"] == by_object["variables"]
    assert by_source["variables"]["R50"] == by_source["variables"]["R60"] == 0.0  # restored by the pops
