"""Cutter radius compensation G41/G42/G40 in the kernel (nc/cutter.py): geometry, held moves, refusals.

The expected tool paths are what LinuxCNC's rs274 prints for the same programs and tool table
(tests/nc/test_cutter_rs274.py compares generated contours with it where it is installed).
"""

from __future__ import annotations

import json

import pytest

from ncvm.machine.config import machine_from_dict

#: tool 1: radius 5.08 mm (rs274's tool table: D0.4 inch); tool 2: radius 30 mm
MACHINE = {"axis": [{"name": a} for a in "XYZ"],
           "tool": [{"number": 1, "radius": 5.08}, {"number": 2, "radius": 30.0}]}

CONTOUR = """G21 G17 G90 G40
T1 M6
G0 X-20 Y-20
G41 D1 G1 X0 Y0 F500
G1 X50 Y0
G3 X60 Y10 I0 J10
G1 X60 Y40
G2 X50 Y30 I0 J-10
G1 X0 Y30
G1 X0 Y0
G40 G1 X-20 Y-20
M2
"""
#: rs274 -t (T1 P1 D0.4) -g: (call, X, Y, arc centre or None)
RS274_PATH = [("rapid", -20.0, -20.0, None), ("feed", -3.5921, 3.5921, None), ("arc", 0.0, 5.08, (0.0, 0.0)),
              ("feed", 50.0, 5.08, None), ("arc", 54.92, 10.0, (50.0, 10.0)), ("feed", 54.92, 40.0, None),
              ("arc", 60.0, 45.08, (60.0, 40.0)), ("arc", 45.8014, 24.92, (60.0, 30.0)),
              ("feed", 5.08, 24.92, None), ("feed", 5.08, 0.0, None), ("feed", -20.0, -20.0, None)]


def _run(run_text, tmp_path, text, name="prog.din", **kw):
    trace = tmp_path / "trace.jsonl"
    r = run_text(text, name=name, machine=machine_from_dict(MACHINE), trace=trace, **kw)
    calls = [json.loads(line) for line in trace.read_text().splitlines()] if trace.exists() else []
    return r, calls


def _moves(calls):
    return [(c["call"], round(c["end"]["X"], 4), round(c["end"]["Y"], 4),
             tuple(round(v, 4) for v in c["center"]) if c["call"] == "arc" else None)
            for c in calls if c["call"] in ("rapid", "feed", "arc")]


def test_outside_corners_are_rounded_and_inside_corners_meet_as_rs274(run_text, tmp_path):
    r, calls = _run(run_text, tmp_path, CONTOUR)
    assert r["status"] == "ok", r["error"]
    assert _moves(calls) == RS274_PATH


def test_g42_puts_the_tool_on_the_other_side(run_text, tmp_path):
    r, calls = _run(run_text, tmp_path, "G0 X-20 Y-20\nG42 D1 G1 X0 Y0 F500\nG1 X50\nG40 G1 X70 Y-20\n")
    assert r["status"] == "ok", r["error"]
    # rs274: the bottom edge is cut from below (y = -5.08); the corner at X0 Y0 is an inside one
    assert _moves(calls)[1:] == [("feed", 2.1042, -5.08, None), ("feed", 50.0, -5.08, None),
                                 ("feed", 70.0, -20.0, None)]


def test_held_move_leaves_before_what_the_next_blocks_send(run_text, tmp_path):
    """A dwell, a coolant M function and a message between two contour moves leave after the held move,
    in program order; the end of the file lets the last held move go before the program ends."""
    text = ("G0 X-20 Y-20\nG41 D1 G1 X0 Y0 F500\nG1 X50\nM8\nG4 P1\n(MSG, half way)\nG1 Y30\nG1 X0\n")
    r, calls = _run(run_text, tmp_path, text)
    assert r["status"] == "ok", r["error"]
    order = [(c["call"], c.get("line")) for c in calls if c["call"] not in ("begin", "end")]
    names = [name for name, _ in order]
    # rs274 sends the same moves and the coolant and dwell in this order (its message comes before the held move)
    assert names == ["rapid", "feed", "arc", "feed", "coolant", "dwell", "message", "feed", "feed", "program_end"]
    assert [m[1:3] for m in _moves(calls)[3:]] == [(44.92, 5.08), (44.92, 24.92), (0.0, 24.92)]


def test_program_stop_releases_the_held_move_first(run_text, tmp_path):
    r, calls = _run(run_text, tmp_path, "G0 X-20 Y-20\nG41 D1 G1 X0 Y0 F500\nG1 X50\nM0\nG1 Y30\nG40 G1 X80\nM2\n")
    assert r["status"] != "error" or r["error"] is None
    names = [c["call"] for c in calls if c["call"] not in ("begin", "end")]
    assert names.index("stop") == names.index("feed", 2) + 1  # the X50 move, then the stop


