"""CPL front end: line classification, linking, the motion queue and WAIT, calls, faults, steps."""

from __future__ import annotations

from pathlib import Path

import pytest

from ncvm.api import check
from ncvm.dialects.cpl.lexer import classify, tokenize
from ncvm.dialects.cpl.linker import LINK_STATS, link
from ncvm.machine.config import load_machine, machine_from_dict

AXES = [{"name": "X"}, {"name": "Y"}, {"name": "Z"}]


def mill(tmp_path: Path, **extra) -> object:
    data = {"axis": AXES, "paths": {"program_path": ["."], "file_root": "files"}}
    data.update(extra)
    return machine_from_dict(data, "<test>", tmp_path)


# -- lines and tokens (CPL manual §2.1.1-2.1.2, L345-406; §2.4.1, L435-455) -------------------------------------------------------
def test_line_classification_and_continuation():
    lines = classify('30 IF X%=3 THEN GOTO 150 ENDIF:\nREM JUMP: DESTINATION1\n40 X = 1 : REM A: B\n'
                     'N100 G90\nG1 X[XPOS]\n')
    assert [ln.kind for ln in lines] == ["cpl", "cont", "cpl", "nc", "nc"]
    assert lines[0].number == 30
    # a colon before REM on the same line does not continue the block
    assert lines[2].number == 40


def test_keyword_with_suffix_is_a_variable():
    toks = tokenize("FOR COUNTER%=START% STEP STEP% TO END%", 1, 0)
    kinds = [(t.kind, t.val if t.kind != "var" else t.val.display) for t in toks]
    assert kinds == [("kw", "FOR"), ("var", "COUNTER%"), ("op", "="), ("var", "START%"), ("kw", "STEP"),
                     ("var", "STEP%"), ("kw", "TO"), ("var", "END%")]


def test_names_significant_characters_and_permanent_forms():
    toks = tokenize("LONGNAME1% #GLOBALNAME @2_COUNTER @ABCDEFGHIJKLMNOPQ! P1TEST% @_R", 1, 0)
    shown = [t.val.display for t in toks]
    assert shown == ["LONGNAME%", "#GLOBALN", "@2", "@ABCDEFGHIJKLMNOP!", "P1%", "@_R"]


def test_rem_ends_the_line_colons_included():
    toks = tokenize("X = 1 : REM A : B = 2", 1, 0)
    assert [t.val for t in toks if t.kind == "op"] == ["=", ":"]


# -- running -----------------------------------------------------------------------------------
def test_expression_precedence_pascal_levels(run_text):
    r = run_text("10 A% = 2 + 3 * 4 : B% = (2 + 3) * 4 : C? = 5 AND 1 <> 0 : D% = 6 - 2 - 1\n"
                 "20 E? = NOT TRUE OR TRUE : F = 7 / 2\nM30\n", name="p.cpl")
    v = r["variables"]
    assert (v["A%"], v["B%"], v["C?"], v["D%"], v["E?"], v["F"]) == (14, 20, True, 3, True, 3.5)


def test_real_is_binary32_and_double_is_binary64(run_text):
    r = run_text("10 R = 0.1 : D! = 0.1 : SAME? = R = D!\n20 RR? = R = 0.1\nM30\n", name="p.cpl")
    v = r["variables"]
    assert v["R"] == pytest.approx(0.10000000149011612, abs=0)
    assert v["D!"] == 0.1
    assert v["SAME?"] is False  # a DOUBLE on one side compares in binary64
    assert v["RR?"] is True  # REAL against a constant compares in binary32 (CPL manual §2.4.3, L650-737)


def test_nc_words_with_expressions_at_preparation(run_text):
    text = ("5 XVALUE=20 : FEED=100 : M3=3\n"
            "N10 G1 X[XVALUE]F[ FEED*2+1000]M[M3]\n"
            "20 XVALUE = 99\n"
            "M30\n")
    r = run_text(text, name="p.cpl")
    assert r["status"] == "ok", r["error"]
    assert r["position"]["X"] == 20.0


def test_standalone_bracket_word_and_message(run_text):
    text = ('10 DIM A$(4) : A$ = "G1"\nN20 G0 X0\nN80 [A$] X10 F500 (MSG, moving)\nM30\n')
    r = run_text(text, name="p.cpl")
    assert r["status"] == "ok", r["error"]
    assert r["motion"]["feed_moves"] == 1
    assert r["output"] == ["moving"]


def test_block_skip(run_text):
    r = run_text("N1 G0 X5\n/N2 G0 X50\nM30\n", name="p.cpl")
    assert r["position"]["X"] == 5.0


def wait_program(with_wait: bool) -> str:
    return ("N10 X0\n"
            "N100 (MSG still running)\n"
            "N20 G1 X150 F6000\n"
            + ("30 WAIT\n" if with_wait else "")
            + "40 XPOS = MPOS(1) - 150\n"
            "50 IF XPOS < 0.0001 THEN\n"
            "N60 (MSG,Position reached)\n"
            "70 ENDIF\n"
            "M30\n")


