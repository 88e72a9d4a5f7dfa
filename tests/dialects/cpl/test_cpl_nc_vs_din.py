"""A CPL program made only of NC blocks moves exactly as the same blocks run as plain DIN.

The CPL side reads its NC blocks itself, queues them and drains the queue at
program end; the DIN side reads the text as columns. Random programs with
lines, arcs in all planes, G90/G91, inch, zero offsets and G92 must give the
same moves, final position and cycle time. The Typ3 osa writes inch and mm as G70/G71 (its G20 selects
a plane, L2372), so the CPL side gets those; it has no G10 (its profile refuses LinuxCNC's G10 L2): the
CPL side writes the zero offset G54 into its active ZS table with FXC (L1759-1776).
"""

from __future__ import annotations

import re

import numpy as np
import pytest

from ncvm.api import run
from ncvm.runtime.session import RunOptions


@pytest.mark.parametrize("seed", range(6))
def test_nc_blocks_in_cpl_move_as_in_din(tmp_path, random_din, seed):
    text = "\n".join(line for line in random_din(seed).splitlines() if line.strip() != "%") + "\n"
    (tmp_path / "p.ngc").write_text(text)
    cpl_text = re.sub(r"\bG2([01])(?!\d)", r"G7\1", text)
    cpl_text = re.sub(r"G10 L2 P1 X(\S+) Y(\S+)", r'10 FXC("X",54)=\1 : FXC("Y",54)=\2', cpl_text)
    (tmp_path / "p.cpl").write_text(cpl_text)
    din, s1 = run(tmp_path / "p.ngc", options=RunOptions(keep_toolpath=True, state_dir=tmp_path / ".a"))
    cpl, s2 = run(tmp_path / "p.cpl", options=RunOptions(keep_toolpath=True, state_dir=tmp_path / ".b"))
    assert din["status"] == cpl["status"] == "ok", cpl["error"]
    a1, a2 = s1.recorder.arrays(), s2.recorder.arrays()
    assert len(a1["kind"]) > 40 and np.array_equal(a1["kind"], a2["kind"])
    np.testing.assert_allclose(a1["end"], a2["end"], rtol=0, atol=1e-9)
    assert cpl["position"] == pytest.approx(din["position"], abs=1e-9)
    assert cpl["cycle_time_s"] == pytest.approx(din["cycle_time_s"], rel=1e-12)
    assert cpl["motion"]["feed_length"] == pytest.approx(din["motion"]["feed_length"], rel=1e-12)
