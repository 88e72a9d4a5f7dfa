"""The reported toolpath follows what the axes do over simulated time (issue 15, rw_SymPas 1).

Spooled segments run in the order they were spooled (SMLR ... SSMSW, manual L1957-1963, L2093-2108), and
moves that overlap in time (MLA without waiting, two tasks, L1616: only the W forms wait) are one combined
path: each canon call goes from the state of all axes at its start to their state at its end.
"""

from __future__ import annotations

import math

from ncvm.api import run
from ncvm.runtime.session import RunOptions


def _run(tmp_path, text: str):
    path = tmp_path / "prog.sap"
    path.write_text(text, encoding="latin-1")
    result, session = run(path, options=RunOptions(state_dir=tmp_path / ".ncvm", gcode=tmp_path / "out.ngc",
                                                  keep_toolpath=True))
    assert result["error"] is None, result["error"]
    arr = session.recorder.arrays()
    return result, arr, session.recorder, (tmp_path / "out.ngc").read_text()


def _g1_x(gcode: str) -> list[float]:
    xs = []
    for line in gcode.splitlines():
        for word in line.split():
            if word.startswith("X") and line.startswith(("G1", "G2", "G3", "G0")):
                xs.append(float(word[1:]))
    return xs


RECT = """program Rect;
begin
  TRVL := 50.0; TRAC := 500.0; TRTVL := 50.0;
  MLAW(A1 := 10.0);
  PHI := 90.0;
  SMLR(A1 := 80.0);
  SMCR(A1 := 0.0, A2 := 10.0);
  SMLR(A2 := 30.0);
  SMCR(A1 := -10.0, A2 := 0.0);
  SMLR(A1 := -80.0);
  SMCR(A1 := 0.0, A2 := -10.0);
  SMLR(A2 := -30.0);
  SMCR(A1 := 10.0, A2 := 0.0);
  SSMSW(A1, A2);
end.
"""


def test_rounded_rectangle_of_smlr_smcr_in_order_L1957_L2101(tmp_path):
    """A 100 x 50 rounded rectangle of SMLR/SMCR: the segments in the order spooled, the arcs turning left
    (PHI = 90) around the corners, bounds Y [0, 50]."""
    result, arr, rec, _ = _run(tmp_path, RECT)
    b = result["motion"]["bounds"]
    assert b["A1"] == [0.0, 100.0] and b["A2"] == [0.0, 50.0]
    ends = [tuple(round(v, 6) for v in e[:2]) for e in arr["end"].tolist()]
    assert ends == [(10, 0), (90, 0), (100, 10), (100, 40), (90, 50), (10, 50), (0, 40), (0, 10), (10, 0)]
    arcs = rec.arcs
    assert len(arcs) == 4 and all(not spec.cw for spec in arcs.values())
    assert [tuple(round(c, 6) for c in arcs[k].center) for k in sorted(arcs)] == [(90, 10), (90, 40), (10, 40),
                                                                                  (10, 10)]
    assert math.isclose(result["motion"]["feed_length"], 10 + 2 * 80 + 2 * 30 + 2 * math.pi * 10, rel_tol=1e-9)


def test_four_smlr_make_a_square_traversed_once_L1957(tmp_path):
    result, arr, _, _ = _run(tmp_path, """program Square;
begin
  TRVL := 50.0; TRAC := 500.0;
  SMLR(A1 := 100.0);
  SMLR(A2 := 100.0);
  SMLR(A1 := -100.0);
  SMLR(A2 := -100.0);
  SSMSW(A1, A2);
end.
""")
    ends = [tuple(round(v, 6) for v in e[:2]) for e in arr["end"].tolist()]
    starts = [tuple(round(v, 6) for v in e[:2]) for e in arr["start"].tolist()]
    assert ends == [(100, 0), (100, 100), (0, 100), (0, 0)]
    assert starts == [(0, 0), (100, 0), (100, 100), (0, 100)]
    assert math.isclose(result["motion"]["feed_length"], 400.0)


def _combined_checks(result, arr, gcode):
    """A1 runs 0 -> 200 and A2 0 -> 150 at the same time, each at 50 mm/s: together the axes run the
    diagonal while both move, then X alone; X never goes back."""
    xs = arr["end"][:, 0]
    assert (xs[1:] >= xs[:-1] - 1e-9).all()
    assert result["motion"]["bounds"]["A1"] == [0.0, 200.0] and result["motion"]["bounds"]["A2"] == [0.0, 150.0]
    # the tool's path: about 150 * sqrt(2) while both run, then 50 mm of X alone
    assert abs(result["motion"]["feed_length"] - (150 * math.sqrt(2) + 50)) < 1.0
    assert result["sympas"]["profile_length"] == 350.0
    gx = _g1_x(gcode)
    assert gx and all(b >= a - 1e-4 for a, b in zip(gx, gx[1:])) and gx[-1] == 200.0


def test_mla_then_mlaw_run_together_L1616(tmp_path):
    """MLA does not wait (only the W forms do, L1616): the A2 move of the MLAW runs while A1 still moves."""
    result, arr, _, gcode = _run(tmp_path, """program M;
begin
  TRVL := 50.0; TRAC := 500.0;
  MLA(A1 := 200.0);
  MLAW(A2 := 150.0);
end.
""")
    _combined_checks(result, arr, gcode)


def test_two_tasks_move_their_axes_at_the_same_time_L2113(tmp_path):
    result, arr, _, gcode = _run(tmp_path, """{$TASK 0}
program T0;
begin
  STARTCNCT(1);
  TRVL := 50.0; TRAC := 500.0;
  MLAW(A1 := 200.0);
  WT(15625);
end.

{$TASK 1}
program T1;
begin
  TRVL := 50.0; TRAC := 500.0;
  MLAW(A2 := 150.0);
end.
""")
    _combined_checks(result, arr, gcode)


MANY = """{$TASK 0}
program Many;
var k: integer;
begin
  STARTCNCT(1);
  TRVL := 100.0; TRAC := 1000.0;
  for k := 1 to 150 do
  begin
    MLA(A1 := 10.0, A2 := 5.0);
    WT(3000);
    MLA(A1 := 0.0, A2 := 0.0);
    WT(3000);
  end;
  STOPCNCT(1);
end.

{$TASK 1}
program Other;
begin
  TRVL := 50.0; TRAC := 1000.0;
  while TRUE do
  begin
    MLAW(A3 := -3.0);
    MLAW(A3 := 0.0);
  end;
end.
"""


def test_reporting_while_the_run_goes_on_gives_the_same_path(tmp_path, monkeypatch):
    """The timeline reports its held moves up to the horizon while the tasks run (more than HOLD moves):
    the toolpath is the same as when everything is reported at the end."""
    from ncvm.dialects.sympas import timeline

    (tmp_path / "a").mkdir()
    (tmp_path / "b").mkdir()
    monkeypatch.setattr(timeline, "HOLD", 64)
    r1, a1, _, _ = _run(tmp_path / "a", MANY)
    monkeypatch.setattr(timeline, "HOLD", 10 ** 9)
    r2, a2, _, _ = _run(tmp_path / "b", MANY)
    assert len(a1["end"]) > 64
    assert (a1["end"] == a2["end"]).all() and (a1["kind"] == a2["kind"]).all()
    assert r1["motion"] == r2["motion"]
