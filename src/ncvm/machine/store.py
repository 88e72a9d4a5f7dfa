"""The permanent store: what a control keeps across power-off, in SQLite (WAL).

CPL permanent variables, central R parameters, offsets and machine data changed
by programs all go here, as (namespace, key) -> JSON value. Every write is its
own transaction unless the caller groups writes with :meth:`Store.batch`; with
WAL and ``synchronous=FULL`` a process killed at any moment leaves the last
committed value of every key, never a torn one.
"""

from __future__ import annotations

import json
import sqlite3
from contextlib import contextmanager
from pathlib import Path
from typing import Any, Iterator

SCHEMA = """
CREATE TABLE IF NOT EXISTS permanent (
    namespace TEXT NOT NULL,
    key       TEXT NOT NULL,
    value     TEXT NOT NULL,
    PRIMARY KEY (namespace, key)
) WITHOUT ROWID;
"""


class Store:
    """A namespaced key/value store in ``<state_dir>/store.sqlite``."""

    def __init__(self, state_dir: str | Path):
        self.path = Path(state_dir) / "store.sqlite"
        self.path.parent.mkdir(parents=True, exist_ok=True)
        self._db = sqlite3.connect(self.path, isolation_level=None, timeout=30.0)
        self._db.execute("PRAGMA journal_mode=WAL")
        self._db.execute("PRAGMA synchronous=FULL")
        self._db.executescript(SCHEMA)
        self._in_batch = False

    def get(self, namespace: str, key: str, default: Any = None) -> Any:
        row = self._db.execute("SELECT value FROM permanent WHERE namespace=? AND key=?", (namespace, key)).fetchone()
        return default if row is None else json.loads(row[0])

    def items(self, namespace: str) -> dict[str, Any]:
        rows = self._db.execute("SELECT key, value FROM permanent WHERE namespace=?", (namespace,))
        return {k: json.loads(v) for k, v in rows}

    def put(self, namespace: str, key: str, value: Any) -> None:
        self._db.execute("INSERT OR REPLACE INTO permanent(namespace, key, value) VALUES (?,?,?)",
                         (namespace, key, json.dumps(value)))

    def delete(self, namespace: str, key: str | None = None) -> None:
        if key is None:
            self._db.execute("DELETE FROM permanent WHERE namespace=?", (namespace,))
        else:
            self._db.execute("DELETE FROM permanent WHERE namespace=? AND key=?", (namespace, key))

    @contextmanager
    def batch(self) -> Iterator[None]:
        """Group several writes into one atomic transaction (all or nothing on a crash)."""
        if self._in_batch:
            yield
            return
        self._in_batch = True
        self._db.execute("BEGIN IMMEDIATE")
        try:
            yield
        except BaseException:
            self._db.execute("ROLLBACK")
            raise
        else:
            self._db.execute("COMMIT")
        finally:
            self._in_batch = False

    def close(self) -> None:
        self._db.close()
