"""The whole-text DIN reader gives exactly the blocks of the line-by-line parser."""

from __future__ import annotations

import pytest

from ncvm.nc.block import DinSyntaxError, parse_din_line, read_din_program
from ncvm.nc.canon import Src

TEXT = """%
(header comment)
G21 G90 G17
n10 g1 x-2.4667 y3.9174 F1500
N20 G3 X-6.8 Y-3.2 I-1.1826 J-4.1928
N30
   X 1.5  Y.5 Z+2.
/N40 G0 Z5
G1X10Y20M3S1000
N50 N60 X1
G54.1 X1 ; tail comment
X1 X2
X1.2.3
(MSG, hello) M0

M30
"""


def _line_by_line(path, text):
    blocks, errors = [], []
    for lineno, line in enumerate(text.splitlines(), 1):
        skip = line.lstrip().startswith("/")
        if skip:
            line = line.replace("/", " ", 1)
        try:
            blk = parse_din_line(line, Src(path, lineno))
        except DinSyntaxError as e:
            errors.append((lineno, e.column, e.message))
            continue
        if blk is not None:
            blocks.append((blk.g, blk.m, blk.words, blk.n, blk.msg, blk.src, skip))
    return blocks, errors


@pytest.mark.parametrize("text", [TEXT, TEXT.replace("\n", "\r\n"), TEXT.replace("\n", "\r"), TEXT + "X9"])
def test_same_blocks_as_line_parser(text):
    blocks, diags = read_din_program("p.ngc", text)
    got = [(b.g, b.m, b.words, b.n, b.msg, b.src, skip) for b, skip in blocks]
    want, errors = _line_by_line("p.ngc", text)
    assert got == want
    assert [(d.span.line, d.span.column, d.message) for d in diags] == errors
    assert [e[0] for e in errors] == [12, 13]


def test_plain_line_values():
    blocks, _ = read_din_program("p.ngc", "N20 G3 X-6.8 Y.5 I-1 J2\nG1X10Y20M3S1000\n")
    first, second = blocks[0][0], blocks[1][0]
    assert (first.g, first.n, first.words) == ((3,), 20, {"X": -6.8, "Y": 0.5, "I": -1.0, "J": 2.0})
    assert (second.g, second.m, second.words) == ((1,), (3,), {"X": 10.0, "Y": 20.0, "S": 1000.0})
    assert first.src == Src("p.ngc", 1) and second.src == Src("p.ngc", 2)


NUMBERS = """N10 G1 X1. Y.5 Z-.5 F+100.
X+1.25Y-0.0
G01X1Y2
G0 X1.2.3
G2 X1 Y1 I.5 J-.5
G3X-1.5J0.
N20 G17
N30 G1 X 5
G1 X-
G1 X5 Y6 Z7 I8 J9 K10 F11
"""


def test_number_forms_as_the_line_parser_reads_them():
    blocks, diags = read_din_program("p.ngc", NUMBERS)
    want, errors = _line_by_line("p.ngc", NUMBERS)
    assert [(b.g, b.m, b.words, b.n, b.msg, b.src, skip) for b, skip in blocks] == want
    assert [(d.span.line, d.span.column, d.message) for d in diags] == errors
    assert blocks[0][0].words == {"X": 1.0, "Y": 0.5, "Z": -0.5, "F": 100.0}
