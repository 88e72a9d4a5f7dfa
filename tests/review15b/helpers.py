"""Run an rw_SymPas program as a user of the APCI-8001 would (`ncvm run --json`, a real process, real
files) and read the JSON document back."""

from __future__ import annotations

import json
import subprocess
import sys
import textwrap
from pathlib import Path

AXIS = """
[[axis]]
name = "{name}"
min = -10.0
max = {max}
rapid = 12000.0
max_feed = 6000.0
accel = 1500.0
"""


def apci_machine(name: str, **maxima: float) -> str:
    """A machine.toml named `name` with one axis per keyword (its right travel limit as the value)."""
    return f'[machine]\nname = "{name}"\n' + "".join(AXIS.format(name=axis, max=top) for axis, top in maxima.items())


GANTRY = apci_machine("APCI-8001 gantry", X=400.0, Y=300.0)
SLIDE = apci_machine("APCI-8001 slide", X=400.0)


def run_json(tmp_path: Path, source: str, *args: str, machine: str = GANTRY, timeout: int = 120) -> dict:
    """Write machine.toml and p.sap (`source` dedented) to tmp_path, run p.sap there; the JSON document."""
    (tmp_path / "machine.toml").write_text(machine)
    program = tmp_path / "p.sap"
    program.write_text(textwrap.dedent(source))
    done = subprocess.run(
        [sys.executable, "-m", "ncvm", "run", "--json", *args, str(program)],
        capture_output=True, text=True, cwd=tmp_path, timeout=timeout,
    )
    return json.loads(done.stdout)