@pytest.mark.parametrize("with_wait", [True, False])
def test_wait_example_block_preparation_runs_ahead(tmp_path, run_text, with_wait):
    """Manual §4.1 L1219-1230: "Position reached" appears only with the WAIT.

    The machine starts at X300 (a home position at the positive end), so the position MPOS reads
    before N10/N20 are executed is not 150; see docs/decisions.md.
    """
    m = mill(tmp_path, machine={"start_position": [300.0, 0.0, 0.0]})
    r = run_text(wait_program(with_wait), name="p.cpl", machine=m)
    assert r["status"] == "ok", r["error"]
    assert ("Position reached" in r["output"]) is with_wait
    assert r["variables"]["XPOS"] == pytest.approx(0.0 if with_wait else 150.0)


def test_wait_duration_and_result(run_text):
    r = run_text("10 WAIT(,1000,E%)\n20 T% = 500\n30 WAIT(,T%)\nM30\n", name="p.cpl")
    assert r["variables"]["E%"] == 1
    assert r["cycle_time_s"] == pytest.approx(1.5)


def test_wait_on_input_signal_from_scenario(tmp_path, run_text):
    m = mill(tmp_path, scenario=[{"time": 0.25, "kind": "input", "address": "IC(4,4,1)", "value": True}])
    r = run_text("10 WAIT(IC(4,4,1)=TRUE,1000,ERG%)\n20 WAIT(IC(4,4,1),250,AGAIN%)\n"
                 "30 WAIT(NOT IC(4,4,1),100,NEVER%)\nM30\n", name="p.cpl", machine=m)
    v = r["variables"]
    assert (v["ERG%"], v["AGAIN%"], v["NEVER%"]) == (2, 0, 1)
    assert r["cycle_time_s"] == pytest.approx(0.35)


def test_wait_that_can_never_end_is_reported(run_text):
    r = run_text("10 WAIT(IC(1,1,1)=TRUE)\nM30\n", name="p.cpl")
    assert r["error"]["code"] == "CPL039"


def test_lookahead_depth_from_machine_file(tmp_path, run_text):
    m = mill(tmp_path, cpl={"lookahead": 1})
    text = "N10 G1 X10 F600\nN20 X20\n30 P = MPOS(1)\nM30\n"
    r = run_text(text, name="p.cpl", machine=m)
    assert r["variables"]["P"] == 10.0  # one block may wait; the first one has been executed


def test_runtime_fault_in_sub_program_names_file_line_and_stack(tmp_path, run_text):
    (tmp_path / "SUB1").write_text("10 A = 1\n20 B = A / 0\n")
    r = run_text("10 X = 1\n20 CALL SUB1\nM30\n", name="main.cpl", machine=mill(tmp_path))
    err = r["error"]
    assert err["code"] == "CPL028"
    assert err["file"].endswith("SUB1") and err["line"] == 2
    assert "(CPL line 20)" in err["message"]
    assert any("main.cpl" in note for note in err["stack"])


def test_step_limit_stops_a_runaway_loop(run_text):
    r = run_text("10 .L\n20 GOTO .L\n", name="p.cpl", max_steps=1000)
    assert r["error"]["code"] == "RUN001"
    r = run_text("10 WHILE TRUE\n20 X = 1\n30 END\n", name="q.cpl", max_steps=1000)
    assert r["error"]["code"] == "RUN001"


def test_step_hook_sees_lines_and_variables(run_text):
    seen = []
    r = run_text("10 A% = 1\n20 A% = A% + 1\nM30\n", name="p.cpl",
                 hook=lambda f, line, v: seen.append((line, dict(v))))
    assert r["status"] == "ok"
    assert seen[0][0] == 1 and seen[1] == (2, {"A%": 1})


def test_link_table_cache_keyed_by_content(tmp_path):
    p = tmp_path / "cache.cpl"
    text = "10 X = 1\nM30\n"
    m = load_machine(None, tmp_path)
    link(str(p), text, m)
    before = LINK_STATS["linked"]
    link(str(p), text, m)
    assert LINK_STATS["linked"] == before
    link(str(p), text + "20 Y = 2\n", m)
    assert LINK_STATS["linked"] == before + 1


def test_check_links_sub_programs_before_anything_runs(tmp_path):
    (tmp_path / "BADSUB.cpl").write_text("10 IF X > 1 THEN\n")
    p = tmp_path / "main.cpl"
    p.write_text("10 CALL BADSUB\nN20 G1 X10 F100\nM30\n")
    diags = check(p, machine=mill(tmp_path))
    assert [d.code for d in diags] == ["CPL004"]
    assert diags[0].span.file.endswith("BADSUB.cpl")


def test_din_header_excludes_program_from_linking(tmp_path, run_text):
    (tmp_path / "P999").write_text("N10 (DIN)\nN20 G1 X10 F100\nM30\n")
    r = run_text("10 CALL P999 DIN\n20 CALL P999\nM30\n", name="p.cpl", machine=mill(tmp_path))
    assert r["status"] == "ok", r["error"]
    assert r["motion"]["feed_moves"] == 2  # excluded from linking, it still runs its NC blocks
    assert r["position"]["X"] == 10.0


