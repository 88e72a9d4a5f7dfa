"""din follows LinuxCNC (issue 14: "`iso` (din; LinuxCNC rs274 is the reference)"). In LinuxCNC's order of
execution the tool change (M6) comes before the tool length offset (G43), so ``T1 M6 G43`` in one block
takes tool 1's length, as ``T1 M6`` and then ``G43`` do. ncvm applies the length of the tool that was in the
spindle before (none), so every later Z stands 25.4 mm lower than the program means, without a word."""

from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

import pytest
from review14b_run import AXES, moves, run

MACHINE = AXES + "[[tool]]\nnumber = 1\nlength = 25.4\n"


@pytest.mark.parametrize("blocks", ["T1 M6\nG43\n", "T1 M6 G43\n"])
def test_g43_takes_the_length_of_the_tool_changed_in_its_block(tmp_path: Path, blocks: str) -> None:
    text = f"G21 G90\n{blocks}G0 X0 Y0 Z50\nG53 G0 Z0\nM2\n"
    rs274 = shutil.which("rs274")
    if rs274:   # the reference: G53 Z0 puts the tool tip at -25.4 (the length is active) in both forms
        (tmp_path / "tool.tbl").write_text("T1 P1 D0 Z1.0 ;\n")   # rs274 reads the table in inches
        (tmp_path / "ref.ngc").write_text(text)
        ref = subprocess.run([rs274, "-t", str(tmp_path / "tool.tbl"), "-g", str(tmp_path / "ref.ngc")],
                             capture_output=True, text=True, input="", timeout=60)
        assert "STRAIGHT_TRAVERSE(0.0000, 0.0000, -25.4000" in ref.stdout, ref.stdout
    result, rows, _ = run(tmp_path, "tlo.ngc", text, MACHINE)
    assert result["status"] == "ok"
    z50 = [m for m in moves(rows) if m[0] == text.splitlines().index("G0 X0 Y0 Z50") + 1]
    assert z50[0][3] == 75.4, moves(rows)   # the slide: Z50 + the tool's length
