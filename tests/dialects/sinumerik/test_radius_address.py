"""The SINUMERIK circle radius address (machine data, ``[sin800] radius_address``, B or U) and the rounding
it asks for between two straight contour blocks (issue 14 part 1; CL 800 manual §5.3.8.2, L4107-4282).

The manual's contour (L4214-4218): start (X750, Y50), ``N5 X400 Y50 B100``, ``N10 X300 Y300``,
``N15 X100 Y400 M17``. B100 rounds the corner at (400, 50) with radius 100: the lines turn by
atan2(250, 100) - 180 deg = 68.2 deg to the right, so the rounding is a G2 arc tangent to both lines,
100 tan(34.1 deg) = 67.703 mm before and after the corner, centre (X467.703, Y150). PREP REF counts it
as an element of its own; INT SEC still finds the manual's X = 320, Y = 250 on the line after it.
"""

from __future__ import annotations

import math

import pytest
from sin800_helpers import R, machine, run_mpf

from ncvm.api import check
from ncvm.diagnostics import UsageError

CONTOUR = "L20\nN5 X400 Y50 B100\nN10 X300 Y300\nN15 X100 Y400 M17\n"
FIVE_PREP_REFS = ("%MPF30\nR50=20 R52=750 R51=50 R53=1\n@710 R100 R50\n@710 R110 R50\n@710 R120 R50\n"
                  "@710 R130 R50\n@710 R140 R50\nM30\n")


def _elements(r, count=5):
    return [[R(r, base + i) for i in range(8)] for base in range(100, 100 + 10 * count, 10)]


def _expected():
    t = 100 * math.tan((math.pi - math.atan2(250, -100)) / 2)  # half the turn between (-1, 0) and (-100, 250)
    u = (-100 / math.hypot(100, 250), 250 / math.hypot(100, 250))  # (h, v) of the second line
    t2 = (400 + u[0] * t, 50 + u[1] * t)
    return t, [[50.0, 750.0, 50.0, 400 + t, 0.0, 0.0, 1.0, 0.0],  # (V, H): Y then X
               [50.0, 400 + t, t2[1], t2[0], 100.0, 0.0, 2.0, 0.0],  # G2, centre 100 above its start
               [t2[1], t2[0], 300.0, 300.0, 0.0, 0.0, 1.0, 0.0],
               [300.0, 300.0, 400.0, 100.0, 0.0, 0.0, 1.0, 1.0],  # the block with M17
               [400.0, 100.0, 400.0, 100.0, 0.0, 0.0, 1.0, 2.0]]  # past the end: only M17


def test_prep_ref_counts_the_b100_rounding_of_the_manuals_contour_as_an_element_l4216(tmp_path):
    r = run_mpf(tmp_path, FIVE_PREP_REFS, files={"L20.spf": CONTOUR}, ok=True)
    t, expected = _expected()
    assert t == pytest.approx(67.703296, abs=1e-6)
    assert _elements(r) == [pytest.approx(e, abs=1e-9) for e in expected]


def test_the_radius_address_is_machine_data_u_as_in_many_programs(tmp_path):
    """``radius_address = "U"``: U100 is the rounding, the same elements; B is then not the radius."""
    r = run_mpf(tmp_path, FIVE_PREP_REFS, 'radius_address = "U"\n',
                files={"L20.spf": CONTOUR.replace("B100", "U100")}, ok=True)
    assert _elements(r) == [pytest.approx(e, abs=1e-9) for e in _expected()[1]]
    r = run_mpf(tmp_path, FIVE_PREP_REFS, 'radius_address = "U"\n', files={"L20.spf": CONTOUR})
    assert r["error"]["code"] == "CL800" and "radius_address" in r["error"]["message"], r["error"]


def test_the_radius_address_must_be_b_or_u(tmp_path):
    with pytest.raises(UsageError, match="radius_address"):
        run_mpf(tmp_path, "%MPF1\nM30\n", 'radius_address = "Q"\n')


def test_u_on_a_circle_is_its_radius(tmp_path):
    """A circle given by its radius in the contour: G3 from (X0, Y0) to (X20, Y0) with U10, a half circle
    about (X10, Y0): I = 10, J = 0."""
    r = run_mpf(tmp_path, "%MPF1\nR50=21 R51=0 R52=0 R53=1\n@710 R100 R50\nM30\n", 'radius_address = "U"\n',
                files={"L21.spf": "L21\nN5 G3 X20 Y0 U10 M17\n"}, ok=True)
    assert [R(r, 100 + i) for i in range(8)] == pytest.approx([0.0, 0.0, 0.0, 20.0, 0.0, 10.0, 3.0, 1.0])


def test_a_rounding_next_to_a_circle_is_refused_clearly(tmp_path):
    r = run_mpf(tmp_path, "%MPF1\nR50=22 R51=0 R52=0 R53=1\n@710 R100 R50\nM30\n",
                files={"L22.spf": "L22\nN5 X10 B2\nN10 G2 X20 Y10 I0 J10 M17\n"})
    assert r["error"]["code"] == "CL800" and "not supported by ncvm" in r["error"]["message"], r["error"]


