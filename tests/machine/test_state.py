"""The state directory is one controller's memory: one run at a time, with real concurrent ``ncvm`` processes.

A run that prints more than a pipe holds blocks while nobody reads its stdout, so the test decides
when the first run may end: every other run meets it while it certainly still holds the directory.
"""

from __future__ import annotations

import os
import signal
import sqlite3
import subprocess
import sys
import time
from pathlib import Path

import pytest

from ncvm.api import run as api_run
from ncvm.machine.state import StateError, StateLock
from ncvm.machine.store import Store
from ncvm.runtime.session import RunOptions

# 3000 read-modify-writes of a permanent variable; each pass prints a line (about 180 KB in all, more
# than a pipe holds)
COUNTER = """\
5 IF @5 = NUL THEN @5 = 0 ENDIF
10 FOR I%=1 TO 3000
20 @5 = @5 + 1
30 PRN#(0,"pass ",I%," of 3000: the permanent counter is counted up by one")
40 NEXT I%
50 PRN#(0,"@5 = ",@5)
M30
"""
QUIET = COUNTER.replace('30 PRN#(0,"pass ",I%," of 3000: the permanent counter is counted up by one")\n', "")
ENV = dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path))


def start(program: Path, state: Path, **kw) -> subprocess.Popen:
    return subprocess.Popen([sys.executable, "-m", "ncvm", "run", str(program), "--state", str(state)],
                            env=ENV, text=True, stdout=subprocess.PIPE, stderr=subprocess.PIPE, **kw)


def holding(proc: subprocess.Popen, state: Path) -> None:
    """Wait until ``proc`` holds the state directory (its pid is in the lock file)."""
    deadline = time.monotonic() + 30
    while time.monotonic() < deadline:
        lock = state / "lock"
        if lock.exists() and lock.read_text().strip() == str(proc.pid):
            return
        assert proc.poll() is None, proc.communicate()
        time.sleep(0.02)
    raise AssertionError("the run never took its state directory")


def counter(state: Path) -> int:
    s = Store(state)
    try:
        return s.get("cpl.perm", "@5")
    finally:
        s.close()


@pytest.fixture
def program(tmp_path) -> Path:
    p = tmp_path / "count.cpl"
    p.write_text(COUNTER)
    return p


def test_runs_on_one_state_are_refused_at_once_while_one_runs_and_every_write_lands(tmp_path, program):
    state = tmp_path / "st"
    first = start(program, state)
    holding(first, state)
    others = [start(program, state) for _ in range(3)]
    for other in others:
        out, err = other.communicate(timeout=60)
        assert other.returncode == 2, err
        assert (f"ncvm: error: state directory {state} is in use by another run (pid {first.pid}); wait for it "
                f"to end or give another --state") in err
        assert "Traceback" not in err and out == ""
    assert first.poll() is None, "the refused runs did not wait for the first one"
    out, err = first.communicate(timeout=60)
    assert first.returncode == 0, err
    assert out.splitlines()[-1].split() == ["@5", "=", "3000"]
    # three more runs, one after the other, each adds its 3000
    program.write_text(QUIET)
    for n in (6000, 9000, 12000):
        result, _ = api_run(program, options=RunOptions(state_dir=state))
        assert result["status"] == "ok" and result["output"][-1].split() == ["@5", "=", str(n)]
    assert counter(state) == 12000


def test_a_killed_run_gives_the_state_back_and_keeps_what_it_committed(tmp_path, program):
    state = tmp_path / "st"
    victim = start(program, state)
    holding(victim, state)
    victim.stdout.read(70_000)  # let it get further than its first block of output
    victim.send_signal(signal.SIGKILL)
    victim.wait()
    db = sqlite3.connect(state / "store.sqlite")
    assert db.execute("PRAGMA integrity_check").fetchone()[0] == "ok"
    db.close()
    kept = counter(state)
    assert 0 < kept < 3000  # it was killed in the middle of its loop
    result, _ = api_run(program, options=RunOptions(state_dir=state))  # not refused: the kill freed the lock
    assert result["status"] == "ok" and result["output"][-1].split() == ["@5", "=", str(kept + 3000)]


def test_one_process_cannot_take_a_state_twice(tmp_path):
    with StateLock(tmp_path / "st"):
        with pytest.raises(StateError, match="is in use by another run"):
            StateLock(tmp_path / "st").acquire()
    StateLock(tmp_path / "st").acquire().release()  # free again


def test_a_state_that_is_a_file_is_refused(tmp_path):
    (tmp_path / "st").write_text("")
    with pytest.raises(StateError, match=f"state directory {tmp_path / 'st'} is a file"):
        StateLock(tmp_path / "st").acquire()


# -- a state directory ncvm cannot use: exit 2 with one line naming the file and what to do --------------------


def ncvm(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "ncvm", *args], env=ENV, text=True, capture_output=True, timeout=60)


def refused(proc: subprocess.CompletedProcess) -> str:
    """The one error line of a run that was refused with exit 2."""
    assert proc.returncode == 2, proc.stderr
    assert "bug in ncvm" not in proc.stderr and "Traceback" not in proc.stderr
    lines = proc.stderr.splitlines()
    assert len(lines) == 1 and lines[0].startswith("ncvm: error: "), proc.stderr
    return lines[0]