@pytest.mark.parametrize(("text", "line", "words"), [
    # LinuxCNC: "Length of cutter compensation entry move is not greater than the tool radius"
    ("G0 X0 Y0\nG41 D1 G1 X3 Y0 F500\n", 2, "entry move"),
    # LinuxCNC: "Tool radius not less than arc radius with comp" (tool inside a 20 mm arc with a 30 mm radius)
    ("G0 X-50 Y0\nG41 D2 G1 X0 Y0 F500\nG3 X20 Y20 I0 J20\n", 3, "not less than the arc radius"),
    # LinuxCNC: "Straight feed in concave corner cannot be reached by the tool without gouging"
    ("G0 X-50 Y-50\nG41 D1 G1 X0 Y0 F500\nG1 X50\nG1 Y2\nG1 X100\nG40 G1 X150 Y0\n", 5, "gouging"),
    # LinuxCNC: "The move just after exiting cutter compensation mode must be straight, not an arc"
    ("G0 X-20 Y-20\nG41 D1 G1 X0 Y0 F500\nG1 X50\nG40\nG2 X70 Y-20 R20\n", 5, "must be straight"),
    ("G0 X-20 Y-20\nG41 D1 G1 X0 Y0 F500\nG55\n", 3, "zero offset"),
    ("G0 X-20 Y-20\nG41 D1 G1 X0 Y0 F500\nT2 M6\n", 3, "tool change"),
    ("G0 X-20 Y-20\nG41 D1 G1 X0 Y0 F500\nG42 D1\n", 3, "on already"),
    ("G19\nG41 D1\n", 2, "G17 or G18"),
    ("G41 D1.5\n", 1, "whole number"),
    # LinuxCNC: "Cannot use canned cycles with cutter radius compensation"
    ("G0 X-20 Y-20 Z5\nG41 D1 G1 X0 Y0 F500\nG81 X10 Y0 Z-2 R1\n", 3, "no canned cycle"),
])
def test_compensation_refuses_what_linuxcnc_refuses(run_text, tmp_path, text, line, words):
    r, _ = _run(run_text, tmp_path, text)
    assert r["error"]["code"] == "NC012" and r["error"]["line"] == line, r["error"]
    assert words in r["error"]["message"]


def test_d_word_naming_a_missing_tool_is_nc008(run_text, tmp_path):
    r, _ = _run(run_text, tmp_path, "G41 D7 G1 X10 F100\n")
    assert r["error"]["code"] == "NC008"


def test_g41_d0_takes_the_radius_of_the_tool_in_the_spindle_as_rs274(run_text, tmp_path):
    """rs274 2.9 (`rs274 -t` with T1 P1 D0.4): `T1 M6` then `G41 D0` cuts as `G41` and `G41 D1`."""
    paths = []
    for d in ("D0", "", "D1"):
        r, calls = _run(run_text, tmp_path, f"T1 M6\nG0 X-20 Y-20\nG41 {d} G1 X0 Y0 F500\nG1 X50 Y0\nG1 X50 Y30\n"
                                            "G40 G1 X80 Y40\nM2\n")
        assert r["status"] == "ok", r["error"]
        paths.append(_moves(calls))
    assert paths[0] == paths[1] == paths[2]
    assert paths[0][1] == ("feed", -3.5921, 3.5921, None)  # rs274: STRAIGHT_FEED(-3.5921, 3.5921, ...)


def test_g41_without_a_tool_radius_cuts_the_programmed_path(run_text, tmp_path):
    """LinuxCNC: with radius 0 (no D word and no tool in the spindle) compensation changes nothing."""
    r, calls = _run(run_text, tmp_path, "G41 G1 X10 Y5 F100\nG1 X20\nG40 G1 X0\n")
    assert r["status"] == "ok", r["error"]
    assert [m[1:3] for m in _moves(calls)] == [(10.0, 5.0), (20.0, 5.0), (0.0, 5.0)]


def test_cpl_refuses_compensation_naming_the_d_number_source(run_text, tmp_path):
    r, _ = _run(run_text, tmp_path, "N10 G1 X10 F100\nN20 G41 X20\nM30\n", name="p.cpl")
    assert r["error"]["code"] == "NC005" and "D number" in r["error"]["message"], r["error"]


SIN_MACHINE = {"axis": MACHINE["axis"], "sin800": {"control": "880", "tool_offsets": [
    {"d": 1, "p": [1, 20, 0.0, 0.0, 5.0, 0.0, 0.0, 0.08]},  # shank cutter: radius P4 5.0 + wear P7 0.08
    {"d": 2, "p": [2, 1, 0.0, 0.0, 0.8]}]}}  # a turning tool (cutting position)


def _sin_contour() -> str:
    body = CONTOUR.replace("G21 G17 G90 G40\nT1 M6\n", "").replace("G41 D1", "G41 D1").replace("M2", "M30")
    return "%MPF1\n" + "".join(f"N{10 * i} {line}\n" for i, line in enumerate(body.splitlines(), 1))


