"""Acceptance audit of the CPL dialect against manual chapters 2-3: what a user of a Typ3 control tries and the
manual states, where the suite did not yet assert it."""

from __future__ import annotations

import pytest


@pytest.fixture
def run(run_text, reference):
    return lambda text, **kw: run_text(text, name="p.cpl", machine=reference(**kw))


# -- §3.1 sub-programs by G address --------------------------------------------------------------------------


CYCLE = '10 #HOLES% = #HOLES% + 1 : #DEPTH = P1\nN1 G1 Z[P1] F100\nN2 G0 Z10\n'


def test_g81_calls_program_99999081_without_a_table_entry_l1073(run, reference):
    """§3.1 L1071-1074: "the programs for the drilling cycles (99999081 through 99999086) are permanently
    assigned to the functions G81 through G86". The machine file maps nothing; G81 calls 99999081 and, being a
    drilling cycle, again after every traversing block until G80: at X0, X10 and X20, not at X30."""
    m = reference()
    (m.program_path[0] / "99999081").write_text(CYCLE)
    r = run("1 #HOLES% = 0\nN1 G0 X0 Y0 Z10\nN2 G81 [-5]\nN3 X10\nN4 X20\nN5 G80\nN6 X30\nM30\n")
    assert r["status"] == "ok", r["error"]
    assert r["variables"]["#HOLES%"] == 3 and r["variables"]["#DEPTH"] == -5.0
    assert r["position"]["X"] == 30.0 and r["motion"]["feed_moves"] == 3


@pytest.mark.parametrize("code", [82, 83, 84, 85, 86])
def test_g82_to_g86_call_their_programs_l1073(run, reference, code):
    m = reference()
    (m.program_path[0] / f"999990{code}").write_text(CYCLE)
    r = run(f"1 #HOLES% = 0\nN1 G0 X0 Y0 Z10\nN2 G{code} [-2]\nN5 G80\nM30\n")
    assert r["status"] == "ok", r["error"]
    assert r["variables"]["#HOLES%"] == 1 and r["variables"]["#DEPTH"] == -2.0


def test_missing_drilling_cycle_program_is_a_link_error(run):
    """Linking checks sub-program calls (§2.3 L413): G81 without program 99999081 stops before anything runs."""
    r = run('10 PRN#(0,"started")\nN2 G81 [-5]\nM30\n')
    assert r["error"]["code"] == "CPL005" and "99999081" in r["error"]["message"]
    assert r["output"] == [] and r["error"]["line"] == 2


def test_machine_file_entry_replaces_a_drilling_cycle(run, reference):
    m = reference(cpl={"calls": {"G81": {"program": "MYDRILL", "modal": True}}})
    (m.program_path[0] / "MYDRILL").write_text(CYCLE)
    r = run("1 #HOLES% = 0\nN2 G81 [-1]\nN3 X5\nN4 G80\nM30\n", cpl={"calls": {"G81": {"program": "MYDRILL",
                                                                                   "modal": True}}})
    assert r["status"] == "ok", r["error"]
    assert r["variables"]["#HOLES%"] == 2


# -- error positions: file:line:col, the CPL line number, every error of a program ----------------------------


@pytest.mark.parametrize("text, line, col", [
    ("10 X=3: X=NUL : Y = X + 1\n", 1, 17),  # the third statement of the block
    ("10 X=1\n20 REPEAT\n30 X=X+1\n40 UNTIL Y=3\n", 4, 4),  # the UNTIL condition
    ("10 X=1 : IF Y=3 THEN X=2 ENDIF\n", 1, 10),  # an IF condition after another statement
    ("10 X=1 : WHILE Y<3 DO X=2 END\n", 1, 10),
    ("10 X=1\n20 GOTO 40\n30 Z=1\n40 X=SQRT(-1)\n", 4, 4),  # with a GOTO: the dispatch form of the program
    ("10 X=1\nN20 G1 X[U] F100\n", 2, 1),  # an [expr] word of an NC block
    ("10 X=1\nN20 G22 K1\n", 2, 1),  # an NC block the NC kernel refuses when it is executed
])
def test_runtime_errors_carry_the_column(run, text, line, col):
    r = run(text)
    assert r["status"] == "error"
    assert (r["error"]["line"], r["error"]["column"]) == (line, col)


