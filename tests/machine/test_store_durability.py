"""When a permanent write is safe (docs/decisions.md, "The permanent store: the durability point").

Every write reaches the operating system (SQLite's write-ahead log) before the statement returns, so a
killed ncvm loses none; the log is fsynced once SYNC_EVERY_S has passed since its last sync and when the
store is closed (the end of the run, an error stop, Ctrl-C, SIGTERM) -- not once a write.
"""

from __future__ import annotations

import os
import signal
import sqlite3
import subprocess
import sys
from pathlib import Path

import pytest

from ncvm.api import run
from ncvm.machine import store as store_module
from ncvm.machine.state import StateError
from ncvm.machine.store import Store
from ncvm.runtime.interrupt import Terminated
from ncvm.runtime.session import RunOptions
from tests.conftest import killed_after

ENV = dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path))


def committed(folder: Path, namespace: str, key: str):
    """The value another connection reads: what was committed, whatever this process still holds."""
    db = sqlite3.connect(folder / "store.sqlite")
    try:
        row = db.execute("SELECT value FROM permanent WHERE namespace=? AND key=?", (namespace, key)).fetchone()
    finally:
        db.close()
    return None if row is None else row[0]


@pytest.fixture
def clock(monkeypatch):
    """The store's monotonic clock, moved on by hand: ``clock.now += 1``."""

    class Clock:
        now = 1000.0

    monkeypatch.setattr(store_module, "monotonic", lambda: Clock.now)
    return Clock


@pytest.fixture
def fsyncs(monkeypatch):
    """The fsyncs of the test, each as the name of what was synced (a file or a folder)."""
    seen = []
    real = os.fsync

    def fsync(fd):
        seen.append(Path(os.readlink(f"/proc/self/fd/{fd}")).name)
        real(fd)

    monkeypatch.setattr(os, "fsync", fsync)
    return seen


def test_a_write_is_committed_to_the_log_without_a_sync_and_the_log_is_synced_once_a_second(tmp_path, clock,
                                                                                          fsyncs):
    s = Store(tmp_path)
    assert s._db.execute("PRAGMA journal_mode").fetchone()[0] == "wal"
    assert s._db.execute("PRAGMA synchronous").fetchone()[0] == 1  # NORMAL: SQLite syncs at checkpoints only
    for i in range(1, 201):
        s.put("cpl.perm", "@5", i)
        assert committed(tmp_path, "cpl.perm", "@5") == str(i)  # another process reads it at once
    assert fsyncs == []
    clock.now += 0.99
    s.put("cpl.perm", "@5", 201)
    assert fsyncs == []
    clock.now += 0.01
    s.put("cpl.perm", "@5", 202)  # a second since the store was opened: the log and, once, its folder
    assert fsyncs == ["store.sqlite-wal", tmp_path.name]
    s.put("cpl.perm", "@5", 203)
    clock.now += 0.5
    s.put("cpl.perm", "@5", 204)
    assert len(fsyncs) == 2
    clock.now += 0.5
    s.put("cpl.perm", "@5", 205)
    assert fsyncs[2:] == ["store.sqlite-wal"]
    s.close()  # nothing written since: nothing to sync
    assert len(fsyncs) == 3
    assert committed(tmp_path, "cpl.perm", "@5") == "205"


def test_close_syncs_what_was_written_since_the_last_sync_and_only_then(tmp_path, clock, fsyncs):
    s = Store(tmp_path)
    s.put("t", "a", 1)
    s.close()
    assert fsyncs == ["store.sqlite-wal", tmp_path.name]
    s = Store(tmp_path)
    assert s.get("t", "a") == 1 and s.dump() == {"t": {"a": 1}}
    s.close()  # only read
    assert len(fsyncs) == 2


def test_a_batch_is_one_write_to_sync(tmp_path, clock, fsyncs):
    s = Store(tmp_path)
    clock.now += 5
    with s.batch():
        for k in range(100):
            s.put("t", str(k), k)
        assert fsyncs == []  # not inside the transaction
    assert fsyncs == ["store.sqlite-wal", tmp_path.name]
    assert committed(tmp_path, "t", "99") == "99"
    s.close()
    assert len(fsyncs) == 2