def test_sinumerik_takes_the_radius_from_the_to_area_and_cuts_the_same_contour(run_text, tmp_path):
    """CL 800 TO table (CL 800 manual §2.3.3, L574-629: type 20-29 shank cutter, P4 radius + P7 radius wear): the shared geometry."""
    trace = tmp_path / "trace.jsonl"
    r = run_text(_sin_contour(), name="p.mpf", machine=machine_from_dict(SIN_MACHINE), trace=trace)
    assert r["status"] == "ok", r["error"]
    calls = [json.loads(line) for line in trace.read_text().splitlines()]
    assert _moves(calls) == RS274_PATH


def test_sinumerik_refuses_compensation_with_a_turning_tool(run_text, tmp_path):
    text = "%MPF1\nN10 G1 X10 F100\nN20 G41 D2 X20\nN30 M30\n"
    r = run_text(text, name="p.mpf", machine=machine_from_dict(SIN_MACHINE))
    assert r["error"]["code"] == "NC005" and "tool type 1" in r["error"]["message"], r["error"]


def test_sinumerik_refuses_another_d_while_compensation_is_on(run_text, tmp_path):
    text = "%MPF1\nN10 G0 X-20 Y-20\nN20 G41 D1 G1 X0 Y0 F500\nN30 G1 X50 D2\nN40 M30\n"
    r = run_text(text, name="p.mpf", machine=machine_from_dict(SIN_MACHINE))
    assert r["error"]["code"] == "NC005" and r["error"]["line"] == 4, r["error"]


def test_sinumerik_acg_reports_the_compensation_group(run_text, tmp_path):
    """ACG (@36b) group 3: G40 G41 G42 (CL 800 manual §11.5 L7392-7410)."""
    text = ("%MPF1\nN10 G0 X-20 Y-20\nN20 @36b R1 K0 K3\nN30 G42 D1 G1 X0 Y0 F500\nN40 @36b R2 K0 K3\n"
            "N50 G1 X50\nN60 G40 G1 X70 Y-20\nN70 @36b R3 K0 K3\nN80 M30\n")
    r = run_text(text, name="p.mpf", machine=machine_from_dict(SIN_MACHINE))
    assert r["status"] == "ok", r["error"]
    assert [r["variables"].get(f"R{n}") for n in (1, 2, 3)] == [40.0, 42.0, 40.0]


def test_entry_move_as_an_arc_as_rs274(run_text, tmp_path):
    """The first move after G41 an arc (rs274 allows it): it runs from where the tool stands to the point a
    radius beside the programmed end, on a circle through both. rs274 -t (T1 P1 D0.4) -g gives
    ARC_FEED(16.4079, 16.4079, 8.2039, 8.2039, 1) and STRAIGHT_FEED(-3.5921, 36.4079)."""
    text = "G21 G17 G90 G40\nT1 M6\nG0 X0 Y0\nG41 D1 G3 X20 Y20 I10 J10 F500\nG1 X0 Y40\nG40 G1 X0 Y60\nM2\n"
    r, calls = _run(run_text, tmp_path, text)
    assert r["status"] == "ok", r["error"]
    assert _moves(calls)[1:] == [("arc", 16.4079, 16.4079, (8.2039, 8.2039)), ("feed", -3.5921, 36.4079, None),
                                 ("feed", 0.0, 60.0, None)]


def test_entry_arc_not_longer_than_the_radius_stops(run_text, tmp_path):
    """As the straight entry: an entry arc whose chord is not longer than the tool radius stops (NC012)."""
    text = "G21 G17 G90 G40\nT1 M6\nG0 X0 Y0\nG42 D1 G3 X3 Y3 I1.5 J1.5 F500\nG1 X0 Y40\nM2\n"
    r, _ = _run(run_text, tmp_path, text)
    assert r["error"]["code"] == "NC012" and r["error"]["line"] == 4


def test_g41_1_takes_the_diameter_from_d_as_rs274(run_text, tmp_path):
    """LinuxCNC's dynamic compensation: G41.1 D10.16 cuts with radius 5.08 and no tool table, as G41 with
    tool 1 does (the same rs274 path); G42.1 D6 the other side with radius 3 (rs274: X49.5132 Y53)."""
    text = CONTOUR.replace("T1 M6\n", "").replace("G41 D1", "G41.1 D10.16")
    r, calls = _run(run_text, tmp_path, text)
    assert r["status"] == "ok", r["error"]
    assert _moves(calls) == RS274_PATH
    r, calls = _run(run_text, tmp_path, "G0 X80 Y60\nG42.1 D6 G1 X50 Y50 F500\nG1 X0 Y50\nG40 G1 X-20 Y30\n")
    assert _moves(calls)[1:] == [("feed", 49.5132, 53.0, None), ("feed", 0.0, 53.0, None),
                                 ("feed", -20.0, 30.0, None)]


def test_g41_1_without_d_stops(run_text, tmp_path):
    r, _ = _run(run_text, tmp_path, "G0 X-20 Y-20\nG41.1 G1 X0 Y0 F500\nG40 G1 X-20 Y-20\n")
    assert r["error"]["code"] == "NC012" and "D word" in r["error"]["message"]
