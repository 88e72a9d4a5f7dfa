"""A DIN program read a stretch at a time (issue 18, bounded memory): the same run, the same errors and the same
refusals whether a program is held whole or read again stretch by stretch as it runs."""

from __future__ import annotations

import pytest

import ncvm.dialects.din as din
from ncvm.nc import block
from tests.conftest import random_program

SMALL = {"CHUNK_CHARS": 64, "HOLD_BYTES": 0}  # stretches of a few lines, nothing held: the streaming path


def both(run_text, monkeypatch, text: str, **opts) -> tuple[dict, dict]:
    """The result of ``text`` read in one stretch and held, then read in tiny stretches and streamed."""
    whole = run_text(text, **opts)
    with monkeypatch.context() as m:
        m.setattr(block, "CHUNK_CHARS", SMALL["CHUNK_CHARS"])
        m.setattr(din, "HOLD_BYTES", SMALL["HOLD_BYTES"])
        streamed = run_text(text, **opts)
    return whole, streamed


@pytest.mark.parametrize("seed", range(6))
def test_a_streamed_run_is_the_held_run(run_text, monkeypatch, seed):
    whole, streamed = both(run_text, monkeypatch, random_program(seed), keep_toolpath=False)
    assert whole["status"] == "ok", whole["error"]
    assert streamed == whole


def test_stretches_number_the_lines_of_the_whole_program(monkeypatch):
    text = "".join(f"G1 X{i} F100\n" + ("(note)\n" if i % 7 == 0 else "") for i in range(60))
    monkeypatch.setattr(block, "CHUNK_CHARS", 40)
    chunks = list(block.read_din_chunks("p.ngc", text))
    assert len(chunks) > 5
    segments, diags = block.read_din_segments("p.ngc", text)
    assert not diags and len([s for c, _ in chunks for s in c]) == len(segments)
    lines = [int(n) for s in segments if isinstance(s, block.PlainRun) for n in s.lines]
    lines += [s[0].src.line for s in segments if not isinstance(s, block.PlainRun)]
    assert sorted(lines) == [n for n, line in enumerate(text.splitlines(), 1) if line != "(note)"]
    run = next(s for s in segments if isinstance(s, block.PlainRun) and s.lines[0] > 20)
    assert run.block(0).words["X"] == float(text.splitlines()[int(run.lines[0]) - 1].split()[1][1:])


def test_a_syntax_error_late_in_a_streamed_program_stops_it_before_any_move(run_text, monkeypatch):
    text = "".join(f"G1 X{i} F100\n" for i in range(50)) + "G1 X1 Y\n" + "G1 X2\n" * 20
    whole, streamed = both(run_text, monkeypatch, text)
    assert whole["error"]["code"] == streamed["error"]["code"] == "NC001"
    assert whole["error"]["line"] == streamed["error"]["line"] == 51
    assert streamed["motion"]["feed_moves"] == 0


def test_a_refused_axis_late_in_a_streamed_program_runs_the_blocks_before_it(run_text, monkeypatch):
    text = "".join(f"G1 X{i} F100\n" for i in range(50)) + "G1 B5\n" + "G1 X2\n" * 20
    whole, streamed = both(run_text, monkeypatch, text)
    assert whole["error"]["code"] == streamed["error"]["code"] == "NC011"
    assert whole["error"]["line"] == streamed["error"]["line"] == 51
    assert whole["motion"]["feed_moves"] == streamed["motion"]["feed_moves"] == 50



def test_a_fault_counts_the_blocks_run_up_to_it(run_text, monkeypatch):
    """An arc the kernel refuses at line 21 after 20 blocks ran (G1 F100 and 19 moves): 21 steps, the
    faulting block with them, held or streamed (the count was 0: the blocks of the stretch were lost)."""
    text = "G1 F100\n" + "".join(f"X{i}\n" for i in range(1, 20)) + "G2 X100 Y0 R1\nM2\n"
    whole, streamed = both(run_text, monkeypatch, text)
    assert whole["error"]["code"] == streamed["error"]["code"] == "NC002"
    assert whole["steps"] == streamed["steps"] == 21
    assert whole["motion"]["feed_moves"] == 19


# -- read from the file (issue 18: a 10,000,000-line file peaked at 680 MB, held whole as text) --------------


def test_a_run_never_reads_the_file_whole(run_text, monkeypatch, refuse_whole_reads, tmp_path, reads):
    """The API does not read a .ngc file into one string (it did: text, then a copy without CR), and the
    dialect reads it in stretches of about CHUNK_CHARS characters, each ending at a line end."""

    def whole(path):
        raise AssertionError(f"{path} read whole")

    pieces = reads
    refuse_whole_reads(whole)
    monkeypatch.setattr(block, "CHUNK_CHARS", 64)
    text = random_program(3)
    r = run_text(text, name="p.ngc")
    assert r["status"] == "ok", r["error"]
    longest = max(len(line) for line in text.splitlines()) + 1
    assert "".join(pieces) == text and max(map(len, pieces)) <= 64 + longest
    monkeypatch.setattr(din, "HOLD_BYTES", 0)  # too long to hold: read twice, the second time as it runs
    pieces.clear()
    assert run_text(text, name="p.ngc") == r and "".join(pieces) == text * 2


