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