def _moves(tmp_path, text, extra="", files=None):
    import json

    from ncvm.api import run
    from ncvm.runtime.session import RunOptions
    (tmp_path / "machine.toml").write_text(machine() + extra)
    for name, body in (files or {}).items():
        (tmp_path / name).write_text(body)
    (tmp_path / "p.mpf").write_text(text)
    result, _ = run(tmp_path / "p.mpf", dialect="sin800", machine=tmp_path / "machine.toml",
                    options=RunOptions(state_dir=tmp_path / ".s", trace=tmp_path / "t.jsonl"))
    rows = [json.loads(x) for x in (tmp_path / "t.jsonl").read_text().splitlines()]
    moves = [(row["call"], round(row["end"]["X"], 6), round(row["end"]["Y"], 6),
              tuple(round(c, 6) for c in row["center"]) if row["call"] == "arc" else None,
              row.get("cw")) for row in rows if row["call"] in ("feed", "rapid", "arc")]
    return result, moves


def test_the_manuals_contour_run_as_motion_rounds_the_b100_corner_l4216(tmp_path):
    """L20 run from (X750, Y50): the line to X467.703, the G2 rounding about (X467.703, Y150) to
    (X374.856, Y112.861), the line to (X300, Y300), the line to (X100, Y400): PREP REF's elements, cut."""
    r, moves = _moves(tmp_path, "%MPF1\nG0 X750 Y50\nG1 F500\nL20\nM30\n",
                      files={"L20.spf": CONTOUR.replace("L20\n", "%SPF20\n")})  # the title line as a header
    assert r["status"] == "ok", r["error"]
    t, el = _expected()
    assert moves == [("rapid", 750.0, 50.0, None, None), ("feed", round(400 + t, 6), 50.0, None, None),
                     ("arc", round(el[1][3], 6), round(el[1][2], 6), (round(400 + t, 6), 150.0), True),
                     ("feed", 300.0, 300.0, None, None), ("feed", 100.0, 400.0, None, None)]


def test_chained_roundings_of_an_incremental_square(tmp_path):
    """A 20 mm square in G91 with U2 at three corners: each side 20 - 2 x 2 at the rounded ends, three
    quarter circles; the path 4 x 20 - 6 x 2 + 3 x pi; back at the start."""
    r, moves = _moves(tmp_path, "%MPF1\nG0 X0 Y0\nG91 G1 F300 X20 U2\nY20 U2\nX-20 U2\nY-20\nM30\n",
                      'radius_address = "U"\n')
    assert r["status"] == "ok", r["error"]
    assert [m[0] for m in moves] == ["rapid", "feed", "arc", "feed", "arc", "feed", "arc", "feed"]
    assert moves[-1][1:3] == (0.0, 0.0) and moves[2][3] == (18.0, 2.0) and moves[2][4] is False
    assert r["motion"]["feed_length"] == pytest.approx(80 - 12 + 3 * math.pi)


def test_decode_ahead_rounds_the_same_corner(tmp_path):
    text = "%MPF1\nG0 X0 Y0\nG1 X100 Y0 B10 F100\nX100 Y100\nM30\n"
    (tmp_path / "a").mkdir()
    (tmp_path / "b").mkdir()
    assert _moves(tmp_path / "a", text)[1] == _moves(tmp_path / "b", text, "decode_ahead = 2\n")[1]


@pytest.mark.parametrize("text, why", [
    ("G1 X100 Y0 B10 F100\nG0 X100 Y100\nM30\n", "not a straight move at feed"),
    ("G1 X100 Y0 B10 F100\nM30\n", "G or M functions"),
    ("G1 X100 Y0 B10 F100\n", "program ends"),
    ("G1 X100 Y0 B10 F100\nX100 Y100 Z5\nM30\n", "leave the plane"),
    ("G1 X100 Y0 B10 F100\nG2 X110 Y10 I0 J10\nM30\n", "not a straight move at feed"),
    ("G1 X10 Y0 B20 F100\nX10 Y100\nM30\n", "the lines are"),
])
def test_a_rounding_the_control_could_not_make_here_stops_with_nc009(tmp_path, text, why):
    r = run_mpf(tmp_path, "%MPF1\nG0 X0 Y0\n" + text)
    assert r["error"]["code"] in ("NC009", "CL800") and why in r["error"]["message"], r["error"]
    assert r["error"]["line"] == 3


def test_g0_with_the_radius_stays_refused_by_the_kernel(tmp_path):
    """A rapid move has no rounding: the kernel's NC009 (a circle radius on a straight move), as for din."""
    r = run_mpf(tmp_path, "%MPF1\nG0 X10 Y0 B5\nX10 Y10\nM30\n")
    assert r["error"]["code"] == "NC009" and r["error"]["line"] == 2, r["error"]


def test_check_takes_the_radius_address_from_the_machine(tmp_path):
    (tmp_path / "machine.toml").write_text(machine() + 'radius_address = "U"\n')
    (tmp_path / "c.spf").write_text(CONTOUR.replace("B100", "U100"))
    diags = check(tmp_path / "c.spf", dialect="sin800", machine=tmp_path / "machine.toml")
    assert not [d for d in diags if d.code == "NC011"]


@pytest.mark.parametrize("address, refused", [("U", False), ("B", True)])
def test_cl800_check_takes_the_radius_address_of_the_nc(tmp_path, address, refused):
    """A CL 800 program's DIN blocks are checked with the NC's machine data ([sin800] radius_address)."""
    (tmp_path / "machine.toml").write_text(machine() + f'radius_address = "{address}"\n')
    (tmp_path / "c.cl8").write_text("PROGRAM 20;\nCHANNEL NC 1;\nID (0-CONTOUR);\nBEGIN\n(:X400 Y50 U100:); LF;\n"
                                    "(:X300 Y300 M17:); LF;\nEND.\n")
    diags = check(tmp_path / "c.cl8", dialect="cl800", machine=tmp_path / "machine.toml")
    assert bool([d for d in diags if d.code == "NC011"]) == refused, diags
