"""SINUMERIK G81-G89 (CL 800 manual L7406, internal G group 9) call the drilling cycle L81-L89 after the
blocks that traverse, modal until G80 (docs/sin800.md "Drilling cycles"; the model is the manual's PROGRAM 81,
L5404-5542, which starts each hole by travelling to the start point with ``PRAP (3)=start_Z``)."""

from __future__ import annotations

from review14_helpers import moves

L81 = "%SPF81\nG1 Z=R26 F100\nG0 Z=R22\nM17\n"
HEAD = "%MPF1\nN10 G71 G90 G94 G17\nN20 S1000 M3\nN25 G0 X0 Y0 Z10\nN30 R22=2 R26=-10\n"


def _holes(rows) -> list[float]:
    """The X of every hole L81 drilled (its G1 Z=R26)."""
    return [m[1] for m in moves(rows) if m[4] == "L81.spf" and m[0] == "feed"]


def test_group6_g92_block_does_not_drill_again(ncvm_run):
    """G92 belongs to the internal G group 6 with G04, G25, G26, G58, G59, G74 (L7403): functions of a
    block that does not traverse. A block ``G92 X0`` moves nothing, so the modal cycle must not run there
    (ncvm already keeps G04 X1 and G58 X5 from drilling). ncvm drills the hole at X10 a second time at the
    G92 block, then the next one: three holes for two positions. Refusing G92 would also be honest."""
    result, rows, _ = ncvm_run("p.mpf", HEAD + "N40 G81 X10\nN50 G92 X0\nN55 X5\nN60 G80\nN99 M30\n",
                               {"L81.spf": L81})
    if result["status"] == "error":  # a refusal of G92 at its block is an acceptable answer
        assert result["error"]["line"] == 7, result["error"]
        return
    assert len(_holes(rows)) == 2, moves(rows)


def test_axis_block_with_a_subprogram_call_still_drills_at_its_position(ncvm_run):
    """docs/sin800.md: "every later block with an axis word ... first travels to its position ..., then runs
    the cycle there". ``N50 X20 L100`` travels to X20, but ncvm goes straight on into L100 and no hole is
    drilled at X20: a hole silently missing from the part. Expected: a hole at X20 (before L100's holes at
    X50 and X60), or a clear refusal of the two calls in one block."""
    l100 = "%SPF100\nG0 X50\nX60\nM17\n"
    result, rows, _ = ncvm_run("p.mpf", HEAD + "N40 G81 X10\nN50 X20 L100\nN60 G80\nN99 M30\n",
                               {"L81.spf": L81, "L100.spf": l100})
    if result["status"] == "error":
        assert result["error"]["line"] == 7, result["error"]
        return
    assert _holes(rows) == [10.0, 20.0, 50.0, 60.0], moves(rows)
