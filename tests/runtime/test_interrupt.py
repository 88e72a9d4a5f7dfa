"""Ctrl-C ends a run at a block boundary: the --json summary and the trace describe the same moves."""

from __future__ import annotations

import json
import signal
import subprocess
import sys
from pathlib import Path

import pytest

from ncvm.runtime import interrupt
from tests.runtime.ctrl_c import ctrl_c, grown_past

NCVM = str(Path(sys.executable).parent / "ncvm")


def test_a_ctrl_c_inside_a_block_is_raised_after_it():
    done = []
    with interrupt.deferring():
        with pytest.raises(KeyboardInterrupt):
            with interrupt.block():
                signal.raise_signal(signal.SIGINT)
                done.append("the block ran to its end")
    assert done == ["the block ran to its end"]
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler


def test_an_interrupted_cpl_run_with_rapids_and_feeds_agrees_with_its_trace(tmp_path):
    (tmp_path / "zig.cpl").write_text("(ZIG)\n10 FOR I% = 1 TO 2000000\nN20 G1 X[I% * 0.001] F9000\n"
                                      "N25 G0 Y[I% * 0.002]\n30 NEXT I%\nM30\n")
    trace = tmp_path / "t.jsonl"
    proc = subprocess.Popen([NCVM, "run", "zig.cpl", "--state", "st", "--json", "--trace", str(trace)],
                            cwd=tmp_path, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    out, err = ctrl_c(proc, grown_past(trace, 200_000), "the trace to grow")
    assert proc.returncode == 1 and "interrupted" in err
    doc = json.loads(out)
    assert doc["error"]["code"] == "RUN004"
    records = [json.loads(line) for line in trace.read_text().splitlines()]
    moves = [r for r in records if r["call"] in ("feed", "rapid")]
    assert doc["motion"]["feed_moves"] == sum(r["call"] == "feed" for r in moves)
    assert doc["motion"]["rapid_moves"] == sum(r["call"] == "rapid" for r in moves)
    assert doc["position"] == moves[-1]["work"]
