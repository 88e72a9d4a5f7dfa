"""When what PRN# writes is safe (docs/decisions.md, "CPL files: the durability point").

Every record reaches the operating system before PRN# returns, so a killed ncvm loses none; a file is
fsynced at CLOSE, at the end of the run, when the run stops with an error, and once SYNC_EVERY_S has
passed since its last fsync -- not once a record (that cost milliseconds a record on a disk).
"""

from __future__ import annotations

import errno
import os
import signal
import stat
import subprocess
import sys
from pathlib import Path

import pytest

import ncvm.dialects.cpl.io.files as files_module
from ncvm.dialects.cpl.io.errors import CplRuntimeError
from ncvm.dialects.cpl.io.files import CplFiles
from ncvm.machine.model import SimClock
from tests.conftest import killed_after

ETX = "\x03\n"


class Fsyncs(list):
    """The fsyncs of files, each as (name, content of the file at that moment); ``dirs``: the paths of the
    directories fsynced; ``order``: the names of both, in the order they came."""

    def __init__(self):
        super().__init__()
        self.dirs: list[Path] = []
        self.order: list[str] = []


@pytest.fixture
def fsyncs(monkeypatch):
    seen = Fsyncs()
    real = os.fsync

    def fsync(fd):
        path = Path(os.readlink(f"/proc/self/fd/{fd}"))
        seen.order.append(path.name)
        if stat.S_ISDIR(os.fstat(fd).st_mode):
            seen.dirs.append(path)
        else:
            with open(f"/proc/self/fd/{fd}", "rb") as f:
                seen.append((path.name, f.read().decode("latin-1")))
        real(fd)

    monkeypatch.setattr(os, "fsync", fsync)
    return seen


@pytest.fixture
def fs(tmp_path):
    return CplFiles(root=tmp_path, clock=SimClock(now=0.0, start_epoch=1_700_000_000.0))


def records(n: int, prefix: str = "REC") -> str:
    return "".join(f"{prefix} {i}\n" for i in range(1, n + 1))


# -- a killed run ---------------------------------------------------------------------------------------------


KILLED = """\
5 OPENW(1,"SEQ") : OPENW(2,"RND",130,12)
10 FOR I%=1 TO 100000000
20 PRN#(1,"REC ",I%)
30 PRN#(2,"R",I%)
40 PRN#(0,"WROTE ",I%)
50 NEXT I%
60 CLOSE(1) : CLOSE(2)
M30
"""


def test_a_run_killed_with_sigkill_loses_no_record_it_said_it_wrote(tmp_path):
    """``ncvm run`` as a process writes a sequential and a random file and says each record it wrote;
    SIGKILL after the 300th: both files hold every record it said (and those it wrote meanwhile), complete,
    in order, ended by the EOF marker -- valid CPL files with nothing torn."""
    (tmp_path / "prog.cpl").write_text(KILLED)
    p = subprocess.Popen([sys.executable, "-m", "ncvm", "run", "prog.cpl", "--state", ".ncvm"], cwd=tmp_path,
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                         env=dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path)))
    said, err = killed_after(p, 300, lambda line, _: int(line.split()[-1]))
    assert said == 300 and p.returncode == -signal.SIGKILL, err
    folder = tmp_path / ".ncvm" / "files"
    seq = (folder / "SEQ").read_bytes().decode("latin-1")
    rnd = (folder / "RND").read_bytes().decode("latin-1")
    assert seq.endswith(ETX) and rnd.endswith(ETX)
    seq_records, rnd_records = seq[:-2].splitlines(), rnd[:-2].splitlines()
    assert len(seq_records) >= said and len(rnd_records) >= said  # the run went on while the test read
    assert seq_records == [f"REC {i:9d}" for i in range(1, len(seq_records) + 1)]
    assert rnd_records == [f"R{i:9d}".ljust(12) for i in range(1, len(rnd_records) + 1)]


# -- where the fsyncs are ---------------------------------------------------------------------------------------


def test_close_fsyncs_the_file_once_with_every_record_in_it(fs, fsyncs):
    fs.OPENW(1, "LOG")
    for i in range(1, 201):
        fs.PRN(1, f"REC {i}")
    assert fsyncs == []  # 200 records written, none fsynced one by one
    fs.PRN(1, "LAST", semicolon=True)
    fs.CLOSE(1)
    assert fsyncs == [("LOG", records(200) + "LAST\n" + ETX)]
    fs.CLOSE(1)  # closing a closed number does nothing
    assert len(fsyncs) == 1


