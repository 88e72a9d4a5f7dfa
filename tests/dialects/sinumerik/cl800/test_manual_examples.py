"""Every CL 800 example of manual chapter 5 that compiles (corrections noted in each file's first lines)
gives the reviewed @ code in ``manual/<case>.spf``; and properties every object program must have."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from ncvm.api import compile_program
from ncvm.dialects.sinumerik.cl800.codegen import MARK, marked

HERE = Path(__file__).parent
MANUAL = HERE / "manual"
ALL_SOURCES = sorted(MANUAL.glob("*.cl8")) + sorted((HERE / "golden").glob("*.cl8")) + sorted(
    (HERE.parents[3] / "examples" / "cl800").glob("*.cl8"))


@pytest.mark.parametrize("source", sorted(MANUAL.glob("*.cl8")), ids=lambda p: p.stem)
def test_manual_example(source: Path, tmp_path: Path):
    out = compile_program(source, out=tmp_path / "obj.spf")
    assert out.read_text() == marked(source.with_suffix(".spf").read_text())


@pytest.mark.parametrize("source", ALL_SOURCES, ids=lambda p: f"{p.parent.name}/{p.stem}")
def test_object_program_properties(source: Path, tmp_path: Path):
    """Blocks <= 120 characters; jumps find their block in their search direction; push list == pop list."""
    *blocks, mark = compile_program(source, out=tmp_path / "obj.spf").read_text().splitlines()
    assert mark.endswith(f") {MARK}") and mark.startswith("(CRC32 ")
    assert re.fullmatch(r"%SPF\d+", blocks[0])
    body = blocks[1:]
    assert all(0 < len(b) <= 120 for b in body)
    assert body[-1].endswith("M17") and not any("M17" in b for b in body[:-1] if "(" not in b)
    numbers = {int(m.group(1)): i for i, b in enumerate(body) if (m := re.match(r"N(\d{4})\b", b))}
    for i, b in enumerate(body):
        for target in _jump_targets(b):
            n = abs(int(target))
            assert n in numbers, f"{source.name}: jump to missing N{n}"
            assert (numbers[n] <= i) if target.startswith("-") else (numbers[n] > i), f"{b}: wrong direction"
    push, pop = _operands(body[0], ("@040", "@041")), _operands(body[-1], ("@042", "@043"))
    assert (push is None) == (pop is None)
    if push:
        assert int(pop[0][-1]) - int(push[0][-1]) == 2 and push[1] == pop[1]


def _jump_targets(block: str) -> list[str]:
    """The block-number operands of the @1xx jumps of a block (last operand; every 2nd after @111's Var)."""
    out = []
    for instr in block.split("@")[1:]:
        words = instr.split()
        code, ops = words[0], [w for w in words[1:] if re.fullmatch(r"[KRP]-?[\d.]+", w)]
        if code == "111":
            out += [op[1:] for op in ops[2::2]]
        elif code.startswith("1"):
            out.append(ops[-1][1:])
    return out


def _operands(block: str, codes: tuple[str, ...]):
    words = block.split()
    for i, w in enumerate(words):
        if w in codes:
            ops = []
            for op in words[i + 1:]:
                if not re.fullmatch(r"[KR]\d+", op):
                    break
                ops.append(op)
            return w, ops
    return None
