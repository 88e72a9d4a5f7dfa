"""The manual's chapter 7 cycles (examples/cl800): they compile, the shipped object programs are the
compiler's output, and (once the sin800 NC is merged) they run with the hand-computed toolpath."""

from __future__ import annotations

import math
import re
from pathlib import Path

import pytest

from ncvm.api import compile_program, run
from ncvm.runtime.session import RunOptions

EXAMPLES = Path(__file__).parents[4] / "examples" / "cl800"


@pytest.mark.parametrize("source,obj", [("hole_pattern.cl8", "L101.spf"), ("deep_hole_drilling.cl8", "L81.spf")])
def test_shipped_object_is_the_compiler_output(source: str, obj: str, tmp_path: Path):
    out = compile_program(EXAMPLES / source, out=tmp_path / obj)
    assert out.read_text() == (EXAMPLES / obj).read_text()


def test_hole_pattern_object_code():
    text = (EXAMPLES / "L101.spf").read_text().splitlines()
    assert text[0] == "%SPF101"
    # WHILE No._act. < number: test at N3001, exit to N3002, jump back from the loop's last block
    assert "N3001 @135 R70 R32 K3002" in text
    assert "R70=R70+1 @100 K-3001" in text
    assert text[-2] == "N3002 @042 K6 R60 R61 R62 R70 R98 R99 M17"
    assert re.fullmatch(r"\(CRC32 [0-9A-F]{8}\) \(COMPILED BY NCVM\)", text[-1])  # the mark line


def _sin800():
    pytest.importorskip("ncvm.dialects.sinumerik")


def test_run_hole_pattern(tmp_path: Path):
    _sin800()
    result, _ = run(EXAMPLES / "drill_hole_pattern.cl8", options=RunOptions(state_dir=tmp_path))
    assert result["status"] == "ok", result["error"]
    motion = result["motion"]
    assert motion["feed_moves"] == 5  # one plunge per hole (L102)
    assert motion["feed_length"] == pytest.approx(100.0)
    pos = result["position"]
    assert pos["X"] == pytest.approx(100 + 4 * 20 * math.cos(math.radians(30)))
    assert pos["Y"] == pytest.approx(50 + 4 * 20 * math.sin(math.radians(30)))
    assert pos["Z"] == pytest.approx(50)


def test_run_deep_hole_drilling(tmp_path: Path):
    _sin800()
    result, _ = run(EXAMPLES / "deep_hole.cl8", options=RunOptions(state_dir=tmp_path))
    assert result["status"] == "ok", result["error"]
    motion = result["motion"]
    # degression passes to Z-18, -33, -43, -48, -53, then the two final passes to Z-56.5 and Z-60
    assert motion["feed_moves"] == 7
    assert motion["feed_length"] == pytest.approx(20 + 16 + 11 + 50 + 55 + 58.5 + 62)
    assert result["position"]["Z"] == pytest.approx(50)