def test_a_scratch_store_syncs_nothing(tmp_path, fsyncs):
    s = Store(tmp_path)
    s.put("t", "a", 1)
    s.close()
    del fsyncs[:]
    scratch = Store(tmp_path, scratch=True)
    scratch.put("t", "a", 2)
    scratch.close()
    assert fsyncs == [] and committed(tmp_path, "t", "a") == "1"


def test_without_a_write_ahead_log_every_commit_is_synced_by_sqlite(tmp_path, monkeypatch, fsyncs):
    """Where SQLite keeps no write-ahead log (it answers the request with the mode it stays in), NORMAL
    could tear a commit at a power cut: the store stays at FULL, a sync a commit, as before."""

    class NoLog(sqlite3.Connection):
        def execute(self, sql, *args):
            return super().execute("PRAGMA journal_mode" if sql == "PRAGMA journal_mode=WAL" else sql, *args)

    real = store_module.sqlite3.connect
    monkeypatch.setattr(store_module.sqlite3, "connect", lambda *a, **k: real(*a, factory=NoLog, **k))
    s = Store(tmp_path)
    assert s._db.execute("PRAGMA journal_mode").fetchone()[0] == "delete"
    assert s._db.execute("PRAGMA synchronous").fetchone()[0] == 2
    s.put("t", "a", 1)
    s.close()
    assert fsyncs == [] and committed(tmp_path, "t", "a") == "1"


def test_a_failing_sync_is_a_state_error_and_the_store_is_closed(tmp_path, clock, monkeypatch):
    s = Store(tmp_path)
    s.put("t", "a", 1)

    def broken(fd):
        raise OSError(5, "Input/output error")

    monkeypatch.setattr(os, "fsync", broken)
    with pytest.raises(StateError) as e:
        s.close()
    assert str(e.value) == (f"the permanent store {tmp_path / 'store.sqlite'} cannot be synced to the disk "
                            f"(Input/output error); the writes of the last second may be lost at a power cut; "
                            f"check the disk, or give another --state")
    assert s._db is None
    assert committed(tmp_path, "t", "a") == "1"


# -- the run: its end, an error stop, Ctrl-C and SIGTERM close the store, so its log is synced ------------------


COUNT = """\
10 @5 = 0
20 FOR I%=1 TO 50
30 @5 = @5 + 1
40 NEXT I%
M30
"""


def run_cpl(tmp_path: Path, text: str, **options):
    prog = tmp_path / "prog.cpl"
    prog.write_text(text)
    return run(prog, options=RunOptions(state_dir=tmp_path / "st", **options))


def synced_at_close(fsyncs: list) -> None:
    """The clock stood still: the only sync was the store's close, the log and its folder."""
    assert fsyncs == ["store.sqlite-wal", "st"]


def test_the_end_of_a_run_syncs_every_write_it_made(tmp_path, clock, fsyncs):
    result, _ = run_cpl(tmp_path, COUNT)
    assert result["status"] == "ok"
    synced_at_close(fsyncs)
    assert committed(tmp_path / "st", "cpl.perm", "@5") == "50"


def test_an_error_stop_syncs_the_writes_before_it(tmp_path, clock, fsyncs):
    result, _ = run_cpl(tmp_path, "10 @5 = 7\n20 @_R(101) = 1\nM30\n")
    assert result["status"] == "error" and result["error"]["code"] == "CPL031"
    synced_at_close(fsyncs)
    assert committed(tmp_path / "st", "cpl.perm", "@5") == "7"


def stop_at_pass(n: int, stop: BaseException):
    """A step hook that raises ``stop`` before the write of pass ``n + 1`` (file line 3): ``n`` writes made."""

    def hook(file, line, variables):
        if line == 3 and variables.get("I%") == n + 1:
            raise stop

    return hook


def test_ctrl_c_syncs_the_writes_before_it(tmp_path, clock, fsyncs):
    result, _ = run_cpl(tmp_path, COUNT, hook=stop_at_pass(20, KeyboardInterrupt()))
    assert result["status"] == "error" and result["error"]["code"] == "RUN004"
    synced_at_close(fsyncs)
    assert committed(tmp_path / "st", "cpl.perm", "@5") == "20"