def test_a_file_read_or_left_unwritten_is_not_fsynced(fs, fsyncs):
    (fs.root / "DATA").write_text("A\n" + ETX)
    fs.OPENR(1, "DATA")
    fs.OPENW(2, "DATA2")  # new: the EOF marker is written, so it is fsynced
    (fs.root / "KEPT").write_text("K\n" + ETX)
    fs.OPENW(3, "KEPT")  # already in the control's form: nothing written
    fs.close_all()
    assert fsyncs == [("DATA2", ETX)]


def test_the_time_budget_fsyncs_a_file_while_it_is_written(fs, fsyncs, monkeypatch):
    """Once SYNC_EVERY_S has passed since the last fsync, the next write fsyncs (here every write)."""
    monkeypatch.setattr(files_module, "SYNC_EVERY_S", 0.0)
    fs.OPENW(1, "LOG")
    fs.PRN(1, "ONE")
    fs.PRN(1, "TWO")
    assert fsyncs == [("LOG", ETX), ("LOG", "ONE\n" + ETX), ("LOG", "ONE\nTWO\n" + ETX)]
    fs.CLOSE(1)
    assert len(fsyncs) == 3  # nothing written since the last one


def test_without_durability_nothing_is_fsynced(tmp_path, fsyncs):
    fs = CplFiles(root=tmp_path, durable=False)
    fs.OPENW(1, "LOG")
    fs.PRN(1, "ONE")
    fs.CLOSE(1)
    assert fsyncs == [] and fsyncs.dirs == [] and (tmp_path / "LOG").read_text() == "ONE\n" + ETX


# -- the directory entry of a new file ---------------------------------------------------------------------------


def test_openw_of_a_new_file_syncs_its_directory_once_before_any_data(fs, fsyncs):
    """A new file's name is in its directory only when the directory is synced: without it a power loss can
    lose the file whose records were fsynced. OPENW syncs it once, at once; records and CLOSE sync the file."""
    fs.OPENW(1, "LOG")
    assert fsyncs.dirs == [fs.root]
    for i in range(1, 4):
        fs.PRN(1, f"REC {i}")
    fs.CLOSE(1)
    assert fsyncs.dirs == [fs.root] and fsyncs == [("LOG", records(3) + ETX)]
    assert fsyncs.order == [fs.root.name, "LOG"]


def test_openw_of_a_file_that_exists_does_not_sync_the_directory(fs, fsyncs):
    (fs.root / "KEPT").write_text("K\n" + ETX)
    fs.OPENW(1, "KEPT")
    fs.PRN(1, "MORE")
    fs.CLOSE(1)
    assert fsyncs.dirs == [] and fsyncs == [("KEPT", "K\nMORE\n" + ETX)]


def test_openw_syncs_the_entry_of_each_folder_it_makes(fs, fsyncs):
    fs.OPENW(1, "/JOBS/DAY1/LOG")
    fs.CLOSE(1)
    jobs = fs.root / "JOBS"
    assert fsyncs.dirs == [fs.root, jobs, jobs / "DAY1"]  # JOBS in the root, DAY1 in JOBS, LOG in DAY1
    assert (jobs / "DAY1" / "LOG").read_text() == ETX


def test_openw_syncs_the_entries_of_a_file_root_it_makes(tmp_path, fsyncs):
    """The file root under a state directory that does not exist yet (the built-in machine's .ncvm/files): the
    state directory's entry, the root's and the file's are synced, each in its parent."""
    state = tmp_path / ".ncvm"
    fs = CplFiles(root=state / "files", clock=SimClock(now=0.0, start_epoch=1_700_000_000.0))
    fs.OPENW(1, "LOG")
    fs.CLOSE(1)
    assert fsyncs.dirs == [tmp_path, state, state / "files"]
    assert (state / "files" / "LOG").read_text() == ETX


def test_a_directory_the_file_system_cannot_sync_is_skipped_quietly(fs, monkeypatch):
    """fsync of a directory fails with EINVAL on some file systems (and platforms): the file is written and
    fsynced all the same."""
    synced, real = [], os.fsync

    def fsync(fd):
        if stat.S_ISDIR(os.fstat(fd).st_mode):
            raise OSError(errno.EINVAL, "Invalid argument")
        synced.append(fd)
        real(fd)

    monkeypatch.setattr(os, "fsync", fsync)
    fs.OPENW(1, "LOG")
    fd = fs.handles[1].fd
    fs.PRN(1, "ONE")
    fs.CLOSE(1)
    assert synced == [fd] and (fs.root / "LOG").read_text() == "ONE\n" + ETX


