"""In a Bosch Typ3 osa program G20 selects a plane (CPL manual L2371-2375, the AXP example: "Plane
switchover with G20"), it does not switch to inch.

Issue 14 opens with this silent error: the AXP example cuts a half circle 797.96 mm long instead of 31.42
mm. `N20 G20 G1 X10` moved X to 254 mm (10 inch); now G20 is the plane switchover (test_typ3osa_profile.py).
"""

from __future__ import annotations

from pathlib import Path

from ncvm.api import run
from ncvm.runtime.session import RunOptions

MACHINE = '[[axis]]\nname = "X"\n[[axis]]\nname = "Y"\n[[axis]]\nname = "Z"\n'


def test_g20_does_not_scale_the_cpl_program_to_inch_l2372(tmp_path: Path):
    (tmp_path / "machine.toml").write_text(MACHINE)
    prog = tmp_path / "g20.cpl"
    prog.write_text("N10 G0 X0 Y0 Z0\nN20 G20 G1 X10 F100\nN30 M30\n")
    result, _ = run(prog, dialect="cpl", machine=tmp_path / "machine.toml",
                    options=RunOptions(state_dir=tmp_path / ".s"))
    if result["error"] is None:  # implemented (a plane) or refused clearly; never inch
        # "position" is in program units (10 either way); the machine's path says what was cut
        assert result["motion"]["bounds"]["X"] == [0.0, 10.0], result["motion"]
        assert abs(result["motion"]["feed_length"] - 10.0) < 1e-9, result["motion"]
    else:
        assert result["error"]["line"] == 2, result["error"]


def test_g20_needs_two_axes_and_g21_is_no_typ3_function(tmp_path: Path):
    """G20 names the main and the secondary axis with the pole (L2372); one axis is no plane (NC009). G21 is
    not a Typ3 osa function: NC004 naming G70/G71."""
    (tmp_path / "machine.toml").write_text(MACHINE)
    for g, code, words in ((20, "NC009", "plane switchover"), (21, "NC004", "G70/G71")):
        prog = tmp_path / f"g{g}.cpl"
        prog.write_text(f"N10 G0 X0 Y0 Z0\nN20 G{g} G1 X10 F100\nN30 M30\n")
        result, _ = run(prog, dialect="cpl", machine=tmp_path / "machine.toml",
                        options=RunOptions(state_dir=tmp_path / ".s"))
        assert result["error"]["code"] == code and result["error"]["line"] == 2, result["error"]
        assert words in result["error"]["message"]
        assert result["motion"]["feed_length"] == 0.0
