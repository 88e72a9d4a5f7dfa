"""The kernel's dialect extension points (extra G handlers, a coordinate transformation) and the affine
maps of nc/transform.py; values computed by hand."""

from __future__ import annotations

import pytest

from ncvm.machine.config import machine_from_dict
from ncvm.nc.block import Block, PlainRun, read_din_segments
from ncvm.nc.canon import Canon, CanonSink, Src
from ncvm.nc.kernel import NcKernel
from ncvm.nc.plainrun import execute_columns
from ncvm.nc.transform import Affine, SingularTransform

SRC = Src("t", 1)


class Ends(CanonSink):
    def __init__(self):
        self.ends = []

    def rapid(self, start, end, src):
        self.ends.append(("rapid", tuple(end)))

    def feed(self, start, end, feed, src):
        self.ends.append(("feed", tuple(end)))


def kernel(offsets=None):
    m = machine_from_dict({"axis": [{"name": n} for n in "XYZ"], **({"offsets": offsets} if offsets else {})})
    sink = Ends()
    return NcKernel(m, Canon([sink])), sink


class Doubling:
    """A transform that doubles every coordinate (an Affine used as the kernel's transform object)."""

    def __init__(self, n):
        self.a = Affine.scaling([0.0] * n, [2.0] * n)
        self.inv = self.a.inverse()

    def forward(self, vec):
        return self.a.apply(vec)

    def inverse(self, vec):
        return self.inv.apply(vec)

    def plane_similarity(self, a, b):
        return self.a.plane_similarity(a, b)


def test_a_registered_g_handler_runs_and_can_take_the_axis_words():
    k, sink = kernel()
    seen = []

    def g123(kern, g, words, src):
        seen.append((g, dict(words)))
        return True  # the axis words were parameters

    k.g_handlers[123] = g123
    k.execute(Block((1, 123), (), {"X": 5.0, "F": 100.0}, None, None, SRC))
    assert seen == [(123, {"X": 5.0, "F": 100.0})]
    assert sink.ends == [] and k.motion == 1 and k.feed == 100.0
    with pytest.raises(Exception) as e:  # other kernels do not know it
        kernel()[0].execute(Block((123,), (), {}, None, None, SRC))
    assert getattr(e.value, "code", None) == "NC004"


def test_a_handler_overrides_a_built_in_g_code():
    k, sink = kernel()
    k.g_handlers[60] = lambda kern, g, words, src: False  # words stay a target
    k.execute(Block((0, 60), (), {"X": 3.0}, None, None, SRC))
    assert sink.ends == [("rapid", (3.0, 0.0, 0.0))]


def test_transform_applies_before_offsets_on_the_fast_and_general_paths():
    k, sink = kernel(offsets={"G54": [100.0, 0.0, 0.0]})
    k.execute(Block((54,), (), {}, None, None, SRC))
    k.set_transform(Doubling(3))
    k.execute(Block((1,), (), {"X": 5.0, "Y": 1.0, "F": 100.0}, None, None, SRC))  # straight: was the fast path
    k.execute(Block((3,), (), {"X": 3.0, "Y": 4.0, "R": 2.5}, None, None, SRC))  # arc: general path
    assert sink.ends[0] == ("feed", (110.0, 2.0, 0.0))
    assert k.machine_pos == pytest.approx((106.0, 8.0, 0.0))
    k.set_transform(None)
    assert k.prog == pytest.approx([6.0, 8.0, 0.0])  # the tool stays put, the programmed position moves
    k.execute(Block((1,), (), {"X": 0.0}, None, None, SRC))
    assert sink.ends[-1] == ("feed", (100.0, 8.0, 0.0))


def test_g53_passes_the_transform_by():
    k, sink = kernel()
    k.set_transform(Doubling(3))
    k.execute(Block((0, 53), (), {"X": 7.0}, None, None, SRC))
    assert sink.ends == [("rapid", (7.0, 0.0, 0.0))] and k.prog == pytest.approx([3.5, 0.0, 0.0])


def test_affine_compose_and_invert():
    n = 3
    t = Affine.shift([1.0, 2.0, 3.0]).then(Affine.scaling([1.0, 1.0, 0.0], [2.0, 3.0, 1.0])) \
        .then(Affine.rotation(n, 0, 1, 90.0, (1.0, 1.0)))
    # (0,0,0) -> (1,2,3) -> (1 + 2*0, 1 + 3*1, 3) = (1, 4, 3) -> about (1,1) by 90 deg: (1 - 3, 1 + 0) = (-2, 1)
    assert t.apply([0.0, 0.0, 0.0]) == pytest.approx([-2.0, 1.0, 3.0])
    assert t.inverse().apply([-2.0, 1.0, 3.0]) == pytest.approx([0.0, 0.0, 0.0])
    with pytest.raises(SingularTransform):
        Affine.scaling([0.0] * n, [1.0, 0.0, 1.0]).inverse()


def test_plane_similarity():
    rot = Affine.rotation(3, 0, 1, 30.0).then(Affine.scaling([0.0] * 3, [2.0, 2.0, 5.0]))
    assert rot.plane_similarity(0, 1) == pytest.approx((2.0, False))
    assert Affine.scaling([0.0] * 3, [-1.0, 1.0, 1.0]).plane_similarity(0, 1) == (1.0, True)
    assert Affine.scaling([0.0] * 3, [2.0, 3.0, 1.0]).plane_similarity(0, 1) is None


def test_plain_runs_go_block_by_block_while_a_transform_is_set():
    segments, _ = read_din_segments("t", "G1 X1 F100\nX2\nX3\n")
    run = next(s for s in segments if isinstance(s, PlainRun))
    k, sink = kernel()
    k.set_transform(Doubling(3))
    lo = 0
    while (bad := execute_columns(k, run, lo, len(run))) is not None:
        k.execute(run.block(bad))
        lo = bad + 1
    assert [e[1][0] for e in sink.ends] == [2.0, 4.0, 6.0]
