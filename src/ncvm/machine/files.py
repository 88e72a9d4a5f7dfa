"""The controller's file root: the one door through which a program reaches files.

A program run by ncvm is untrusted input, and its file names reach the host's file system only here.
:meth:`FileRoot.place` turns the control's name into components below the root: ``\\`` is ``/``, and
a leading ``/`` or a drive letter (``C:``) names the root of the *control's* file system, which is
this folder -- never the host's root. NUL and empty names are refused.

Every access then walks the components one by one from a descriptor of the root, each directory
opened relative to the one before it (``openat``) with ``O_NOFOLLOW | O_DIRECTORY``:

* ``..`` in a name takes back the component before it (as the control's own paths do); one that
  climbs above the root is refused;
* a symbolic link is read and its target walked the same way (its ``..`` climbs back one opened
  directory), so a link that stays inside the root works and one that leads out of it (``..`` past
  the root, or an absolute target elsewhere) is refused; a directory swapped for a link while the walk runs makes the open fail, never follow it;
* the machine file in ``private`` is never opened, replaced or removed, under any name: a program
  that rewrote it would choose the next run's file root;
* a directory in ``private`` (the state directory, whose store holds the machine's memory) is
  never entered, nor answered about as a name's last component (FILEACCESS would tell its folder
  from a missing name), even when it lies inside the root; a hard link to one of its files is not opened;
* only regular files are opened: a FIFO, device or socket is refused after an ``lstat`` and is not
  opened at all (the open itself uses ``O_NONBLOCK`` and the descriptor is checked again).

Callers keep the descriptor :meth:`FileRoot.open` returns for as long as they write, so nothing that
changes in the tree afterwards can redirect their writes.
"""

from __future__ import annotations

import errno
import os
import stat
from collections.abc import Callable, Iterable, Iterator
from contextlib import contextmanager
from pathlib import Path

from ..records import FrozenRecord
from ..source import without_bom

_DIRECTORY = os.O_RDONLY | os.O_DIRECTORY | os.O_NOFOLLOW | os.O_CLOEXEC
_FILE = os.O_NOFOLLOW | os.O_NONBLOCK | os.O_CLOEXEC
MAX_LINKS = 40  # as the kernel's ELOOP limit


class FileRootError(ValueError):
    """A name the file root refuses; the message says why (it follows the name, e.g. "lies outside
    the file root")."""


class Place(FrozenRecord):
    """A name placed below a file root: its components (no ``..``, no ``.``) and the name as the
    program wrote it."""

    __slots__ = ("parts", "shown")

    def __init__(self, parts: tuple[str, ...], shown: str):
        self.parts = parts
        self.shown = shown


def file_kind(mode: int) -> str:
    """What an entry that is no regular file is, for a message ("a FIFO", "a directory", ...)."""
    for test, word in ((stat.S_ISDIR, "a directory"), (stat.S_ISFIFO, "a FIFO"), (stat.S_ISSOCK, "a socket"),
                       (stat.S_ISCHR, "a device"), (stat.S_ISBLK, "a device"), (stat.S_ISLNK, "a symbolic link")):
        if test(mode):
            return word
    return "no regular file"


def read_all(fd: int) -> bytes:
    """Everything from the descriptor's position to the end."""
    chunks = []
    while chunk := os.read(fd, 1 << 20):
        chunks.append(chunk)
    return b"".join(chunks)


#: what fsync of a directory says where the platform or file system cannot sync one (nothing to do there)
_NO_DIRECTORY_SYNC = {errno.EINVAL, errno.EBADF, errno.ENOTSUP, errno.EOPNOTSUPP}


def sync_directory(fd: int) -> None:
    """Make the entries of the directory open as ``fd`` durable: a file or folder just made in it is found
    after a power loss, as its synced data is. Quietly nothing where the directory cannot be synced."""
    try:
        os.fsync(fd)
    except OSError as e:
        if e.errno not in _NO_DIRECTORY_SYNC:
            raise


def _make_durable_folders(path: Path) -> None:
    """``path`` and the folders above it that are missing, made, each one's entry synced in its parent (the
    file root under a new state directory: a file made in it is not lost with the folder)."""
    missing = []
    while not os.path.lexists(path) and path != path.parent:
        missing.append(path)
        path = path.parent
    for folder in reversed(missing):
        try:
            os.mkdir(folder)
        except FileExistsError:
            continue  # made meanwhile (or a link): opened as before
        fd = os.open(folder.parent, os.O_RDONLY | os.O_DIRECTORY | os.O_CLOEXEC)
        try:
            sync_directory(fd)
        finally:
            os.close(fd)