def test_subprogram_m30_returns_and_locals_are_separate(tmp_path, run_text):
    (tmp_path / "SUB.cpl").write_text("10 X% = 5 : #G% = X%\nN20 G0 X7\nM30\n30 #G% = 99\n")
    r = run_text("10 X% = 1\n20 CALL SUB\n30 Y% = X%\nN40 G0 Y3\nM30\n", name="p.cpl", machine=mill(tmp_path))
    v = r["variables"]
    assert (v["X%"], v["Y%"], v["#G%"]) == (1, 1, 5)
    assert r["position"] == {"X": 7.0, "Y": 3.0, "Z": 0.0}


def test_goto_out_of_loops_and_case(run_text):
    text = ("10 N% = 0\n20 FOR I% = 1 TO 100\n30 CASE I% OF\n40 LABEL 7 : GOTO .OUT\n"
            "50 OTHERWISE N% = N% + 1\n60 ENDCASE\n70 NEXT I%\n80 .OUT\n90 WHILE TRUE\n100 GOTO 120\n"
            "110 END\n120 DONE? = TRUE\nM30\n")
    r = run_text(text, name="p.cpl")
    v = r["variables"]
    assert (v["N%"], v["I%"], v["DONE?"]) == (6, 7, True)


def test_global_fields_are_shared_with_sub_programs(tmp_path, run_text):
    (tmp_path / "FILL.cpl").write_text('10 FOR I% = 1 TO 3\n20 #TAB(I%) = I% * 1.5\n30 NEXT\n40 #NAME$ = "FILLED"\n'
                                       '50 MID$(#NAME$, 7) = "!"\n')
    r = run_text("10 DIM #TAB(3) : DIM #NAME$(10)\n20 CALL FILL\n30 S = #TAB(1) + #TAB(2) + #TAB(3)\nM30\n",
                 name="p.cpl", machine=mill(tmp_path))
    assert r["status"] == "ok", r["error"]
    assert r["variables"]["S"] == 9.0
    assert r["variables"]["#NAME$"] == "FILLED!"


def test_parameters_not_passed_are_nul_and_views_convert(tmp_path, run_text):
    (tmp_path / "VIEW.cpl").write_text('10 #A% = P1% : #B! = P1! : #MISSING? = P3 = NUL : #S$ = P2$\n')
    r = run_text('10 CALL VIEW [4, "TXT"]\nM30\n', name="p.cpl", machine=mill(tmp_path))
    v = r["variables"]
    assert (v["#A%"], v["#B!"], v["#MISSING?"], v["#S$"]) == (4, 4.0, True, "TXT")
    r = run_text('10 CALL VIEW [2.5, "TXT"]\nM30\n', name="q.cpl", machine=mill(tmp_path))
    assert r["error"]["code"] == "CPL021"


@pytest.mark.parametrize("text, code", [
    ("10 X =\n", "CPL001"), ("10 IF THEN\n", "CPL001"), ("N10 G1 X[\n", "CPL001"), ('10 X = "abc\n', "CPL001"),
    ("10 X(1,2,3)=1\n", "CPL001"), ("N10 G1 X1 X2\n", "CPL001"), ('10 X = "A" + 1\n', "CPL032"),
    ("10 I% = 99999999999\n", "CPL027"), ('10 A$ = "G1 Q"\nN20 [A$]\n', "CPL001"), ("10 @101 = 1\n", "CPL001"),
    ("10 @_R(0) = 1\n", "CPL031"), ("10 X% = 5 AND TRUE\n", "CPL032"), ("10 WHILE 1 DO\n20 END\n", "CPL032"),
    ('10 X = CHR$(300)\n', "CPL021"), ("10 Y = P1 + 1\n", "CPL020"), ("10 X = 1 / 0.0\n", "CPL028"),
])
def test_malformed_programs_give_codes_not_tracebacks(run_text, text, code):
    r = run_text(text, name="bad.cpl")
    assert r["status"] == "error" and r["error"]["code"] == code, r["error"]


def test_prn_message_window_formats(run_text):
    text = ('10 I% = 42 : R = 2.5 : D! = 2.5 : B? = TRUE\n'
            '20 PRN#(0,"I",I%,"R",R,"D",D!,"B",B?)\n'
            '30 PRN#(0,"VALUE ##.### MM",(37/3),"!")\n'
            '40 LJUST\n'
            '50 PRN#(0,"I",I%,"R",R)\n'
            '60 PRN#(0,"TOO BIG ##",123)\nM30\n')
    r = run_text(text, name="p.cpl")
    # the too-small template gives the warning PRN FORMAT INCORRECT and '*' (manual L4035)
    assert r["output"] == ["I       42R   2.500D        2.500000BTRUE", "VALUE 12.333 MM!", "I42R2.500",
                           "warning CPL620: PRN FORMAT INCORRECT: TOO BIG **", "TOO BIG **"]
