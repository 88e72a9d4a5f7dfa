"""A DIN program opened with a ``%`` line ends at its closing ``%`` or at M2/M30, as rs274 holds it to; one that
reaches the file's end first was cut short (a CAM post or a pipe that died mid-stream, a copy made in half) and
is refused with NC016 before anything runs, by run and check alike. Nothing after the closing ``%`` is read."""

from __future__ import annotations

import json
import subprocess
import sys

import pytest

import ncvm.dialects.din as din
from ncvm import api
from ncvm.api import run
from ncvm.machine.config import default_machine_text
from ncvm.nc import block
from ncvm.runtime.session import RunOptions

NCVM = [sys.executable, "-m", "ncvm"]
BODY = "G21 G90\nG1 X10 F1000\nY10\n"


def ran(tmp_path, text: str, newline: str | None = "\n", machine=None) -> dict:
    path = tmp_path / "p.ngc"
    with open(path, "w", newline=newline) as f:
        f.write(text)
    result, _ = run(path, dialect="din", machine=machine, options=RunOptions(state_dir=tmp_path / ".ncvm"))
    return result


def checked(tmp_path, text: str, newline: str | None = "\n", machine=None) -> list[tuple[str, str, int, int]]:
    path = tmp_path / "p.ngc"
    with open(path, "w", newline=newline) as f:
        f.write(text)
    return [(d.severity, d.code, d.span.line, d.span.column) for d in api.check(path, "din", machine)]


CUT = [  # (program, newline, the line and column of the error: just past the last text)
    ("%\n" + BODY + "X0 Y1", "\n", 5, 6),  # cut in the middle of a block
    ("%\n" + BODY, "\n", 4, 4),  # cut at a line end
    ("%\r\n" + BODY.replace("\n", "\r\n") + "X0 Y1", None, 5, 6),  # CR LF
    ("%\n" + BODY + "X0 Y10\n\n\n  \n", "\n", 5, 7),  # blank lines after the cut: at the last text
    ("\n \n%\n" + BODY, "\n", 6, 4),  # blank lines before the opening %
    ("  % \n" + BODY, "\n", 4, 4),  # blanks around the opening %
    ("%\n", "\n", 1, 2),  # a lone %
    ("%\n" + BODY + "/M30\n", "\n", 5, 5),  # a program end under block skip, skip on: not an end
    ("%\n" + BODY + "M3 S1000\n(M30 in a comment)\n", "\n", 6, 19),
]


@pytest.mark.parametrize("text, newline, line, column", CUT)
def test_a_program_opened_with_percent_and_cut_short_does_not_run(tmp_path, text, newline, line, column):
    r = ran(tmp_path, text, newline)
    assert (r["status"], r["error"]["code"], r["error"]["line"], r["error"]["column"]) == ("error", "NC016", line,
                                                                                           column)
    assert r["steps"] == 0 and r["motion"]["feed_moves"] == 0
    assert "may be cut short" in r["error"]["message"] and f"ends at line {line}" in r["error"]["message"]
    assert checked(tmp_path, text, newline) == [("error", "NC016", line, column)]


COMPLETE = [  # (program, newline, the X it ends at)
    ("%\n" + BODY + "X20\n%\n", "\n", 20.0),  # closing %
    ("%\n" + BODY + "X20\nM30\n%\n", "\n", 20.0),  # M30, then %
    ("%\n" + BODY + "X20\nM2\n", "\n", 20.0),  # M2 without %
    ("%\n" + BODY + "N90 X20 M30\n\n\n", "\n", 20.0),  # M30 in a block with a move, blank lines after
    ("%\r\n" + BODY.replace("\n", "\r\n") + "X20\r\n%\r\n", None, 20.0),  # CR LF
    ("%\n" + BODY + "X20\n \t%  \n\n\n", "\n", 20.0),  # blanks around the closing %, blank lines after it
    ("%\n" + BODY + "X20\n%", "\n", 20.0),  # a closing % with no line end
    ("%\n%\n", "\n", 0.0),  # an empty program
    (BODY + "X20\n", "\n", 20.0),  # not opened with %: may end without M2/M30, as before
]


@pytest.mark.parametrize("text, line", [
    (BODY + "%\nX20\n", 4),  # a % line in a program that does not open with one
    ("(header)\n%\n" + BODY + "%\nG1 X99\n", 2),  # a tape after a comment: its trailer would run
])
def test_a_percent_line_where_no_tape_opens_is_refused(tmp_path, text, line):
    """rs274 refuses a % line after the first (its parser reads it as a bad character): a tape opens and
    closes with %, and what follows a closing % would run here if the mark were taken for nothing."""
    r = ran(tmp_path, text, "\n")
    assert (r["status"], r["error"]["code"], r["error"]["line"], r["steps"]) == ("error", "NC016", line, 0)
    assert checked(tmp_path, text, "\n") == [("error", "NC016", line, 1)]


@pytest.mark.parametrize("text, newline, x", COMPLETE)
def test_a_program_that_ends_as_it_should_runs(tmp_path, text, newline, x):
    r = ran(tmp_path, text, newline)
    assert r["status"] == "ok", r["error"]
    assert r["position"]["X"] == x
    assert checked(tmp_path, text, newline) == []