def identity(st: os.stat_result) -> tuple[int, int]:
    """What tells two names of the same file apart from two files: device and inode."""
    return st.st_dev, st.st_ino


def _identity_at(folder: str, name: str) -> tuple[int, int] | None:
    try:
        return identity(os.stat(os.path.join(folder, name), follow_symlinks=False))
    except OSError:
        return None


class FileRoot:
    """One folder a program's names are confined to (the file root, the bitmap folder, a program
    folder); ``private``: folders and files never reachable from it (the state directory, the machine
    file)."""

    def __init__(self, path: Path | str, private: Iterable[Path | str] = ()):
        self.path = Path(path)
        self.private = tuple(Path(p) for p in private)

    # -- names -----------------------------------------------------------------------------
    @staticmethod
    def place(name: str, cwd: str = "") -> Place:
        """The control's name ``name`` below the root; relative to ``cwd`` (components below the root,
        ``/``-separated) unless it begins at the control's root (``/``, ``\\`` or a drive letter)."""
        if "\x00" in name:
            raise FileRootError(f"{name!r} holds a NUL character")
        text = name.strip().replace("\\", "/")
        if len(text) >= 2 and text[1] == ":" and text[0].isascii() and text[0].isalpha():
            text = "/" + text[2:]
        if not text.startswith("/") and cwd:
            text = f"{cwd}/{text}"
        parts: list[str] = []
        for part in text.split("/"):
            if part == "..":
                if not parts:
                    raise FileRootError(f"{name.strip()} lies outside the file root")
                parts.pop()
            elif part not in ("", "."):
                parts.append(part)
        if not parts:
            raise FileRootError(f"{name!r} names no file")
        return Place(tuple(parts), name.strip())

    def path_of(self, place: Place) -> Path:
        """Where the place lies as the host names it: for messages, and for a program look-up that hands
        the path on (the file root's own operations never open a file by this name)."""
        return self.path.joinpath(*place.parts)

    # -- the walk --------------------------------------------------------------------------
    def _private_ids(self) -> set[tuple[int, int]]:
        ids = set()
        for p in self.private:
            try:
                ids.add(identity(os.stat(p)))
            except OSError:
                pass  # not there yet: nothing to reach
        return ids

    def _private_files(self, root: tuple[int, int]) -> set[tuple[int, int]]:
        """The files of the private folders (asked only for a file with more than one name), apart from
        the file root ``root`` (device, inode) when it lies inside one (the built-in machine's)."""
        ids = set()
        for folder in self.private:
            for here, dirs, names in os.walk(folder):
                dirs[:] = [d for d in dirs if _identity_at(here, d) != root]
                for name in names:
                    try:
                        ids.add(identity(os.stat(os.path.join(here, name), follow_symlinks=False)))
                    except OSError:
                        pass
        return ids

    def _open_root(self, create: bool, durable: bool = False) -> int:
        if create and durable:
            _make_durable_folders(self.path)
        elif create:
            self.path.mkdir(parents=True, exist_ok=True)
        return os.open(self.path, os.O_RDONLY | os.O_DIRECTORY | os.O_CLOEXEC)

    def _inside(self, target: str, shown: str) -> list[str]:
        """The components below the root of an absolute link target, which must lie inside it."""
        real = os.path.realpath(self.path)
        norm = os.path.normpath(target)
        if norm == real:
            return []
        if not norm.startswith(real.rstrip("/") + "/"):
            raise FileRootError(f"{shown}: a symbolic link leads out of the file root")
        return norm[len(real.rstrip("/")) + 1:].split("/")

    @contextmanager
    def _entry(self, place: Place, make_dirs: bool = False, follow: bool = True, durable: bool = False
               ) -> Iterator[tuple[int, str, os.stat_result | None]]:
        """(descriptor of the directory, name in it, its lstat or None when missing) of the place's
        last component, every link on the way resolved inside the root. ``make_dirs``: missing
        directories (and the root) are made; ``durable``: each one's entry synced in its parent.
        ``follow=False``: a link as last component is refused."""
        shown = place.shown
        private = self._private_ids()
        fds = [self._open_root(make_dirs, durable)]
        try:
            if identity(os.fstat(fds[0])) in private:
                raise FileRootError(f"{shown}: the file root is the state directory")
            todo, links = list(place.parts), 0
            while True:
                part = todo.pop(0)
                if part == "..":
                    if len(fds) == 1:
                        raise FileRootError(f"{shown} lies outside the file root")
                    os.close(fds.pop())
                if part in ("..", "", "."):
                    if not todo:
                        raise FileRootError(f"{shown} names a directory")
                    continue
                try:
                    st = os.stat(part, dir_fd=fds[-1], follow_symlinks=False)
                except FileNotFoundError:
                    st = None
                if st is not None and stat.S_ISLNK(st.st_mode) and (todo or follow):
                    links += 1
                    if links > MAX_LINKS:
                        raise FileRootError(f"{shown}: too many symbolic links")
                    target = os.readlink(part, dir_fd=fds[-1])
                    if target.startswith("/"):
                        for fd in fds[1:]:
                            os.close(fd)
                        del fds[1:]
                        head = self._inside(target, shown)
                    else:
                        head = target.split("/")
                    todo[:0] = [p for p in head if p] or ["."]
                    continue
                if not todo:
                    if st is not None and identity(st) in private:
                        what = "the state directory" if stat.S_ISDIR(st.st_mode) else "the machine file"
                        raise FileRootError(f"{shown} is {what}, outside the file root")
                    yield fds[-1], part, st
                    return
                if st is None:
                    if not make_dirs:
                        raise FileNotFoundError(errno.ENOENT, "no such directory", shown)
                    try:
                        os.mkdir(part, 0o777, dir_fd=fds[-1])
                        if durable:
                            sync_directory(fds[-1])
                    except FileExistsError:
                        pass  # made meanwhile: opened below like any directory
                try:
                    fds.append(os.open(part, _DIRECTORY, dir_fd=fds[-1]))
                except OSError as e:
                    was_directory = st is None or stat.S_ISDIR(st.st_mode)
                    if was_directory and e.errno in (errno.ELOOP, errno.ENOTDIR):  # swapped for a link meanwhile
                        raise FileRootError(f"{shown}: a directory on the way became a symbolic link") from None
                    raise
                if identity(os.fstat(fds[-1])) in private:
                    raise FileRootError(f"{shown} lies in the state directory, outside the file root")
        finally:
            for fd in fds:
                os.close(fd)

    @staticmethod
    def require_file(st: os.stat_result, shown: str) -> None:
        """Refuse anything but a regular file (a directory, FIFO, device, socket or link)."""
        if not stat.S_ISREG(st.st_mode):
            raise FileRootError(f"{shown} is {file_kind(st.st_mode)}, not a file")

    # -- what a program does with a name ------------------------------------------------------
    def stat(self, place: Place, follow: bool = True) -> os.stat_result | None:
        """The entry's status (links inside the root followed; with ``follow=False`` a link as the last
        component is not), None when it does not exist."""
        try:
            with self._entry(place, follow=follow) as (_dfd, _name, st):
                return st
        except (FileNotFoundError, NotADirectoryError):
            return None

    def open(self, place: Place, write: bool = False, create: bool = False, follow: bool = True,
             durable: bool = False) -> int:
        """A descriptor of the regular file at ``place``, at offset 0: read-only, or read-write with
        ``write``; ``create`` makes a missing file (and its folders), ``durable`` with its directory
        entry synced (:func:`sync_directory`: the data a writer syncs later is not lost with the name
        after a power loss). ``follow=False`` refuses a symbolic link as the last component even when it
        stays inside the root."""
        with self._entry(place, make_dirs=create, follow=follow, durable=durable) as (dfd, name, st):
            if st is None and not create:
                raise FileNotFoundError(errno.ENOENT, "no such file", place.shown)
            if st is not None:
                self.require_file(st, place.shown)
            flags = _FILE | (os.O_RDWR if write else os.O_RDONLY) | (os.O_CREAT if create else 0)
            try:
                fd = os.open(name, flags, 0o666, dir_fd=dfd)
            except OSError as e:
                if e.errno in (errno.ELOOP, errno.ENXIO):  # swapped for a link or a FIFO since the lstat
                    raise FileRootError(f"{place.shown} changed while it was opened") from None
                raise
            if st is None and durable:  # made now (or meanwhile by another: one sync more, no harm)
                try:
                    sync_directory(dfd)
                except BaseException:
                    os.close(fd)
                    raise
        try:
            st = os.fstat(fd)
            self.require_file(st, place.shown)
            if identity(st) in self._private_ids():  # the machine file under another name, a hard link
                raise FileRootError(f"{place.shown} is the machine file, outside the file root")
            if st.st_nlink > 1 and identity(st) in self._private_files(identity(os.stat(self.path))):
                raise FileRootError(f"{place.shown} is a hard link to a file of the state directory")
            os.set_blocking(fd, True)
        except BaseException:
            os.close(fd)
            raise
        return fd

    def read_bytes(self, place: Place, follow: bool = True) -> bytes:
        """The whole content of the regular file at ``place``."""
        fd = self.open(place, follow=follow)
        try:
            return read_all(fd)
        finally:
            os.close(fd)

    def unlink(self, place: Place) -> None:
        """Remove the regular file at ``place`` (FileNotFoundError when there is none)."""
        with self._entry(place) as (dfd, name, st):
            if st is None:
                raise FileNotFoundError(errno.ENOENT, "no such file", place.shown)
            self.require_file(st, place.shown)
            os.unlink(name, dir_fd=dfd)

    def replace(self, place: Place, data: bytes, finish: Callable[[int], None] = lambda fd: None,
                durable: bool = True) -> None:
        """Write a whole file atomically: a temporary file beside it gets ``data``, the old file's access
        rights (0o644 for a new one) and ``finish(fd)`` (sync, date), then is renamed over the old one,
        so a crash leaves the old file or the new one, never half of one. ``durable``: the directory
        is synced too, so the rename itself survives a crash."""
        with self._entry(place, make_dirs=True) as (dfd, name, st):
            if st is not None:
                self.require_file(st, place.shown)
            mode = stat.S_IMODE(st.st_mode) if st is not None else 0o644
            tmp = f".{name}.{os.urandom(4).hex()}.tmp"
            fd = os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_EXCL | os.O_NOFOLLOW | os.O_CLOEXEC, 0o600, dir_fd=dfd)
            try:
                with os.fdopen(fd, "wb") as f:
                    f.write(data)
                    f.flush()
                    os.fchmod(f.fileno(), mode)
                    finish(f.fileno())
                os.replace(tmp, name, src_dir_fd=dfd, dst_dir_fd=dfd)
            except BaseException:
                try:
                    os.unlink(tmp, dir_fd=dfd)
                except OSError:
                    pass
                raise
            if durable:
                sync_directory(dfd)

    def names(self) -> list[str]:
        """The names of the root's own entries, sorted (OSError when the root cannot be listed)."""
        fd = self._open_root(False)
        try:
            return sorted(os.listdir(fd))
        finally:
            os.close(fd)

    def find(self, name: str, ignore_case: bool = False) -> Place | None:
        """The entry ``name`` as written, else (``ignore_case``, a name without a folder) the root's one
        entry of that name in any case; None when there is none or the name is refused. The entry may
        be anything (a link as the last component is not followed): opening it decides."""
        try:
            place = self.place(name)
            if self.stat(place, follow=False) is not None:
                return place
            if not ignore_case or len(place.parts) != 1:
                return None
            entries = self.names()
        except (FileRootError, OSError):
            return None
        low = name.lower()
        match = next((e for e in sorted(entries) if e.lower() == low), None)
        return None if match is None else Place((match,), match)


