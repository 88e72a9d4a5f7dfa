"""Inch programs and rotary axes (CPL manual L1329-1337, L1975: "with rotary axes ... the unit is always in
degrees"; LinuxCNC likewise): G20 scales the linear axis words by 25.4, never a rotary axis's, in every
path of the kernel that reads axis words (docs/decisions.md, issue 16)."""

from __future__ import annotations

import pytest

from ncvm.machine.config import machine_from_dict
from ncvm.nc.block import Block
from ncvm.nc.canon import Canon, CanonSink, Src
from ncvm.nc.kernel import NcKernel
from ncvm.nc.transform import Affine, AffineTransform

SRC = Src("t", 1)


class Ends(CanonSink):
    def __init__(self):
        self.ends = []

    def rapid(self, start, end, src):
        self.ends.append(tuple(round(v, 6) for v in end))

    def feed(self, start, end, feed, src):
        self.ends.append(tuple(round(v, 6) for v in end))


def _inch_kernel():
    m = machine_from_dict({"axis": [{"name": "X", "rapid": 6000.0},
                                    {"name": "A", "kind": "rotary", "rapid": 6000.0, "min": -720.0,
                                     "max": 720.0}]})
    sink = Ends()
    k = NcKernel(m, Canon([sink]))
    k.execute(Block((20,), (), {}, None, None, SRC))
    return k, sink


def _run(k, *blocks):
    for g, words in blocks:
        k.execute(Block(g, (), words, None, None, SRC))


@pytest.mark.parametrize("transformed", [False, True], ids=["generated path", "general path"])
def test_a_move_turns_a_by_the_degrees_programmed(transformed):
    k, sink = _inch_kernel()
    if transformed:
        k.set_transform(AffineTransform(Affine.identity(2)))
    _run(k, ((0, 90), {"X": 1.0, "A": 90.0}), ((1, 91), {"X": 1.0, "A": 90.0, "F": 10.0}))
    assert sink.ends == [(25.4, 90.0), (50.8, 180.0)]
    assert k.workpiece_position() == pytest.approx({"X": 2.0, "A": 180.0})


def test_g10_and_g92_take_a_in_degrees():
    k, sink = _inch_kernel()
    _run(k, ((10,), {"L": 2.0, "P": 1.0, "X": 1.0, "A": 45.0}), ((0, 90), {"X": 0.0, "A": 0.0}),
         ((92,), {"A": 10.0}), ((0,), {"A": 20.0}))
    assert sink.ends == [(25.4, 45.0), (25.4, 55.0)]
