"""[sin800] strict_nc (CL 800 manual L7079): R stores keep 8 significant digits, range +/-99999999."""

from __future__ import annotations

from pathlib import Path

import pytest
from sin800_helpers import MACHINE, run_mpf

from ncvm.api import run
from ncvm.dialects.sinumerik.ncdata import Cl800Error, nc8
from ncvm.runtime.session import RunOptions


def _run(tmp_path: Path, text: str, strict: bool):
    return run_mpf(tmp_path, text, f"strict_nc = {'true' if strict else 'false'}\n")


def test_nc8_rounding_and_range():
    assert nc8(1.0 / 3.0) == 0.33333333
    assert nc8(2.0 / 3.0) == 0.66666667
    assert nc8(123456.789012) == 123456.79
    assert nc8(-99999999.0) == -99999999.0
    assert nc8(0.000000004) == 0.0
    with pytest.raises(Cl800Error):
        nc8(99999999.6)  # rounds to 100000000: one digit too many


def test_strict_division_keeps_eight_digits(tmp_path):
    # R1 = 1/3 = 0.33333333; R2 = R1*3 = 0.99999999 (floats would give 1.0)
    text = "%MPF1\nR1=1/3 R2=R1*3 @630 R3 K30 @613 R4 K2\n"
    r = _run(tmp_path, text, True)["variables"]
    assert (r["R1"], r["R2"], r["R4"]) == (0.33333333, 0.99999999, 1.4142136)
    assert r["R3"] == 0.5
    loose = _run(tmp_path, text, False)["variables"]
    assert loose["R2"] == 1.0 and loose["R4"] == 2 ** 0.5


def test_strict_overflow_is_the_cl800_error(tmp_path):
    r = _run(tmp_path, "%MPF1\nR1=50000000\nR2=R1*2\nM30\n", True)
    assert r["error"]["code"] == "CL800" and r["error"]["line"] == 3
    # without strict_nc too (issue 15): the range of L7079 is the control's, not an option's
    loose = _run(tmp_path, "%MPF1\nR1=50000000\nR2=R1*2\nM30\n", False)
    assert loose["error"]["code"] == "CL800" and loose["error"]["line"] == 3 and loose["variables"].get("R2", 0.0) == 0.0


def test_strict_rounds_system_memory_reads(tmp_path):
    # ACPM after a move to X 1/3: the position read keeps 8 digits
    r = _run(tmp_path, "%MPF1\nR5=1/3\nG90 G0 X=R5\n@714 @361 R1 K1\n", True)
    assert r["variables"]["R1"] == 0.33333333


def test_strict_int_sec_result_and_machine_file_r(tmp_path):
    # contour L21 from (Y0, X0) to (Y100, X300): Y = X / 3; the path X10 from Y0 to Y50 meets it at
    # Y = 10/3 = 3.3333333 (8 digits); R10 from the machine file: 0.123456789 -> 0.12345679
    (tmp_path / "L21.spf").write_text("L21\nN5 X300 Y100 M17\n")
    text = "%MPF1\nG90 G0 X10 Y0\nR50=21 R51=0 R52=0 R53=1\n@710 R54 R50\n@711 R70 R54 R62 X10 Y50\n"
    for strict, y, r10 in ((True, 3.3333333, 0.12345679), (False, 10 / 3, 0.123456789)):
        (tmp_path / "machine.toml").write_text(MACHINE + f"strict_nc = {'true' if strict else 'false'}\n"
                                               "r = { R10 = 0.123456789 }\n")
        (tmp_path / "prog.mpf").write_text(text)
        result, _ = run(tmp_path / "prog.mpf", dialect="sin800", machine=tmp_path / "machine.toml",
                        options=RunOptions(state_dir=tmp_path / ".ncvm"))
        v = result["variables"]
        assert (v["R70"], v["R71"], v["R72"], v["R10"]) == (1.0, y, 10.0, r10)