def test_runtime_error_in_a_sub_program_points_into_it(run, reference):
    m = reference()
    (m.program_path[0] / "SUBERR").write_text("10 A=1 : B=SQRT(-A)\n")
    r = run("10 X=1\n20 CALL SUBERR\nM30\n")
    assert r["error"]["code"] == "CPL029" and r["error"]["file"].endswith("SUBERR")
    assert (r["error"]["line"], r["error"]["column"]) == (1, 10) and "(CPL line 10)" in r["error"]["message"]
    assert r["error"]["stack"] == ["called from p.cpl at " + str(reference().program_path[0] / "p.cpl") + ":2:4"]


@pytest.mark.parametrize("text, code, col", [
    ("10 X=1 : CALL P999\n", "CPL014", 10),  # §3.3 L1086
    ("10 X=1 : WAIT\n", "CPL009", 10),  # §4.1 L1201
])
def test_block_rules_point_at_the_statement(run, reference, text, code, col):
    (reference().program_path[0] / "P999").write_text("10 A=1\n")
    r = run(text)
    assert r["error"]["code"] == code and r["error"]["column"] == col and "(CPL line 10)" in r["error"]["message"]


def test_every_lexical_error_is_reported_with_its_cpl_line(tmp_path, reference):
    """A character the lexer cannot read no longer hides the errors of the blocks after it."""
    from ncvm.api import check
    path = tmp_path / "lx.cpl"
    path.write_text("10 @101=1\n20 X=$\n30 Y=(1\n40 Z=1:\nW=@0\n")
    diags = check(path, machine=reference())
    assert [(d.span.line, d.span.column) for d in diags] == [(1, 4), (2, 6), (3, 7), (5, 3)]
    assert [d.message.endswith(f"(CPL line {n})") for d, n in zip(diags, (10, 20, 30, 40))] == [True] * 4


def test_numbered_line_after_a_colon_is_named_as_such(run):
    """§2.1.2 L375-380: after a block that ends with ':' comes a line without a line number."""
    r = run("10 X=1:\n20 Y=2\n")
    assert r["error"]["code"] == "CPL001" and r["error"]["line"] == 2
    assert "has no line number" in r["error"]["message"]


# -- §3.3 programs excluded from linking -----------------------------------------------------------------------


def test_cpl_expression_in_a_din_excluded_program_is_an_error_l1101(run, reference):
    """§3.3 L1101-1104: a sub-program with CPL elements excluded by DIN gives an error at run time. `X[5]` is
    the CPL syntax of §2.1.1 (L357); the block used to be dropped without a word."""
    (reference().program_path[0] / "DINEXPR").write_text("N10 G1 X[5] F100\n")
    r = run("10 CALL DINEXPR DIN\n20 A=1\nM30\n")
    assert r["error"]["code"] == "CPL030" and "DINEXPR" in r["error"]["message"]


def test_variable_parameter_in_a_din_excluded_program_is_an_error(run, reference):
    m = reference(cpl={"calls": {"M66": "TOOLMSG"}})
    (m.program_path[0] / "TOOLMSG").write_text("5 PDIM P1$(20)\n10 #MSG$ = P1$\n")
    (m.program_path[0] / "DINCALL").write_text("N10 M66 [T$]\n")
    r = run("10 CALL DINCALL DIN\nM30\n", cpl={"calls": {"M66": "TOOLMSG"}})
    assert r["error"]["code"] == "CPL030"


