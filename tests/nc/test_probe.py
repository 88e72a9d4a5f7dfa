"""Probing (nc/probe.py): the switch point on a block's path, and the canon ``probe`` call that CPL's G75
and SINUMERIK's MEAS M make just before their cut move."""

from __future__ import annotations

import pytest

from ncvm.api import run
from ncvm.nc.canon import CanonSink
from ncvm.nc.probe import OffPath, trip_on_path
from ncvm.runtime.session import RunOptions


def test_the_axes_the_event_leaves_out_follow_the_straight_path():
    start, end = {"X": 0.0, "Y": 10.0}, {"X": 100.0, "Y": 30.0}
    assert trip_on_path({"X": 25.0}, start, end) == {"X": 25.0, "Y": 15.0}
    with pytest.raises(OffPath, match=r"the probe position X = 120 is not on the block's path \(0 to 100\)"):
        trip_on_path({"X": 120.0}, start, end)
    with pytest.raises(OffPath, match="gives no position for axis X"):
        trip_on_path({}, start, end)


class Calls(CanonSink):
    def __init__(self):
        self.calls = []

    def probe(self, trip, target, src):
        self.calls.append(("probe", trip, src.line))

    def feed(self, start, end, feed, src):
        self.calls.append(("feed", end, src.line))


def _run(tmp_path, name, program, machine):
    (tmp_path / "m.toml").write_text(machine)
    (tmp_path / name).write_text(program)
    sink = Calls()
    result, _ = run(tmp_path / name, machine=tmp_path / "m.toml",
                    options=RunOptions(state_dir=tmp_path / ".ncvm", extra_sinks=[sink]))
    assert result["status"] == "ok", result["error"]
    return sink.calls


AXES = '[[axis]]\nname = "X"\n[[axis]]\nname = "Y"\n[[axis]]\nname = "Z"\n'


def test_cpl_g75_announces_the_trip_before_its_cut_move(tmp_path):
    calls = _run(tmp_path, "p.cpl", "N1 G1 X5 F500\nN2 G75 X50 F500\nN3 G75 X60\nM30\n",
                 AXES + '[[scenario]]\ntime = 0\nkind = "probe"\nX = 40.0\n')
    assert calls == [("feed", (5.0, 0.0, 0.0), 1), ("probe", {"X": 40.0}, 2), ("feed", (40.0, 0.0, 0.0), 2),
                     ("probe", None, 3), ("feed", (60.0, 0.0, 0.0), 3)]


def test_sinumerik_meas_m_announces_the_trip_and_reads_either_event_form(tmp_path):
    machine = AXES + '[sin800]\ncontrol = "880"\n'
    program = "%MPF1\nG1 F1000 Y10\n@720 R93 K1 X100 Y10\nM30\n"
    table = _run(tmp_path, "p.mpf", program,
                 machine + '[[scenario]]\ntime = 0\nkind = "probe"\nposition = { X = 42.5 }\n')
    keys = _run(tmp_path, "p.mpf", program, machine + '[[scenario]]\ntime = 0\nkind = "probe"\nX = 42.5\n')
    assert table == keys == [("feed", (0.0, 10.0, 0.0), 2), ("probe", {"X": 42.5, "Y": 10.0}, 3),
                             ("feed", (42.5, 10.0, 0.0), 3)]
