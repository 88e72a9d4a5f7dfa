"""Chapter 6: CPL files on real files under the machine's file root (manual L3835-4457).

On disk a CPL file is what the control kept: records of latin-1 text, each ended by LF (not part of
its length), then the EOF marker ``ETX LF``. A random file's records all have the record length,
padded with blanks. Byte offsets, record numbers and record offsets are 1-based; the EOF position is
data size + 1. Files written by other tools (no marker, CR LF line ends) are read as well and are put
into this form when they are opened for writing.

Durability (docs/decisions.md, "CPL files: the durability point"): every completed record -- a PRN#
without ``;``, a CHR$(13) inside the output, a random record written in place -- and every REWRITE is
handed to the operating system (``pwrite``) before the statement returns, so what a program wrote
survives ncvm being killed at any moment. A file OPENW creates has its directory entry synced at once (and
those of folders it makes), so a file whose data is synced is not lost with its name after a power loss.
A file is ``os.fsync`` ed at CLOSE (and so at the end of the
run and when the run stops with an error, which close every file) and, while it is written, once
:data:`SYNC_EVERY_S` has passed since its last fsync: a crash of the host loses at most that much. The
text of a record still open with ``;`` is kept in memory until the record is completed.

Every name goes through the machine's file root (:class:`ncvm.machine.files.FileRoot`): a name that
leads out of it -- ``..`` past the root, a symbolic link pointing out, the state directory -- or that
names a FIFO, device or socket is INVALID FILE NAME. A file open for writing keeps its descriptor
until CLOSE, so later PRN# write to the file OPENW opened whatever happens to its name meanwhile.

The class :class:`CplFiles` is one program run's file table (logical numbers 1..9). Its methods are
named after the CPL statements; arguments follow the CPL argument order (omitted = None).
"""

from __future__ import annotations

import os
import stat
import time
from pathlib import Path
from typing import Callable

from ....machine.files import FileRoot, FileRootError, Place, identity, read_all
from ....records import Record
from .editor import call_parameters
from .errors import CplRuntimeError, CplWarning, WarnFn, fail, warning
from .format import OutputMode, format_items
from .strings import CharacterField, StringView, scan_number
from .values import text_of

EOF_MARKER = "\x03\n"
MAX_RECORD = 1024
MAX_NAME = 30
MIN_RESERVED = 130
REAL_MAX = 3.4028234663852886e38
INT_MIN, INT_MAX = -(2**31), 2**31 - 1
#: seconds of writing after which a file open for writing is fsynced again (docs/decisions.md): an fsync a
#: record cost milliseconds on a disk, one a second costs a fraction of a percent
SYNC_EVERY_S = 1.0


class Handle(Record):
    """One open logical file: its records in memory, the pointer, and (for writing) the disk file."""

    __slots__ = ("number", "name", "place", "ident", "writing", "reclen", "records", "rec", "off", "pending", "remark",
                 "reserved", "data_size", "fd", "size", "unsynced", "synced_at")

    def __init__(self, number: int, name: str, place: Place, ident: tuple[int, int], writing: bool,
                 reclen: int | None, records: list[str], rec: int = 0, off: int = 0, pending: str | None = None,
                 remark: str = "", reserved: int = MIN_RESERVED, data_size: int = 0, fd: int | None = None,
                 size: int = 0, unsynced: bool = False, synced_at: float = 0.0):
        self.number = number
        self.name = name
        self.place = place
        self.ident = ident  # device and inode: the same file under another name is the same file
        self.writing = writing
        self.reclen = reclen
        self.records = records
        self.rec = rec  # 0-based record index; len(records) = on the EOF marker
        self.off = off  # 0-based offset inside the record
        self.pending = pending  # sequential: text of a record still open with ';'
        self.remark = remark
        self.reserved = reserved
        self.data_size = data_size  # bytes before the EOF marker
        self.fd = fd  # a file open for writing: its descriptor until CLOSE
        self.size = size  # bytes of the disk file (written through fd only, so no fstat a record)
        self.unsynced = unsynced  # written since its last fsync
        self.synced_at = synced_at  # time.monotonic() of its last fsync (or of OPENW)

    @property
    def random(self) -> bool:
        return self.reclen is not None

    def byte_of(self, rec: int) -> int:
        """0-based byte offset of record ``rec``."""
        if self.random:
            return rec * (self.reclen + 1)
        return sum(len(r) + 1 for r in self.records[:rec])


