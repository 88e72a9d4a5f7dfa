"""The permanent store: values survive, batches are atomic, a killed writer leaves it consistent."""

from __future__ import annotations

import os
import sqlite3

import pytest

from ncvm.machine import store as store_module
from ncvm.machine.state import StateError
from ncvm.machine.store import SCHEMA, Store

WRITER = """
import sys
from ncvm.machine.store import Store
s = Store(sys.argv[1])
i = s.get("t", "a", 0)
while True:
    i += 1
    with s.batch():
        s.put("t", "a", i)
        s.put("t", "pad", "x" * 5000)   # make each transaction span several pages
        s.put("t", "b", i)
    s.put("t", "c", i)
    print(i, flush=True)                 # printed only once both transactions committed
"""


def test_values_persist_across_opens(tmp_path):
    s = Store(tmp_path)
    s.put("cpl", "@1", 42)
    s.put("cpl", "A$", "text")
    s.put("sin800", "R900", 1.5)
    s.close()
    s = Store(tmp_path)
    assert s.items("cpl") == {"@1": 42, "A$": "text"}
    assert s.get("sin800", "R900") == 1.5 and s.get("sin800", "R901", "none") == "none"
    s.delete("cpl", "@1")
    assert s.items("cpl") == {"A$": "text"}
    s.delete("cpl")
    assert s.items("cpl") == {}


def test_failed_batch_rolls_back(tmp_path):
    s = Store(tmp_path)
    s.put("t", "a", 1)
    try:
        with s.batch():
            s.put("t", "a", 2)
            raise ValueError("power failure in the middle")
    except ValueError:
        pass
    assert s.get("t", "a") == 1


def test_writer_killed_at_any_moment_leaves_store_consistent(tmp_path, killed_writer):
    last_seen = 0
    for delay in (0.02, 0.05, 0.09, 0.13, 0.19, 0.25):
        printed = killed_writer(WRITER, delay)
        db = sqlite3.connect(tmp_path / "store.sqlite")
        assert db.execute("PRAGMA integrity_check").fetchone()[0] == "ok"
        db.close()
        s = Store(tmp_path)
        a, b, c = s.get("t", "a"), s.get("t", "b"), s.get("t", "c")
        s.close()
        assert a == b, "a batch was torn by the kill"
        assert c in (a, a - 1), "the single write after the batch is either there or not"
        assert a >= max(printed), "a value reported as committed was lost"
        assert a > last_seen, "the writer made progress and nothing went backwards"
        last_seen = a


# -- a store ncvm cannot use: a clear StateError naming the file and what to do ------------------------------

def filled_store(folder, keys: int = 300) -> None:
    s = Store(folder)
    with s.batch():
        for k in range(keys):
            s.put("cpl.perm", f"@{k}", "x" * 200)
    s.close()


def test_a_file_that_is_no_database_is_refused_and_left_alone(tmp_path):
    png = b"\x89PNG\r\n\x1a\n" + bytes(range(256)) * 8
    (tmp_path / "store.sqlite").write_bytes(png)
    with pytest.raises(StateError) as e:
        Store(tmp_path)
    assert str(e.value) == (f"{tmp_path / 'store.sqlite'} is not an ncvm permanent store (not a SQLite database); "
                            f"move it away or give another --state")
    assert (tmp_path / "store.sqlite").read_bytes() == png


def test_a_database_of_another_program_is_refused_and_left_alone(tmp_path):
    db = sqlite3.connect(tmp_path / "store.sqlite")
    db.execute("CREATE TABLE invoices (id INTEGER, amount REAL)")
    db.commit()
    db.close()
    before = (tmp_path / "store.sqlite").read_bytes()
    with pytest.raises(StateError, match=r"store.sqlite is not an ncvm permanent store \(it holds the tables "
                                         r"invoices\); move it away or give another --state"):
        Store(tmp_path)
    assert (tmp_path / "store.sqlite").read_bytes() == before  # not converted to WAL, no table added
    assert not (tmp_path / "store.sqlite-wal").exists()


def test_a_truncated_store_is_refused_as_damaged(tmp_path):
    filled_store(tmp_path)
    path = tmp_path / "store.sqlite"
    os.truncate(path, path.stat().st_size // 2)
    with pytest.raises(StateError, match=rf"^the permanent store {path} is damaged \(.+\); move it away to start "
                                         r"again from the machine file, or give another --state$"):
        Store(tmp_path)


def test_a_store_of_an_earlier_ncvm_is_kept(tmp_path):
    db = sqlite3.connect(tmp_path / "store.sqlite")
    db.executescript(SCHEMA + "INSERT INTO permanent VALUES ('cpl.perm', '@5', '12000');")
    db.close()
    s = Store(tmp_path)
    assert s.get("cpl.perm", "@5") == 12000
    s.close()


def test_a_store_another_program_keeps_locked_is_refused_after_a_short_wait(tmp_path, monkeypatch):
    Store(tmp_path).close()
    shell = sqlite3.connect(tmp_path / "store.sqlite", isolation_level=None)
    shell.execute("BEGIN EXCLUSIVE")
    monkeypatch.setattr(store_module, "BUSY_TIMEOUT_S", 0.2)
    s = Store(tmp_path)  # reading goes on (WAL): the write waits BUSY_TIMEOUT_S, then gives up
    assert s._db.execute("PRAGMA busy_timeout").fetchone()[0] == 200  # ms: the wait is bounded, not endless
    with pytest.raises(StateError, match=f"the permanent store {tmp_path / 'store.sqlite'} is locked by another "
                                         "program; close the program that has it open"):
        s.put("cpl.perm", "@5", 1)
    shell.close()
    s.put("cpl.perm", "@5", 2)  # the same store goes on once the other program has let go
    assert s.get("cpl.perm", "@5") == 2
    s.close()


def test_a_full_store_says_so_and_keeps_what_was_written_before(tmp_path):
    s = Store(tmp_path)
    s.put("cpl.perm", "@5", 7)
    pages = s._db.execute("PRAGMA page_count").fetchone()[0]
    s._db.execute(f"PRAGMA max_page_count = {pages}")  # the file may not grow: as on a full disk
    with pytest.raises(StateError, match=f"cannot write the permanent store {tmp_path / 'store.sqlite'}: the disk is "
                                         "full; free some space and run again"):
        with s.batch():
            s.put("cpl.perm", "@5", 8)
            s.put("cpl.perm", "@6", "x" * 100_000)
    with pytest.raises(StateError, match="the disk is full"):
        s.put("cpl.perm", "@7", "x" * 100_000)
    assert s.get("cpl.perm", "@5") == 7 and s.get("cpl.perm", "@6") is None
    s.close()
