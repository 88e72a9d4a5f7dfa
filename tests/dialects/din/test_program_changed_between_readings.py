"""A DIN program read a second time as it runs (past ``din.HOLD_BYTES``) must be the program its first reading
checked: a file changed in between stops the run with RUN008 before the first stretch that differs, naming that
stretch's first line; the stretches before it have run and their motion is reported (docs/decisions.md "a DIN
program changed while it runs")."""

from __future__ import annotations

from pathlib import Path

import pytest

import ncvm.dialects.din as din
from ncvm.api import run
from ncvm.diagnostics import RuntimeFault
from ncvm.nc import block
from ncvm.nc.block import COLUMNS_FROM, text_stretches
from ncvm.runtime.session import RunOptions

#: 3,000 feed moves on a 100 x 30 grid and M30: about 17 stretches of 4,096 characters
TEXT = "\n".join(["G21 G90 G17 G94 F150"] + [f"G1 X{i % 100}.0 Y{i // 100}.0" for i in range(3000)] + ["M30"]) + "\n"


@pytest.fixture
def program(tmp_path, monkeypatch) -> Path:
    monkeypatch.setattr(block, "CHUNK_CHARS", 4096)
    path = tmp_path / "grid.ngc"
    path.write_text(TEXT)
    return path


def first_lines() -> list[int]:
    """The first line of each stretch the program is read in."""
    out, line = [], 1
    for piece in text_stretches(TEXT):
        out.append(line)
        line += piece.count("\n")
    return out


def second_pass(path: Path, edit) -> tuple[int, RuntimeFault | None]:
    """The blocks a second pass over ``path`` reads after ``edit()`` changed it, and its fault (None)."""
    blocks = 0
    with din.ProgramStretches(str(path), None) as stretches:
        for _ in stretches(COLUMNS_FROM):
            pass
        edit()
        try:
            for stretch in stretches(COLUMNS_FROM):
                blocks += len(stretch.lines)
        except RuntimeFault as e:
            return blocks, e
    return blocks, None


def test_an_unchanged_file_is_read_again_as_it_was(program):
    assert second_pass(program, lambda: None) == (TEXT.count("\n"), None)


def test_a_character_changed_stops_before_its_stretch(program):
    """Same length, another character (X50.0 Y20.0 -> Y2?.0, line 2,052): the stretches before it are read."""
    at = next(line for line in reversed(first_lines()) if line <= 2052)
    blocks, fault = second_pass(program, lambda: program.write_text(TEXT.replace("X50.0 Y20.0", "X50.0 Y2?.0")))
    assert (fault.code, fault.span.line, blocks) == ("RUN008", at, at - 1)
    assert f"changed while it ran (line {at})" in fault.message


def test_a_file_cut_at_a_stretch_end_stops_where_the_first_reading_went_on(program):
    """Cut exactly after its third stretch: every piece read is as it was, but the program ends early."""
    keep = sum(len(piece) for piece in list(text_stretches(TEXT))[:3])
    blocks, fault = second_pass(program, lambda: program.write_text(TEXT[:keep]))
    assert (fault.code, fault.span.line, blocks) == ("RUN008", first_lines()[3], first_lines()[3] - 1)


def test_a_file_grown_past_its_end_stops_at_what_was_added(program):
    """Lines appended after M30 past a whole stretch: the last stretch differs (it reads more) and stops there."""
    blocks, fault = second_pass(program, lambda: program.write_text(TEXT + "G0 Z50\n" * 2000))
    assert (fault.code, fault.span.line) == ("RUN008", first_lines()[-1])


def test_a_run_stops_with_run008_and_reports_the_motion_before_it(program, monkeypatch):
    """A whole run through the API, its program read twice (HOLD_BYTES 0) and changed while the second reading
    runs its first stretch: the run ends in error RUN008, the blocks before the changed stretch moved."""
    real, passes = din.file_stretches, []

    def written_over_while_running(file, at=None):
        passes.append(file)
        for k, piece in enumerate(real(file, at)):
            yield piece
            if len(passes) == 2 and k == 0:
                program.write_text(TEXT.replace("X50.0 Y20.0", "X50.0 Y2?.0"))

    monkeypatch.setattr(din, "file_stretches", written_over_while_running)
    monkeypatch.setattr(din, "HOLD_BYTES", 0)
    result, _ = run(program, dialect="din", options=RunOptions(state_dir=program.parent / ".ncvm"))
    at = next(line for line in reversed(first_lines()) if line <= 2052)
    assert result["status"] == "error"
    assert (result["error"]["code"], result["error"]["line"]) == ("RUN008", at)
    assert result["motion"]["feed_moves"] == at - 2  # lines 2 .. at-1
    assert result["steps"] == at - 1