@pytest.mark.parametrize("pdim, expected", [(True, "ok"), (False, "CPL026")])
def test_din_excluded_program_calls_by_m_address_with_pdim_l1161(run, reference, pdim, expected):
    """§3.4 L1149-1175: a string constant passed by a program selected without linking reaches the sub-program
    only through PDIM ("invalid variable" without it). The excluded program's M66 call runs (it used to be
    executed as a bare M66, the sub-program never called); the sub-program, which no linked program reaches,
    is linked when it is called."""
    calls = {"calls": {"M66": "TOOLMSG"}}
    m = reference(cpl=calls)
    (m.program_path[0] / "TOOLMSG").write_text(("5 PDIM P1$(20)\n" if pdim else "") + "10 #MSG$ = P1$\n")
    (m.program_path[0] / "DINCALL").write_text('N10 G0 X5\nN20 M66 ["T1 READY"]\nN30 G0 X7\n')
    r = run("10 CALL DINCALL DIN\n20 WAIT\n30 X = MPOS(1)\nM30\n", cpl=calls)
    if expected == "ok":
        assert r["status"] == "ok", r["error"]
        assert r["variables"]["#MSG$"] == "T1 READY" and r["variables"]["X"] == 7.0
    else:
        assert r["error"]["code"] == expected and r["error"]["file"].endswith("TOOLMSG")


def test_din_header_program_runs_a_drilling_cycle(run, reference):
    """"(DIN)" in the first line (L1115-1120): G81 in it calls 99999081 at N20 and again after N30 (§3.1, §3.2)."""
    m = reference()
    (m.program_path[0] / "99999081").write_text("10 #HOLES% = #HOLES% + 1\n")
    (m.program_path[0] / "DRILL").write_text("N10 (DIN)\nN20 G81 [-5]\nN30 X10\nN40 G80\nN50 X20\n")
    r = run("10 #HOLES% = 0\n20 CALL DRILL\nM30\n")
    assert r["status"] == "ok", r["error"]
    assert r["variables"]["#HOLES%"] == 2 and r["position"]["X"] == 20.0


def test_link_error_of_a_program_reached_through_an_excluded_one(run, reference):
    calls = {"calls": {"M67": "BADSUB"}}
    m = reference(cpl=calls)
    (m.program_path[0] / "BADSUB").write_text("10 X=(1\n")
    (m.program_path[0] / "DINCALL").write_text("N10 M67\n")
    r = run("10 CALL DINCALL DIN\nM30\n", cpl=calls)
    assert r["error"]["code"] == "CPL001" and r["error"]["file"].endswith("BADSUB")


def test_main_program_with_din_header_runs_unlinked_l1115(run, reference):
    """L1115-1120: "(DIN)" as a remark in the first line excludes the program from linking; the PDIM example
    (L1161-1175) starts such a main program. Its P call runs with the string constant for PDIM."""
    (reference().program_path[0] / "SP").write_text("10 PDIM P1$(4)\n20 #P$ = P1$\nM30\n")
    r = run('N10 (DIN)\nN50 P SP["TEST"]\nN60 G0 X5\nM30\n')
    assert r["status"] == "ok", r["error"]
    assert r["variables"]["#P$"] == "TEST" and r["position"]["X"] == 5.0


def test_main_program_with_din_header_and_cpl_is_an_error_l1101(run):
    r = run("N10 (DIN)\nN20 G0 X5\n30 X=1\nM30\n")
    assert r["error"]["code"] == "CPL030" and (r["error"]["line"], r["error"]["column"]) == (3, 4)


# -- §4.1 WAIT parameters ------------------------------------------------------------------------------------


@pytest.mark.parametrize("text", [
    "10 WAIT(IC(1,1,1)=1)\n",  # L1213: <state> is a BOOLEan expression
    "10 WAIT(,1000,E)\n",  # L1217: <result var> is an Integer variable
    "10 WAIT(,1000,E!)\n",
])
def test_wait_parameter_types_are_checked_when_linking(run, text):
    r = run(text + "M30\n")
    assert r["error"]["code"] == "CPL032" and r["steps"] == 0


