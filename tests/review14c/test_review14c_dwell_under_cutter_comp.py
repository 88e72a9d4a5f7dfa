"""Issue 14 §2: "the plot and the G-code sink show the compensated path", differential against rs274. Under
G41 a block ``G1 X0 G4 P1`` (a contour element with a dwell in its block) is a move in LinuxCNC's order of
execution: rs274 cuts the square's top edge and stays left of it. ncvm drops the move (see
test_review14c_dwell_with_motion.py), so the compensated path jumps to the wrong side of the contour
(X 22.54, outside the square's right edge) and the run ends normally: a gouged part without a word."""

from __future__ import annotations

from pathlib import Path

from review14c_run import RS274, ncvm, reference

SQUARE = ("G21 G90\nT1 M6\nG0 X-10 Y-10\nG41 D1 G1 X0 Y0 F100\nG1 X20\nG1 Y20\nG1 X0 G4 P1\nG1 Y0\n"
          "G40 G1 X-10 Y-10\nM2\n")
# rs274's compensated path for tool 1 (radius 2.54 mm): the square 20 x 20 shrunk by the radius
EXPECTED = [(-10.0, -10.0, 0.0), (-1.7961, 1.7961, 0.0), (0.0, 2.54, 0.0), (17.46, 2.54, 0.0),
            (17.46, 17.46, 0.0), (2.54, 17.46, 0.0), (2.54, 0.0, 0.0), (-10.0, -10.0, 0.0)]


def test_a_dwell_in_a_contour_block_keeps_the_compensated_path(tmp_path: Path) -> None:
    if RS274:
        assert [end for _, end in reference(tmp_path, SQUARE)] == EXPECTED
    result, moves = ncvm(tmp_path, SQUARE)
    assert result["status"] != "ok" or [end for _, end in moves] == EXPECTED, (result["status"], moves)
