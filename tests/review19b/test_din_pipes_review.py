"""Review of a DIN program from a pipe and of a long program read twice (small19, dinread19), as a machine-shop
user with CAM output would use them. Each test is one defect found; its docstring says what is expected and why.

The commands run ``python -m ncvm`` in a temporary folder. A test that waits for the program to reach a point
(a read of its standard input, a message on stderr) waits with a generous deadline only so that a defect
cannot hang the suite; nothing here asserts a duration.
"""

from __future__ import annotations

import json
import os
import pty
import select
import signal
import subprocess
import sys
import termios
import time
from pathlib import Path

import pytest

import ncvm.dialects.din as din
from ncvm.api import run
from ncvm.nc import block
from ncvm.nc.block import COLUMNS_FROM
from ncvm.runtime.session import RunOptions

NCVM = [sys.executable, "-m", "ncvm"]
#: how long a test waits for something ncvm should say at once before it calls the defect (no speed asserted)
DEADLINE_S = 15.0
PROGRAM = b"G21 G90\nG1 X10 F1000\nY10\nM30\n"


def _stderr_within(proc: subprocess.Popen, seconds: float) -> bytes:
    """What ``proc`` wrote on stderr until it wrote a line or ended, waiting at most ``seconds``."""
    said = b""
    end = time.monotonic() + seconds
    fd = proc.stderr.fileno()
    while time.monotonic() < end and b"\n" not in said:
        ready, _, _ = select.select([fd], [], [], 0.2)
        if ready:
            more = os.read(fd, 4096)
            if not more:
                break
            said += more
        elif proc.poll() is not None:
            break
    return said


def _reading_stdin(pid: int) -> bool:
    """Whether process ``pid`` is blocked in read(2) on file descriptor 0 (x86-64: system call 0)."""
    try:
        return Path(f"/proc/{pid}/syscall").read_text().split()[:2] == ["0", "0x0"]
    except OSError:
        return False


