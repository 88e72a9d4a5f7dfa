"""SINUMERIK G53 and POS MSYS suppress the zero offsets for one block and keep the tool length: "All zero
point-, PRESET-, and the DRF offsets are suppressed with the POS-MSYS statement, i.e. the tool offsets must
be cancelled for approaching a fixed machine point" (CL 800 planning guide §5.3.8.1, L4083); G53 is group 4
of §11.5 (L7396), the zero offset suppression (docs/decisions.md, "Issue 14: G53 and POS MSYS")."""

from __future__ import annotations

import pytest
from sin800_helpers import R, machine, run_mpf

#: D1: a cutter (type 20) 50 mm long; G54 shifts Z by -20, an external zero offset Y by 7
MACHINE = machine(extra='tool_offsets = [ { d = 1, p = [1, 20, 50.0] } ]\n'
                        'zero_offsets = { EXTERNAL = [0.0, 7.0, 0.0], DRF = [0.0, 0.0, 0.25] }\n'
                        '[offsets]\nG54 = [10.0, 0.0, -20.0]\n')

#: the machine actual values of X Y Z after the block (@361, read after STOP DEC @714)
READ = "@714 @361 R1 K1 @361 R2 K2 @361 R3 K3\n"


@pytest.mark.parametrize("block", ["G53 G0 X100 Y40 Z500", "@706 G0 X100 Y40 Z500"])
def test_l4083_machine_block_keeps_the_tool_length(tmp_path, block):
    """X100 Y40 Z500 is the machine point of the tool tip: the slide stands 50 mm (D1) above it on Z; G54,
    the external zero offset and DRF do not count (L4083)."""
    r = run_mpf(tmp_path, f"%MPF1\nG54 D1 G0 X0 Y0 Z0\n{block}\n{READ}M30\n", machine_text=MACHINE, ok=True)
    assert (R(r, 1), R(r, 2), R(r, 3)) == (100.0, 40.0, pytest.approx(550.0))


def test_l4083_without_a_tool_offset_the_point_is_the_machine_point(tmp_path):
    """D0: no tool length, the block goes to the programmed machine point itself."""
    r = run_mpf(tmp_path, f"%MPF1\nG54 D0 G0 X0 Y0 Z0\nG53 G0 Z500\n{READ}M30\n", machine_text=MACHINE, ok=True)
    assert R(r, 3) == pytest.approx(500.0)


def test_the_next_block_is_in_the_workpiece_frame_again(tmp_path):
    """G53 acts in its block only (group 4, blockwise): the next Z0 is G54's zero plus the tool length."""
    r = run_mpf(tmp_path, f"%MPF1\nG54 D1 G0 X0 Y0 Z0\nG53 G0 Z500\nZ0\n{READ}M30\n", machine_text=MACHINE, ok=True)
    assert R(r, 3) == pytest.approx(-20.0 + 0.25 + 50.0)
