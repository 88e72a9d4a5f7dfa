"""The program's run-time errors and ncvm's own faults are told apart (pyfaults, runtime.locate.raised_by_generated).

A Python error is the program's RUNTIME ERROR only when a generated statement raised it by its own operation
(NUL in arithmetic, an index beyond the field, SQRT of a negative number, division by zero); the value helpers
raise the manual's error themselves. The same Python error raised inside ncvm (the NC kernel, the planner, a
sink, a runtime helper) is an internal error: exit 70, "bug in ncvm", never a CPL0xx about the user's program.
"""

from __future__ import annotations

import math
import os
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

from ncvm.api import run
from ncvm.runtime.session import RunOptions

SUB_NUL = "1 Y = Q + 1\nN2 M30\n"


def error_of(run, text: str) -> dict:
    r = run(text)
    assert r["status"] == "error", r
    return r["error"]


# -- the manual's errors, where the program causes them ---------------------------------------------------
@pytest.mark.parametrize("line", ["20 Y = Z + 1", "20 A? = Z < 1", "20 Y = -Z", "20 Y = ABS(Z)", "20 Y% = INT(Z)",
                                  "20 Y = SIN(Z)", "20 Y = SQRT(Z)", "20 Y = TAN(Z)", "20 Y = Z * 2 - 1"])
def test_nul_in_an_expression_is_variable_not_assigned_manual_L758(run, line):
    """A variable never assigned is NUL (CPL manual §2.5, L758-769): used in an operation, RUNTIME ERROR
    VARIABLE NOT ASSIGNED, at its line and column."""
    e = error_of(run, f"10 X = 1\n{line}\nN30 M30\n")
    assert (e["code"], e["line"], e["column"]) == ("CPL020", 2, 4), e
    assert "VARIABLE NOT ASSIGNED" in e["message"]


def test_nul_in_a_sub_program_names_the_call_stack_manual_L758(tmp_path):
    (tmp_path / "SUB1.cpl").write_text(SUB_NUL)
    (tmp_path / "p.cpl").write_text("10 X = 1\n20 CALL SUB1\nN30 M30\n")
    r, _ = run(tmp_path / "p.cpl", options=RunOptions(state_dir=tmp_path / ".ncvm"))
    e = r["error"]
    assert (e["code"], Path(e["file"]).name, e["line"]) == ("CPL020", "SUB1.cpl", 1), e
    assert e["stack"] == [f"called from p.cpl at {tmp_path / 'p.cpl'}:2:4"], e


@pytest.mark.parametrize("line", ["30 Y = SQRT(Y)", "30 Y = ASIN(Y)", "30 Y = ACOS(Y)"])
def test_sqrt_of_a_negative_number_is_a_runtime_error_manual_L824(run, line):
    """SQRT: "the input value must not be a negative value" (CPL manual §2.5.1, L824-828)."""
    e = error_of(run, f"10 X = 1\n20 Y = -4\n{line}\nN40 M30\n")
    assert (e["code"], e["line"]) == ("CPL029", 3), e


@pytest.mark.parametrize("text", ["10 DIM X(3)\n20 X(4) = 5\n", "10 DIM X(3)\n20 I% = 4\n30 Y = X(I%)\n",
                                  "10 DIM X(3,2)\n20 I% = 1\n30 Y = X(I%,3)\n", "10 DIM X(3)\n20 I% = -1\n30 X(I%) = 1\n"])
def test_an_index_outside_the_field_is_an_error_manual_L700(run, text):
    """A field holds the elements its DIM gives (CPL manual §2.4.3, L684-707): an index beyond is an error."""
    e = error_of(run, text + "N90 M30\n")
    assert (e["code"], e["line"]) == ("CPL031", text.count("\n")), e


@pytest.mark.parametrize("use", ["50 Y = X(1)", "50 X(1) = 2", "50 X(1,1) = 2", "50 A$ = T$(1)"])
def test_a_field_before_its_dim_is_field_not_dimensioned_manual_L700(run, use):
    """"Prior to the initial access to the field variables, the index range ... must be dimensioned"
    (CPL manual §2.4.3, L700): a DIM in a branch that did not run leaves the field undimensioned (CPL035).
    This used to read VARIABLE NOT ASSIGNED (CPL020)."""
    dim = "DIM T$(2,5)" if "T$" in use else "DIM X(3,2)" if "1,1" in use else "DIM X(3)"
    e = error_of(run, f"10 B? = FALSE\n20 IF B? THEN\n30 {dim}\n40 ENDIF\n{use}\nN60 M30\n")
    assert (e["code"], e["line"]) == ("CPL035", 5), e
    assert "field not dimensioned" in e["message"]