def test_a_fifo_without_a_writer_says_what_it_waits_for(tmp_path):
    """``ncvm run -d din part.fifo`` with no process writing the FIFO waits in open(2) and says nothing at all:
    no prompt, no spinner (stderr is not a terminal), no time-out; a user or a batch job sees a command that
    hangs for ever. Expected: before it blocks, one line on stderr naming the FIFO and that the run waits for
    a writer (or a refusal that exits), as the brief of the pipe feature asks ("must not hang forever
    silently")."""
    fifo = tmp_path / "part.fifo"
    os.mkfifo(fifo)
    proc = subprocess.Popen([*NCVM, "run", "-d", "din", str(fifo)], cwd=tmp_path, stdin=subprocess.DEVNULL,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    try:
        said = _stderr_within(proc, DEADLINE_S)
    finally:
        if proc.poll() is None:  # let the run go on: give it its writer
            with open(fifo, "wb") as writer:
                writer.write(PROGRAM)
        proc.communicate(timeout=120)
    assert "part.fifo" in said.decode(errors="replace"), \
        f"nothing said while waiting {DEADLINE_S:.0f} s for a writer: {said!r}"


def test_a_terminal_on_stdin_is_not_read_as_a_program_in_silence(tmp_path):
    """``ncvm run -d din -`` typed at a terminal without a pipe (a forgotten ``< part.ngc``) reads the terminal
    until Ctrl-D and says nothing (with stderr on the terminal too it shows the progress spinner "running 0
    moves, 0:00 simulated", which reads as a run that hangs). Expected: a refusal (a program is piped, not
    typed) or a line on stderr saying that the program is read from the terminal and how to end it, before
    anything is typed."""
    master, slave = pty.openpty()
    proc = subprocess.Popen([*NCVM, "run", "-d", "din", "-"], cwd=tmp_path, stdin=slave, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE)
    os.close(slave)
    try:
        said = _stderr_within(proc, DEADLINE_S)
    finally:
        if proc.poll() is None:  # type the program and Ctrl-D
            os.write(master, PROGRAM + termios.tcgetattr(master)[6][termios.VEOF])
        proc.communicate(timeout=120)
        os.close(master)
    assert said.strip(), f"nothing said in {DEADLINE_S:.0f} s while the terminal was read as the program"


def test_ctrl_c_while_the_program_is_read_from_stdin_names_run004(tmp_path):
    """Ctrl-C while ``ncvm run -d din -`` waits for its pipe prints only "ncvm: run interrupted by the user"
    (exit 1), where Ctrl-C during the run prints "error RUN004" and the summary "stopped with error RUN004",
    SIGTERM at the same point "ncvm: error RUN009: ...", and --json says RUN004. A log must tell an operator's
    Ctrl-C from the other stops by its code (docs/decisions.md, "SIGTERM and SIGHUP end a run ... with error
    RUN009, not Ctrl-C's RUN004"). Expected: RUN004 on stderr."""
    proc = subprocess.Popen([*NCVM, "run", "-d", "din", "-"], cwd=tmp_path, stdin=subprocess.PIPE,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    proc.stdin.write(PROGRAM[:10])  # the writer is still at work
    proc.stdin.flush()
    end = time.monotonic() + DEADLINE_S
    while not _reading_stdin(proc.pid) and time.monotonic() < end and proc.poll() is None:
        time.sleep(0.05)
    if not _reading_stdin(proc.pid):
        proc.kill()
        proc.communicate()
        pytest.skip("cannot see the process read its standard input (/proc/PID/syscall)")
    proc.send_signal(signal.SIGINT)
    _, err = proc.communicate(timeout=120)
    assert proc.returncode == 1
    assert "RUN004" in err.decode(), err.decode()


def test_a_piped_program_cut_before_its_end_does_not_end_normally(tmp_path):
    """A CAM post or a copy that dies mid-stream leaves ncvm a program opened with ``%`` and cut in the middle of a
    block, with neither the closing ``%`` nor M2/M30; ``cat part.ngc | ncvm run -d din -`` then says "ended
    normally" with exit 0, and ``ncvm check -d din -`` finds nothing: a silently wrong answer for the half of a
    part. rs274 (the DIN reference, docs/din.md) refuses such a file: "File ended with no percent sign"
    (NCE_FILE_ENDED_WITH_NO_PERCENT_SIGN, read_text), and one without ``%`` and without a program end with "File
    ended with no percent sign or program end". Expected: an error (or at least a warning) naming the missing
    end, from run and check alike."""
    cut = b"%\nG21 G90\nG1 X10 F1000\nY10\nX0 Y1"  # "X0 Y10\nM30\n%\n" lost
    ran = subprocess.run([*NCVM, "run", "-d", "din", "-"], cwd=tmp_path, input=cut, capture_output=True,
                         timeout=120)
    checked = subprocess.run([*NCVM, "check", "-d", "din", "-"], cwd=tmp_path, input=cut, capture_output=True,
                             timeout=120)
    said = ran.stderr.decode()
    assert ran.returncode != 0 or "warning" in said, said
    assert "0 diagnostic(s)" not in checked.stderr.decode(), checked.stderr.decode()


#: 3,000 feed moves, every line as long as the others (the line a rewrite adds shifts the rest by one line)
OLD = "\n".join(["G21 G90 G17 G94 F150"] + [f"G1 X{i % 100:03d}.0 Y{i // 100:03d}.0" for i in range(3000)]
                + ["M30"]) + "\n"
#: the same part 500 mm further in Y, with one line more at its top: the CAM post's next version of the file
NEW = "G1 X000.5 Y000.5\n" + OLD.replace(" Y0", " Y5")


@pytest.mark.parametrize("held_stretches", [6, None], ids=["held_prefix", "held_whole"])
def test_a_file_rewritten_while_its_first_reading_is_under_way_is_not_run_as_a_mixture(
        tmp_path, monkeypatch, held_stretches):
    """A CAM post writes the program again in place while the run's first reading is in the stretches the run
    holds. The first reading reads the old file's first stretches and, from the position it stood at, the new
    file's bytes; the second reading (from the first stretch not held) finds what the first reading recorded
    there, so nothing is seen: the run ends "ok" with a part that is neither version (the old contour for
    about 600 lines, then the new one 500 mm away, a line read twice at the seam). docs/decisions.md ("RUN008
    covers what is read again") says a change inside the held stretches that changes their length stops the
    run with RUN008; before dinread19 the whole file was read again and compared, so this was RUN008 at line
    1. Expected: RUN008 (or a refusal) whenever the file changed during the run's readings, e.g. its size or
    modification time differ from those at the start of the first reading; never a run of a mixture."""
    monkeypatch.setattr(block, "CHUNK_CHARS", 4096)
    program = tmp_path / "grid.ngc"
    program.write_text(OLD)
    if held_stretches:
        with din.ProgramStretches(str(program), None) as stretches:
            costs = [din.held_bytes(stretch) for stretch in stretches(COLUMNS_FROM)]
        assert len(costs) > held_stretches + 2
        monkeypatch.setattr(din, "HOLD_BYTES", sum(costs[:held_stretches]))
    real, passes = din.file_stretches, []

    def rewritten_during_the_first_reading(file, at=None):
        passes.append(at)
        for k, piece in enumerate(real(file, at)):
            yield piece
            if len(passes) == 1 and k == 1:  # the first reading has read two stretches
                program.write_text(NEW)

    monkeypatch.setattr(din, "file_stretches", rewritten_during_the_first_reading)
    trace = tmp_path / "run.trace"
    result, _ = run(program, dialect="din", options=RunOptions(state_dir=tmp_path / ".ncvm", trace=trace))
    ends = [json.loads(line)["end"]["Y"] for line in trace.read_text().splitlines() if '"call": "feed"' in line]
    old_only = sum(1 <= y < 30 for y in ends)  # rows 1-29 of the old part: not in the new file
    new_only = sum(y >= 500 for y in ends)  # the new part: not in the old file
    assert result["status"] == "error", f"ran a mixture: {old_only} moves of the old file, {new_only} of the new"
    assert result["error"]["code"] in ("RUN008", "NC001")


def test_translate_from_stdin_says_it_reads_files_not_that_there_is_no_program(tmp_path):
    """``cat part.ngc | ncvm translate -d din - -o part_lcnc.ngc``: translate reads files only
    (docs/decisions.md, pipes: "ncvm compile and translate still read files only"), but the refusal says
    "no such program: -", which sends a user looking for a missing file while run and check take ``-``.
    Expected: a usage error that says translate takes a program file, not stdin."""
    done = subprocess.run([*NCVM, "translate", "-d", "din", "-", "-o", "out.ngc"], cwd=tmp_path, input=PROGRAM,
                          capture_output=True, timeout=120)
    said = done.stderr.decode()
    assert done.returncode == 2, said
    assert "no such program" not in said, said
    assert "stdin" in said or "pipe" in said, said
