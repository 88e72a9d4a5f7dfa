"""M0, the programmed stop: every dialect reports it with the same line and, as the operator's cycle start
would, goes on (issue 15); a SINUMERIK machine may end the run there instead (``[sin800] m0 = "stop"``)."""

from __future__ import annotations

from pathlib import Path

import pytest

from ncvm.api import run
from ncvm.runtime.session import RunOptions

MACHINE = '[[axis]]\nname = "X"\n[[axis]]\nname = "Y"\n[[axis]]\nname = "Z"\n[sin800]\ncontrol = "880"\n'

PROGRAMS = {
    "din": ("p.nc", "N100 G0 X10\nN104 M0\nN105 G1 F100 X20\nM2\n"),
    "cpl": ("p.cpl", "10 A=1\nN100 G0 X10\nN104 M0\n20 A=2\nN105 G1 F100 X20\nN110 M30\n"),
    "sin800": ("p.mpf", "%MPF1\nN100 G0 X10\nN104 M0\nN105 G1 F100 X20\nN110 M30\n"),
}


def _run(tmp_path: Path, dialect: str, extra: str = "") -> dict:
    name, text = PROGRAMS[dialect]
    (tmp_path / "machine.toml").write_text(MACHINE + extra)
    (tmp_path / name).write_text(text)
    result, _ = run(tmp_path / name, dialect=dialect, machine=tmp_path / "machine.toml",
                    options=RunOptions(state_dir=tmp_path / ".s"))
    assert result["status"] == "ok", result["error"]
    return result


@pytest.mark.parametrize("dialect", sorted(PROGRAMS))
def test_m0_is_reported_and_the_run_continues_in_every_dialect(tmp_path: Path, dialect: str):
    result = _run(tmp_path, dialect)
    assert result["output"] == ["M0 at N104: programmed stop (continued)"]
    assert result["position"]["X"] == 20.0 and result["motion"]["feed_moves"] == 1


def test_m0_without_a_block_number_names_its_line(tmp_path: Path):
    (tmp_path / "p.nc").write_text("G0 X10\nM0\nG1 F100 X20\n")
    result, _ = run(tmp_path / "p.nc", dialect="din", options=RunOptions(state_dir=tmp_path / ".s"))
    assert result["output"] == ["M0 at line 2: programmed stop (continued)"]


def test_sin800_m0_stop_option_ends_the_run_there(tmp_path: Path):
    result = _run(tmp_path, "sin800", 'm0 = "stop"\n')
    assert result["output"] == ["M0 at N104: programmed stop (run ends)"]
    assert result["position"]["X"] == 10.0 and result["motion"]["feed_moves"] == 0
