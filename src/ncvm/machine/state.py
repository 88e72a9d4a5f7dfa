"""The state directory: the controller's memory, used by one run at a time.

A real control has one memory and one program owning it, so ``ncvm run`` takes its state directory
for the whole run: an exclusive ``flock`` on ``<state>/lock``, held by the open descriptor, so a run
that is killed gives it back at once. A second run on the same directory is refused at once, never
left to overwrite the first run's permanent values with those it read at its start.
"""

from __future__ import annotations

import errno
import fcntl
import os
import stat
from pathlib import Path

from ..diagnostics import UsageError
from .files import file_kind

LOCK_NAME = "lock"
STORE_NAME = "store.sqlite"


def store_files(state_dir: Path) -> tuple[Path, ...]:
    """The permanent store and the files SQLite keeps beside it."""
    return tuple(state_dir / (STORE_NAME + tail) for tail in ("", "-wal", "-shm", "-journal"))


class StateError(UsageError):
    """The state directory or its store cannot be used (exit 2): the message names the file and the remedy."""


class StateLock:
    """Holds ``<state>/lock`` from :meth:`acquire` to :meth:`release` (or the process's end).

    ``reader``: a run that only reads the state directory (``ncvm translate``, on a scratch copy of the store)
    takes a shared lock on the lock file as it stands, writes nothing and creates nothing: a run holding the
    directory refuses it, and it refuses a run that starts while it reads."""

    def __init__(self, state_dir: str | Path, reader: bool = False):
        self.dir = Path(state_dir)
        self.path = self.dir / LOCK_NAME
        self.reader = reader
        self._fd: int | None = None

    def acquire(self) -> "StateLock":
        """Take the directory, creating it if needed; refuse at once when another run holds it."""
        if self.reader:
            return self._share()
        try:
            self.dir.mkdir(parents=True, exist_ok=True)
            # never through a symlink, never blocking on a FIFO: the pid is written into what is opened
            fd = os.open(self.path, os.O_RDWR | os.O_CREAT | os.O_CLOEXEC | os.O_NOFOLLOW | os.O_NONBLOCK, 0o666)
        except FileExistsError:
            what = "a symbolic link to nothing" if self.dir.is_symlink() else "a file, not a directory"
            raise StateError(f"state directory {self.dir} is {what}; give another --state") from None
        except OSError as e:
            if e.errno in (errno.ELOOP, errno.EISDIR):
                raise self._not_a_file() from None
            if e.errno == errno.ENOSPC:
                raise StateError(f"state directory {self.dir} cannot be written: the disk is full; free some "
                                 f"space or give another --state") from None
            raise StateError(f"state directory {self.dir} cannot be written ({e.strerror}); make it writable "
                             f"or give another --state") from None
        self._take(fd, fcntl.LOCK_EX)
        if not _holds_a_pid(fd):  # a hard link to another file, or a file of the user's: never emptied
            os.close(fd)
            raise StateError(f"{self.path} holds something other than the pid of a run; move it away (ncvm keeps "
                             f"the pid of the run that holds the state directory there) and run again")
        self._fd = fd
        try:  # who holds it, for the message of a refused run; the lock itself is the flock
            os.ftruncate(fd, 0)
            os.pwrite(fd, f"{os.getpid()}\n".encode(), 0)
        except OSError:
            pass  # a full disk: the store reports it when it is written
        return self

    def _share(self) -> "StateLock":
        """The reader's lock: shared, on the lock file if there is one (none: no run has held the directory)."""
        try:
            fd = os.open(self.path, os.O_RDONLY | os.O_CLOEXEC | os.O_NOFOLLOW | os.O_NONBLOCK)
        except FileNotFoundError:
            return self
        except OSError as e:
            if e.errno in (errno.ELOOP, errno.EISDIR):
                raise self._not_a_file() from None
            raise StateError(f"state directory {self.dir} cannot be read ({e.strerror}); give another --state") from None
        self._take(fd, fcntl.LOCK_SH)
        self._fd = fd
        return self

    def _take(self, fd: int, mode: int) -> None:
        """Lock the open lock file ``fd`` (``mode``: exclusive or shared) at once, or close it and refuse."""
        if not stat.S_ISREG(os.fstat(fd).st_mode):
            os.close(fd)
            raise self._not_a_file()
        try:
            fcntl.flock(fd, mode | fcntl.LOCK_NB)
        except BlockingIOError:
            holder = _read_pid(fd)
            os.close(fd)
            by = f" (pid {holder})" if holder else ""
            raise StateError(f"state directory {self.dir} is in use by another run{by}; wait for it to end "
                             f"or give another --state") from None
        except OSError as e:  # a file system without locks
            os.close(fd)
            raise StateError(f"state directory {self.dir} cannot be locked ({e.strerror}); give a state "
                             f"directory on a local disk with --state") from None

    def _not_a_file(self) -> StateError:
        return StateError(f"{self.path} is {not_a_file(self.path)}, not a file; remove it (ncvm keeps the pid "
                          f"of the run that holds the state directory there) and run again")

    def release(self) -> None:
        if self._fd is not None:
            if not self.reader:
                try:
                    os.ftruncate(self._fd, 0)  # no pid of a run that has ended
                except OSError:
                    pass
            os.close(self._fd)  # closing the descriptor drops the flock
            self._fd = None

    def __enter__(self) -> "StateLock":
        return self.acquire()

    def __exit__(self, *exc) -> None:
        self.release()


def not_a_file(path: Path) -> str | None:
    """What stands at ``path`` when it is neither a plain file nor absent ("a symbolic link", ...), else None."""
    try:
        mode = os.lstat(path).st_mode
    except OSError:
        return None
    return None if stat.S_ISREG(mode) else file_kind(mode)


def _holds_a_pid(fd: int) -> bool:
    """The lock file is empty or holds a pid: only then may it be overwritten."""
    try:
        if os.fstat(fd).st_size > 32:
            return False
        text = os.pread(fd, 32, 0).decode("ascii", "replace").strip()
    except OSError:
        return False
    return text == "" or text.isdigit()


def _read_pid(fd: int) -> int | None:
    try:
        text = os.pread(fd, 32, 0).decode("ascii", "replace").strip()
    except OSError:
        return None
    return int(text) if text.isdigit() else None


def disk_full(folder: Path) -> bool:
    """Whether the file system of ``folder`` has (next to) no room left: SQLite reports a full disk met
    while growing its shared-memory file as an I/O error."""
    try:
        st = os.statvfs(folder)
    except OSError:
        return False
    return st.f_bavail * st.f_frsize < 64 * 1024