@pytest.mark.parametrize("text", ["10 Z = 0.0\n20 X = 1 / Z\n", "10 Z! = 0.0\n20 X! = 1 / Z!\n"])
def test_division_by_zero_is_an_error(run, text):
    e = error_of(run, text + "N30 M30\n")
    assert (e["code"], e["line"]) == ("CPL028", 2), e


@pytest.mark.parametrize("text, code", [
    ("10 X% = 2147483647\n20 Y% = X% + 1\n", "CPL027"),  # INTEGER beyond 32 bits (manual L655)
    ("10 X! = 10000000000.0\n20 FOR I% = 1 TO 40\n30 X! = X! * X!\n40 NEXT I%\n", "CPL042"),  # beyond DOUBLE
    ("10 X = 10000000000.0\n20 Y = X * X * X * X\n", "CPL042"),  # beyond REAL
])
def test_a_value_beyond_its_range_is_an_error(run, text, code):
    e = error_of(run, text + "N90 M30\n")
    assert e["code"] == code and e["line"] in (2, 3), e


@pytest.mark.parametrize("text, detail", [
    ('10 R = SD(1, "ABC", 1)', "G group 'ABC'"),  # SD(1,g,...): the G group is a number (manual L2196-2218)
    ('10 FIL("ABC", 1, 1, 1)', "x = 'ABC'"),  # FIL(x,y,...): a coordinate is a number
])
def test_a_text_where_a_number_is_needed_is_invalid_parameter(run, text, detail):
    """These used to fail inside ncvm's helpers with a Python TypeError/ValueError (read as CPL020/CPL029)."""
    e = error_of(run, text + "\nN20 M30\n")
    assert (e["code"], e["line"]) == ("CPL023", 1) and detail in e["message"], e


@pytest.mark.parametrize("statement, code", [
    ("r = z + 1", "CPL020"), ("r = z < 1", "CPL020"), ("r = -z", "CPL020"), ("r = abs(z)", "CPL020"),
    ("r = int(z)", "CPL020"), ("r = math.sqrt(z)", "CPL020"), ("r = z[1]", "CPL035"), ("z[1] = 2", "CPL035"),
    ("r = z.row(1)", "CPL035"), ("r = f[4]", "CPL031"), ("f[4] = 1", "CPL031"), ("r = 1 / 0.0", "CPL028"),
    ("r = math.sqrt(-1.0)", "CPL029"),
    # generated code that is itself wrong: ncvm's bug, whatever the program did
    ("r = z()", None), ("r = 'A' + 1", None), ("r = (1,)[3]", None), ("r = {}['X']", None), ("r = f.row", None),
    ("r = len(1)", None),
])
def test_only_the_generated_statements_own_operation_is_the_programs_error(statement, code):
    """pyfaults.program_error on errors raised by code standing for a generated statement, and on the same
    errors raised by code of ncvm's (always None: an internal error). A tuple index, a call, a KeyError in
    generated code is a bug of the code generator, not the program's."""
    from ncvm.dialects.cpl.pyfaults import program_error

    def raised(filename: str) -> BaseException:
        try:
            exec(compile(statement, filename, "exec"), {"math": math, "z": None, "f": [0.0] * 4})
        except Exception as e:  # noqa: BLE001 - the error to sort out
            return e
        pytest.fail("no error")

    found = program_error(raised("<generated p.cpl>"), {"<generated p.cpl>": None})
    assert (found[0] if found else None) == code
    assert program_error(raised("ncvm/nc/kernel.py"), {"<generated p.cpl>": None}) is None


# -- ncvm's own faults ----------------------------------------------------------------------------------
#: the first WAIT drains 40 plain blocks (column-wise: planner.add_columns, move_batch), the second one block
#: (one by one: the kernel, the planner's rows, the recorder's feed; nc.block.columnar)
PROGRAM = ("10 X = 1.5\n15 FOR I% = 1 TO 40\nN20 G1 X[X] Y[I%] F1000\n25 NEXT I%\n30 Y = TAN(X)\n40 WAIT\n"
           "N45 G1 X0.5\n46 WAIT\nN50 G1 X20 M3 S1000\nN60 M30\n")

