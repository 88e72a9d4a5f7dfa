"""Fifth review of issue 18: a DIN program edited while it runs.

A DIN run past ``HOLD_BYTES`` reads its file twice (dialects/din/__init__.py ``_read``): once for its errors and
refusals, then again, a stretch at a time, as it runs. A user who edits the file in place while a long drilling
program runs (an editor that writes in place, ``>>``, a CAM post writing over the old output) changes what the
second reading sees, and the second reading neither looks at its errors nor at the blocks the first refused:
the run ends "ok" (exit 0) on blocks that were never checked. A silently wrong answer; the run should notice
that its program changed (or check what it reads again) and say so.

Real processes and a real file: the test waits (``/proc/<pid>/fdinfo``) until the run's open program file is read
from its start a second time, then writes into the program's last hole, which that reading has not reached.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import time
from pathlib import Path

import pytest

pytestmark = pytest.mark.skipif(not Path("/proc/self/fdinfo").is_dir(), reason="needs Linux /proc")

#: holes in the drilling program: 150,000 lines, past what a run holds (a drilling program of about 50,000 lines)
HOLES = 30_000


def _drilling(path: Path) -> bytes:
    lines = ["G21 G90 G17 G94 F150"]
    for i in range(HOLES):
        lines += [f"G0 X{i % 300}.0 Y{i // 300}.0", "G0 Z2", "G1 Z-12 F150", "G4 P0.5", "G0 Z2"]
    data = ("\n".join(lines) + "\nM30\n").encode()
    path.write_bytes(data)
    return data


def _program_fd(pid: int, path: Path) -> str | None:
    for fd in os.listdir(f"/proc/{pid}/fd"):
        try:
            if os.readlink(f"/proc/{pid}/fd/{fd}") == str(path):
                return fd
        except OSError:
            continue
    return None


def _wait_for_second_reading(proc: subprocess.Popen, path: Path) -> None:
    """Until the run's program file is read from its start again (its offset goes back)."""
    furthest, fd = 0, None
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline and proc.poll() is None:
        fd = fd or _program_fd(proc.pid, path)
        if fd is not None:
            try:
                pos = int(Path(f"/proc/{proc.pid}/fdinfo/{fd}").read_text().split()[1])
            except (OSError, IndexError, ValueError):
                pos = furthest
            if pos < furthest:
                return
            furthest = pos
        time.sleep(0.002)
    pytest.fail("the run did not read its program a second time (held it whole?)")


def _run_edited(tmp_path: Path, edit) -> tuple[int, dict]:
    program = tmp_path / "drill.ngc"
    data = _drilling(program)
    proc = subprocess.Popen([sys.executable, "-m", "ncvm", "run", "-d", "din", "--state", str(tmp_path / "st"),
                             "--json", str(program)], stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    try:
        _wait_for_second_reading(proc, program)
        with open(program, "r+b") as f:  # in place: the same file the run has open
            edit(f, data)
        out, _ = proc.communicate(timeout=300)
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
    return proc.returncode, json.loads(out)


def _write_at_last(text: bytes, new: bytes):
    assert len(text) == len(new)

    def edit(f, data):
        f.seek(data.rfind(text))
        f.write(new)
    return edit


def test_syntax_error_written_while_it_runs_is_not_skipped_silently(tmp_path):
    """The last hole's feed block becomes ``G1 Z-12 F1?0``: a program with that line fails with NC001 (cannot read
    '?0'). Written while the run is under way, the run skips the block without a word and ends ok (exit 0, one
    step fewer, the last hole not drilled)."""
    rc, result = _run_edited(tmp_path, _write_at_last(b"G1 Z-12 F150", b"G1 Z-12 F1?0"))
    assert (rc, result["status"]) != (0, "ok"), result["steps"]


def test_axis_the_machine_lacks_written_while_it_runs_is_not_run_silently(tmp_path):
    """The last retract becomes ``G0 A5``: on the 3-axis mill a program with that block stops with NC011 (axis A
    is not configured). Written while the run is under way, the block runs as if it were not there and the run
    ends ok (exit 0) with the tool left at Z-12 in the last hole."""
    rc, result = _run_edited(tmp_path, _write_at_last(b"G0 Z2\n", b"G0 A5\n"))
    assert (rc, result["status"]) != (0, "ok"), result["position"]


def test_program_cut_short_while_it_runs_does_not_end_ok(tmp_path):
    """The file is cut to half its length (its M30 gone) while the run is under way: the run ends ok (exit 0)
    after half the holes, its summary that of a program nobody checked."""
    rc, result = _run_edited(tmp_path, lambda f, data: f.truncate(len(data) // 2))
    assert (rc, result["status"]) != (0, "ok"), (result["steps"], result["position"])
