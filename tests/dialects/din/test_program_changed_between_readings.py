"""A DIN program read a second time as it runs (past ``din.HOLD_BYTES``) must be the program its first reading
checked: a file changed in between stops the run with RUN008 before the first stretch that differs, naming that
stretch's first line; the stretches before it have run and their motion is reported (docs/decisions.md "a DIN
program changed while it runs")."""

from __future__ import annotations

import os
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


def stretch_ends() -> list[int]:
    """Where each stretch of TEXT ends, in characters from its start."""
    ends, at = [], 0
    for piece in text_stretches(TEXT):
        at += len(piece)
        ends.append(at)
    return ends


def run_edited_once_read(program: Path, monkeypatch, edit) -> dict:
    """A run of ``program`` holding its first three stretches, ``edit()`` applied to the file when its first
    reading has ended (before the blocks run): the JSON summary."""
    with din.ProgramStretches(str(program), None) as stretches:
        costs = [din.held_bytes(stretch) for stretch in stretches(COLUMNS_FROM)]
    real, passes = din.file_stretches, []

    def edited_after_the_first_reading(file, at=None):
        passes.append(at)
        if len(passes) == 2:
            edit()
        yield from real(file, at)

    monkeypatch.setattr(din, "file_stretches", edited_after_the_first_reading)
    monkeypatch.setattr(din, "HOLD_BYTES", sum(costs[:3]))
    result, _ = run(program, dialect="din", options=RunOptions(state_dir=program.parent / ".ncvm"))
    assert len(passes) == 2 and passes[1] is not None  # read again from the fourth stretch on, not from the start
    return result


def test_a_run_holding_a_prefix_reads_the_rest_as_it_was_and_ends_as_a_run_held_whole(program, monkeypatch):
    result = run_edited_once_read(program, monkeypatch, lambda: None)
    assert result["status"] == "ok" and result["steps"] == 3002, result["error"]
    assert result == run(program, dialect="din", options=RunOptions(state_dir=program.parent / ".ncvm"))[0]


def test_a_held_stretch_rewritten_at_its_length_runs_what_was_checked(program, monkeypatch):
    """A character of the second stretch changed (X50.0 Y4.0 -> Y4?0, line 452; a syntax error had it been
    there when read): that stretch is held as its first reading read it, and the stretches read again are as
    they were: the run is the checked program's."""
    assert stretch_ends()[0] < TEXT.index("X50.0 Y4.0\n") < stretch_ends()[1]
    result = run_edited_once_read(program, monkeypatch,
                                  lambda: program.write_text(TEXT.replace("X50.0 Y4.0\n", "X50.0 Y4?0\n")))
    assert result["status"] == "ok" and result["steps"] == 3002, result["error"]


@pytest.mark.parametrize("edit, where", [
    (lambda text: text.replace("X50.0 Y4.0\n", "X50.0 Y4.05\n"), "held"),  # a held stretch one character longer
    (lambda text: text[:stretch_ends()[1]], "held"),  # cut inside what is held
    (lambda text: text[:stretch_ends()[2]], "held"),  # cut exactly where the held stretches end
    (lambda text: text.replace("X50.0 Y20.0", "X50.0 Y2?.0"), 2052),  # past them, at their length
    (lambda text: text[:stretch_ends()[5]], "cut"),  # cut past them at a stretch end
    (lambda text: text + "G0 Z50\n" * 2000, "last"),  # lines appended
])
def test_a_file_changed_where_it_is_read_again_stops_with_run008(program, monkeypatch, edit, where):
    """The file changed after its first reading where the run reads it again (from the fourth stretch): a held
    stretch grown or the file cut before the fourth stretch shifts or takes away what is read again (RUN008 at
    the fourth stretch's first line, the held blocks having run); a change past the held stretches stops before
    its own stretch, a file cut or grown at the stretch it ends in."""
    result = run_edited_once_read(program, monkeypatch, lambda: program.write_text(edit(TEXT)))
    firsts = first_lines()
    at = {"held": firsts[3], "cut": firsts[6], "last": firsts[-1]}.get(where)
    if at is None:
        at = next(line for line in reversed(firsts) if line <= where)
    assert (result["status"], result["error"]["code"], result["error"]["line"]) == ("error", "RUN008", at)
    assert result["steps"] == at - 1  # every block before it: one a line


@pytest.mark.parametrize("cut", [None, 1, 2])
def test_a_file_of_lone_cr_line_ends_is_read_again_from_where_it_stood(program, monkeypatch, cut):
    """Lone CR line ends: where the file stands after a stretch is a position with the line-end decoder's state
    in it (a pending CR). Read again from there the run is the one of the file held whole; cut inside the held
    stretches, that position cannot be restored and the run stops with RUN008 at the fourth stretch's line."""
    data = TEXT.replace("\n", "\r").encode("latin-1")
    program.write_bytes(data)
    ends = [len(TEXT[:end]) for end in stretch_ends()]  # a character a byte: the same offsets
    result = run_edited_once_read(program, monkeypatch,
                                  lambda: cut is not None and program.write_bytes(data[:ends[cut] - 5]))
    if cut is None:
        assert result["status"] == "ok" and result["steps"] == 3002, result["error"]
    else:
        assert (result["status"], result["error"]["code"], result["error"]["line"]) == ("error", "RUN008",
                                                                                      first_lines()[3])
        assert result["steps"] == first_lines()[3] - 1


def test_a_file_is_read_from_a_later_stretch_only_after_a_whole_pass(program):
    """Where a later stretch starts is known from the first whole reading only: asked before it, no guess."""
    with din.ProgramStretches(str(program), None) as stretches:
        with pytest.raises(ValueError, match="after a whole pass"):
            stretches(COLUMNS_FROM, 3)
        assert sum(len(s.lines) for s in stretches(COLUMNS_FROM)) == TEXT.count("\n")
        assert next(iter(stretches(COLUMNS_FROM, 3))).first == first_lines()[3] - 1


def first_pass_with(path: Path, edit) -> RuntimeFault | None:
    """The fault of a first whole pass over ``path`` during which ``edit()`` runs after its second stretch."""
    with din.ProgramStretches(str(path), None) as stretches:
        try:
            for k, _ in enumerate(stretches(COLUMNS_FROM)):
                if k == 1:
                    edit()
        except RuntimeFault as e:
            return e
    return None


def test_a_file_rewritten_during_the_first_reading_is_compared_again(program):
    """The first reading went on in the new version: read once more, it differs from what was read at line 1
    (the new version's first stretch): RUN008 before any block runs."""
    fault = first_pass_with(program, lambda: program.write_text(TEXT.replace("Y0.0", "Y9.5")))
    assert fault is not None and fault.code == "RUN008" and fault.span.line == 1


@pytest.mark.parametrize("edit", ["touch", "same text"])
def test_a_file_touched_during_the_first_reading_runs(program, edit):
    """Its times changed, its text did not: the comparison finds every piece as read."""
    def change():
        if edit == "touch":
            program.touch()
        else:
            program.write_text(TEXT)
    os.utime(program, ns=(1, 1))  # the first reading begins at another modification time than the edit's
    assert first_pass_with(program, change) is None
