"""The block buffer: without ``[cpl] lookahead`` preparation runs at most BLOCK_BUFFER blocks ahead."""

from __future__ import annotations

from pathlib import Path

import pytest

from ncvm.dialects.cpl.runtime import BLOCK_BUFFER
from ncvm.machine.config import machine_from_dict

LOOP = """\
N1 G90 G1 F60000
10 I% = 1
20 WHILE I% <= {n} DO
G1 X[I% * 0.001]
30 I% = I% + 1
40 END
50 P = MPOS(1)
60 Q = CPOS(1)
M30
"""


def machine(tmp_path: Path, **cpl):
    data = {"axis": [{"name": "X", "max": 1000.0}, {"name": "Y"}, {"name": "Z"}],
            "paths": {"program_path": ["."], "file_root": "files"}}
    if cpl:
        data["cpl"] = cpl
    return machine_from_dict(data, "<test>", tmp_path)


@pytest.mark.parametrize("cpl", [{}, {"lookahead": 0}], ids=["unset", "zero"])
def test_a_full_buffer_executes_its_older_half(tmp_path, run_text, cpl):
    n = BLOCK_BUFFER + BLOCK_BUFFER // 4
    r = run_text(LOOP.format(n=n), name="p.cpl", machine=machine(tmp_path, **cpl))
    assert r["status"] == "ok", r["error"]
    # N1 and the first BLOCK_BUFFER - 1 moves filled the buffer: its older half ran (N1 and the moves to
    # X (BLOCK_BUFFER / 2 - 1) * 0.001), the newer half and the rest wait (MPOS is a REAL: 1e-6)
    assert r["variables"]["P"] == pytest.approx((BLOCK_BUFFER // 2 - 1) * 0.001, rel=1e-6)
    assert r["variables"]["Q"] == pytest.approx(n * 0.001)  # preparation has seen every block
    assert r["motion"]["feed_moves"] == n and r["position"]["X"] == pytest.approx(n * 0.001)


def test_fewer_blocks_than_the_buffer_all_wait_for_the_wait(tmp_path, run_text):
    r = run_text(LOOP.format(n=BLOCK_BUFFER - 2), name="p.cpl", machine=machine(tmp_path))
    assert r["variables"]["P"] == 0.0  # nothing executed without WAIT (manual §4.1's example)


def test_a_configured_depth_is_kept_exactly(tmp_path, run_text):
    r = run_text(LOOP.format(n=100), name="p.cpl", machine=machine(tmp_path, lookahead=10))
    assert r["variables"]["P"] == pytest.approx(0.090)


def test_cpos_follows_preparation_across_the_buffer_running_over(tmp_path, run_text):
    text = ("N1 G90 G1 F60000\n10 I% = 1 : BAD% = 0\n20 WHILE I% <= {n} DO\nG1 X[I% * 0.001]\n"
            "30 IF ABS(CPOS(1) - I% * 0.001) > 0.0001 THEN BAD% = BAD% + 1 ENDIF\n40 I% = I% + 1\n50 END\nM30\n")
    r = run_text(text.format(n=BLOCK_BUFFER + 100), name="p.cpl", machine=machine(tmp_path))
    assert r["status"] == "ok", r["error"]
    assert r["variables"]["BAD%"] == 0
