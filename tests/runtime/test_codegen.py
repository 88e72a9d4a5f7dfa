"""Generated Python code: line maps back to the program, caching by content, the step limit."""

from __future__ import annotations

import pytest

from ncvm.diagnostics import RuntimeFault
from ncvm.runtime.codegen import PySource, compile_cached
from ncvm.runtime.locate import generated_frames
from ncvm.runtime.steps import StepCounter


def build_loop(filename: str) -> PySource:
    src = PySource(filename)
    with src.block("def main(steps, out):", 1):
        src.emit("n = 0", 2)
        src.emit("i = 0", 2)
        with src.block("while i < 10:", 3):
            src.emit("if steps.steps + 2 > steps.limit: steps.runaway(FILE, 3)", 3)  # a group tested at its head
            src.emit("steps.steps += 2", 3)
            src.emit("n += 1", 3)
            src.emit("i += 1", 4)
        src.emit("out.append(n)", 5)
        src.emit("out.append(10 // (i - 10))", 6)
    return src


def test_generated_code_runs_and_faults_map_to_program_lines():
    src = build_loop("<prog.x>")
    ns = {"FILE": "prog.x"}
    exec(src.compile(), ns)
    out = []
    counter = StepCounter()
    with pytest.raises(ZeroDivisionError) as exc:
        ns["main"](counter, out)
    assert out == [10]
    assert counter.steps == 20
    assert [f.line for f in generated_frames(exc.tb, {"<prog.x>": src})] == [6]


def test_compile_cache_returns_the_same_code_object_for_the_same_text():
    a = build_loop("<cache.x>").compile()
    b = build_loop("<cache.x>").compile()
    assert a is b
    assert compile_cached("x = 1\n", "<other>") is not a


def test_empty_block_gets_pass():
    src = PySource("<e>")
    with src.block("if True:"):
        pass
    exec(src.compile(), {})
    assert src.lines == ["if True:", "    pass"]


def test_step_limit_faults_with_position():
    src = build_loop("<limit.x>")
    ns = {"FILE": "prog.x"}
    exec(src.compile(), ns)
    with pytest.raises(RuntimeFault) as e:
        ns["main"](StepCounter(limit=7), [])
    assert e.value.code == "RUN001"
    assert (e.value.span.file, e.value.span.line) == ("prog.x", 3)
