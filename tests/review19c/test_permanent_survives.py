"""Review 19c: does permanent data survive? The defects found, one failing test each.

A maintenance engineer's view of today's durability work (the permanent store's WAL and sync budget, SINUMERIK
central R and NC data written through, the CPL file's directory fsync). What held is in the review's report;
what did not is here.

A signal's exception (Ctrl-C's KeyboardInterrupt, SIGTERM's Terminated) is raised by its handler at the first
bytecode after the SQLite call that was running when it came. The tests put it exactly there, right after
``BEGIN IMMEDIATE`` returned, by wrapping the store's connection: the same moment a real signal hit 2 times in
25 SIGTERMs sent at random moments to a SINUMERIK program writing tool and zero offsets in a loop (exit 2,
"cannot start a transaction within a transaction; check the disk").
"""

from __future__ import annotations

import json
import os
import signal
import sqlite3
import subprocess
import sys
import time
from pathlib import Path

import ncvm.machine.store as store_module
from ncvm.api import run
from ncvm.machine.state import StateError
from ncvm.machine.store import Store
from ncvm.runtime.session import RunOptions

ROOT = Path(__file__).resolve().parents[2]

# ZOPS loads a PRESET offset (it takes effect, and is stored, at the end or the reset after a stop), R900 is
# written through, the TOS write at N30 is an NC data write: one store transaction (Store.batch)
NC_DATA_PROGRAM = """%MPF9400
N10 @435 K1 K4
N20 R900=7
N30 @420 K0 K1 K5 K7.5
N40 M30
"""


class _Connection:
    """A SQLite connection whose first ``BEGIN IMMEDIATE`` meets a signal: ``after`` False, just before the
    statement; True, just after it returned (the transaction open)."""

    def __init__(self, db: sqlite3.Connection, after: bool, signal_it):
        self._db, self._after, self._signal, self._armed = db, after, signal_it, True

    def execute(self, sql: str, *args):
        hit = self._armed and sql == "BEGIN IMMEDIATE"
        if hit:
            self._armed = False
            if not self._after:
                self._signal()
        cursor = self._db.execute(sql, *args)
        if hit:
            self._signal()
        return cursor

    def __getattr__(self, name: str):
        return getattr(self._db, name)


class _Sqlite:
    """The ``sqlite3`` module as the store sees it: the first connection opened is wrapped."""

    def __init__(self, after: bool, signal_it):
        self._after, self._signal, self._opened = after, signal_it, 0

    def connect(self, *args, **kwargs):
        db = sqlite3.connect(*args, **kwargs)
        self._opened += 1
        return _Connection(db, self._after, self._signal) if self._opened == 1 else db

    def __getattr__(self, name: str):
        return getattr(sqlite3, name)


def _interrupt():
    raise KeyboardInterrupt


def _dump(state: Path) -> dict:
    with Store(state) as store:
        return store.dump()


def test_store_batch_interrupted_right_after_begin_leaves_no_open_transaction(tmp_path):
    """A Ctrl-C (or SIGTERM) raised just after ``BEGIN IMMEDIATE`` returned must roll the transaction back like
    one raised inside the batch: the store stays usable and later writes are committed. ``Store.batch`` runs
    BEGIN outside its ``try``: the transaction stays open, the next batch fails with "cannot start a
    transaction within a transaction" (a StateError saying "check the disk") and a plain ``put`` meanwhile
    joins the open transaction and is rolled back at close: a write the program made, silently lost."""
    store = Store(tmp_path)
    store.put("ns", "a", 1)
    store._db = _Connection(store._db, after=True, signal_it=_interrupt)
    try:
        with store.batch():
            store.put("ns", "a", 2)
    except KeyboardInterrupt:
        pass
    store.put("ns", "b", 3)  # after the stop: e.g. what the end of the run writes
    try:
        with store.batch():
            store.put("ns", "c", 4)
    except StateError as e:
        raise AssertionError(f"the store was left in the interrupted transaction: {e}") from None
    store._db = store._db._db
    store.close()
    assert _dump(tmp_path) == {"ns": {"a": 1, "b": 3, "c": 4}}