def test_sigterm_syncs_the_writes_before_it(tmp_path, clock, fsyncs):
    with pytest.raises(Terminated):
        run_cpl(tmp_path, COUNT, hook=stop_at_pass(30, Terminated(signal.SIGTERM)))
    synced_at_close(fsyncs)
    assert committed(tmp_path / "st", "cpl.perm", "@5") == "30"


# -- real processes -----------------------------------------------------------------------------------------------


KILLED = """\
10 FOR I%=1 TO 100000000
20 @5 = I%
30 @_R(1) = I% * 0.5
40 PRN#(0,"WROTE ",I%)
50 NEXT I%
M30
"""


def test_a_run_killed_with_sigkill_keeps_every_write_it_said_it_made(tmp_path):
    """``ncvm run`` as a process writes two permanent variables a pass and says so after both; SIGKILL after
    the 300th pass (long before a second's sync): the store holds every write it said, and nothing torn."""
    (tmp_path / "prog.cpl").write_text(KILLED)
    p = subprocess.Popen([sys.executable, "-m", "ncvm", "run", "prog.cpl", "--state", "st"], cwd=tmp_path,
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=ENV)
    said, err = killed_after(p, 300, lambda line, _: int(line.split()[-1]))
    assert said == 300 and p.returncode == -signal.SIGKILL, err
    db = sqlite3.connect(tmp_path / "st" / "store.sqlite")
    assert db.execute("PRAGMA integrity_check").fetchone()[0] == "ok"
    db.close()
    s = Store(tmp_path / "st")
    n, r = s.get("cpl.perm", "@5"), s.get("cpl.perm", "@_R(1)")
    s.close()
    assert n >= said  # the run went on while the test read
    assert r in (n * 0.5, (n - 1) * 0.5)  # killed between the two writes of a pass, or after both


@pytest.mark.parametrize("signum", [signal.SIGINT, signal.SIGTERM])
def test_a_run_stopped_by_ctrl_c_or_sigterm_closes_its_store(tmp_path, signum):
    """Ctrl-C and SIGTERM end the run as an error stop does: the store is closed (its log synced, then folded
    into the store by SQLite: no log is left), every write kept."""
    (tmp_path / "prog.cpl").write_text(KILLED)
    p = subprocess.Popen([sys.executable, "-m", "ncvm", "run", "prog.cpl", "--state", "st"], cwd=tmp_path,
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=ENV)
    try:
        for line in p.stdout:
            if line.split()[-1] == "300":
                break
        p.send_signal(signum)
        out, err = p.communicate(timeout=60)
    finally:
        p.kill()
    assert p.returncode not in (0, -signum) and "Traceback" not in err, err
    said = int(out.splitlines()[-1].split()[-1]) if out.strip() else 300
    assert not (tmp_path / "st" / "store.sqlite-wal").exists()
    s = Store(tmp_path / "st")
    n, r = s.get("cpl.perm", "@5"), s.get("cpl.perm", "@_R(1)")
    s.close()
    assert n in (said, said + 1)  # stopped between a pass's writes and the line that says so, or after it
    assert r in (n * 0.5, (n - 1) * 0.5)


WRITER = """
import sys
from ncvm.machine.store import Store
s = Store(sys.argv[1])
for i in range(1, 301):
    s.put("t", f"{sys.argv[2]}{i}", i)
s.close()
"""


def test_two_processes_writing_one_store_at_once_keep_every_write(tmp_path):
    """Two processes (not runs: a run locks its state directory) write 300 keys each into one store at the
    same time: with commits no longer synced one by one they interleave, and every write is kept."""
    writers = [subprocess.Popen([sys.executable, "-c", WRITER, str(tmp_path), name], env=ENV, text=True,
                                stderr=subprocess.PIPE) for name in ("a", "b")]
    for w in writers:
        _, err = w.communicate(timeout=120)
        assert w.returncode == 0, err
    s = Store(tmp_path)
    assert s.items("t") == {f"{name}{i}": i for name in ("a", "b") for i in range(1, 301)}
    s.close()
