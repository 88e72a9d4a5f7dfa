"""A DIN program read a stretch at a time (issue 18, bounded memory): the same run, the same errors and the same
refusals whether a program is held whole or read again stretch by stretch as it runs."""

from __future__ import annotations

import pytest

import ncvm.dialects.din as din
from ncvm.nc import block
from tests.conftest import random_program

SMALL = {"CHUNK_CHARS": 64, "KEEP_CHARS": 0}  # stretches of a few lines, nothing held: the streaming path


def both(run_text, monkeypatch, text: str, **opts) -> tuple[dict, dict]:
    """The result of ``text`` read in one stretch and held, then read in tiny stretches and streamed."""
    whole = run_text(text, **opts)
    with monkeypatch.context() as m:
        m.setattr(block, "CHUNK_CHARS", SMALL["CHUNK_CHARS"])
        m.setattr(din, "KEEP_CHARS", SMALL["KEEP_CHARS"])
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
