"""A division by zero or a domain error is the program's CL 800 error only when the generated code of the
program raised it itself (runtime.locate.raised_by_generated); the same Python error raised inside ncvm (the
NC kernel, a helper of the @ codes) is an internal error, never "CL 800 error: arithmetic error"."""

from __future__ import annotations

import math

import pytest
from sin800_helpers import run_mpf

PROGRAM = "%MPF1\nN10 R1=0.5 @634 R2 R1\nN20 G1 X10 Y5 F1000\nM30\n"
BUGS = {
    "ZeroDivisionError": lambda: 1 / 0,
    "ValueError": lambda: math.sqrt(-1.0),
    "OverflowError": lambda: math.exp(1000.0),
}


def test_division_by_zero_in_the_program_is_cl800_at_its_line(tmp_path):
    e = run_mpf(tmp_path, "%MPF1\nN10 R1=0 R2=5/R1\nM30\n")["error"]
    assert (e["code"], e["message"], e["line"]) == ("CL800", "CL 800 error: division by zero", 2)


@pytest.mark.parametrize("kind", sorted(BUGS))
@pytest.mark.parametrize("target", ["ncvm.dialects.sinumerik.runtime.Channel.arc_sin", "ncvm.nc.kernel.NcKernel.execute"])
def test_a_python_error_inside_ncvm_is_not_a_cl800_error(tmp_path, monkeypatch, kind, target):
    def broken(*args, **kwargs):
        BUGS[kind]()

    monkeypatch.setattr(target, broken)
    with pytest.raises(Exception) as raised:  # noqa: PT011 - each kind in turn
        result = run_mpf(tmp_path, PROGRAM)
        pytest.fail(f"reported as the program's error: {result.get('error')}")
    assert type(raised.value).__name__ == kind
