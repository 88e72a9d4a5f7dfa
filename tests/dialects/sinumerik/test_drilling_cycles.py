"""G80-G89 on the SINUMERIK 8xx call the drilling cycles L81-L89 (internal G group 9, CL 800 manual L7406;
issue 14 part 3).

The model of a cycle is the manual's own PROGRAM 81, the deep-hole drilling cycle (§7.4, L5404-5542), with
its transfer parameters (L483-486): R22 start point, R24 degression, R25 first drilling depth, R26 final
depth, R27/R28 dwell times. ``examples/cl800/deep_hole_drilling.cl8`` is it with the manual's typing errors
corrected; the tests compile it with the CL 800 compiler into L81.spf and drill with G81.
"""

from __future__ import annotations

import json
from pathlib import Path

from sin800_helpers import R, machine, run_mpf

from ncvm.api import compile_program, run
from ncvm.runtime.session import RunOptions

EXAMPLES = Path(__file__).parents[3] / "examples" / "cl800"
PARAMS = "R22=2 R24=2 R25=5 R26=-14 R27=0.5 R28=0.25"  # start Z2, degression 2, first depth 5, final Z-14


def _l81(tmp_path: Path) -> str:
    compile_program(EXAMPLES / "deep_hole_drilling.cl8", out=tmp_path / "L81.spf")
    return (tmp_path / "L81.spf").read_text()


def _moves(tmp_path: Path, text: str, files: dict | None = None, extra: str = "") -> list[tuple]:
    """(kind, X, Y, Z, file) of each move, and the dwells, from the run's trace."""
    (tmp_path / "machine.toml").write_text(machine() + extra)
    for name, body in (files or {}).items():
        (tmp_path / name).write_text(body)
    (tmp_path / "prog.mpf").write_text(text)
    trace = tmp_path / "t.jsonl"
    result, _ = run(tmp_path / "prog.mpf", dialect="sin800", machine=tmp_path / "machine.toml",
                    options=RunOptions(state_dir=tmp_path / ".s", trace=trace))
    assert result["status"] == "ok", result["error"]
    out = []
    for row in map(json.loads, trace.read_text().splitlines()):
        if row["call"] in ("rapid", "feed"):
            e = row["end"]
            out.append((row["call"], e["X"], e["Y"], e["Z"], Path(row["file"]).name))
        elif row["call"] == "dwell":
            out.append(("dwell", row["seconds"]))
    return out


def _hole(x: float, y: float) -> list[tuple]:
    """The manual's PROGRAM 81 by hand for the PARAMS: first depth 2-5 = -3; the cut distribution ends at
    -14+2 = -12 (value 5, 3, 1, -1 against the degression 2); then (remain = (e_depth - 1) - (-14)) / 2 = 2
    above the final depth twice, counter = 2. PREP CYC's second register R78 (1 without diameter
    programming, CL 800 manual L5443) is the rapid-traverse distance."""
    hole = [("rapid", x, y, 2.0, "L81.spf")]  # (:G0 G64 G90:); PRAP (3)=start_Z
    for depth, back_to in ((-3.0, -2.0), (-6.0, None), (-8.0, None), (-10.0, None)):
        hole += [("feed", x, y, depth, "L81.spf"), ("dwell", 0.5), ("rapid", x, y, 2.0, "L81.spf"), ("dwell", 0.25)]
        if back_to is not None:  # value 3 > degression 2: back at rapid to the old depth + 1
            hole.append(("rapid", x, y, back_to, "L81.spf"))
    hole += [("feed", x, y, -12.0, "L81.spf"), ("dwell", 0.5), ("rapid", x, y, 2.0, "L81.spf"), ("dwell", 0.25),
             ("feed", x, y, -14.0, "L81.spf"), ("dwell", 0.5), ("rapid", x, y, 2.0, "L81.spf")]
    return hole


def test_g81_runs_the_manuals_deep_hole_cycle_l81_at_each_position_until_g80_l5404(tmp_path):
    """G81 with the manual's L81 (L5404-5542): at X10 Y10 and, modal, at X30 Y10; after G80 the move to X50
    is only a move. Every depth and dwell is the one the manual's program computes (by hand in _hole)."""
    l81 = _l81(tmp_path)
    moves = _moves(tmp_path, f"%MPF1\nN10 G17 G90 G94 S1000 M3 F100\nN20 G0 X0 Y0 Z50\nN30 {PARAMS}\n"
                             "N40 G81 X10 Y10\nN50 X30\nN60 G80 X50\nN70 M30\n", {"L81.spf": l81})
    expected = ([("rapid", 0.0, 0.0, 50.0, "prog.mpf"), ("rapid", 10.0, 10.0, 50.0, "prog.mpf")] + _hole(10.0, 10.0)
                + [("rapid", 30.0, 10.0, 2.0, "prog.mpf")] + _hole(30.0, 10.0) + [("rapid", 50.0, 10.0, 2.0, "prog.mpf")])
    assert moves == expected