#: a bug of each kind, as ncvm's code would make it: the same operations that are the program's errors when a
#: generated statement makes them
BUGS = {
    "TypeError": lambda: None + 1,
    "ValueError": lambda: math.sqrt(-1.0),
    "KeyError": lambda: {}["X"],
    "IndexError": lambda: [][0],
    "AttributeError": lambda: None.row,
    "ZeroDivisionError": lambda: 1 / 0,
    "OverflowError": lambda: math.exp(1000.0),
}
#: (module, owner, attribute): the NC kernel, the planner, a sink of the canon calls, two runtime helpers
TARGETS = [
    ("ncvm.nc.kernel", "NcKernel", "execute"),
    ("ncvm.nc.kernel", "NcKernel", "end_program"),
    ("ncvm.nc.planner", "Planner", "add_columns"),
    ("ncvm.nc.planner", "Planner", "_plan_rest"),  # a flush of one move from rest (the one-block WAIT)
    ("ncvm.sinks.toolpath", "ToolpathRecorder", "move_batch"),
    ("ncvm.sinks.toolpath", "ToolpathRecorder", "feed"),
    ("ncvm.nc.planner", "Planner", "stop"),  # a short run's moves are planned at the exact stop (WAIT, M3)
    ("ncvm.dialects.cpl.values", None, "word"),
    ("ncvm.dialects.cpl.builtins", None, "_num"),
]


def _broken(kind: str):
    def broken(*args, **kwargs):
        BUGS[kind]()
    return broken


@pytest.mark.parametrize("kind", sorted(BUGS))
@pytest.mark.parametrize("target", TARGETS, ids=lambda t: f"{t[0].rsplit('.', 1)[1]}.{t[2]}")
def test_a_python_error_inside_ncvm_is_never_the_programs_error(tmp_path, monkeypatch, kind, target):
    import importlib

    module, owner, name = target
    obj = importlib.import_module(module)
    monkeypatch.setattr(getattr(obj, owner) if owner else obj, name, _broken(kind))
    (tmp_path / "p.cpl").write_text(PROGRAM)
    with pytest.raises(Exception) as raised:  # noqa: PT011 - each kind in turn
        result, _ = run(tmp_path / "p.cpl", options=RunOptions(state_dir=tmp_path / ".ncvm"))
        pytest.fail(f"reported as the program's error: {result.get('error')}")
    assert type(raised.value).__name__ == kind


def test_recursion_inside_ncvm_is_not_the_programs_nesting(tmp_path, monkeypatch):
    """CPL stops the program's own nesting at the CALL (CPL006/CPL007): Python's recursion limit reached
    inside ncvm is an internal error, not CPL007 or RUN003 about the program."""
    def endless(*args, **kwargs):
        return endless(*args, **kwargs)

    monkeypatch.setattr("ncvm.dialects.cpl.builtins._num", endless)
    (tmp_path / "p.cpl").write_text(PROGRAM)
    with pytest.raises(RuntimeError, match="recursion limit was reached inside ncvm"):
        result, _ = run(tmp_path / "p.cpl", options=RunOptions(state_dir=tmp_path / ".ncvm"))
        pytest.fail(f"reported as the program's error: {result.get('error')}")


SITECUSTOMIZE = textwrap.dedent('''
    import importlib, math, os
    module, owner, name, kind = os.environ["NCVM_TEST_BUG"].split(":")
    obj = importlib.import_module(module)
    obj = getattr(obj, owner) if owner else obj
    BUGS = {"TypeError": lambda: None + 1, "ValueError": lambda: math.sqrt(-1.0), "KeyError": lambda: {}["X"],
            "IndexError": lambda: [][0], "AttributeError": lambda: None.row}
    def broken(*args, **kwargs):
        BUGS[kind]()
    setattr(obj, name, broken)
''')


@pytest.mark.parametrize("target, kind", [
    ("ncvm.nc.kernel:NcKernel:execute:TypeError", "TypeError"),
    ("ncvm.nc.planner:Planner:stop:ValueError", "ValueError"),
    ("ncvm.sinks.toolpath:ToolpathRecorder:feed:KeyError", "KeyError"),
    ("ncvm.dialects.cpl.values::word:IndexError", "IndexError"),
    ("ncvm.dialects.cpl.builtins::_num:AttributeError", "AttributeError"),
])
def test_the_command_reports_an_internal_error_with_exit_70(tmp_path, target, kind):
    """A real ``ncvm run`` process with the bug put in by a sitecustomize on PYTHONPATH."""
    (tmp_path / "site").mkdir()
    (tmp_path / "site" / "sitecustomize.py").write_text(SITECUSTOMIZE)
    (tmp_path / "p.cpl").write_text(PROGRAM)
    env = {**os.environ, "PYTHONPATH": str(tmp_path / "site"), "NCVM_TEST_BUG": target}
    env.pop("NCVM_DEBUG", None)
    p = subprocess.run([sys.executable, "-m", "ncvm", "run", "p.cpl"], cwd=tmp_path, env=env,
                       capture_output=True, text=True, timeout=120)
    assert p.returncode == 70, p.stderr
    assert f"internal error: {kind}" in p.stderr and "bug in ncvm" in p.stderr
    assert "CPL0" not in p.stderr and "RUNTIME ERROR" not in p.stderr
