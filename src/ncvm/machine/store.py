"""The permanent store: what a control keeps across power-off, in SQLite (WAL).

CPL permanent variables, central R parameters, offsets and machine data changed
by programs all go here, as (namespace, key) -> JSON value. Every write is its
own transaction unless the caller groups writes with :meth:`Store.batch`.

Durability (docs/decisions.md, "The permanent store: the durability point"), the
point CPL files have: with WAL and ``synchronous=NORMAL`` a committed write is in
the write-ahead log, handed to the operating system, before the statement
returns, so a process killed at any moment leaves the last committed value of
every key, never a torn one. The log is synced to the disk (``os.fsync``) at the
first write once :data:`SYNC_EVERY_S` has passed since the last sync, and at
:meth:`Store.close` (the end of the run, an error stop, Ctrl-C, SIGTERM): a crash
of the host loses at most that last second, never the store's consistency.

Only one run uses a store at a time (:mod:`ncvm.machine.state` locks the state
directory), so a run may keep the values it read. Every SQLite failure (another
program holding the file, a damaged or foreign file, a read-only directory, a
full disk) becomes a :class:`StateError` naming the file and what to do.
"""

from __future__ import annotations

import errno
import os
from contextlib import contextmanager
from pathlib import Path
from time import monotonic
from typing import Any, Iterator

from ..lazy import lazy
from .state import STORE_NAME, StateError, disk_full, not_a_file, store_files

sqlite3 = lazy("sqlite3")  # a check opens no store
json = lazy("json")  # for the values of a store a program opens

SCHEMA = """
CREATE TABLE IF NOT EXISTS permanent (
    namespace TEXT NOT NULL,
    key       TEXT NOT NULL,
    value     TEXT NOT NULL,
    PRIMARY KEY (namespace, key)
) WITHOUT ROWID;
"""
#: ``PRAGMA application_id`` of an ncvm store ("NCVM"): a SQLite file of another program is never written
APPLICATION_ID = 0x4E43564D
#: how long to wait for a program other than ncvm (an sqlite3 shell, a backup) to let go of the file
BUSY_TIMEOUT_S = 2.0
#: seconds of writing after which the write-ahead log is synced again (docs/decisions.md): a sync a write
#: cost 0.1-4.4 ms a write on the disk (docs/performance.md), one a second costs nothing measurable
SYNC_EVERY_S = 1.0


def _plain_files(state_dir: Path) -> None:
    """Refuse a store or side file that is not a plain file: SQLite would call a FIFO, a directory or a
    symlinked side file an open or disk error; through a symlink, two state directories (two locks) could
    share one store and lose each other's writes."""
    for path in store_files(state_dir):
        kind = not_a_file(path)
        if kind:
            raise StateError(f"{path} is {kind}, not a file; move it away or give another --state")


def _fsync(path: Path, flags: int) -> None:
    fd = os.open(path, flags | os.O_CLOEXEC)
    try:
        os.fsync(fd)
    finally:
        os.close(fd)