def find_in(folders: Iterable[Path], candidates: Iterable[str], ignore_case: bool = True,
            private: Iterable[Path | str] = ()) -> Path | None:
    """The first regular file one of ``candidates`` names in the first folder that has one (program and
    list look-ups). Each folder confines the names as a file root does: an absolute name or one that
    climbs out finds nothing, nor does a link that leads out or a FIFO -- so the answer never tells
    whether a host file exists. ``private``: folders no name may reach even inside a folder."""
    for folder in folders:
        root = FileRoot(folder, private)
        for cand in candidates:
            place = root.find(cand, ignore_case)
            if place is None:
                continue
            try:
                st = root.stat(place)
            except (FileRootError, OSError):
                continue
            if st is not None and stat.S_ISREG(st.st_mode):
                return root.path_of(place)
    return None


def heads(folders: Iterable[Path], suffixes: tuple[str, ...], size: int = 200) -> Iterator[tuple[Path, str]]:
    """(path, first ``size`` characters) of each regular file directly in the folders whose suffix (lower
    case, "" for none) is one of ``suffixes``, in name order: the programs a control finds by their
    header. Confined as :func:`find_in`: a link that leads out, a FIFO or a device is passed over, and
    only the head of a file is read (a program folder may hold large files)."""
    for folder in folders:
        root = FileRoot(folder)
        try:
            names = root.names()
        except OSError:
            continue
        for name in names:
            if Path(name).suffix.lower() not in suffixes:
                continue
            place = Place((name,), name)
            try:
                fd = root.open(place)
            except (FileRootError, OSError):
                continue
            try:
                head = os.read(fd, size)
            except OSError:
                continue
            finally:
                os.close(fd)
            yield root.path_of(place), without_bom(head.decode("latin-1"))  # read as programs are read