def test_a_cl800_program_selects_the_cycle_in_its_din_blocks(tmp_path):
    """A CL 800 main program (compiled to @ code, then run) drills with (:G81:) the same way; the transfer
    parameters are its PAR variables."""
    l81 = _l81(tmp_path)
    (tmp_path / "main.cl8").write_text(
        "PROGRAM 100;\nCHANNEL NC 1;\nID (0-G81-TEST);\nPAR REAL: R22:=start_Z, R24:=deg, R25:=first, R26:=final,\n"
        "  R27:=dwell_A, R28:=dwell_B;\nBEGIN\nstart_Z=2; deg=2; first=5; final=-14; dwell_A=0.5; dwell_B=0.25; LF;\n"
        "(:G17 G90 G94 S1000 M3 F100:); LF;\n(:G0 X0 Y0 Z50:); LF;\n(:G81 X10 Y10:); LF;\n(:G80:); LF;\nEND.\n")
    compile_program(tmp_path / "main.cl8", out=tmp_path / "L100.spf")
    moves = _moves(tmp_path, "%MPF1\nL100\nM30\n", {"L81.spf": l81})
    assert moves == [("rapid", 0.0, 0.0, 50.0, "L100.spf"), ("rapid", 10.0, 10.0, 50.0, "L100.spf")] + _hole(10.0, 10.0)


CYCLE = "%SPF82\n(COUNTS ITS CALLS IN R900, DRILLS TO R3 AND BACK TO R2)\nR900=R900+1\nG1 Z=R3\nG0 Z=R2\nM17\n"


def test_the_cycle_runs_after_blocks_with_an_axis_word_only_and_reads_r_set_in_the_block(tmp_path):
    """Modal until G80: a block without an axis word (F, S, M, R only) does not drill; R parameters written
    in the positioning block itself are the cycle's (they are decoded before the block executes)."""
    r = run_mpf(tmp_path, "%MPF1\nG0 X0 Y0 Z10 F200 S500 M3\nR2=2 R3=-5 G82 X5\nF300\nR3=-7 Y5\nG80\nX9\nM30\n",
                files={"L82.spf": CYCLE}, ok=True)
    assert R(r, 900) == 2.0


def test_positions_of_a_plain_run_and_of_a_sub_program_call_the_cycle(tmp_path):
    """Constant blocks (compiled as one run) and the blocks of a sub-program called while G82 is selected
    each drill; the cycle's own blocks do not call it again."""
    sub = "%SPF5\nX20\nX30\nM17\n"
    r = run_mpf(tmp_path, "%MPF1\nG0 X0 Y0 Z10 F200\nR2=2 R3=-5\nG82\nX1\nX2\nY3\nL5\nG80\nX40\nM30\n",
                files={"L82.spf": CYCLE, "L5.spf": sub}, ok=True)
    assert R(r, 900) == 5.0


def test_g80_in_a_sub_program_ends_the_cycle_for_the_caller(tmp_path):
    r = run_mpf(tmp_path, "%MPF1\nG0 X0 Y0 Z10 F200\nR2=2 R3=-5\nG82 X1\nL6\nX2\nM30\n",
                files={"L82.spf": CYCLE, "L6.spf": "%SPF6\nG80\nM17\n"}, ok=True)
    assert R(r, 900) == 1.0


def test_a_missing_cycle_program_stops_at_the_selecting_block_naming_it(tmp_path):
    """"a clear error when the cycle program is missing" (issue 14): RUN002 at G83, naming L83."""
    r = run_mpf(tmp_path, "%MPF1\nG0 X0 Y0 Z10\nG83 X5 Y5\nM30\n")
    err = r["error"]
    assert err["code"] == "RUN002" and err["line"] == 3 and "L83" in err["message"], err