#: bytes a run's files may grow by without ``[cpl] file_space`` (docs/decisions.md)
FILE_SPACE = 1 << 30


class CplFiles(Record):
    """The file table of one CPL program run.

    ``root``: the machine's file root; ``cwd``: the current directory inside it (names without a
    path are looked up there); ``clock``: an object with ``now`` (simulated seconds) and
    ``start_epoch``, used as the modification time of files the program writes; ``message``: where
    PRN#(0,...) goes (the message window); ``warn``: receives :class:`CplWarning` s;
    ``active``: paths of programs that are running (ERASE answers 3, FILEACCESS sets bit 5);
    ``private``: folders no name may reach (the state directory).
    """

    __slots__ = ("root", "private", "clock", "message", "warn", "mode", "cwd", "active", "editor_block",
                 "on_editor_block", "durable", "space", "trim_zeros", "grown", "handles", "messages", "warnings",
                 "_message_pending", "on_outside", "_own", "fileroot")

    def __init__(self, root: Path, private: tuple = (), clock: object | None = None,
                 message: Callable[[str], None] | None = None, warn: WarnFn | None = None,
                 mode: OutputMode | None = None, cwd: str = "", active: set[Path] | None = None,
                 editor_block: str | None = None, on_editor_block: Callable[[str], None] | None = None,
                 durable: bool = True, space: int = 0, trim_zeros: bool = True, grown: int = 0,
                 handles: dict[int, Handle] | None = None, messages: list[str] | None = None,
                 warnings: list[CplWarning] | None = None, _message_pending: str = "",
                 on_outside: Callable[[str], None] | None = None):
        self.root = Path(root)
        self.private = private
        self.clock = clock
        self.message = message
        self.warn = warn
        self.mode = OutputMode() if mode is None else mode
        self.cwd = cwd
        self.active = set() if active is None else active
        #: the NC block selected in the editor when the program runs as an editor dialog (PRN#(0)/INP#(0))
        self.editor_block = editor_block
        #: told the new text each time PRN#(0) overwrites the editor block
        self.on_editor_block = on_editor_block
        self.durable = durable
        #: bytes the program's files may grow by in this run (``[cpl] file_space``; 0: no limit): the
        #: controller's file memory, so that a runaway PRN# loop ends with FILE MEMORY FULL, not a full disk
        self.space = space
        #: numbers written to files lose their trailing zeros (L4001); ``[cpl] file_zeros = "keep"`` keeps the
        #: fixed decimals of STR$ and DSP
        self.trim_zeros = trim_zeros
        self.grown = grown  # what the run's writes added to its files, less what REWRITE and shorter files gave back
        self.handles = {} if handles is None else handles
        #: the PRN#(0) lines and warnings, kept only while no ``message`` / ``warn`` listener takes them
        self.messages = [] if messages is None else messages
        self.warnings = [] if warnings is None else warnings
        self._message_pending = _message_pending
        #: told of the first INP# from each file this run has not written: run-time input left by earlier runs
        #: (``ncvm translate`` marks the path that follows it FROZEN); None: nobody asks
        self.on_outside = on_outside
        self._own: set = set()  # identities of the files this run wrote from the start or read
        self.fileroot = FileRoot(self.root, self.private)  # where the program's names may reach

    # -- names ---------------------------------------------------------------------------
    def place_of(self, name) -> Place:
        """The control's file name (a string, or an INTEGER n meaning "P<n>", CPL manual L4342; L4365; L4303) placed in the
        file root, relative to the current directory unless it begins with a path from the root."""
        if isinstance(name, int) and not isinstance(name, bool):
            name = f"P{name}"
        text = text_of(name)
        if not text or not text.strip() or "\x00" in text:  # CHR$(0) ends a name on the control's side
            raise fail("INVALID_FILE_NAME", "NUL" if text is None else repr(text))
        text = text.strip()
        base = text.replace("\\", "/").rstrip("/").split("/")[-1]
        if len(base) > MAX_NAME or base in (".", ".."):
            raise fail("INVALID_FILE_NAME", text)
        return self._confined(self.fileroot.place, text, self.cwd)

    @staticmethod
    def _confined(fn, *args, **kw):
        """``fn(*args)`` with a name the file root refuses as INVALID FILE NAME."""
        try:
            return fn(*args, **kw)
        except FileRootError as e:
            raise fail("INVALID_FILE_NAME", str(e)) from None

    def open_for_writing(self, st: os.stat_result | None) -> bool:
        """Whether the file of status ``st`` is open for writing by OPENW (under any name)."""
        return st is not None and any(h.writing and h.ident == identity(st) for h in self.handles.values())

    def stat_of(self, place: Place) -> os.stat_result | None:
        """The status of the file or directory at ``place`` (None: missing); INVALID FILE NAME when
        the name is refused or a folder on the way cannot be searched."""
        try:
            return self._confined(self.fileroot.stat, place)
        except OSError as e:
            raise fail("INVALID_FILE_NAME", f"{place.shown}: {e.strerror}") from None

    def enter_directory_of(self, program: Path | str, origin: Path | None = None) -> None:
        """The current directory of a run is the main program's, when it lies in the file root (CPL manual
        L4381): names without a path are looked up there; elsewhere it stays the root. ``origin``: the file
        root this one is a scratch copy of (a translation), where the program lies."""
        try:
            folder = Path(program).resolve().parent.relative_to((origin or self.root).resolve())
        except ValueError:
            return
        self.cwd = folder.as_posix() if folder.parts else ""

    @staticmethod
    def _check_number(n, error: str = "INVALID_LOGICAL_NUMBER") -> int:
        if not isinstance(n, int) or isinstance(n, bool) or not 1 <= n <= 9:
            raise fail(error, repr(n))
        return n

    def _handle(self, n, error: str = "INVALID_LOGICAL_NUMBER") -> Handle:
        n = self._check_number(n, error)
        if n not in self.handles:
            raise fail("FILE_NOT_OPEN", f"logical number {n}")
        return self.handles[n]

    # -- reading a file into records -------------------------------------------------------
    @staticmethod
    def _parse(raw: bytes) -> tuple[list[str], bool]:
        """The records of a file's bytes and whether they were already in the control's exact form."""
        raw = raw.decode("latin-1")
        canonical = raw.endswith(EOF_MARKER) and "\r" not in raw
        body = raw
        cut = body.find("\x03")
        if cut >= 0:
            body = body[:cut]
        if not body:
            return [], canonical and cut == len(raw) - 2
        lines = body.split("\n")
        if lines[-1] == "":
            lines.pop()
        records = [line[:-1] if line.endswith("\r") else line for line in lines]
        return records, canonical

    def read_records(self, place: Place) -> list[str]:
        """The records of a file, in whatever form it is (for readers outside the file table);
        INVALID FILE NAME when the name is refused, OSError (FileNotFoundError) when it cannot be read."""
        return self._parse(self._confined(self.fileroot.read_bytes, place))[0]

    @staticmethod
    def _check_reclen(records: list[str], reclen: int | None, name: str) -> None:
        if reclen is None:
            return
        if not isinstance(reclen, int) or isinstance(reclen, bool) or not 1 <= reclen <= MAX_RECORD:
            raise fail("INVALID_COMPONENT_LENGTH", f"record length {reclen!r} (1..{MAX_RECORD})")
        for i, r in enumerate(records, 1):
            if len(r) != reclen:
                raise fail("INVALID_COMPONENT_LENGTH",
                           f"{name}: record {i} has {len(r)} characters, not {reclen}")

    # -- opening and closing ----------------------------------------------------------------
    def _open(self, place: Place, write: bool) -> int:
        """A descriptor of the file (OPENW creates a missing one); every refusal is a CPL file error."""
        try:
            return self._confined(self.fileroot.open, place, write=write, create=write,
                                  durable=write and self.durable)
        except OSError as e:
            if not write and isinstance(e, (FileNotFoundError, NotADirectoryError)):
                raise fail("FILE_NOT_FOUND", place.shown) from None
            raise fail("INVALID_FILE_NAME", f"{place.shown}: {e.strerror}") from None

    def OPENW(self, n, name, *rest) -> None:  # noqa: N802
        """``OPENW(n,name[,length][,remark][,reclen])``; a 4th argument that is a number is reclen."""
        n = self._check_number(n)
        length, remark, reclen = (list(rest) + [None, None, None])[:3]
        if isinstance(remark, int) and not isinstance(remark, bool):
            if reclen is not None:
                raise fail("INVALID_PARAMETER", "OPENW: remark must be a string")
            remark, reclen = None, remark
        if length is None:
            length = MIN_RESERVED
        if isinstance(length, float) and length.is_integer():
            length = int(length)
        if not isinstance(length, int) or isinstance(length, bool) or length < MIN_RESERVED:
            raise fail("ILLEGAL_FILE_SIZE", f"{length!r} bytes, at least {MIN_RESERVED}")
        place = self.place_of(name)
        if n in self.handles:
            raise fail("INVALID_LOGICAL_NUMBER", f"{n} is already open")
        fd = self._open(place, write=True)
        try:
            st = os.fstat(fd)
            if self.open_for_writing(st):
                raise fail("FILE_ALREADY_OPEN", place.shown)
            ident = identity(st)
            records, canonical = self._parse(read_all(fd))
            self._check_reclen(records, reclen, place.shown)
            h = Handle(n, place.shown, place, ident, True, reclen, records, rec=len(records),
                       remark=text_of(remark) or "", reserved=length, fd=fd, size=st.st_size,
                       synced_at=time.monotonic())
            h.data_size = sum(len(r) + 1 for r in records)
            if not records:  # a new or empty file: what it holds, this run wrote
                self._own.add(ident)
            if not canonical:
                self._rewrite_all(h)
        except BaseException:
            os.close(fd)
            raise
        self.handles[n] = h

    def OPENR(self, n, name, reclen=None) -> None:  # noqa: N802
        """``OPENR(n,name[,reclen])``: the pointer on record 1; with reclen every record must have it."""
        n = self._check_number(n)
        place = self.place_of(name)
        if n in self.handles:
            raise fail("INVALID_LOGICAL_NUMBER", f"{n} is already open")
        fd = self._open(place, write=False)
        try:
            ident = identity(os.fstat(fd))
            records, _ = self._parse(read_all(fd))
        finally:
            os.close(fd)
        self._check_reclen(records, reclen, place.shown)
        h = Handle(n, place.shown, place, ident, False, reclen, records)
        h.data_size = sum(len(r) + 1 for r in records)
        self.handles[n] = h

    def CLOSE(self, n) -> None:  # noqa: N802
        """``CLOSE(n)``: a record still open with ``;`` is ended, the file is fsynced (closing a closed number
        does nothing)."""
        n = self._check_number(n)
        h = self.handles.pop(n, None)
        if h is None or h.fd is None:
            return
        try:
            if h.pending is not None:
                self._append_record(h, h.pending)
                h.pending = None
        finally:
            try:
                self._sync(h)  # also after a failed last record: what was written before it
            finally:
                os.close(h.fd)
                h.fd = None

    def close_all(self) -> None:
        """End of the program (or of a run stopped by an error): every file still open is closed as by CLOSE,
        each one even when closing another fails; then the first failure is raised."""
        first = None
        for n in list(self.handles):
            try:
                self.CLOSE(n)
            except CplRuntimeError as e:
                first = first or e
        if first is not None:
            raise first

    def REWRITE(self, n) -> None:  # noqa: N802
        """``REWRITE(n)``: the data of a file open for writing is overwritten from the start."""
        h = self._handle(n)
        if not h.writing:
            raise fail("WRONG_ACCESS", f"REWRITE needs OPENW ({h.name})")
        h.records, h.rec, h.off, h.pending, h.data_size = [], 0, 0, None, 0
        self._own.add(h.ident)
        self._rewrite_all(h)

    # -- writing to disk (always through the descriptor OPENW opened) -----------------------
    def _stamp(self, fd: int) -> None:
        """The file dated at the program's time."""
        if self.clock is not None:
            t = float(getattr(self.clock, "start_epoch", 0.0)) + float(getattr(self.clock, "now", 0.0))
            try:
                os.utime(fd, (t, t))
            except (OverflowError, ValueError, OSError):
                pass  # a simulated time beyond what the file system can stamp: the file keeps its real time

    def _sync(self, h: Handle) -> None:
        """The file's writes made durable (``os.fsync``) if it has any since the last time."""
        if not h.unsynced:
            return
        if self.durable:
            try:
                os.fsync(h.fd)
            except OSError as e:
                raise fail("FILE_NOT_WRITTEN", f"{h.name}: {e.strerror}") from None
        h.unsynced, h.synced_at = False, time.monotonic()

    def _write_at(self, h: Handle, offset: int, text: str, end: int | None = None) -> None:
        """``text`` written at byte ``offset``; the file cut at ``end`` when given; dated; fsynced when
        :data:`SYNC_EVERY_S` has passed since the last fsync. FILE MEMORY FULL before a write past the run's
        file space, FILE CANNOT BE WRITTEN when the host refuses it (a full disk)."""
        data = text.encode("latin-1", errors="replace")
        size = end if end is not None else max(h.size, offset + len(data))
        growth = size - h.size
        self._check_space(h.name, growth)
        try:
            while data:
                done = os.pwrite(h.fd, data, offset)
                data, offset = data[done:], offset + done
            if size < h.size:  # cut shorter: REWRITE, or a file that held more after its EOF marker
                os.ftruncate(h.fd, size)
            h.size, h.unsynced = size, True
            self._stamp(h.fd)
        except OSError as e:
            self.grown += self._resize(h)
            raise fail("FILE_NOT_WRITTEN", f"{h.name}: {e.strerror}") from None
        self.grown += growth  # a file cut shorter (REWRITE) gives its space back
        if time.monotonic() - h.synced_at >= SYNC_EVERY_S:
            self._sync(h)

    @staticmethod
    def _resize(h: Handle) -> int:
        """After a failed write: the size the disk file really has (a write may have ended part way); returns
        what it grew by."""
        h.unsynced = True
        try:
            size = os.fstat(h.fd).st_size
        except OSError:
            return 0
        grown, h.size = size - h.size, size
        return grown

    def _check_space(self, name: str, growth: int) -> None:
        if self.space and growth > 0 and self.grown + growth > self.space:
            raise fail("FILE_MEMORY_FULL", f"{name}: the files of this run may grow by {self.space:,} bytes "
                                           f"([cpl] file_space), {self.grown:,} are written")

    def _rewrite_all(self, h: Handle) -> None:
        data = "".join(r + "\n" for r in h.records) + EOF_MARKER
        self._write_at(h, 0, data, end=len(data.encode("latin-1", errors="replace")))

    def replace_records(self, place: Place, records: list[str]) -> None:
        """Write a whole file in the control's form atomically (FileRoot.replace: a temporary file beside
        it, synced and dated like every file the program writes, renamed over the old one keeping its
        access rights), so a crash leaves either the old file or the new one, never a half-written one.
        INVALID FILE NAME when the name is refused, FILE MEMORY FULL past the run's file space; OSError when it
        cannot be written."""
        data = ("".join(r + "\n" for r in records) + EOF_MARKER).encode("latin-1", errors="replace")
        st = self.stat_of(place)
        growth = len(data) - (st.st_size if st is not None else 0)
        self._check_space(place.shown, growth)
        self._confined(self.fileroot.replace, place, data, finish=self._finish_whole, durable=self.durable)
        self.grown += growth

    def _finish_whole(self, fd: int) -> None:
        """A whole file written beside the old one, dated and fsynced before it is renamed over it."""
        self._stamp(fd)
        if self.durable:
            os.fsync(fd)

    def _append_record(self, h: Handle, text: str) -> None:
        """A completed record at the EOF marker (sequential files): written over the old marker."""
        if len(text) > MAX_RECORD:
            raise fail("BLOCK_EXCEEDS_1024", f"{len(text)} characters")
        data = text + "\n" + EOF_MARKER
        self._write_at(h, h.data_size, data, end=h.data_size + len(data))
        h.records.append(text)
        h.data_size += len(text) + 1
        h.rec, h.off = len(h.records), 0

    def _put_random(self, h: Handle, rec: int, image: str) -> None:
        """Record ``rec`` of a random file written in place (or appended at the EOF marker)."""
        tail = EOF_MARKER if rec >= len(h.records) else ""
        self._write_at(h, h.byte_of(rec), image + "\n" + tail)
        if rec >= len(h.records):
            h.records.append(image)
            h.data_size += len(image) + 1
        else:
            h.records[rec] = image

    # -- PRN# ------------------------------------------------------------------------------
    def PRN(self, n, *items, semicolon: bool = False) -> None:  # noqa: N802 - PRN#
        """``PRN#(n,e1,e2,...[;])``: the items concatenated by the rules of format.py; n = 0 is the
        message window (or the editor block in an editor dialog)."""
        if n == 0:
            self._prn_message(items, semicolon)
            return
        h = self._handle(n)
        if not h.writing:
            raise fail("WRONG_ACCESS", f"PRN# needs OPENW ({h.name})")
        text = self._format(items, trim=self.trim_zeros)
        segments = text.split("\r")  # CHR$(13) starts a new record
        for i, seg in enumerate(segments):
            last = i == len(segments) - 1
            complete = not (last and semicolon)
            if len(seg) > MAX_RECORD:
                raise fail("BLOCK_EXCEEDS_1024", f"{len(seg)} characters")
            if h.random:
                self._prn_random(h, seg, complete, keep_tail=semicolon and last)
            else:
                pending = (h.pending or "") + seg
                if complete:
                    h.pending = None
                    self._append_record(h, pending)
                else:
                    if len(pending) > MAX_RECORD:
                        raise fail("BLOCK_EXCEEDS_1024", f"{len(pending)} characters")
                    h.pending = pending

    def _prn_random(self, h: Handle, seg: str, complete: bool, keep_tail: bool) -> None:
        rec = h.rec
        old = h.records[rec] if rec < len(h.records) else " " * h.reclen
        head = old[: h.off]
        if keep_tail:  # with ';' the rest of the old record stays (L4025)
            image = (head + seg + old[len(head) + len(seg):])[: h.reclen]
        else:  # without ';' the rest is blanked
            image = (head + seg)[: h.reclen]
        image = image.ljust(h.reclen)
        self._put_random(h, rec, image)
        if complete:
            h.rec, h.off = rec + 1, 0
        else:
            h.off = min(h.off + len(seg), h.reclen)
            if h.off >= h.reclen:
                h.rec, h.off = rec + 1, 0

    def _format(self, items, trim: bool = False) -> str:
        result = format_items(items, ljust=self.mode.ljust, on_overflow="star", trim=trim)
        if result.overflows:
            self._warn(warning("PRN_FORMAT_INCORRECT", result.text))
        return result.text

    def _prn_message(self, items, semicolon: bool) -> None:
        text = self._message_pending + self._format(items)
        if semicolon:
            self._message_pending = text
            return
        self._message_pending = ""
        if self.editor_block is not None:
            self.editor_block = text.replace("\r", "")
            if self.on_editor_block is not None:
                self.on_editor_block(self.editor_block)
            return
        for line in text.split("\r"):
            if self.message is not None:
                self.message(line)
            else:
                self.messages.append(line)

    def _warn(self, w: CplWarning) -> None:
        if self.warn is not None:
            self.warn(w)
        else:
            self.warnings.append(w)

    # -- INP# ------------------------------------------------------------------------------
    def INP(self, n, *targets, semicolon: bool = False) -> list:  # noqa: N802 - INP#
        """``INP#(n,v1,v2,...[;])``: read values from the current record.

        Each target says what is read: a type letter ``"I"``, ``"R"``, ``"D"``, ``"B"`` or ``"S"``
        (a non-dimensioned variable), a :class:`CharacterField` (filled in place, as many characters
        as its DIM size) or a :class:`StringView` (``MID$(E$,s,c)``: c characters written into E$ at
        s). Returns one value per target (None = NUL), which the caller stores into plain variables.
        A number or BOOLEAN that cannot be read gives NUL and leaves the position where it is.
        """
        if n == 0:
            return self._inp_editor(targets)
        h = self._handle(n)
        if h.writing:
            raise fail("WRONG_ACCESS", f"INP# needs OPENR ({h.name})")
        values = []
        for target in targets:
            if h.rec >= len(h.records):
                values.append(None)
                continue
            record = h.records[h.rec]
            value, h.off = self._read_one(record, h.off, target)
            values.append(value)
        if h.rec < len(h.records) and (not semicolon or h.off >= len(h.records[h.rec])):
            h.rec, h.off = h.rec + 1, 0  # with ';' the pointer stays until the record is used up
        if self.on_outside is not None and h.ident not in self._own:
            self._own.add(h.ident)
            said = ", ".join("NUL" if v is None else repr(v) for v in values)
            self.on_outside(f"controller file {h.name} read ({said}), left by earlier runs")
        return values

    @staticmethod
    def _read_one(record: str, off: int, target):
        if isinstance(target, CharacterField):
            text = record[off: off + target.size]
            target.assign(text)
            return text, off + len(text)
        if isinstance(target, StringView):
            count = target.count if target.count is not None else target.source.size - target.start + 1
            text = record[off: off + count]
            target.source.write(target.start, count, text)
            return text, off + len(text)
        if target == "S":  # a non-dimensioned string takes the rest of the record (ncvm's reading; the CPL manual is silent)
            return record[off:], len(record)
        if target == "B":
            rest = record[off:].lstrip(" ")
            for word, value in (("TRUE", True), ("FALSE", False)):
                if rest.upper().startswith(word):
                    return value, len(record) - len(rest) + len(word)
            return None, off
        if target not in ("I", "R", "D"):
            raise TypeError(f"INP# target {target!r}")
        found = scan_number(record[: _integer_end(record, off)] if target == "I" else record, off)
        if found is None:
            return None, off
        value, end = found
        if target == "I":
            if not INT_MIN <= value <= INT_MAX:
                raise fail("INVALID_INTEGER_VALUE", record[off:end].strip())
            return int(value), end
        try:
            value = float(value)
        except OverflowError:  # an integer text of more than 309 digits
            value = float("inf")
        if (target == "R" and abs(value) > REAL_MAX) or value in (float("inf"), float("-inf")):
            raise fail("INVALID_FLOAT_VALUE", record[off:end].strip())
        return value, end

    def _inp_editor(self, targets) -> list:
        """``INP#(0,P1,...)`` in an editor dialog: the call parameters of the selected block, one per
        target (editor.call_parameters). A parameter is read by INP#'s rules, but it must be read
        whole: one that is no constant of the target's type (``X%``, ``2*A``) and a missing one give
        NUL. A string target takes the parameter's text (a string constant without its quotes)."""
        params = call_parameters(self.editor_block or "")
        values = []
        for i, target in enumerate(targets):
            text = params[i] if i < len(params) else ""
            if isinstance(target, (CharacterField, StringView)) or target == "S":
                text = text[1:-1] if len(text) >= 2 and text[0] == text[-1] == '"' else text
                values.append(self._read_one(text, 0, target)[0] if text else None)
                continue
            value, end = self._read_one(text, 0, target) if text else (None, 0)
            values.append(value if value is not None and not text[end:].strip() else None)
        return values

    # -- positions -------------------------------------------------------------------------
    def EOF(self, n) -> bool:  # noqa: N802
        """``EOF(n)``: TRUE when the pointer is on the EOF marker (at once for an empty file)."""
        h = self._handle(n)
        return h.rec >= len(h.records)

    def FILEPOS(self, n, mode=None) -> int:  # noqa: N802
        """``FILEPOS(n[,mode])``: random 1 byte, 2 record (default), 3 offset in the record; sequential 1 byte."""
        h = self._handle(n, "INVALID_FILE_NUMBER")
        allowed = (1, 2, 3) if h.random else (1,)
        if mode is None:
            mode = 2 if h.random else 1
        if mode not in allowed:
            raise fail("INVALID_PARAMETER", f"FILEPOS mode {mode!r}")
        if mode == 1:  # a record still open with ';' counts with what it holds so far
            return h.byte_of(h.rec) + h.off + len(h.pending or "") + 1
        if mode == 2:
            return h.rec + 1
        return h.off + 1  # 1 on the EOF marker

    def SEEK(self, n, k, o=None) -> None:  # noqa: N802
        """``SEEK(n,k[,o])``: record k (random) or byte k (sequential), 0 = the EOF marker; o = offset in
        the record (random only)."""
        h = self._handle(n, "INVALID_FILE_NUMBER")
        if not isinstance(k, int) or isinstance(k, bool):
            raise fail("INVALID_COMPONENT", repr(k))
        if not h.random:
            if h.writing:
                raise fail("WRONG_ACCESS", f"SEEK on a sequential file needs OPENR ({h.name})")
            if o is not None:
                raise fail("INVALID_PARAMETER", "record offset on a sequential file")
            if k == 0:
                h.rec, h.off = len(h.records), 0
                return
            if not 1 <= k <= h.data_size:
                raise fail("INVALID_COMPONENT", f"byte {k} of {h.data_size}")
            byte = k - 1
            for i, r in enumerate(h.records):
                if byte <= len(r):
                    h.rec, h.off = i, byte
                    return
                byte -= len(r) + 1
            return
        if o is not None and (not isinstance(o, int) or not 1 <= o <= h.reclen + 1):
            raise fail("INVALID_PARAMETER", f"record offset {o!r} (1..{h.reclen + 1})")
        if k == 0:
            k = len(h.records) + 1
        if not 1 <= k <= len(h.records) + 1:
            raise fail("INVALID_COMPONENT", f"record {k} of {len(h.records)}")
        h.rec, h.off = k - 1, (o or 1) - 1

    def FILESIZE(self, n, k=None) -> int:  # noqa: N802
        """``FILESIZE(n[,k])`` on a file opened with OPENR: 1 bytes used, 2 bytes before the EOF marker,
        3 records that fit (random), 4 records up to EOF (random)."""
        h = self._handle(n, "INVALID_FILE_NUMBER")
        if h.writing:
            raise fail("WRONG_ACCESS", f"FILESIZE needs OPENR ({h.name})")
        k = 1 if k is None else k
        if k not in ((1, 2, 3, 4) if h.random else (1, 2)):
            raise fail("INVALID_PARAMETER", f"FILESIZE k {k!r}")
        used = h.data_size + len(EOF_MARKER)
        return {1: used, 2: h.data_size, 3: used // ((h.reclen or 1) + 1), 4: len(h.records)}[k]

    # -- the file system -------------------------------------------------------------------
    def _is_active(self, ident: tuple[int, int]) -> bool:
        if any(h.ident == ident for h in self.handles.values()):
            return True
        for p in self.active:
            try:
                if identity(os.stat(p)) == ident:
                    return True
            except OSError:
                pass
        return False

    def ERASE(self, name) -> int:  # noqa: N802
        """``ERASE(name)``: 0 erased, 1 does not exist, 2 erase-protected, 3 active; 1-3 also warn."""
        place = self.place_of(name)
        st = self.stat_of(place)
        if st is not None and not stat.S_ISDIR(st.st_mode):
            self._confined(FileRoot.require_file, st, place.shown)  # a FIFO, device or socket
        if st is None or stat.S_ISDIR(st.st_mode):
            code = 1
        elif not st.st_mode & stat.S_IWUSR:
            code = 2
        elif self._is_active(identity(st)):
            code = 3
        else:
            try:
                self._confined(self.fileroot.unlink, place)
                return 0
            except FileNotFoundError:
                code = 1  # gone meanwhile
            except PermissionError:
                code = 2  # the folder does not let it go
        reason = {1: "does not exist", 2: "is erase-protected", 3: "is active"}[code]
        self._warn(warning("FILE_NOT_ERASED", f"{place.shown} {reason}"))
        return code

    def _status(self, name) -> os.stat_result | None:
        """The status of a file or directory for FILEACCESS/FILEDATE; None for a name that does not
        exist, is refused or names a FIFO, device or socket."""
        try:
            st = self.stat_of(self.place_of(name))
        except (OSError, CplRuntimeError):
            return None
        if st is None or not (stat.S_ISREG(st.st_mode) or stat.S_ISDIR(st.st_mode)):
            return None
        return st

    def FILEACCESS(self, name) -> int:  # noqa: N802
        """``FILEACCESS(name)``: -1 missing, else bits 1 X, 2 W, 4 R, 8 directory, 16 active program."""
        st = self._status(name)
        if st is None:  # a bad name also means "does not exist"
            return -1
        mode = st.st_mode
        bits = 0
        bits |= 1 if mode & stat.S_IXUSR and not stat.S_ISDIR(mode) else 0
        bits |= 2 if mode & stat.S_IWUSR else 0
        bits |= 4 if mode & stat.S_IRUSR else 0
        bits |= 8 if stat.S_ISDIR(mode) else 0
        bits |= 16 if stat.S_ISREG(mode) and self._is_active(identity(st)) else 0
        return bits

    def FILEDATE(self, name, mode=None) -> str:  # noqa: N802
        """``FILEDATE(name[,mode])``: 1 "dd.mm.yy" (default), 2 "hh.mm.ss"; "" on any access error."""
        st = self._status(name)
        if st is None:  # the manual: an access error gives "", never an error
            return ""
        try:
            t = time.gmtime(st.st_mtime)
        except (OverflowError, OSError, ValueError):
            return ""
        if mode in (None, 1):
            return f"{t.tm_mday:02d}.{t.tm_mon:02d}.{t.tm_year % 100:02d}"
        if mode == 2:
            return f"{t.tm_hour:02d}.{t.tm_min:02d}.{t.tm_sec:02d}"
        return ""


def _integer_end(record: str, off: int) -> int:
    """For an INTEGER target the number ends at a decimal point."""
    cut = record.find(".", off)
    return len(record) if cut < 0 else cut
