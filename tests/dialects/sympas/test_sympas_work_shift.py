"""The card's work shift (machine position less user position, per axis: the REF point of homing, SZPA/SZPR and
the AZO table, manual Table 37 ``zerooffset``, L1422-1497) is kept between moves and worked out anew when a
statement moves the zero point: the trace's ``work`` coordinates, the plot's points and the program bounds follow every change,
while a run of moves under one zero point does not work it out per move (issue 18: ``--plot`` must not
double the run's CPU)."""

from __future__ import annotations

import json

import numpy as np
import pytest

from ncvm.api import run
from ncvm.dialects.sympas import card as card_module
from ncvm.runtime.session import RunOptions

#: each statement between the moves moves the zero point of A1 or A2: every move ends at its programmed
#: (user) position, whatever the machine position is
ZERO_CHANGES = """\
program Zero;
begin
  TRVL := 100.0; TRAC := 1000.0;
  MLAW(A1 := 10.0, A2 := 10.0);
  SZPA(A1 := 100.0);
  MLAW(A1 := 20.0, A2 := 20.0);
  SZPR(A2 := 50.0);
  MLAW(A1 := 30.0, A2 := 30.0);
  AZO(1);
  MLAW(A1 := 40.0, A2 := 40.0);
  SHP(A1 := 1000.0);
  MLAW(A1 := 1050.0, A2 := 50.0);
  JHLW(A1);
  MLAW(A1 := 60.0, A2 := 60.0);
end.
"""

MACHINE = """\
[[axis]]
name = "X"
min = -2000.0
max = 2000.0
[[axis]]
name = "Y"
min = -2000.0
max = 2000.0
[[axis]]
name = "Z"
min = -2000.0
max = 2000.0
[sympas]
zero_offsets = {1 = [5.0, 7.0, 0.0]}
ref_positions = {A1 = -5.0}
"""

#: (line, machine X, machine Y) of each MLAW: SZPA A1 100, SZPR A2 50, AZO(1) adds (5, 7), SHP makes machine
#: 145 the user 1000, homing puts the REF switch (machine -5) at user 0 and clears the zero offset
EXPECTED = [(4, 10.0, 10.0, 10.0, 10.0), (6, 120.0, 20.0, 20.0, 20.0), (8, 130.0, 80.0, 30.0, 30.0),
            (10, 145.0, 97.0, 40.0, 40.0), (12, 195.0, 107.0, 1050.0, 50.0), (14, 60.0, 117.0, 60.0, 60.0)]


def _run(tmp_path, text: str, **options):
    program = tmp_path / "zero.sap"
    program.write_text(text)
    (tmp_path / "machine.toml").write_text(MACHINE)
    result, session = run(program, dialect="sympas", machine=tmp_path / "machine.toml",
                          options=RunOptions(state_dir=tmp_path / "st", **options))
    assert result["status"] == "ok", result["error"]
    return result, session


def test_work_coordinates_follow_every_change_of_the_zero_point(tmp_path):
    """SZPA, SZPR, AZO, SHP and homing between moves, with the plot asked for too: each feed move's ``work``
    end in the trace (the canon ``frame`` calls the plot also takes) is its programmed position, its ``end``
    the machine's."""
    trace = tmp_path / "t.jsonl"
    _run(tmp_path, ZERO_CHANGES, trace=trace, plot=True)
    feeds = [r for r in map(json.loads, trace.read_text().splitlines()) if r["call"] == "feed"]
    got = [(r["line"], r["end"]["X"], r["end"]["Y"], r["work"]["X"], r["work"]["Y"]) for r in feeds]
    assert got == EXPECTED


def test_a_run_under_one_zero_point_works_the_shift_out_once(tmp_path, monkeypatch):
    """2,000 moves with the plot's frames asked for and no statement that moves the zero point: the shift is
    worked out once for the run (per axis), not once per move."""
    calls = []
    user_shift = card_module.Card.user_shift

    def counted(self, a):
        calls.append(a.number)
        return user_shift(self, a)

    monkeypatch.setattr(card_module.Card, "user_shift", counted)
    moves = "".join(f"  MLAW(A1 := {i % 100}.0, A2 := {i // 100}.5);\n" for i in range(1, 2001))
    result, session = _run(tmp_path, "program Many;\nbegin\n  TRVL := 100.0; TRAC := 10000.0;\n" + moves + "end.\n",
                           plot=True)
    assert result["motion"]["feed_moves"] == 2000 and session.plot.moves == 2000
    assert len(calls) <= 4 * 3, len(calls)  # once for the moves, and the run's end (three axes each)


def test_the_plot_draws_each_move_in_the_zero_point_it_ran_with(tmp_path, monkeypatch):
    """The plot of a rw_SymPas run draws each move at its program coordinates, less the zero point in force for
    it, as the trace's ``work`` (review18e; docs/decisions.md), also where the recorder showed the plot windows
    of moves while the program ran (a run longer than toolpath.WINDOW): here windows of two moves. Before, every
    point was its machine position less the zero point at the end of the run."""
    from ncvm.sinks import toolpath

    def drawn(folder, window):
        monkeypatch.setattr(toolpath, "WINDOW", window)
        folder.mkdir()
        _, session = _run(folder, ZERO_CHANGES, plot=True)
        return session.plot.drawn()[(False, 0)]

    short, long = drawn(tmp_path / "short", 1 << 16), drawn(tmp_path / "long", 2)
    np.testing.assert_array_equal(short, long)
    ends = [(x, y) for _, _, _, x, y in EXPECTED]
    points = [tuple(p) for p in long[:, :2].tolist()]
    assert all(end in points for end in ends), (ends, points)


def test_program_bounds_are_the_trace_work_coordinates_of_the_moves(tmp_path, monkeypatch):
    """``motion.bounds_program`` (and the ``sympas`` part's, and the summary line's) are the lowest and highest
    ``work`` coordinates the trace gives the moves: each move less the zero point it ran with (review18e), also
    in windows of two moves. Before, every move was taken less the zero point at the end of the run."""
    from ncvm.sinks import toolpath

    for window in (1 << 16, 2):
        monkeypatch.setattr(toolpath, "WINDOW", window)
        folder = tmp_path / str(window)
        folder.mkdir()
        trace = folder / "t.jsonl"
        result, _ = _run(folder, ZERO_CHANGES, trace=trace)
        moves = [r for r in map(json.loads, trace.read_text().splitlines()) if "work" in r]
        for axis, program_axis in (("X", "A1"), ("Y", "A2")):
            work = [m["work"][axis] for m in moves]
            expected = pytest.approx([min(work), max(work)], abs=1e-6)  # the trace's figures: 6 decimals
            assert result["motion"]["bounds_program"][program_axis] == expected, window
            assert result["sympas"]["axes"][program_axis]["bounds_program"] == expected
        # the machine's bounds less the zero point at the end (A2: 57) were [-57, 60]
        assert result["motion"]["bounds_program"]["A2"] == [10.0, 60.0]