def test_wait_with_every_form_of_the_manual_l1232(run):
    """L1232-1239 in one program, no input ever set: E% = 1 after 1000 ms; WAIT(,TIME%) returns nothing;
    NOT IC(3,2,1) holds at once (C% = 0); IC(4,4,1)=E7? with E7? TRUE times out after 250 ms (ERG% = 1);
    IC(2,0,2)=(E1? OR E2?) with both FALSE holds at once."""
    r = run("10 WAIT(,1000,E%)\n15 TIME% = 500\n20 WAIT(,TIME%)\n30 WAIT(NOT IC(3,2,1),,C%)\n"
            "35 E7? = TRUE\n40 WAIT(IC(4,4,1)=E7?,250,ERG%)\n45 E1? = FALSE : E2? = FALSE\n"
            "50 WAIT(IC(2,0,2)=(E1? OR E2?))\n60 T% = CLOCK\nN70 WAIT\nM30\n")
    assert r["status"] == "ok", r["error"]
    v = r["variables"]
    assert (v["E%"], v["C%"], v["ERG%"], v["T%"]) == (1, 0, 1, 1750)


def test_wait_in_an_nc_block_without_parameters_still_drains(run):
    """L1197-1203: "N20 WAIT" is WAIT as an NC block; a comment after a blank is not a parameter list."""
    r = run("N10 G1 X50 F3000\nN20 WAIT (MSG, waited)\n30 X = MPOS(1)\nM30\n")
    assert r["status"] == "ok", r["error"]
    assert r["variables"]["X"] == 50.0 and "waited" in r["output"]


# -- sub-programs along the program path ---------------------------------------------------------------------


def test_program_names_tell_upper_from_lower_case_l3853(run, reference):
    """§6.1.1 L3853-3857: "A distinction is made between upper- and lower-case letters" (P12_Data_Dial and
    P12_DATA_DIAL are two files). CALL finds a program as written or with ".cpl", in that case only."""
    folder = reference().program_path[0]
    (folder / "Sub1.cpl").write_text("10 #HIT% = 1\n")
    assert run("10 CALL Sub1\nM30\n")["variables"] == {"#HIT%": 1}
    assert run("10 CALL Sub1.cpl\nM30\n")["variables"] == {"#HIT%": 1}
    r = run("10 CALL SUB1\nM30\n")
    assert r["error"]["code"] == "CPL005" and "SUB1" in r["error"]["message"]
    (folder / "P999.CPL").write_text("10 #HIT% = 2\n")  # an archive copied from a PC: the extension in capitals
    assert run("10 CALL P999\nM30\n")["variables"] == {"#HIT%": 2}


# -- §2.4.3 definable permanent variables --------------------------------------------------------------------


@pytest.mark.parametrize("anw, expected", [
    ("DEF REAL @EFGH ;the same declaration in both files\n", "ok"),
    ("DEF INT @EFGH\n", "CPL038"),  # one name, two types: which variable would @EFGH be?
    ("DEF REAL @EFGHIJKLMNOPQRSTU(3)\nDEF REAL @EFGHIJKLMNOPQRSTV\n", "CPL038"),  # 16 significant (L560-562)
])
def test_one_name_declared_twice(run, reference, anw, expected):
    root = reference().file_root
    root.mkdir(parents=True, exist_ok=True)
    (root / "wmhperm.dat").write_text("DEF REAL @EFGH ;simple REAL variable\n")
    (root / "anwperm.dat").write_text(anw)
    r = run("10 @EFGH = 4.1\nM30\n")
    assert (r["status"] if expected == "ok" else r["error"]["code"]) == expected


# -- nesting beyond what Python blocks and its parser take -----------------------------------------------------


def test_deeply_nested_structures_run_in_the_flat_form(run):
    """120 nested IFs (Python allows 100 nested blocks): the program is generated as a dispatch loop and
    runs; the manual sets no IF nesting limit (CASE only: 10, §2.5.7 L1044)."""
    depth = 120
    text = "".join(f"{i} IF TRUE THEN\n" for i in range(1, depth + 1)) + "500 X% = 1\n"
    text += "".join(f"{600 + i} ENDIF\n" for i in range(depth)) + "M30\n"
    r = run(text)
    assert r["status"] == "ok", r["error"]
    assert r["variables"] == {"X%": 1}


