"""Shared fixtures: write a program into a temporary folder and run it; random plain DIN programs."""

from __future__ import annotations

import math
import os
import random
import shlex
import signal
import socket
import subprocess
import sys
import threading
import time
from pathlib import Path

import pytest
from hypothesis import settings

from ncvm.api import run
from ncvm.runtime.session import RunOptions

# hypothesis (tests/robustness/test_fuzz.py): in CI the same examples every time and no example database,
# so that a failure repeats; elsewhere random examples, with failures kept in .hypothesis/ and tried first
settings.register_profile("ci", derandomize=True, database=None, print_blob=True)
settings.register_profile("dev")
settings.load_profile("ci" if os.environ.get("CI") == "true" else "dev")


def _memory_backed_temp_root(min_free: int = 2 * 2**30) -> None:
    """Put the tests' tmp_path folders on /dev/shm where it is a tmpfs with room to spare.

    A state directory used to commit every permanent write with ``synchronous=FULL`` (an fsync each; now the
    store syncs its log once a second and at its close): on a disk shared with other work one fsync can take
    several milliseconds, and the tests that count thousands of writes spent most of their time waiting for
    the disk. On tmpfs the same writes, locks, renames, kills and
    files happen; only the wait for the platter goes. A small /dev/shm (a container's 64 MB) or none at all
    keeps the usual temporary folder; an explicit --basetemp or PYTEST_DEBUG_TEMPROOT wins.
    """
    shm = "/dev/shm"
    if "PYTEST_DEBUG_TEMPROOT" in os.environ or not os.path.isdir(shm) or not os.access(shm, os.W_OK):
        return
    fs = os.statvfs(shm)
    if fs.f_bavail * fs.f_frsize >= min_free:
        os.environ["PYTEST_DEBUG_TEMPROOT"] = shm  # read by pytest when it makes its first tmp_path


_memory_backed_temp_root()


@pytest.fixture
def run_text(tmp_path: Path):
    """run_text(text, name="prog.din", machine=None, **options) -> result dict."""

    def _run(text: str, name: str = "prog.din", machine=None, dialect=None, **opts):
        path = tmp_path / name
        path.write_text(text, encoding="latin-1")
        options = RunOptions(state_dir=tmp_path / ".ncvm", **opts)
        result, _session = run(path, dialect=dialect, machine=machine, options=options)
        return result

    return _run



def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


@pytest.fixture
def free_port() -> int:
    """A TCP port on 127.0.0.1 that nothing listens on (free when asked)."""
    return _free_port()


@pytest.fixture
def dask_processes(tmp_path: Path):
    """start(nworkers=1, tmpfs_on=None) -> address: ``dask scheduler`` and ``dask worker`` as processes of
    their own, on 127.0.0.1 only, ready when it returns; stopped after the test (SIGTERM to each process
    group, SIGKILL after 30 s). With `tmpfs_on` the worker runs in a mount namespace of its own with an empty
    tmpfs on that folder: a worker host that has the same path, but not the same files."""
    distributed = pytest.importorskip("distributed")
    dask = str(Path(sys.executable).parent / "dask")
    quiet = {"stdout": subprocess.DEVNULL, "stderr": subprocess.DEVNULL, "start_new_session": True}
    procs: list[subprocess.Popen] = []

    def start(nworkers: int = 1, tmpfs_on: Path | None = None) -> str:
        port = _free_port()
        address = f"tcp://127.0.0.1:{port}"
        procs.append(subprocess.Popen([dask, "scheduler", "--host", "127.0.0.1", "--port", str(port),
                                       "--no-dashboard"], **quiet))
        worker = [dask, "worker", address, "--host", "127.0.0.1", "--nthreads", "1", "--nworkers", str(nworkers),
                  "--no-dashboard", "--local-directory", str(tmp_path)]
        if tmpfs_on is not None:
            worker = ["unshare", "-m", "sh", "-c",
                      f"mount -t tmpfs none {shlex.quote(str(tmpfs_on))} && cd / && exec {shlex.join(worker)}"]
        procs.append(subprocess.Popen(worker, **quiet))
        with distributed.Client(address, timeout=60) as client:
            client.wait_for_workers(nworkers, timeout=60)
        return address

    try:
        yield start
    finally:
        for p in reversed(procs):
            os.killpg(p.pid, signal.SIGTERM)
            try:
                p.wait(timeout=30)
            except subprocess.TimeoutExpired:
                os.killpg(p.pid, signal.SIGKILL)
                p.wait()