def _run_interrupted(folder: Path, after: bool, monkeypatch):
    folder.mkdir()
    program = folder / "nc.mpf"
    program.write_text(NC_DATA_PROGRAM)
    monkeypatch.setattr(store_module, "sqlite3", _Sqlite(after, _interrupt))
    try:
        result, _ = run(program, dialect="sin800", options=RunOptions(state_dir=folder / "st"))
        outcome = (result["status"], result["error"]["code"] if result["error"] else None)
    except StateError as e:
        outcome = ("StateError", str(e))
    monkeypatch.undo()
    return outcome, _dump(folder / "st")


def test_sin800_ctrl_c_during_an_nc_data_write_stops_as_run004_with_the_store_of_any_ctrl_c(tmp_path, monkeypatch):
    """docs/decisions.md, "SINUMERIK: NC data and central R written through": a run stopped with Ctrl-C leaves
    the store as before (the end of the run writes what the stop caught on its way, and the PRESET offsets
    ZOPS loaded). A Ctrl-C a moment later, while the TOS write's transaction begins, must end the same way:
    RUN004 and the same store. It raised a StateError out of the run ("cannot start a transaction within a
    transaction; check the disk", exit 2 at the command line) and the end of the run's writes were lost."""
    before = _run_interrupted(tmp_path / "before", after=False, monkeypatch=monkeypatch)
    assert before[0] == ("error", "RUN004")
    assert before[1]["sin800"]["zo"]["PRESET"][0] == 4.0
    during = _run_interrupted(tmp_path / "during", after=True, monkeypatch=monkeypatch)
    assert during == before


# a real process with the real SIGTERM handler: the signal is sent to itself right after BEGIN IMMEDIATE
_DRIVER = """
import os, signal, sys, runpy
sys.path.insert(0, {tests!r})
import ncvm.machine.store as store_module
from review19c.test_permanent_survives import _Sqlite
store_module.sqlite3 = _Sqlite({after!r}, lambda: os.kill(os.getpid(), signal.SIGTERM))
sys.argv = ["ncvm", "run", "nc.mpf", "-d", "sin800", "--state", "st"]
runpy.run_module("ncvm", run_name="__main__")
"""


def _terminated(folder: Path, after: bool):
    folder.mkdir()
    (folder / "nc.mpf").write_text(NC_DATA_PROGRAM)
    driver = _DRIVER.format(tests=str(ROOT / "tests"), after=after)
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(ROOT / "src"), os.environ.get("PYTHONPATH", "")]))
    done = subprocess.run([sys.executable, "-c", driver], cwd=folder, capture_output=True, text=True, timeout=120,
                          env=env)
    return done.returncode, done.stderr, _dump(folder / "st")


def test_sin800_sigterm_during_an_nc_data_write_ends_with_run009_and_keeps_the_store(tmp_path):
    """`ncvm run --help`: "128 + the signal stopped by SIGTERM" (RUN009), and the store as SIGTERM leaves it
    anywhere else. A SIGTERM that lands while an NC data write's transaction begins ended with exit 2, "the
    permanent store ... cannot be used (cannot start a transaction within a transaction); check the disk":
    a supervisor's stop told as a disk fault, and the end of the run's writes (the PRESET offsets) lost."""
    code, err, store = _terminated(tmp_path / "before", after=False)
    assert code == 128 + signal.SIGTERM, err
    code_during, err_during, store_during = _terminated(tmp_path / "during", after=True)
    assert "check the disk" not in err_during
    assert code_during == 128 + signal.SIGTERM, err_during
    assert store_during == store


# --- decode-ahead: a G58 block behind a block that faults when it executes ---------------------------------

MACHINE_DECODE_AHEAD = """
[machine]
name = "880 with decode-ahead"
[[axis]]
name = "X"
min = -300.0
max = 300.0
[[axis]]
name = "Y"
min = -200.0
max = 200.0
[[axis]]
name = "Z"
min = -150.0
max = 300.0
[sin800]
control = "880"
decode_ahead = {n}
"""

# N20 faults when it executes (NC014: a thread with the spindle standing); N30 sets the programmable offset G58
G58_BEHIND_A_FAULT = """%MPF9401
N10 G0 X0 Y0 Z50
N20 G33 Z10 K2
N30 G58 X10 Y5
N40 M30
"""