@pytest.mark.parametrize("ending", ["\r\n", "\r"])
def test_cr_lf_and_lone_cr_files_run_as_lf_files(run_text, monkeypatch, tmp_path, ending):
    """A file's lines end in LF, CR LF or a lone CR (source.lines reads all three): the same run, streamed from
    the file, and an error on the same line with its source line; a byte-order mark is no character."""
    text = random_program(4)
    lf = run_text(text, name="lf.ngc", keep_toolpath=False)
    path = tmp_path / "cr.ngc"
    path.write_bytes(b"\xef\xbb\xbf" + text.replace("\n", ending).encode("latin-1"))
    from ncvm.api import run
    from ncvm.runtime.session import RunOptions

    for chunk in (64, block.CHUNK_CHARS):
        with monkeypatch.context() as m:
            m.setattr(block, "CHUNK_CHARS", chunk)
            m.setattr(din, "HOLD_BYTES", 0)
            r, _ = run(path, options=RunOptions(state_dir=tmp_path / ".ncvm", keep_toolpath=False))
        assert r == lf
    bad = text.replace("\n", ending, 30).split(ending)
    assert len(bad) == 31
    path.write_bytes(ending.join(bad[:30] + ["G1 X1 Y (late)\n" + bad[30]]).encode("latin-1"))
    monkeypatch.setattr(block, "CHUNK_CHARS", 64)
    r, _ = run(path, options=RunOptions(state_dir=tmp_path / ".ncvm"))
    assert (r["error"]["code"], r["error"]["line"]) == ("NC001", 31)
    from ncvm.diagnostics import Diagnostic, Span

    shown = Diagnostic("NC001", "x", Span(str(path), 31, r["error"]["column"])).render().split("\n")
    assert shown[1] == "    G1 X1 Y (late)"


def test_stepping_trace_and_plot_of_a_streamed_run_are_those_of_the_held_run(run_text, monkeypatch, tmp_path):
    """The debugger's hook sees every block with its line and position, the trace and the plot get every
    move: the same whether the program is held or read again stretch by stretch as it runs."""
    text = random_program(5).replace("\n", "\n/G1 X999 (skipped)\n", 1)
    seen = {}
    for held in (True, False):
        steps = []
        with monkeypatch.context() as m:
            if not held:
                m.setattr(block, "CHUNK_CHARS", SMALL["CHUNK_CHARS"])
                m.setattr(din, "HOLD_BYTES", SMALL["HOLD_BYTES"])
            trace = tmp_path / f"t{held}.jsonl"
            r = run_text(text, name="p.ngc", trace=trace, plot=True,
                         hook=lambda file, line, pos, steps=steps: steps.append((line, tuple(pos))))
        assert r["status"] == "ok", r["error"]
        seen[held] = (r, steps, trace.read_text())
    assert seen[True] == seen[False]
    r, steps, trace = seen[True]
    assert len(steps) == r["steps"] and 3 not in [line for line, _ in steps]  # "/G1 X999" skipped
    assert trace.count('"call": "feed"') + trace.count('"call": "arc"') == r["motion"]["feed_moves"] + \
        r["motion"]["arc_moves"]


def test_program_end_stops_reading(run_text, monkeypatch):
    """M2 ends the run where it stands: the blocks after it are neither run nor read for refusals that the run
    never reaches (a later line with an axis the machine lacks is no error)."""
    text = "".join(f"G1 X{i} F100\n" for i in range(40)) + "M2\n" + "G1 B5\n" + "G1 X2\n" * 40
    whole, streamed = both(run_text, monkeypatch, text)
    assert whole["status"] == streamed["status"] == "ok"
    assert whole["motion"]["feed_moves"] == streamed["motion"]["feed_moves"] == 40
    assert whole == streamed


def test_a_missing_or_unreadable_program_is_a_usage_error(tmp_path):
    """Not read by the API any more, a .ngc file that cannot be opened still stops before the run with the
    message of a file the API reads (the command line exits 2 on it)."""
    from ncvm.api import run
    from ncvm.diagnostics import UsageError
    from ncvm.runtime.session import RunOptions

    for path, dialect in ((tmp_path / "none.ngc", None), (tmp_path / "none", "din"), (tmp_path, "din")):
        with pytest.raises(UsageError, match=f"cannot read {path}: "):
            run(path, dialect=dialect, options=RunOptions(state_dir=tmp_path / "s"))
    assert not (tmp_path / "s").exists()  # stopped before the state was touched


def test_a_program_from_a_named_pipe_is_read_once(tmp_path):
    """The API runs a program it is given as a FIFO (the command line takes files only): its readability check
    must not open the pipe (that would take the writer's data), and the pipe is read once, from where it
    stands."""
    import os
    import subprocess
    import sys
    import threading

    fifo = tmp_path / "p.ngc"
    os.mkfifo(fifo)

    def write():
        with open(fifo, "w") as pipe:
            pipe.write("G1 X1 F100\nG1 X2 Y3\nM2\n")

    threading.Thread(target=write, daemon=True).start()
    code = ("import json, sys\nfrom pathlib import Path\nfrom ncvm.api import run\n"
            "from ncvm.runtime.session import RunOptions\n"
            "r, _ = run(sys.argv[1], options=RunOptions(state_dir=Path(sys.argv[2])))\n"
            "print(json.dumps([r['status'], r['motion']['feed_moves'], r['position']]))\n")
    done = subprocess.run([sys.executable, "-c", code, str(fifo), str(tmp_path / "s")], capture_output=True,
                          text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == '["ok", 2, {"X": 2.0, "Y": 3.0, "Z": 0.0}]'