def test_a_damaged_or_foreign_store_stops_the_run_before_it_starts(tmp_path):
    prog = tmp_path / "count.cpl"
    prog.write_text(QUIET)
    state = tmp_path / "st"
    state.mkdir()
    (state / "store.sqlite").write_bytes(b"\x89PNG\r\n\x1a\n" + bytes(2000))
    line = refused(ncvm("run", str(prog), "--state", str(state)))
    assert line == (f"ncvm: error: {state / 'store.sqlite'} is not an ncvm permanent store (not a SQLite "
                    f"database); move it away or give another --state")


def mount(request, *args: str) -> None:
    """Mount for the test's duration (root only: the real read-only and full file systems)."""
    if os.geteuid() != 0 or subprocess.run(["mount", *args], capture_output=True).returncode != 0:
        pytest.skip("needs root and mount")
    request.addfinalizer(lambda: subprocess.run(["umount", "-l", args[-1]], check=True))


def test_a_read_only_state_directory_is_refused(tmp_path, request):
    prog = tmp_path / "count.cpl"
    prog.write_text(QUIET)
    folder = tmp_path / "ro"
    assert api_run(prog, options=RunOptions(state_dir=folder / "st"))[0]["status"] == "ok"
    mount(request, "--bind", str(folder), str(folder))
    subprocess.run(["mount", "-o", "remount,bind,ro", str(folder)], check=True)
    line = refused(ncvm("run", str(prog), "--state", str(folder / "st")))
    assert line == (f"ncvm: error: state directory {folder / 'st'} cannot be written (Read-only file system); "
                    f"make it writable or give another --state")
    with pytest.raises(StateError, match=f"state directory {folder / 'new'} cannot be written"):
        api_run(prog, options=RunOptions(state_dir=folder / "new"))


def test_a_full_disk_stops_the_run_with_what_to_do_and_the_store_keeps_what_was_committed(tmp_path, request):
    prog = tmp_path / "count.cpl"
    prog.write_text(QUIET)
    disk = tmp_path / "disk"
    disk.mkdir()
    mount(request, "-t", "tmpfs", "-o", "size=256k", "tmpfs", str(disk))
    state = disk / "st"
    line = refused(ncvm("run", str(prog), "--state", str(state)))
    assert line == (f"ncvm: error: cannot write the permanent store {state / 'store.sqlite'}: the disk is full; "
                    f"free some space and run again (the store keeps what was written before)")
    with pytest.raises(StateError, match=f"cannot write the permanent store {disk / 'new' / 'store.sqlite'}: "
                                         "the disk is full"):
        api_run(prog, options=RunOptions(state_dir=disk / "new"))
    subprocess.run(["mount", "-o", "remount,size=16m", str(disk)], check=True)  # space freed
    kept = counter(state)
    assert 0 < kept < 3000
    out = ncvm("run", str(prog), "--state", str(state))
    assert out.returncode == 0 and out.stdout.split() == ["@5", "=", str(kept + 3000)]


# -- what stands at <state>/lock or <state>/store.sqlite is not always a plain file -------------------------------


def test_a_lock_that_is_a_symlink_is_refused_and_its_target_left_whole(tmp_path):
    """The lock file is truncated to hold the pid: followed through a symlink, that would empty any file
    the user may write (a run as root emptied /etc/passwd)."""
    victim = tmp_path / "victim.txt"
    victim.write_text("keep me\n")
    state = tmp_path / "st"
    state.mkdir()
    (state / "lock").symlink_to(victim)
    prog = tmp_path / "count.cpl"
    prog.write_text(QUIET)
    line = refused(ncvm("run", str(prog), "--state", str(state)))
    assert f"{state / 'lock'} is a symbolic link" in line and "remove it" in line
    assert victim.read_text() == "keep me\n"


@pytest.mark.parametrize("how", ["hard link", "a file of the user"])
def test_a_lock_that_holds_no_pid_is_refused_and_left_whole(tmp_path, how):
    """A hard link to another file passes O_NOFOLLOW; its text is not a pid, so it is never emptied."""
    victim = tmp_path / "victim.txt"
    victim.write_text("keep me\n")
    state = tmp_path / "st"
    state.mkdir()
    if how == "hard link":
        os.link(victim, state / "lock")
    else:
        (state / "lock").write_text("keep me\n")
    prog = tmp_path / "count.cpl"
    prog.write_text(QUIET)
    line = refused(ncvm("run", str(prog), "--state", str(state)))
    assert f"{state / 'lock'} holds something other than the pid of a run; move it away" in line
    assert victim.read_text() == "keep me\n" and (state / "lock").read_text() == "keep me\n"


def test_a_lock_left_by_a_killed_run_is_taken_over(tmp_path):
    state = tmp_path / "st"
    state.mkdir()
    (state / "lock").write_text("999999999\n")
    with StateLock(state):
        assert (state / "lock").read_text() == f"{os.getpid()}\n"
    assert (state / "lock").read_text() == ""