def _stored_after(tmp_path: Path, decode_ahead: int) -> tuple[str, dict]:
    folder = tmp_path / f"da{decode_ahead}"
    folder.mkdir()
    (folder / "machine.toml").write_text(MACHINE_DECODE_AHEAD.format(n=decode_ahead))
    (folder / "g58.mpf").write_text(G58_BEHIND_A_FAULT)
    result, _ = run(folder / "g58.mpf", dialect="sin800", machine=folder / "machine.toml",
                    options=RunOptions(state_dir=folder / "st"))
    return result["error"]["code"], _dump(folder / "st")


def test_decode_ahead_g58_block_behind_a_faulting_block_is_not_stored(tmp_path):
    """docs/sin800.md, "Decode-ahead and STOP DEC": a zero-offset block first executes the blocks decoded
    before it, and "when a fault stops the run, blocks still in the buffer are not executed". N20 faults when
    it executes, so the control never executes N30's G58: the store must not keep G58 X10 Y5, as a lockstep
    run (decode_ahead = 0) keeps none. With decode_ahead = 4 the G58 words are put into the NC data before the
    buffer runs (``Offsets.programmable_zo`` changes the live vector, then ``_changed`` runs the buffer, which
    faults) and the end of the run stores them: a decoded-ahead block persists a zero offset the control
    never reached, and the next run starts from it ("G58 X10 kept from an earlier run")."""
    lockstep = _stored_after(tmp_path, 0)
    assert lockstep == ("NC014", {})
    assert _stored_after(tmp_path, 4) == lockstep


# --- two runs at once: a batch on a state directory another run holds ---------------------------------------

# counts in a permanent variable for a long time: another run holding the state directory, writing all along
COUNTER = """(COUNTER - a permanent count, written 10,000 times a second)
10 IF @1 = NUL THEN @1 = 0 ENDIF
20 FOR I% = 1 TO 5000000
30 @1 = @1 + 1
40 NEXT I%
M30
"""

QUIET = """(QUIET - writes nothing permanent)
10 A% = 1
M30
"""


def _stored_count(state: Path) -> int | None:
    try:
        db = sqlite3.connect(f"file:{state / 'store.sqlite'}?mode=ro", uri=True)
        try:
            row = db.execute("SELECT value FROM permanent WHERE key='@1'").fetchone()
        finally:
            db.close()
    except sqlite3.Error:
        return None
    return None if row is None else int(row[0])


def test_shared_state_batch_program_refused_by_another_run_reports_no_permanent_writes(tmp_path):
    """docs/batch.md / `ncvm run --help` ("--shared-state: ... its permanent writes stay"; the summary: "the
    report lists each write"): a program refused with RUN007 because another run holds the state directory
    never ran (0 steps), so it wrote nothing. The batch compares the store before and after the program
    outside the run's lock, and reports the other run's writes as this program's ("QUIET ... wrote cpl.perm
    @1 = 95479"; the summary "2 program(s) wrote permanent data"): a report that is silently wrong about who
    changed the permanent memory."""
    state = tmp_path / "st"
    (tmp_path / "counter.cpl").write_text(COUNTER)
    batch = tmp_path / "batch"
    batch.mkdir()
    for n in range(5):
        (batch / f"quiet{n}.cpl").write_text(QUIET)
    writer = subprocess.Popen([sys.executable, "-m", "ncvm", "run", "counter.cpl", "--state", str(state)],
                              cwd=tmp_path, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        for _ in range(600):  # until it writes (at most a minute on a busy machine)
            if (_stored_count(state) or 0) > 0:
                break
            if writer.poll() is not None:
                break
            time.sleep(0.1)
        assert writer.poll() is None and (_stored_count(state) or 0) > 0, "the counting run did not start"
        done = subprocess.run([sys.executable, "-m", "ncvm", "run", "batch", "--shared-state", "-j", "1",
                               "--state", str(state), "--report", "report.json"],
                              cwd=tmp_path, capture_output=True, text=True, timeout=300)
        still_writing = writer.poll() is None
    finally:
        writer.kill()
        writer.wait()
    assert still_writing, "the counting run ended before the batch did"
    programs = json.loads((tmp_path / "report.json").read_text())["programs"]
    assert [p["error"]["code"] for p in programs] == ["RUN007"] * 5, done.stderr
    assert [p["permanent_writes"]["store"] for p in programs] == [[]] * 5
