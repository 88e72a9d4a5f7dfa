"""Issue 16 item 4: comments `(file:line)` optional (`--source-comments`); the brief: "`--source-comments`
lines pointing at the right source lines". A CL 800 program (.cl8) is compiled to an object program
L<n>.spf that exists only inside ncvm; the run's trace and its errors name the .cl8 line, but the
translation's comments name the object program's line: `(L80.spf:3)` points at no file the user has."""

from __future__ import annotations

import json

from tests.review16e.helpers import ncvm, translate, write

PROGRAM = """(* two moves written as DIN blocks *)
PROGRAM 80;
CHANNEL NC 0;
BEGIN
  LF; (: G90 G00 X40 Y30 Z50 :); LF;
  (: G01 Z10 F100 :); LF;
END.
"""


def test_source_comments_name_the_cl800_source_line(tmp_path):
    write(tmp_path, {"drill.cl8": PROGRAM})
    rc, out, err = translate(tmp_path, "drill.cl8", "--source-comments")
    assert rc == 0, err
    run = ncvm(tmp_path, "run", "drill.cl8", "--trace", "run.jsonl")
    assert run.returncode == 0, run.stderr
    moves = [r for r in map(json.loads, (tmp_path / "run.jsonl").read_text().splitlines()) if "work" in r]
    assert [(m["file"], m["line"]) for m in moves] == [("drill.cl8", 5), ("drill.cl8", 6)]
    assert "G0 X40 Y30 Z50 (drill.cl8:5)" in out, out
    assert "G1 Z10 F100 (drill.cl8:6)" in out, out


BRANCH = """PROGRAM 91;
CHANNEL NC 0;
BEGIN
  LF; (: G90 G00 X40 Y30 Z50 :); LF;
  IF INT 1.3 THEN
    (: G01 Z10 F100 :); LF;
  ELSE
    (: G01 Z20 F100 :); LF;
  ENDIF;
END.
"""

INPUT_SET = """[[scenario]]
time = 0.0
kind = "input"
byte = 1
bit = 3
value = 1
"""


def test_frozen_mark_names_the_cl800_source_line(tmp_path):
    """Issue 16 item 3: the output marks the block "with a comment naming the decision and its source line":
    the IF INT of a .cl8 program is its line 5, not a line of the object program L91.spf."""
    write(tmp_path, {"branch.cl8": BRANCH, "input.toml": INPUT_SET})
    rc, out, err = translate(tmp_path, "branch.cl8", "--scenario", "input.toml")
    assert rc == 0, err
    marks = [line for line in out.splitlines() if line.startswith("(FROZEN:")]
    assert marks, out
    assert all("branch.cl8:5" in mark for mark in marks), marks
