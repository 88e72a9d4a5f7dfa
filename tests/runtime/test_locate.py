"""Locating a fault: the traceback of generated code back to program lines, columns and frames."""

from __future__ import annotations

import pytest

from ncvm.runtime.codegen import PySource
from ncvm.runtime.locate import fault_line, generated_frames


def two_units() -> tuple[PySource, PySource]:
    """A caller unit (program lines 10-11) calling a callee unit (program lines 20-22) that divides by zero."""
    caller = PySource("<caller>")
    with caller.block("def main(sub):", 10, 1):
        caller.emit("x = 1", 10, 3)
        caller.emit("return sub(x)", 11, 5)
    callee = PySource("<callee>")
    with callee.block("def sub(x):", 20):
        callee.emit("y = x - 1", 21)
        callee.emit("return x // y", 22)
    return caller, callee


def fault_traceback():
    caller, callee = two_units()
    ns: dict = {}
    exec(caller.compile(), ns)
    exec(callee.compile(), ns)
    with pytest.raises(ZeroDivisionError) as exc:
        ns["main"](ns["sub"])
    return caller, callee, exc.tb


def test_frames_of_generated_code_outermost_first_with_line_and_column():
    caller, callee, tb = fault_traceback()
    frames = generated_frames(tb, {"<caller>": caller, "<callee>": callee})
    assert [(f.filename, f.line, f.col) for f in frames] == [("<caller>", 11, 5), ("<callee>", 22, None)]
    assert [f.frame.f_code.co_name for f in frames] == ["main", "sub"]
    assert frames[1].frame.f_locals["y"] == 0  # the frame keeps the unit's variables at the fault


def test_frames_of_other_code_are_left_out():
    caller, callee, tb = fault_traceback()  # the test's own frame and pytest's are in the traceback too
    assert [f.filename for f in generated_frames(tb, {"<callee>": callee})] == ["<callee>"]
    assert generated_frames(tb, {}) == []
    assert generated_frames(None, {"<caller>": caller}) == []


def test_fault_line_is_the_innermost_frame_of_one_unit():
    caller, callee, tb = fault_traceback()
    assert fault_line(tb, callee) == 22
    assert fault_line(tb, caller) == 11
    assert fault_line(tb, PySource("<elsewhere>")) is None