def test_a_program_end_under_block_skip_ends_the_program_when_skip_is_off(tmp_path):
    machine = tmp_path / "machine.toml"
    machine.write_text(default_machine_text() + "\n[setting_data]\nblock_skip = false\n")
    text = "%\n" + BODY + "/M30\n"
    r = ran(tmp_path, text, machine=machine)
    assert r["status"] == "ok", r["error"]
    assert checked(tmp_path, text, machine=machine) == []


def test_nothing_after_the_closing_percent_is_read_or_run(tmp_path):
    """rs274 reads no further than the closing %: the blocks after it do not move the machine, an error there
    is none; a check warns of them, at the first line after it."""
    text = "%\n" + BODY + "%\n\n(a second part)\nG1 X50\nG1 X1 @\n"
    r = ran(tmp_path, text)
    assert r["status"] == "ok" and r["position"] == {"X": 10.0, "Y": 10.0, "Z": 0.0}, r["error"]
    assert checked(tmp_path, text) == [("warning", "NC016", 7, 1)]


def test_an_error_before_the_cut_is_reported_with_it(tmp_path):
    text = "%\nG21 G90\nG1 X1 @\nG1 X10 F100\nX5"
    assert checked(tmp_path, text) == [("error", "NC001", 3, 7), ("error", "NC016", 5, 3)]
    r = ran(tmp_path, text)
    assert r["status"] == "error" and r["steps"] == 0


@pytest.mark.parametrize("command", ["run", "check"])
def test_a_cut_program_from_a_pipe_is_refused(tmp_path, command):
    """``cat part.ngc | ncvm run -d din -`` with the CAM post dead mid-stream: an error, not "ended normally"."""
    cut = b"%\nG21 G90\nG1 X10 F1000\nY10\nX0 Y1"
    done = subprocess.run([*NCVM, command, "-d", "din", "-"], cwd=tmp_path, input=cut, capture_output=True,
                          timeout=120)
    said = done.stderr.decode()
    assert done.returncode == 1, said
    assert "<stdin>:5:6: error NC016: program opened with % (line 1) ends at line 5" in said, said
    whole = subprocess.run([*NCVM, command, "-d", "din", "-"], cwd=tmp_path, input=cut + b"0\nM30\n%\n",
                           capture_output=True, timeout=120)
    assert whole.returncode == 0, whole.stderr.decode()


def long_program(lines: int, tail: str) -> str:
    return "%\nG21 G90 F1000\n" + "".join(f"G1 X{i % 97} Y{i % 13}\n" for i in range(lines)) + tail


@pytest.mark.parametrize("budget", [0, 1 << 40], ids=["read_again", "held"])
@pytest.mark.parametrize("tail, outcome", [
    ("%\n", ("ok", None, None)),  # the closing % at the end of the last stretch
    ("G1 X200", ("error", "NC016", 3003)),  # cut
    ("%\n" + "G1 X500\n" * 2000 + "G1 X1 @\n", ("ok", None, None)),  # a second stretch after the closing %
])
def test_a_long_program_read_in_stretches_ends_where_it_does_whole(tmp_path, monkeypatch, budget, tail, outcome):
    """3,000 moves in stretches of about 4,096 characters, held or read again as they run: the closing % or
    the cut is found wherever it falls, and what follows the closing % neither runs nor fails."""
    monkeypatch.setattr(block, "CHUNK_CHARS", 4096)
    monkeypatch.setattr(din, "HOLD_BYTES", budget)
    r = ran(tmp_path, long_program(3000, tail))
    error = r["error"] or {}
    assert (r["status"], error.get("code"), error.get("line")) == outcome
    if outcome[0] == "ok":
        assert r["motion"]["feed_moves"] == 3000 and r["position"]["X"] == 2999 % 97
    diags = checked(tmp_path, long_program(3000, tail))
    assert [d[1:3] for d in diags if d[0] == "error"] == ([outcome[1:]] if outcome[1] else [])


def test_the_json_of_a_cut_program(tmp_path):
    (tmp_path / "p.ngc").write_text("%\n" + BODY + "X0 Y1")
    done = subprocess.run([*NCVM, "run", "p.ngc", "--json", "--state", "st"], cwd=tmp_path, capture_output=True,
                          timeout=120)
    doc = json.loads(done.stdout)
    assert done.returncode == 1 and doc["status"] == "error" and doc["error"]["code"] == "NC016"


def test_a_percent_with_words_after_it_is_no_tape_mark_and_no_block(tmp_path):
    """%O1000: the block reader would drop the line (a % line is nothing): refused at the %, and the program it
    leaves unclosed is said too; a comment beside a % is a tape mark still."""
    text = "%\n" + BODY + "%O1000\n"
    r = ran(tmp_path, text, "\n")
    assert (r["status"], r["error"]["code"], r["error"]["line"], r["error"]["column"], r["steps"]) == \
        ("error", "NC001", 5, 1, 0)
    assert checked(tmp_path, text, "\n") == [("error", "NC001", 5, 1), ("error", "NC016", 5, 7)]
    r = ran(tmp_path, "% (START)\n" + BODY + "% (END)\nG1 X99\n", "\n")
    assert r["status"] == "ok" and r["motion"]["bounds"]["X"][1] == 10.0