def test_decode_ahead_keeps_the_order_of_positions_and_cycles(tmp_path):
    """With blocks decoded ahead ([sin800] decode_ahead) the cycle still follows its position."""
    text = "%MPF1\nG0 X0 Y0 Z10 F200\nR2=2 R3=-5\nG82 X1\nX2\nG80\nM30\n"
    runs = []
    for name, extra in (("lockstep", ""), ("ahead", "decode_ahead = 3\n")):
        (tmp_path / name).mkdir()
        runs.append(_moves(tmp_path / name, text, {"L82.spf": CYCLE}, extra))
    assert runs[0] == runs[1] and [m[1] for m in runs[0] if m[0] == "feed"] == [1.0, 2.0]


def test_acg_reads_the_executed_drilling_function_of_group_9_l7406(tmp_path):
    """ACG (@36b) group 9 (L7406): G82 while selected, G80 after."""
    r = run_mpf(tmp_path, "%MPF1\nG0 X0 Y0 Z10 F200\nR2=2 R3=-5\nG82\n@714 @36b R10 K0 K9\nG80\n"
                          "@714 @36b R11 K0 K9\nM30\n", files={"L82.spf": CYCLE}, ok=True)
    assert (R(r, 10), R(r, 11)) == (82.0, 80.0)


def test_check_warns_of_a_missing_cycle_program_as_the_run_stops(tmp_path):
    """G81-G89 call L81-L89 on the program path (L7406): ``ncvm check`` warns RUN002 at the first block that
    selects a cycle whose program is missing, where the run stops with RUN002; with L81.spf beside the
    program the check is clean."""
    from ncvm.api import check

    (tmp_path / "machine.toml").write_text(machine())
    prog = tmp_path / "p.mpf"
    prog.write_text(f"%MPF1\n{PARAMS}\nG81 X10 Y10\nX20\nG82 X30\nG81 X40\nG80\nM30\n")
    diags = check(prog, dialect="sin800", machine=tmp_path / "machine.toml")
    assert [(d.code, d.severity, d.span.line) for d in diags] == [("RUN002", "warning", 3),
                                                                   ("RUN002", "warning", 5)]
    assert "L81" in diags[0].message and "the run stops here" in diags[0].message
    result = run_mpf(tmp_path, prog.read_text())
    assert result["status"] == "error" and result["error"]["code"] == "RUN002" and result["error"]["line"] == 3
    _l81(tmp_path)
    (tmp_path / "L82.spf").write_text("%SPF82\nG4 F0.5\nM17\n")
    assert check(prog, dialect="sin800", machine=tmp_path / "machine.toml") == []


def test_a_block_that_selects_and_deselects_is_refused_by_check_and_run_l7406(tmp_path):
    """``G81 X10 G80``: group 9 (L7406) holds one active function; a block with two has no one meaning and is
    refused (SIN001) by check and run alike (review 14c: before, the last one written won silently)."""
    from ncvm.api import check

    (tmp_path / "machine.toml").write_text(machine())
    prog = tmp_path / "p.mpf"
    prog.write_text("%MPF1\nG0 X0 Y0 Z10\nG81 X10 G80\nX20\nG81 X30\nM30\n")
    diags = check(prog, dialect="sin800", machine=tmp_path / "machine.toml")
    assert [(d.code, d.span.line) for d in diags if d.severity == "error"] == [("SIN001", 3)]
    result = run_mpf(tmp_path, prog.read_text())
    assert result["status"] == "error" and result["error"]["code"] == "SIN001" and result["error"]["line"] == 3


def test_check_of_a_cl800_source_warns_of_the_missing_cycle_at_its_statement_l7406(tmp_path):
    """A CL 800 program whose DIN block selects G81 (L7406) without L81 on the program path: check warns RUN002
    at the source line of that block, by the rule sin800 check uses on the object program; with L81.spf
    there the check is clean."""
    from ncvm.api import check

    (tmp_path / "machine.toml").write_text(machine())
    prog = tmp_path / "drill.cl8"
    prog.write_text("PROGRAM 82;\nCHANNEL NC 0;\nBEGIN\n  LF; (: G90 G00 X0 Y0 Z10 :); LF;\n"
                    "  (: R2=2 R3=-5 G81 X10 :); LF;\n  (: G80 :); LF;\nEND.\n")
    diags = check(prog, machine=tmp_path / "machine.toml")
    assert [(d.code, d.severity, d.span.line) for d in diags] == [("RUN002", "warning", 5)]
    _l81(tmp_path)
    assert [d.code for d in check(prog, machine=tmp_path / "machine.toml")] == []