@pytest.mark.parametrize("expr", ["+".join(["1"] * 300), "-" * 5000 + "1", "NOT " * 3000 + "1"])
def test_expressions_too_deep_are_nesting_too_deep(run, expr):
    """§2.5.1 L782-791: the nesting a control allows depends on the memory an expression needs; beyond it the
    manual's error is RUNTIME ERROR 2153 NESTING TOO DEEP (L3773), at the block, before the start."""
    r = run(f"5 A% = 1\n10 X% = {expr}\nM30\n")
    assert r["error"]["code"] == "2153" and r["error"]["line"] == 2 and "(CPL line 10)" in r["error"]["message"]
    assert r["steps"] == 0


@pytest.mark.parametrize("goto", ["", "5 GOTO 10\n"])
def test_for_exit_value_beyond_the_integer_range(run, goto):
    """§2.5.5 L934: after the loop the counter is past the end value; past +2147483647 (L655) an INTEGER cannot
    hold it: INVALID INTEGER VALUE at NEXT, in the structured and in the GOTO form of a program alike (the
    structured form used to leave 2147483648 in I%)."""
    r = run(goto + "10 FOR I%=2147483646 TO 2147483647 : NEXT\n20 J% = I%\nM30\n")
    assert r["error"]["code"] == "CPL027" and (r["error"]["line"], r["error"]["column"]) == (1 + bool(goto), 38)


def test_check_lists_link_and_type_errors_together_in_source_order(tmp_path, reference):
    """A type error no longer hides behind a link error of another block (or another program)."""
    from ncvm.api import check
    m = reference()
    (m.program_path[0] / "SUBT").write_text('10 Y% = "B"\n')
    path = tmp_path / "ce.cpl"
    path.write_text('10 X% = "A"\n20 CALL NOPE\n30 CALL SUBT\n')
    diags = check(path, machine=m)
    assert [(d.code, d.span.line) for d in diags if d.span.file == str(path)] == [("CPL021", 1), ("CPL005", 2)]
    assert [d.code for d in diags if d.span.file.endswith("SUBT")] == ["CPL021"]


@pytest.mark.parametrize("text, words", [
    ("10 @_RES_DOUBLE = 1\n", "reserved for internal applications"),  # §2.4.3 L544
    ("10 @4$ = \"A\"\n", "INTEGER permanent variable"),  # @1..@100 are INTEGER (L542)
])
def test_permanent_names_the_manual_rules_out(run, text, words):
    r = run(text + "M30\n")
    assert r["error"]["code"] == "CPL001" and words in r["error"]["message"]


# -- §2.4.3 INTEGER is 32 bits, also inside expressions ------------------------------------------------------------


@pytest.mark.parametrize("text, col", [
    ("10 A% = 65536 : B! = A% * A%\n", 17),  # stored into a DOUBLE
    ("10 A% = 2147483647 : B = A% + 1\n", 22),  # stored into a REAL
    ("10 A% = 65536 : IF A% * A% > 0 THEN B = 1 ENDIF\n", 17),  # compared
    ("10 A% = 65536 : X = A% * A% / 2\n", 17),  # divided (the quotient is REAL)
    ("10 A% = -2147483648 : IF -A% > 0 THEN B = 1 ENDIF\n", 23),
])
def test_integer_results_outside_32_bits_are_invalid_integer_value(run, text, col):
    """L655: "An INTEGER variable occupies 32 bits ... -2.147.483.648 through +2.147.483.647"; + - * of two
    INTEGERs is INTEGER (digest §4.2), so a result past that range is INVALID INTEGER VALUE wherever it is used,
    not only when stored into an INTEGER variable (it used to reach REAL variables and comparisons as 2^32)."""
    r = run(text + "M30\n")
    assert r["error"]["code"] == "CPL027" and r["error"]["column"] == col


def test_integer_expressions_in_range_and_big_constants_are_unchanged(run):
    """L484-490: a constant takes the precision of its context (D2! = -123456789012345 is the manual's)."""
    r = run("10 A% = 6 : B = A% * 2 : D2! = -123456789012345 : E! = 2147483647 * 2\n"
            "20 IF A% * A% = 36 THEN C? = TRUE ENDIF\nM30\n")
    assert r["status"] == "ok", r["error"]
    v = r["variables"]
    assert (v["B"], v["D2!"], v["E!"], v["C?"]) == (12.0, -123456789012345.0, 4294967294.0, True)