@pytest.fixture
def killed_writer(tmp_path: Path):
    """killed_writer(code, delay) -> the numbers it printed: `python -c code tmp_path` (a writer that prints a
    number per record written), killed without warning (SIGKILL) `delay` s after its first number."""
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path))

    def kill(code: str, delay: float) -> list[int]:
        proc = subprocess.Popen([sys.executable, "-c", code, str(tmp_path)], stdout=subprocess.PIPE, text=True,
                                env=env)
        first = proc.stdout.readline()  # the writer runs
        assert first.strip().isdigit()
        time.sleep(delay)
        proc.send_signal(signal.SIGKILL)
        printed = [int(x) for x in [first, *proc.stdout.read().split()] if str(x).strip()]
        proc.wait()
        return printed

    return kill

PLANE_AXES = {17: (0, 1, "IJ"), 18: (2, 0, "KI"), 19: (1, 2, "JK")}


def random_program(seed: int) -> str:
    """Lines, arcs in all planes, G90/G91, inch, zero offsets, feeds, blank and N-only lines, comments."""
    rnd = random.Random(seed)
    out = ["%", "(random plain program)", "G21 G90 G17", f"G10 L2 P1 X{rnd.uniform(-20, 20):.3f} Y{rnd.uniform(-5, 5):.3f}",
           "G54", "G92 X0 Y0 Z0", "F1000"]
    if rnd.random() < 0.3:
        out.append("G20")
    pos = [0.0, 0.0, 0.0]
    absolute, plane, n, arc_mode = True, 17, 10, False
    for _ in range(rnd.randint(50, 400)):
        r = rnd.random()
        if r < 0.03:
            absolute = not absolute
            out.append("G90" if absolute else "G91")
            continue
        if r < 0.06:
            plane = rnd.choice((17, 18, 19))
            out.append(f"G{plane}")
            continue
        if r < 0.08:
            out.append(rnd.choice(["", "N5", "(note)", f"F{rnd.randint(100, 3000)}", "   "]))
            continue
        words = []
        if rnd.random() < 0.8:
            words.append(f"N{n}")
            n += 10
        if rnd.random() < 0.25:
            a, b, letters = PLANE_AXES[plane]
            ca, cb = pos[a] + rnd.uniform(-8, 8), pos[b] + rnd.uniform(-8, 8)
            turn = rnd.uniform(-3, 3)
            ra, rb = pos[a] - ca, pos[b] - cb
            end = list(pos)
            end[a] = round(ca + ra * math.cos(turn) - rb * math.sin(turn), 4)
            end[b] = round(cb + ra * math.sin(turn) + rb * math.cos(turn), 4)
            if rnd.random() < 0.3:  # helix
                end[3 - a - b] = round(pos[3 - a - b] + rnd.uniform(-2, 2), 4)
            words.append(rnd.choice(("G2", "G3", "G02", "G03")))
            arc_mode = True
            for i in sorted({a, b, 3 - a - b}):
                if end[i] != pos[i] or i in (a, b):
                    words.append(f"{'XYZ'[i]}{(end[i] if absolute else end[i] - pos[i]):.4f}")
            words.append(f"{letters[0]}{ca - pos[a]:.4f}")
            words.append(f"{letters[1]}{cb - pos[b]:.4f}")
        else:
            if arc_mode or rnd.random() < 0.7:  # a straight move after an arc names its G code
                words.append(rnd.choice(("G0", "G1", "G00", "G01")))
                arc_mode = False
            end = list(pos)
            for i in range(3):
                if rnd.random() < 0.6:
                    end[i] = round(pos[i] + rnd.uniform(-10, 10), 4)
                    words.append(f"{'XYZ'[i]}{(end[i] if absolute else end[i] - pos[i]):.4f}")
        if rnd.random() < 0.1:
            words.append(f"F{rnd.randint(100, 3000)}")
        pos = end
        out.append(" ".join(words))
    out.append("M30")
    return "\n".join(out) + "\n"


@pytest.fixture
def random_din():
    """random_din(seed) -> the text of a random plain DIN program (see random_program)."""
    return random_program


def fifo_with(path: Path, text: str) -> Path:
    """A FIFO at ``path`` that a thread writes ``text`` to once a reader opens it."""
    os.mkfifo(path)

    def write():
        with open(path, "w") as pipe:
            pipe.write(text)

    threading.Thread(target=write, daemon=True).start()
    return path


def killed_after(p: subprocess.Popen, count: int, counted) -> tuple[int, str]:
    """Reads the stdout of the run ``p`` until ``counted(line, so_far)`` reaches ``count`` (what the program said
    it wrote), then SIGKILLs it: (the count reached, its stderr)."""
    said = 0
    try:
        for line in p.stdout:
            said = counted(line, said)
            if said == count:
                break
        p.send_signal(signal.SIGKILL)
    finally:
        p.kill()
        _, err = p.communicate(timeout=60)
    return said, err

