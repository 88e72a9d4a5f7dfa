"""Central R900-R999 and NC data are in the store as the program writes them (docs/decisions.md, "SINUMERIK:
NC data and central R written through"): a run killed at any moment keeps every write it made; a run that
ends, faults or is stopped leaves the store as the end-of-run batch used to."""

from __future__ import annotations

import json
import os
import signal
import sqlite3
import subprocess
import sys
from pathlib import Path

import pytest
from sin800_helpers import MACHINE, R, run_mpf

from ncvm.machine.store import Store
from tests.conftest import killed_after

ENV = dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path))


def committed(state: Path) -> dict:
    """What another connection reads of the namespace sin800: what was committed, whatever the run holds."""
    db = sqlite3.connect(state / "store.sqlite")
    try:
        rows = db.execute("SELECT key, value FROM permanent WHERE namespace='sin800'").fetchall()
    finally:
        db.close()
    return {k: json.loads(v) for k, v in rows}


def stored(state: Path) -> dict:
    with Store(state) as s:
        return s.items("sin800")


# -- in the store before the next statement ------------------------------------------------------------------------


def watch(state: Path, seen: list):
    """A step hook that notes, before every block, the block's line and the central R committed."""

    def hook(file, line, variables):
        if (state / "store.sqlite").exists():
            seen.append((line, committed(state).get("central_r")))

    return hook


@pytest.mark.parametrize("extra", ["", "decode_ahead = 3\n"])
def test_a_store_into_a_central_r_is_committed_before_the_next_block(tmp_path, extra):
    """By name, through a pointer, by an exchange and by a read of NC data into it; a local R is not written."""
    from ncvm.api import run
    from ncvm.runtime.session import RunOptions

    (tmp_path / "machine.toml").write_text(MACHINE + extra)
    (tmp_path / "p.mpf").write_text("%MPF1\nR900=1 R5=910 R6=2\nG0 X1\n@201 P5 K7\n@202 R900 R6\n"
                                    "@400 K2240 K1500 @300 R920 K2240\nR7=3\nM30\n")
    seen: list = []
    state = tmp_path / "st"
    result, _ = run(tmp_path / "p.mpf", dialect="sin800", machine=tmp_path / "machine.toml",
                    options=RunOptions(state_dir=state, hook=watch(state, seen)))
    assert result["status"] == "ok", result["error"]
    assert seen == [(2, None), (3, {"900": 1.0}), (4, {"900": 1.0}), (5, {"900": 1.0, "910": 7.0}),
                    (6, {"900": 2.0, "910": 7.0}), (7, {"900": 2.0, "910": 7.0, "920": 1500.0}),
                    (8, {"900": 2.0, "910": 7.0, "920": 1500.0})]


def test_nc_data_are_committed_by_the_statement_that_writes_them(tmp_path):
    seen = []
    state = tmp_path / "st"

    def hook(file, line, variables):
        if (state / "store.sqlite").exists():
            data = committed(state)
            seen.append((line, data.get("to", {}).get("0:1", [0.0] * 3)[2], data.get("zo", {}).get("G54.coarse"),
                         data.get("nc_md"), (data.get("mib") or [0.0] * 6)[5]))

    from ncvm.api import run
    from ncvm.runtime.session import RunOptions

    (tmp_path / "machine.toml").write_text(MACHINE)
    (tmp_path / "p.mpf").write_text("%MPF1\n@420 K0 K1 K2 K30\n@430 K1 K1 K0 K10\n@400 K2240 K1500\n@212 K5 K7\n"
                                    "G0 X1\nM30\n")
    result, _ = run(tmp_path / "p.mpf", dialect="sin800", machine=tmp_path / "machine.toml",
                    options=RunOptions(state_dir=state, hook=hook))
    assert result["status"] == "ok", result["error"]
    assert seen == [(2, 0.0, None, None, 0.0), (3, 30.0, None, None, 0.0), (4, 30.0, [10.0, 0.0, 0.0], None, 0.0),
                    (5, 30.0, [10.0, 0.0, 0.0], {"2240": 1500.0}, 0.0),
                    (6, 30.0, [10.0, 0.0, 0.0], {"2240": 1500.0}, 7.0), (7, 30.0, [10.0, 0.0, 0.0], {"2240": 1500.0}, 7.0)]


# -- the store as the end of the run left it -------------------------------------------------------------------------


def test_a_central_r_written_and_cleared_leaves_no_entry(tmp_path):
    """The store's entry is what the end of the run would write at each moment: a central R set and cleared
    again by a run that started without one leaves the store without the key, as before."""
    r = run_mpf(tmp_path, "%MPF1\nR931=5\nR931=0\nM30\n", ok=True)
    assert R(r, 931) == 0.0 and stored(tmp_path / ".ncvm") == {}


def test_a_central_r_set_back_to_the_value_an_earlier_run_left_keeps_the_entry_as_it_was(tmp_path):
    run_mpf(tmp_path, "%MPF1\nR931=5\nM30\n", ok=True)
    run_mpf(tmp_path, "%MPF1\nR931=6 R932=1\nR931=5 R932=0\nM30\n", ok=True)
    assert stored(tmp_path / ".ncvm") == {"central_r": {"931": 5.0}}