def test_a_directory_sync_that_fails_refuses_openw_and_keeps_no_descriptor(fs, monkeypatch):
    real = os.fsync

    def fsync(fd):
        if stat.S_ISDIR(os.fstat(fd).st_mode):
            raise OSError(errno.EIO, "Input/output error")
        real(fd)

    monkeypatch.setattr(os, "fsync", fsync)
    before = set(os.listdir("/proc/self/fd"))
    with pytest.raises(CplRuntimeError) as err:
        fs.OPENW(1, "LOG")
    assert "LOG: Input/output error" in err.value.message and fs.handles == {}
    assert set(os.listdir("/proc/self/fd")) <= before


def prn_program(n: int, tail: str) -> str:
    return f'5 OPENW(1,"LOG")\n10 FOR I%=1 TO {n}\n20 PRN#(1,"REC ",I%)\n30 NEXT I%\n{tail}M30\n'


def logged(n: int) -> str:
    return "".join(f"REC {i:9d}\n" for i in range(1, n + 1))


def test_a_run_ending_without_close_fsyncs_its_file(run_text, tmp_path, fsyncs, monkeypatch):
    monkeypatch.setattr(files_module, "SYNC_EVERY_S", float("inf"))
    r = run_text(prn_program(300, ""), name="p.cpl")
    assert r["status"] == "ok", r["error"]
    assert fsyncs == [("LOG", logged(300) + ETX)]


def test_a_run_stopped_by_an_error_fsyncs_its_file_with_the_open_record(run_text, fsyncs, monkeypatch):
    """CPL028 (division by zero) after 300 records and a record open with ';': the file is closed as by
    CLOSE, so the open record is ended and everything is fsynced once."""
    monkeypatch.setattr(files_module, "SYNC_EVERY_S", float("inf"))
    r = run_text(prn_program(300, '40 PRN#(1,"OPEN";)\n50 A=1/0\n'), name="p.cpl")
    assert r["error"]["code"] == "CPL028" and r["error"]["line"] == 6
    assert fsyncs == [("LOG", logged(300) + "OPEN\n" + ETX)]


def test_close_all_closes_every_file_when_one_cannot_be_written(fs, fsyncs, monkeypatch):
    """The first file's last record fails (a full disk): the second is still fsynced and closed, and the
    failure is reported."""
    fs.OPENW(1, "FULL")
    fs.OPENW(2, "FINE")
    fs.PRN(1, "OPEN", semicolon=True)
    fs.PRN(2, "DONE")
    full = fs.handles[1].fd
    real = os.pwrite

    def pwrite(fd, data, offset):
        if fd == full:
            raise OSError(28, "No space left on device")
        return real(fd, data, offset)

    monkeypatch.setattr(os, "pwrite", pwrite)
    with pytest.raises(CplRuntimeError) as err:
        fs.close_all()
    assert err.value.code == "CPL615" and fs.handles == {}
    assert ("FINE", "DONE\n" + ETX) in fsyncs and [name for name, _ in fsyncs] == ["FULL", "FINE"]


def test_an_fsync_the_host_refuses_is_a_file_error_and_the_file_is_closed(fs, monkeypatch):
    fs.OPENW(1, "LOG")
    fd = fs.handles[1].fd

    def failing(_fd):
        raise OSError(5, "Input/output error")

    monkeypatch.setattr(os, "fsync", failing)
    with pytest.raises(CplRuntimeError) as err:
        fs.CLOSE(1)
    assert err.value.message == "FILE CANNOT BE WRITTEN: LOG: Input/output error"
    with pytest.raises(OSError):
        os.fstat(fd)


# -- the size kept with the handle instead of an fstat a record ---------------------------------------------------


def test_data_after_the_eof_marker_is_cut_by_the_next_record(fs):
    (fs.root / "LOG").write_text("A\n" + ETX + "OLD TEXT AFTER THE MARKER\n" + ETX)
    fs.OPENW(1, "LOG")
    fs.PRN(1, "B")
    assert (fs.root / "LOG").read_text() == "A\nB\n" + ETX
    fs.CLOSE(1)


def test_a_write_that_ended_part_way_is_written_over_by_the_next(fs, monkeypatch):
    """A full disk took 12 bytes of a record: the next record, once there is room, leaves no trace of them
    and the file space counts the file as it is."""
    fs.space = 10_000
    fs.OPENW(1, "LOG")
    real = os.pwrite

    def part_way(fd, data, offset):
        real(fd, data[:12], offset)
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(os, "pwrite", part_way)
    with pytest.raises(CplRuntimeError):
        fs.PRN(1, "A RECORD THE DISK HAD NO ROOM FOR")
    monkeypatch.setattr(os, "pwrite", real)
    fs.PRN(1, "B")
    fs.CLOSE(1)
    assert (fs.root / "LOG").read_text() == "B\n" + ETX
    assert fs.grown == len("B\n" + ETX)
