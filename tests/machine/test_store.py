"""The permanent store: values survive, batches are atomic, a killed writer leaves it consistent."""

from __future__ import annotations

import os
import signal
import sqlite3
import subprocess
import sys
import time

from ncvm.machine.store import Store

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


def test_writer_killed_at_any_moment_leaves_store_consistent(tmp_path):
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path))
    last_seen = 0
    for delay in (0.05, 0.11, 0.17, 0.23, 0.31, 0.37):
        proc = subprocess.Popen([sys.executable, "-c", WRITER, str(tmp_path)], stdout=subprocess.PIPE, text=True,
                                env=env)
        # wait for the writer to be running, then kill it without warning after `delay`
        first = proc.stdout.readline()
        assert first.strip().isdigit()
        time.sleep(delay)
        proc.send_signal(signal.SIGKILL)
        printed = [int(x) for x in [first, *proc.stdout.read().split()] if str(x).strip()]
        proc.wait()
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
