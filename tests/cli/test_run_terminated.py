"""``ncvm run`` stopped by SIGTERM (``kill``, ``timeout``, a batch system) or SIGHUP (the terminal closed)
ends as ``ncvm translate`` does (runtime/interrupt.py ``ended_by_termination``): exit 128 + the signal,
one line on stderr with error RUN009 naming the signal, not Ctrl-C's RUN004 (a JSON document on stdout with
--json), no hidden temporary file beside an output,
the G-code and the plot not written (an existing one left as it was), the trace's lines up to the stop,
each of them whole JSON."""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from ncvm.outpaths import replacing

ENDLESS_CPL = "N1 G71 G90 G17 F6000\n10 WHILE TRUE DO\nG1 X10\nG1 X0\n20 END\nM30\n"


def _stopped(tmp_path: Path, sig: int, *outputs: str) -> subprocess.CompletedProcess:
    program = tmp_path / "p.cpl"
    program.write_text(ENDLESS_CPL)
    trace = tmp_path / "t.jsonl"
    proc = subprocess.Popen([sys.executable, "-m", "ncvm", "run", "--state", str(tmp_path / "st"), "--trace",
                             str(trace), *outputs, str(program)], cwd=tmp_path, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True)
    try:
        deadline = time.monotonic() + 120
        while (not trace.exists() or trace.stat().st_size < 20_000) and time.monotonic() < deadline \
                and proc.poll() is None:
            time.sleep(0.1)
        assert proc.poll() is None and trace.stat().st_size >= 20_000, "the run never got going"
        proc.send_signal(sig)
        out, err = proc.communicate(timeout=60)
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.communicate()
    return subprocess.CompletedProcess(proc.args, proc.returncode, out, err)


@pytest.mark.parametrize("sig", [signal.SIGTERM, signal.SIGHUP], ids=["SIGTERM", "SIGHUP"])
def test_a_run_stopped_by_a_signal_leaves_whole_outputs_and_no_temporary_files(tmp_path, sig):
    (tmp_path / "old.png").write_bytes(b"the plot of an earlier run")
    done = _stopped(tmp_path, sig, "--gcode", "out.ngc", "--plot", "old.png")
    name = signal.Signals(sig).name
    assert done.returncode == 128 + sig, done.stderr
    sender = "sent from outside: kill, timeout, a batch system" if sig == signal.SIGTERM else "the terminal closed"
    assert f"ncvm: error RUN009: run stopped by {name} ({sender}); no --gcode out.ngc or --plot old.png written" \
        in done.stderr
    assert "RUN004" not in done.stderr and "by the user" not in done.stderr  # a supervisor, not Ctrl-C
    assert "Traceback" not in done.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["old.png", "p.cpl", "st", "t.jsonl"]
    assert (tmp_path / "old.png").read_bytes() == b"the plot of an earlier run"
    lines = (tmp_path / "t.jsonl").read_text().splitlines()
    records = [json.loads(line) for line in lines]  # every line whole
    assert records[0]["call"] == "begin" and len(records) > 100
    assert all(r["time"] is not None for r in records if r["call"] == "feed")  # timed to rest at the stop


def test_json_stdout_stays_json(tmp_path):
    done = _stopped(tmp_path, signal.SIGTERM, "--json")
    assert done.returncode == 128 + signal.SIGTERM
    doc = json.loads(done.stdout)
    assert doc["status"] == "error" and doc["error"]["code"] == "RUN009"
    assert doc["error"]["message"].startswith("run stopped by SIGTERM (sent from outside: kill, timeout, a batch "
                                              "system); the trace ")


def test_replacing_puts_a_whole_file_in_place_or_leaves_the_old_one(tmp_path):
    target = tmp_path / "plot.svg"
    target.write_text("old")
    target.chmod(0o640)
    with pytest.raises(KeyboardInterrupt):
        with replacing(target) as name:
            assert name.endswith(".part.svg") and Path(name).parent == tmp_path
            Path(name).write_text("half")
            raise KeyboardInterrupt
    assert target.read_text() == "old" and [p.name for p in tmp_path.iterdir()] == ["plot.svg"]
    link = tmp_path / "link.svg"
    link.symlink_to(target)
    with replacing(link) as name:
        Path(name).write_text("new")
    assert link.is_symlink() and target.read_text() == "new" and target.stat().st_mode & 0o777 == 0o640
    assert sorted(p.name for p in tmp_path.iterdir()) == ["link.svg", "plot.svg"]


def test_replacing_writes_a_fifo_as_it_is(tmp_path):
    fifo = tmp_path / "plot.png"
    os.mkfifo(fifo)
    reader = subprocess.Popen(["cat", str(fifo)], stdout=subprocess.PIPE)
    with replacing(fifo) as name:
        assert name == str(fifo)
        Path(name).write_bytes(b"drawn")
    assert reader.communicate(timeout=30)[0] == b"drawn"
    assert fifo.is_fifo() and [p.name for p in tmp_path.iterdir()] == ["plot.png"]