KIND_WORDS = {"fifo": "FIFO", "directory": "directory", "symbolic link": "symbolic link"}


@pytest.mark.parametrize("kind", ["fifo", "directory"])
def test_a_lock_that_is_no_plain_file_is_refused_naming_it(tmp_path, kind):
    state = tmp_path / "st"
    state.mkdir()
    if kind == "fifo":
        os.mkfifo(state / "lock")
    else:
        (state / "lock").mkdir()
    prog = tmp_path / "count.cpl"
    prog.write_text(QUIET)
    line = refused(ncvm("run", str(prog), "--state", str(state)))
    assert f"{state / 'lock'} is a {KIND_WORDS[kind]}, not a file" in line and "remove it" in line


@pytest.mark.parametrize("side", ["-wal", "-shm"])
def test_a_side_file_of_the_store_that_is_a_symlink_is_named(tmp_path, side):
    """SQLite does not write through it, but called it "unable to open database file"."""
    state = tmp_path / "st"
    Store(state).close()
    victim = tmp_path / "victim"
    victim.write_text("keep me\n")
    (state / f"store.sqlite{side}").unlink(missing_ok=True)
    (state / f"store.sqlite{side}").symlink_to(victim)
    prog = tmp_path / "count.cpl"
    prog.write_text(QUIET)
    line = refused(ncvm("run", str(prog), "--state", str(state)))
    assert f"{state / ('store.sqlite' + side)} is a symbolic link, not a file; move it away" in line
    assert victim.read_text() == "keep me\n"


@pytest.mark.parametrize("kind", ["fifo", "directory", "symbolic link"])
def test_a_store_that_is_no_plain_file_is_refused_naming_it(tmp_path, kind):
    """A symlink to the store of another state directory: two runs, each holding its own lock, would write
    one store at once."""
    state = tmp_path / "st"
    state.mkdir()
    if kind == "fifo":
        os.mkfifo(state / "store.sqlite")
    elif kind == "directory":
        (state / "store.sqlite").mkdir()
    else:
        Store(tmp_path / "other").close()
        (state / "store.sqlite").symlink_to(tmp_path / "other" / "store.sqlite")
    prog = tmp_path / "count.cpl"
    prog.write_text(QUIET)
    line = refused(ncvm("run", str(prog), "--state", str(state)))
    assert f"{state / 'store.sqlite'} is a {KIND_WORDS[kind]}, not a file" in line and "move it away" in line


def test_a_state_that_is_a_broken_symlink_is_named_as_such(tmp_path):
    (tmp_path / "st").symlink_to(tmp_path / "nowhere")
    with pytest.raises(StateError, match=f"state directory {tmp_path / 'st'} is a symbolic link to nothing"):
        StateLock(tmp_path / "st").acquire()


@pytest.mark.parametrize("statement", ['ERASE("st/store.sqlite")', 'ERASE("st/lock")', 'ERASE("/st/store.sqlite-wal")',
                                       'OPENW(1,"st/lock",1000)', 'OPENW(1,"ST/../st/link/x.I",1000)'])
def test_a_program_cannot_touch_the_store_or_lock_of_a_state_directory_in_the_file_root(tmp_path, statement):
    """file_root = "." with the state directory beside the programs: an ERASE of the store lost every permanent
    value, an ERASE of the lock let a second run in."""
    axes = "".join(f'[[axis]]\nname = "{n}"\n' for n in "XYZ")
    (tmp_path / "machine.toml").write_text(axes + '[paths]\nfile_root = "."\n')
    (tmp_path / "st" / "link").mkdir(parents=True)
    prog = tmp_path / "clobber.cpl"
    prog.write_text(f"10 @5 = 7\n20 {statement}\n30 @5 = 8\nM30\n")
    proc = ncvm("run", str(prog), "--machine", str(tmp_path / "machine.toml"), "--state", str(tmp_path / "st"))
    assert proc.returncode == 1 and "error CPL609: INVALID FILE NAME" in proc.stderr, proc.stderr
    assert "lies in the state directory, outside the file root" in proc.stderr
    assert (tmp_path / "st" / "lock").is_file() and counter(tmp_path / "st") == 7
    assert not (tmp_path / "st" / "link" / "x.I").exists()


def test_a_program_still_reaches_its_files_beside_the_state_directory(tmp_path):
    axes = "".join(f'[[axis]]\nname = "{n}"\n' for n in "XYZ")
    (tmp_path / "machine.toml").write_text(axes + '[paths]\nfile_root = "."\n')
    prog = tmp_path / "log.cpl"
    prog.write_text('10 OPENW(1,"mine",1000)\n20 PRN#(1,"kept")\n30 CLOSE(1)\n40 ERASE("lockfile")\nM30\n')
    (tmp_path / "lockfile").write_text("x\n")
    proc = ncvm("run", str(prog), "--machine", str(tmp_path / "machine.toml"), "--state", str(tmp_path / "st"))
    assert proc.returncode == 0, proc.stderr
    assert (tmp_path / "mine").read_text(encoding="latin-1").startswith("kept")
    assert not (tmp_path / "lockfile").exists()
