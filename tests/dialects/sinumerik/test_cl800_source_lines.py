"""Messages of a CL 800 run name the line of the .cl8 source, not of the generated object program.

Issue 15 (CL 800 item 5): run-time messages of a CL 800 program point at the ``.cl8`` source line; the
manual (L357: "It is difficult to find an @ code statement generated from a CL 800 statement, as the
listings of source and @ codes are significantly different as far as the line numbering is concerned")
is why: a user cannot find "line 3" of an object program ncvm wrote only in memory. Errors already do
this (``p.cl8:8: ... note: object program L201.spf line 4``); the M0 line and the soft-limit warning do not.
"""

from __future__ import annotations

from pathlib import Path

from ncvm.api import run
from ncvm.runtime.session import RunOptions

MACHINE = ('[[axis]]\nname = "X"\nmin = -500.0\nmax = 500.0\n[[axis]]\nname = "Y"\n[[axis]]\nname = "Z"\n'
           '[sin800]\ncontrol = "880"\n')

M0_PROGRAM = """PROGRAM 201;
CHANNEL NC 1;
LOCAL REAL: R60;
BEGIN
  R60 = 0;
  (:G0 X10:); LF;
  (:M00:); LF;
  R60 = 20;
  (:G1 F100:); PRAP (1)=R60; LF;
END.
"""

LIMIT_PROGRAM = """PROGRAM 202;
CHANNEL NC 1;
LOCAL REAL: R60;
BEGIN
  (:G0 X10:); LF;
  R60 = 900;
  (:G1 F100:); PRAP (1)=R60; LF;
END.
"""


def _run(tmp_path: Path, text: str) -> dict:
    (tmp_path / "machine.toml").write_text(MACHINE)
    (tmp_path / "p.cl8").write_text(text)
    result, _ = run(tmp_path / "p.cl8", dialect="cl800", machine=tmp_path / "machine.toml",
                    options=RunOptions(state_dir=tmp_path / ".s"))
    return result


def test_m0_line_of_a_cl800_program_names_the_source_line(tmp_path: Path):
    result = _run(tmp_path, M0_PROGRAM)
    assert result["status"] == "ok", result["error"]
    assert result["position"]["X"] == 20.0
    # the (:M00:) statement is line 7 of p.cl8; "line 3" is a line of the generated L201.spf
    assert len(result["output"]) == 1 and "line 7" in result["output"][0], result["output"]


def test_soft_limit_warning_of_a_cl800_program_names_the_source_line(tmp_path: Path):
    result = _run(tmp_path, LIMIT_PROGRAM)
    text = " ".join(str(v) for v in result["limit_violations"])
    assert "p.cl8" in text and ".spf" not in text, result["limit_violations"]
    # the block of `R60 = 900;` and `(:G1 F100:); PRAP (1)=R60; LF;` runs at its end, the PRAP line
    assert text.endswith("p.cl8:7)"), result["limit_violations"]


def test_trace_of_a_cl800_program_names_the_source_lines(tmp_path: Path):
    """The same class as the M0 line (issue 15): each trace record names the .cl8 statement of its block."""
    import json

    (tmp_path / "machine.toml").write_text(MACHINE)
    (tmp_path / "p.cl8").write_text(M0_PROGRAM)
    trace = tmp_path / "t.jsonl"
    result, _ = run(tmp_path / "p.cl8", dialect="cl800", machine=tmp_path / "machine.toml",
                    options=RunOptions(state_dir=tmp_path / ".s", trace=trace))
    assert result["status"] == "ok", result["error"]
    records = [json.loads(line) for line in trace.read_text().splitlines()]
    placed = [(r["call"], Path(r["file"]).name, r["line"]) for r in records if "file" in r]
    assert ("rapid", "p.cl8", 6) in placed and ("stop", "p.cl8", 7) in placed and ("feed", "p.cl8", 9) in placed
    assert not any(name.endswith(".spf") for _, name, _ in placed)


def test_m0_in_a_compiled_loop_names_the_source_line_not_the_compiler_block_number(tmp_path: Path):
    """The WHILE loop's block gets the number N3001 from the compiler (compiler block numbers have 4 digits, L6421): a number
    the user never wrote, so the M0 line names the .cl8 line instead (issue 15, CL 800 5)."""
    program = ("PROGRAM 205;\nCHANNEL NC 1;\nLOCAL REAL: R60;\nBEGIN\n  R60 = 0;\n  WHILE R60 < 2 DO\n    BEGIN\n"
               "      (:M00:); LF;\n      R60 = R60 + 1;\n    END;\nEND.\n")
    result = _run(tmp_path, program)
    assert result["status"] == "ok", result["error"]
    assert result["output"] == ["M0 at line 8: programmed stop (continued)"] * 2
