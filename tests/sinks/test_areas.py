"""The protection-zone check on recorded moves (work areas and dead ranges, CPL SD 200)."""

from __future__ import annotations

from ncvm.nc.canon import ArcSpec, Src
from ncvm.sinks.areas import DEAD, WORK, zone_check
from ncvm.sinks.toolpath import ToolpathRecorder


def recorded(*moves):
    """A recorder with X Y Z moves: ("line", end) or ("arc", end, spec), block n on line n."""
    rec = ToolpathRecorder()
    rec.begin(("X", "Y", "Z"), (0.0, 0.0, 0.0))
    here = (0.0, 0.0, 0.0)
    for n, (kind, end, *spec) in enumerate(moves, 1):
        if kind == "line":
            rec.feed(here, end, 1000.0, Src("p", n))
        else:
            rec.arc(here, end, spec[0], 1000.0, Src("p", n))
        here = end
    return rec


def lines(check):
    return [(v.zone.number, v.line) for v in check.first()]


def test_a_full_circle_around_the_dead_range_touches_it_only_when_its_radius_reaches_in():
    # dead range X 8..12, Y -2..2 (centre (10,0), size 4 x 4); circles about (0,0) start and end at (r,0)
    zones = [(1, DEAD, ("X", "Y"), (10.0, 0.0), (4.0, 4.0))]
    for r, hit in ((7.9, False), (8.0, False), (9.0, True), (30.0, False)):
        rec = recorded(("line", (0.0, -r, 0.0)), ("arc", (0.0, -r, 0.0), ArcSpec(0, 1, (0.0, 0.0), True, r)))
        assert lines(zone_check(zones, ("X", "Y", "Z"), rec)) == ([(1, 2)] if hit else []), r


def test_an_arc_in_another_plane_is_followed_along_its_curve():
    # X-Z half circle about (10,0,0), radius 10, from (0,0,0) up over Z10 to (20,0,0); dead range in X-Z:
    # X 9..11, Z 9.5..12 is cut by the top of the arc (Z = 10 at X 10) but not by its chord (Z = 0)
    zones = [(1, DEAD, ("X", "Z"), (10.0, 10.75), (2.0, 2.5))]
    spec = ArcSpec(2, 0, (0.0, 10.0), False, 10.0)  # plane Z-X: a = Z, b = X, centre (Z 0, X 10), through Z 10
    rec = recorded(("arc", (20.0, 0.0, 0.0), spec))
    assert lines(zone_check(zones, ("X", "Y", "Z"), rec)) == [(1, 1)]


def test_work_area_reports_the_first_move_that_leaves_it_per_area():
    zones = [(1, WORK, ("X", "Y"), (0.0, 0.0), (100.0, 100.0)), (2, WORK, ("Y", "Z"), (0.0, 0.0), (10.0, 10.0))]
    rec = recorded(("line", (50.0, 5.0, 0.0)), ("line", (50.0, 6.0, 0.0)), ("line", (51.0, 6.0, 0.0)))
    assert lines(zone_check(zones, ("X", "Y", "Z"), rec)) == [(2, 2), (1, 3)]


def test_an_arc_seen_slanted_is_tested_on_its_sampled_curve():
    # a helix in X-Y rising in Z, against an X-Z dead range: the quarter circle about (0,0) from (10,0,0) to
    # (0,10,10) passes X 7.07 at Z 5; dead range X 6..8, Z 4..6 is hit, X 9.5..9.9 at Z 4..6 is not (X 7.07)
    spec = ArcSpec(0, 1, (0.0, 0.0), False, 10.0)
    rec = recorded(("line", (10.0, 0.0, 0.0)), ("arc", (0.0, 10.0, 10.0), spec))
    hit = [(1, DEAD, ("X", "Z"), (7.0, 5.0), (2.0, 2.0)), (2, DEAD, ("X", "Z"), (9.7, 5.0), (0.4, 2.0))]
    assert lines(zone_check(hit, ("X", "Y", "Z"), rec)) == [(1, 2)]