@pytest.mark.parametrize("goto", ["", "5 GOTO 10\n"])
def test_for_counts_with_any_numerical_variable_l924(run, goto):
    """§2.5.5 L924: "FOR <numerical variable>=<start value> ...": a permanent @n, a field element (its index
    taken at every pass), a global and @_R count like a local; each ends past its end value (L934)."""
    r = run(goto + "10 FOR @1=1 TO 3 : NEXT\n20 DIM F%(3) : FOR F%(1)=1 TO 3 : S%=F%(1) : NEXT\n"
            "30 FOR #G=0 STEP 0.5 TO 1 : NEXT\n40 FOR @_R(3)=1 TO 2 : NEXT\n"
            "50 DIM K%(2,2) : J%=1 : FOR K%(J%,2)=5 STEP -1 TO 4 : NEXT\n"
            "60 A% = @1 : B% = F%(1) : C = #G : D! = @_R(3) : E% = K%(1,2)\nM30\n")
    assert r["status"] == "ok", r["error"]
    v = r["variables"]
    assert (v["A%"], v["B%"], v["S%"], v["C"], v["D!"], v["E%"]) == (4, 4, 3, 1.5, 3.0, 3)


def test_for_with_a_parameter_or_a_non_number_is_an_error(run):
    assert run('10 FOR A$="A" TO "C" : NEXT\nM30\n')["error"]["code"] == "CPL001"


@pytest.mark.parametrize("name", ["/etc/hostname", "../p.cpl", "sub/P999", ".."])
def test_call_takes_a_program_name_not_a_host_path(run, name):
    """§6.1.1 L3851: a file name has alphanumeric characters, "." and "_". CALL used to open any file of the
    host (an absolute path, or ../ out of the program path) and print its lines in the link errors."""
    r = run(f"10 CALL {name}\nM30\n")
    assert r["error"]["code"] == "CPL001" and "program name" in r["error"]["message"]


@pytest.mark.parametrize("block, ok", [
    ("10 CALL P999 : REM the remark is no instruction", True),
    ("10 .AGAIN: CALL P999", True),
    ("10 CALL P999 : CALL P999", False),
    ("10 X=1 : CALL P999", False),
    ("10 IF TRUE THEN CALL P999 ENDIF", False),
])
def test_call_in_a_block_of_its_own_l1068(run, reference, block, ok):
    (reference().program_path[0] / "P999").write_text("10 #N% = #N% + 1\n")
    r = run("5 #N% = 0\n" + block + "\nM30\n")
    assert (r["status"] == "ok") is ok and (ok or r["error"]["code"] == "CPL014")


def test_drilling_cycle_runs_after_the_moves_of_a_called_program(run, reference):
    """A built-in drilling cycle behaves as a modal entry of the machine file: after every traversing block,
    also one of a sub-program called while it is active (§3.2 L1079-1081)."""
    m = reference()
    (m.program_path[0] / "99999081").write_text(CYCLE)
    (m.program_path[0] / "ROW").write_text("N1 X10\nN2 X20\n")
    r = run("1 #HOLES% = 0\nN1 G0 X0 Y0 Z10\nN2 G81 [-5]\n10 CALL ROW\nN5 G80\nM30\n")
    assert r["status"] == "ok", r["error"]
    assert r["variables"]["#HOLES%"] == 3


def test_check_reports_the_type_error_of_every_statement(tmp_path, reference):
    """One check lists every type error (a condition that is no BOOLEAN, the assignments of L655-667 that
    need a conversion), not only the first, each at its statement."""
    from ncvm.api import check
    path = tmp_path / "types.cpl"
    path.write_text('10 IF 3 THEN\n20 B% = 2\n30 ENDIF\n40 C$ = 4\n50 FOR I% = 1 TO "A"\n60 NEXT I%\n70 D% = "X"\n')
    diags = check(path, machine=reference())
    assert [(d.code, d.span.line, d.span.column) for d in diags] == [
        ("CPL032", 1, 4), ("CPL021", 4, 4), ("CPL032", 5, 4), ("CPL021", 7, 4)]