class Store:
    """A namespaced key/value store in ``<state_dir>/store.sqlite``.

    ``scratch``: the run reads what the state directory holds and writes to a copy in memory that ends with
    it (``ncvm translate``: a translation leaves the permanent data as it found it).
    """

    def __init__(self, state_dir: str | Path, scratch: bool = False):
        self.path = Path(state_dir) / STORE_NAME
        self._db: sqlite3.Connection | None = None
        self._in_batch = False
        #: the write-ahead log to sync, None when SQLite syncs every commit itself (no WAL) or nothing is on disk
        self._log: Path | None = None
        self._unsynced = False  # written since the last sync
        self._synced_at = monotonic()
        self._folder_synced = False  # the folder is synced once: the names of the store and its log last
        if scratch:
            self._open_copy()
            return
        try:
            self.path.parent.mkdir(parents=True, exist_ok=True)
        except OSError as e:
            raise StateError(f"cannot create the state directory {self.path.parent} ({e.strerror}); "
                             f"give another --state") from None
        _plain_files(self.path.parent)
        try:
            self._db = sqlite3.connect(self.path, isolation_level=None, timeout=BUSY_TIMEOUT_S)
            self._adopt()
            self._durability()
        except sqlite3.Error as e:
            self.close()
            raise self._error(e) from None
        except StateError:
            self.close()
            raise

    def _open_copy(self) -> None:
        """The scratch store: the state directory's store (if any) copied into memory, the directory untouched.
        SQLite opens even a read-only connection with side files (``-wal``, ``-shm``) beside the store and may
        fold a left-over ``-wal`` into it, so the store and its ``-wal`` are opened from a copy elsewhere."""
        import shutil  # here, not at the top: only a translation reads a store so
        import tempfile

        _plain_files(self.path.parent)
        try:
            copy = sqlite3.connect(":memory:", isolation_level=None)
            if self.path.is_file():
                with tempfile.TemporaryDirectory(prefix="ncvm-state-") as folder:
                    for path in store_files(self.path.parent)[:2]:  # the store and its write-ahead log
                        if path.is_file():
                            shutil.copyfile(path, Path(folder) / path.name)
                    try:
                        with Store(folder) as source:
                            source._db.backup(copy)
                    except StateError as e:  # named as the user knows it
                        raise StateError(str(e).replace(folder, str(self.path.parent))) from None
            copy.executescript(SCHEMA)
        except sqlite3.Error as e:
            raise self._error(e) from None
        except OSError as e:
            raise StateError(f"cannot read the permanent store {self.path} ({e.strerror}); give another "
                             f"--state") from None
        self._db = copy

    def _durability(self) -> None:
        """WAL with ``synchronous=NORMAL``: a commit writes the log, :meth:`sync` syncs it. Where SQLite cannot
        keep a write-ahead log it stays in rollback mode, and there only ``FULL`` keeps every commit whole
        through a power cut: every commit is synced as before."""
        mode = self._db.execute("PRAGMA journal_mode=WAL").fetchone()[0]
        if str(mode).lower() == "wal":
            self._db.execute("PRAGMA synchronous=NORMAL")
            self._log = store_files(self.path.parent)[1]
        else:
            self._db.execute("PRAGMA synchronous=FULL")

    def __enter__(self) -> "Store":
        return self

    def __exit__(self, *exc) -> None:
        self.close()

    def _adopt(self) -> None:
        """Refuse a file that is not an ncvm store or is damaged; stamp a new (or an older ncvm's) store."""
        db = self._db
        app = db.execute("PRAGMA application_id").fetchone()[0]
        tables = [name for (name,) in db.execute("SELECT name FROM sqlite_master WHERE type='table'")]
        older = app == 0 and tables in ([], ["permanent"])
        if older and tables:
            older = [c[1] for c in db.execute("PRAGMA table_info(permanent)")] == ["namespace", "key", "value"]
        if app != APPLICATION_ID and not older:
            what = f"it holds the tables {', '.join(tables)}" if tables else f"application id {app:#x}"
            raise StateError(f"{self.path} is not an ncvm permanent store ({what}); move it away or give "
                             f"another --state")
        problems = [row[0] for row in db.execute("PRAGMA quick_check")]
        if problems != ["ok"]:
            raise StateError(self._damaged(problems[0]))
        if app != APPLICATION_ID:
            db.executescript(f"BEGIN IMMEDIATE; {SCHEMA} PRAGMA application_id = {APPLICATION_ID}; COMMIT;")

    def get(self, namespace: str, key: str, default: Any = None) -> Any:
        try:
            row = self._db.execute("SELECT value FROM permanent WHERE namespace=? AND key=?",
                                   (namespace, key)).fetchone()
        except sqlite3.Error as e:
            raise self._error(e) from None
        return default if row is None else json.loads(row[0])

    def items(self, namespace: str) -> dict[str, Any]:
        try:
            rows = self._db.execute("SELECT key, value FROM permanent WHERE namespace=?", (namespace,)).fetchall()
        except sqlite3.Error as e:
            raise self._error(e) from None
        return {k: json.loads(v) for k, v in rows}

    def dump(self) -> dict[str, dict[str, Any]]:
        """Everything the store holds, namespace -> key -> value, read in one statement (one snapshot)."""
        try:
            rows = self._db.execute("SELECT namespace, key, value FROM permanent ORDER BY namespace, key").fetchall()
        except sqlite3.Error as e:
            raise self._error(e) from None
        out: dict[str, dict[str, Any]] = {}
        for namespace, key, value in rows:
            out.setdefault(namespace, {})[key] = json.loads(value)
        return out

    def replace(self, content: dict[str, dict[str, Any]]) -> None:
        """Make the store hold exactly ``content`` (nothing for ``{}``), all or nothing."""
        with self.batch():
            self._write("DELETE FROM permanent", ())
            for namespace, entries in content.items():
                for key, value in entries.items():
                    self.put(namespace, key, value)

    def put(self, namespace: str, key: str, value: Any) -> None:
        self._write("INSERT OR REPLACE INTO permanent(namespace, key, value) VALUES (?,?,?)",
                    (namespace, key, json.dumps(value)))

    def delete(self, namespace: str, key: str | None = None) -> None:
        if key is None:
            self._write("DELETE FROM permanent WHERE namespace=?", (namespace,))
        else:
            self._write("DELETE FROM permanent WHERE namespace=? AND key=?", (namespace, key))

    def _write(self, sql: str, args: tuple) -> None:
        self._unsynced = True  # before: a Ctrl-C right after the commit still leaves it to close's sync
        try:
            self._db.execute(sql, args)
        except sqlite3.Error as e:
            self._rollback()
            raise self._error(e) from None
        if not self._in_batch:
            self._committed()

    def _committed(self) -> None:
        """A transaction was committed: the log is synced when :data:`SYNC_EVERY_S` has passed since the last
        sync (checked here, at a write: no timer, no thread)."""
        if monotonic() - self._synced_at >= SYNC_EVERY_S:
            self.sync()

    def sync(self) -> None:
        """Every committed write made durable: the write-ahead log ``os.fsync`` ed (and, the first time, its
        folder), if anything was committed since the last sync. The log is opened by name: SQLite keeps it
        while a connection is open and gives no handle on it."""
        if not self._unsynced or self._log is None:
            return
        try:
            _fsync(self._log, os.O_RDONLY)
            if not self._folder_synced:
                _fsync(self._log.parent, os.O_RDONLY | os.O_DIRECTORY)
                self._folder_synced = True
        except FileNotFoundError:
            pass  # no log: SQLite folded it into the store and removed it, syncing the store as it did
        except OSError as e:
            raise self._sync_error(e) from None
        self._unsynced, self._synced_at = False, monotonic()

    @contextmanager
    def batch(self) -> Iterator[None]:
        """Group several writes into one atomic transaction (all or nothing on a crash)."""
        if self._in_batch:
            yield
            return
        self._in_batch = True
        try:
            try:  # one handler from BEGIN on: a Ctrl-C or SIGTERM as BEGIN returns must not leave it open
                try:
                    self._db.execute("BEGIN IMMEDIATE")
                except sqlite3.Error as e:
                    raise self._error(e) from None
                yield
            except BaseException:
                self._rollback()  # only where a transaction is open
                raise
            try:
                self._db.execute("COMMIT")
            except sqlite3.Error as e:
                self._rollback()
                raise self._error(e) from None
        finally:
            self._in_batch = False
        self._committed()

    def _rollback(self) -> None:
        """Give up the open transaction, if SQLite has not already (it does on a full disk)."""
        try:
            if self._db.in_transaction:
                self._db.execute("ROLLBACK")
        except sqlite3.Error:
            pass  # the connection is unusable; the committed values are still in the file

    def close(self) -> None:
        """Sync what was committed, then close (the connection is closed even when the sync fails)."""
        if self._db is not None:
            try:
                self.sync()
            finally:
                self._db.close()
                self._db = None

    # -- what to tell the user --------------------------------------------------------------
    def _damaged(self, detail: str) -> str:
        detail = " ".join(detail.replace("*** in database main ***", "").split())
        return (f"the permanent store {self.path} is damaged ({detail}); move it away to start again from "
                f"the machine file, or give another --state")

    def _sync_error(self, e: OSError) -> StateError:
        if e.errno == errno.ENOSPC:
            return StateError(f"cannot write the permanent store {self.path}: the disk is full; free some space "
                              f"and run again (the store keeps what was synced before)")
        return StateError(f"the permanent store {self.path} cannot be synced to the disk ({e.strerror}); the "
                          f"writes of the last second may be lost at a power cut; check the disk, or give "
                          f"another --state")

    def _error(self, e: sqlite3.Error) -> StateError:
        name = getattr(e, "sqlite_errorname", "") or ""
        where, state = self.path, self.path.parent
        if name.startswith(("SQLITE_BUSY", "SQLITE_LOCKED")):
            text = (f"the permanent store {where} is locked by another program; close the program that has it "
                    f"open (an sqlite3 shell, a backup) and run again")
        elif name == "SQLITE_NOTADB":
            text = f"{where} is not an ncvm permanent store (not a SQLite database); move it away or give another --state"
        elif name.startswith("SQLITE_CORRUPT"):
            text = self._damaged(str(e))
        elif name == "SQLITE_FULL" or (name.startswith("SQLITE_IOERR") and disk_full(state)):
            text = (f"cannot write the permanent store {where}: the disk is full; free some space and run again "
                    f"(the store keeps what was written before)")
        elif name.startswith(("SQLITE_READONLY", "SQLITE_CANTOPEN", "SQLITE_PERM", "SQLITE_AUTH")):
            text = (f"cannot write the permanent store {where} ({e}); make the state directory {state} and its "
                    f"files writable, or give another --state")
        else:  # SQLITE_IOERR and the rest: the disk or the file system failed
            text = f"the permanent store {where} cannot be used ({e}); check the disk, or give another --state"
        return StateError(text)
