"""The kernel's public API for front ends: fork (a shadow that runs ahead), place (position without a move)
and linear (the straight-move path, generated or transformed)."""

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
        self.ends.append(tuple(end))

    def feed(self, start, end, feed, src):
        self.ends.append(tuple(end))


def kernel():
    m = machine_from_dict({"axis": [{"name": n, "rapid": 6000.0} for n in "XYZ"],
                           "offsets": {"G54": [100.0, 0.0, 0.0]}})
    sink = Ends()
    return NcKernel(m, Canon([sink])), sink


def test_a_fork_runs_blocks_without_changing_the_kernel_or_its_canon():
    k, sink = kernel()
    k.execute(Block((0,), (), {"X": 5.0}, None, None, SRC))
    k.machine.plc.inputs["E1"] = 1
    before = (k.machine_pos, list(k.prog), list(k.g92), k.machine.clock.now)
    shadow = k.fork()
    shadow.execute(Block((0, 91), (), {"X": 10.0}, None, None, SRC))
    shadow.execute(Block((92,), (), {"Y": 7.0}, None, None, SRC))
    shadow.machine.plc.inputs["E1"] = 0
    assert shadow.machine_pos == (115.0, 0.0, 0.0) and shadow.prog == [15.0, 7.0, 0.0]
    assert shadow.machine.clock.now > before[3]
    assert (k.machine_pos, k.prog, k.g92, k.machine.clock.now) == before
    assert k.absolute and k.machine.plc.inputs["E1"] == 1
    assert sink.ends == [(105.0, 0.0, 0.0)]  # only the kernel's own move reached its sinks


def test_place_sets_the_position_without_a_move():
    k, sink = kernel()
    t = k.machine.clock.now
    k.place((110.0, 2.0, 3.0))
    assert k.machine_pos == (110.0, 2.0, 3.0) and k.prog == [10.0, 2.0, 3.0]  # through the G54 offset
    k.place([1.0, 2.0, 3.0], prog=[0.5, 0.5, 0.5])  # a caller with its own zero point
    assert k.machine_pos == (1.0, 2.0, 3.0) and k.prog == [0.5, 0.5, 0.5]
    assert sink.ends == [] and k.machine.clock.now == t


def test_linear_is_the_generated_path_until_a_transform_is_set_and_again_after():
    k, sink = kernel()
    k.execute(Block((0,), (), {"X": 0.0}, None, None, SRC))
    generated = k.linear
    k.set_transform(AffineTransform(Affine.rotation(3, 0, 1, 90.0)))
    assert k.linear is not generated
    k.linear(k, 0, {"X": 1.0}, SRC)
    assert sink.ends[-1] == pytest.approx((100.0, 1.0, 0.0))
    k.set_transform(None)
    assert k.linear is generated
    k.linear(k, 0, {"X": 2.0}, SRC)
    assert sink.ends[-1] == pytest.approx((102.0, 1.0, 0.0))
