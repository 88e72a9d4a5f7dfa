"""Issue 16 item 5 "Always a complete file: the output is written to a temporary file and moved into place
only when the run ended normally; a failed run leaves no output". A translation stopped from outside (the
user's Ctrl-C, a `kill`, a batch system's SIGTERM) leaves its temporary `.OUT.*.body` file in the folder of
OUT, e.g. LinuxCNC's nc_files, growing while the program ran (a runaway loop: tens of MB)."""

from __future__ import annotations

import signal
import subprocess
import sys
import time

import pytest

from tests.review16e.helpers import mill, write

RUNAWAY = "N10 G90 G17 G54 G0 X0 Y0 Z5\n10 WHILE TRUE DO\nN20 G1 X1 F1000\nN30 X0\n40 END\nN50 M30\n"


@pytest.mark.parametrize("sig", [signal.SIGINT, signal.SIGTERM, signal.SIGHUP], ids=["SIGINT", "SIGTERM", "SIGHUP"])
def test_stopped_translation_leaves_nothing_beside_out(tmp_path, sig):
    write(tmp_path, {"machine.toml": mill(), "loop.cpl": RUNAWAY})
    out_dir = tmp_path / "nc_files"
    out_dir.mkdir()
    p = subprocess.Popen([sys.executable, "-m", "ncvm", "translate", "loop.cpl", "-m", "machine.toml", "-o",
                          str(out_dir / "part.ngc")], cwd=tmp_path, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    try:
        deadline = time.monotonic() + 120
        while not any(out_dir.iterdir()) and time.monotonic() < deadline:
            time.sleep(0.2)
        assert any(out_dir.iterdir()), "the translation never started writing"
        time.sleep(1.0)
        p.send_signal(sig)
        p.wait(timeout=60)
    finally:
        if p.poll() is None:
            p.kill()
            p.wait()
    assert p.returncode != 0
    assert sorted(f.name for f in out_dir.iterdir()) == []
    if sig != signal.SIGINT:  # a supervisor's signal has its own code (RUN009), not Ctrl-C's RUN004
        name = signal.Signals(sig).name
        assert p.returncode == 128 + sig
        assert f"ncvm: error RUN009: translation stopped by {name} (" in p.stderr.read().decode()