def test_a_faulting_run_keeps_what_it_wrote_before_the_fault(tmp_path):
    r = run_mpf(tmp_path, "%MPF1\nR930=3 @420 K0 K1 K2 K30\nR1=0 R2=1/R1\nR931=4\nM30\n")
    assert r["error"]["code"] == "CL800"
    assert stored(tmp_path / ".ncvm") == {"central_r": {"930": 3.0}, "to": {"0:1": [0.0, 0.0, 30.0] + [0.0] * 13}}


def test_strict_nc_rounding_of_a_power_on_value_is_kept_at_the_end_as_before(tmp_path):
    """A central R the power-on rounds (strict_nc) differs from the machine file's value: the end of the run
    writes it, though the program never stored into it."""
    run_mpf(tmp_path, "%MPF1\nR1=1\nM30\n", "strict_nc = true\nr = { R960 = 1.123456789 }\n", ok=True)
    assert stored(tmp_path / ".ncvm") == {"central_r": {"960": 1.1234568}}


def test_preset_offsets_loaded_take_effect_and_are_kept_at_the_end(tmp_path):
    run_mpf(tmp_path, "%MPF1\n@435 K1 K6\nG0 X2\nM30\n", ok=True)
    assert stored(tmp_path / ".ncvm") == {"zo": {"PRESET": [6.0, 0.0, 0.0]}}


def test_ctrl_c_keeps_the_writes_before_it(tmp_path):
    from ncvm.api import run
    from ncvm.runtime.session import RunOptions

    def hook(file, line, variables):
        if variables.get("R900") == 20.0 and line == 3:
            raise KeyboardInterrupt

    (tmp_path / "p.mpf").write_text(COUNT)
    result, _ = run(tmp_path / "p.mpf", dialect="sin800", options=RunOptions(state_dir=tmp_path / "st", hook=hook))
    assert result["error"]["code"] == "RUN004"
    assert stored(tmp_path / "st") == {"central_r": {"900": 20.0}}


COUNT = "%MPF1\nN10 R1=0\nN20 @135 R1 K50 K30\nR900=R900+1\n@620 R1 @100 K-20\nN30 M30\n"


# -- real processes -----------------------------------------------------------------------------------------------


KILLED = """\
%MPF1
N10 R1=0
N20 @135 R1 K99999999 K30
R900=R900+1 R901=R900*0.5 @420 K0 K1 K2 R900 @430 K1 K1 K0 R900
(MSG WROTE)
@620 R1 @100 K-20
N30 M30
"""


def start(tmp_path: Path, extra: str = "") -> subprocess.Popen:
    (tmp_path / "machine.toml").write_text(MACHINE + extra)
    (tmp_path / "prog.mpf").write_text(KILLED)
    return subprocess.Popen([sys.executable, "-m", "ncvm", "run", "prog.mpf", "--machine", "machine.toml", "--state",
                             "st", "--max-steps", "100000000"], cwd=tmp_path, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True, env=ENV)


def said_after(p: subprocess.Popen, count: int) -> int:
    """Reads the program's messages until ``count`` of them: each says a pass wrote."""
    said = 0
    for line in p.stdout:
        said += line.strip() == "WROTE"
        if said == count:
            break
    return said


@pytest.mark.parametrize("extra", ["", "decode_ahead = 3\n"])
def test_a_run_killed_with_sigkill_keeps_every_write_it_said_it_made(tmp_path, extra):
    """``ncvm run`` as a process writes two central R, a tool offset and a zero offset a pass and says so in
    the next block; SIGKILL after the 300th message: the store holds every write it said, nothing torn."""
    p = start(tmp_path, extra)
    said, err = killed_after(p, 300, lambda line, so_far: so_far + (line.strip() == "WROTE"))
    assert said == 300 and p.returncode == -signal.SIGKILL, err
    db = sqlite3.connect(tmp_path / "st" / "store.sqlite")
    assert db.execute("PRAGMA integrity_check").fetchone()[0] == "ok"
    db.close()
    data = stored(tmp_path / "st")
    n = data["central_r"]["900"]
    assert n >= said  # the run went on while the test read
    assert data["central_r"]["901"] in (n * 0.5, (n - 1) * 0.5)  # killed between two writes of a pass, or not
    assert data["to"]["0:1"][2] in (n, n - 1) and data["zo"]["G54.coarse"][0] in (n, n - 1)


@pytest.mark.parametrize("signum", [signal.SIGINT, signal.SIGTERM])
def test_a_run_stopped_by_ctrl_c_or_sigterm_keeps_every_write(tmp_path, signum):
    p = start(tmp_path)
    try:
        said_after(p, 300)
        p.send_signal(signum)
        out = p.stdout.read()  # (through the reader's buffer: communicate would skip what it read ahead)
        err = p.stderr.read()
        p.wait(timeout=60)
    finally:
        p.kill()
    assert p.returncode not in (0, -signum) and "Traceback" not in err, err
    said = 300 + out.split().count("WROTE")
    assert not (tmp_path / "st" / "store.sqlite-wal").exists()
    data = stored(tmp_path / "st")
    n = data["central_r"]["900"]
    assert n in (said, said + 1)  # stopped between a pass's writes and its message, or after it
    assert data["central_r"]["901"] in (n * 0.5, (n - 1) * 0.5)
    assert data["to"]["0:1"][2] in (n, n - 1) and data["zo"]["G54.coarse"][0] in (n, n - 1)
