"""SINUMERIK H words go to the PLC as auxiliary functions (docs/decisions.md "Issue 14: the H word": "ncvm
treats it as a machine-specific M function"; CL 800 manual L3072, bit 5400.0 "defines whether auxiliary
functions are to be output to the PLC"). Two M functions of a block both reach the PLC; of two H functions
ncvm hands on the last and drops the first without a word."""

from __future__ import annotations

from pathlib import Path

from review14b_run import SIN800_MACHINE, run


def aux(rows: list[dict]) -> list[tuple]:
    return [(r["code"], r["line"]) for r in rows if r["call"] == "aux"]


def test_two_m_functions_of_a_block_both_reach_the_plc(tmp_path: Path) -> None:
    """The model the decision names: M94 M95 in one block, both handed to the PLC (this passes)."""
    result, rows, _ = run(tmp_path, "mm.mpf", "%MPF1\nN1 M94 M95\nN2 M30\n", SIN800_MACHINE)
    assert result["status"] == "ok"
    assert aux(rows) == [("M94", 2), ("M95", 2)]


def test_two_h_functions_of_a_block_are_not_silently_dropped(tmp_path: Path) -> None:
    """``N1 H12 H13``: both auxiliary functions go to the PLC (as M94 M95 do), or the block is refused
    clearly. ncvm hands on H13 only and reports the run ok: the PLC never sees H12."""
    result, rows, stderr = run(tmp_path, "hh.mpf", "%MPF1\nN1 H12 H13\nN2 M30\n", SIN800_MACHINE)
    if result["status"] == "ok":
        assert aux(rows) == [("H12", 2), ("H13", 2)], aux(rows)
    else:
        assert result["error"]["line"] == 2, stderr
