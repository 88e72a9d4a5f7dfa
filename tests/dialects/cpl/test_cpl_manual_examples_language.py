"""CPL manual examples, language core (CPL manual §2-3, L302-1179: expressions in NC words, permanents, loops, CALL, PDIM).

Each test runs the manual's program, repaired only where an OCR slip or the
comment says why, and asserts the result the manual states.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from ncvm.api import run as run_program
from ncvm.runtime.session import RunOptions

C1SUB = "5 XVALUE=P1 : FEED=P2 : COMPTAB=P3 : M3=3\nN10 G1 X[XVALUE]F[ FEED*2+1000]M[M3]\n"


def test_c1_expressions_in_nc_words_of_a_sub_program_l359(run_text, reference):
    """§2.1.1 L359-369, called with P1..P3 = 20, 100, 3: N10 is G1 X20 F1200 M3 (M3 is a variable named like
    the M function). Lines 15/16 read the feed and the spindle sense back (SD(5,1,2), SD(12,1))."""
    m = reference()
    (m.program_path[0] / "C1SUB").write_text(C1SUB + "15 WAIT\n16 #F% = SD(5,1,2) : #SP% = SD(12,1)\nM30\n")
    r = run_text("10 CALL C1SUB [20, 100, 3]\nM30\n", name="p.cpl", machine=m)
    assert r["status"] == "ok", r["error"]
    assert r["variables"] == {"#F%": 1200, "#SP%": 3} and r["position"]["X"] == 20.0


def test_c1_g22_selects_the_compensation_table_of_p3_l366(run_text, reference):
    """N20 G22 K[COMPTAB] selects tool compensation table K<COMPTAB> (the database tables K4 and K5 of TC,
    L1854-1884; docs/decisions.md, issue 14): the example runs, and an H word after it reads that table."""
    m = reference()
    (m.program_path[0] / "C1SUB").write_text(C1SUB + "N20 G22 K[COMPTAB]\nN30 H2\n40 WAIT\n50 #L = TC(1)\nM30\n")
    r = run_text("1 TC(1,2,5)=7.5 : TC(1,2,4)=3\n10 CALL C1SUB [20, 100, 5]\nM30\n", name="p.cpl", machine=m)
    assert r["status"] == "ok", r["error"]
    assert r["position"]["X"] == 20.0 and r["variables"]["#L"] == 7.5


def test_c1_g22_of_a_table_that_is_no_database_table_stops_l366(run_text, reference):
    m = reference()
    (m.program_path[0] / "C1SUB").write_text(C1SUB + "N20 G22 K[COMPTAB]\nM30\n")
    r = run_text("10 CALL C1SUB [20, 100, 3]\nM30\n", name="p.cpl", machine=m)
    assert r["error"]["code"] == "NC009" and r["error"]["line"] == 3 and "K3" in r["error"]["message"]
    assert r["position"]["X"] == 20.0


GOLDEN = Path(__file__).parents[2] / "programs" / "cpl"


def test_c5_permanent_values_survive_a_new_run_l517(tmp_path):
    """§2.4.3 L517-533 and L639-652 (the golden variables.cpl, with the wmhperm.dat of L623-637): a second
    program finds the permanent values; the local and the global one are gone."""
    options = RunOptions(state_dir=tmp_path / ".ncvm")
    first, _ = run_program(GOLDEN / "variables.cpl", machine=GOLDEN / "machine.toml", options=options)
    assert first["status"] == "ok", first["error"]
    reader = tmp_path / "reader.cpl"
    reader.write_text("10 A% = @36% : B% = @ABCD% : C% = @2 : D = @WZKOR(3,2) : E$ = @PSTR1$ : F$ = @PSTR2$(3)\n"
                      "20 G! = @IJKL! : H? = @MNOP? : I% = @WZNR%(2)\n"
                      "30 LGONE? = NUMBER1% = NUL : GGONE? = #NUMBER2% = NUL\nM30\n", encoding="latin-1")
    r, _ = run_program(reader, machine=GOLDEN / "machine.toml", options=options)
    assert r["status"] == "ok", r["error"]
    v = r["variables"]
    assert (v["A%"], v["B%"], v["C%"], v["E$"], v["F$"], v["I%"]) == (3, 4, 2, "ABC", "DE", 6)
    assert v["D"] == pytest.approx(7.6) and v["G!"] == 5.12345 and v["H?"] is True
    assert v["LGONE?"] is True and v["GGONE?"] is True


def test_c13_for_with_a_variable_step_into_file_p222_l940(run_text, reference):
    """§2.5.5 L940-958 with its file: the printed records need STEP%=2 at the start (the text shows 1, which
    would give 1/1, 2/1, ...; CPL manual L944-958) and ``SORT`` is SQRT (OCR). NJUST: numbers in 9 places."""
    m = reference()
    r = run_text('10 OPENW(1,"P222",130)\n20 STEP%=2 : START%=1 : END%=3500 : NJUST\n'
                 "30 FOR COUNTER%=START% STEP STEP% TO END%\n40 STEP%=ROUND(STEP%*SQRT(STEP%))\n"
                 '50 PRN#(1,"COUNTER: ",COUNTER%," STEP SIZE: ",STEP%)\n60 NEXT\n70 CLOSE(1)\nM30\n',
                 name="p.cpl", machine=m)
    assert r["status"] == "ok", r["error"]
    pairs = [(1, 3), (4, 5), (9, 11), (20, 36), (56, 216), (272, 3175), (3447, 178902)]
    records = [f"COUNTER: {c:9d} STEP SIZE: {s:9d}" for c, s in pairs]
    assert (m.file_root / "P222").read_text(encoding="latin-1") == "\n".join(records) + "\n\x03\n"


WHILE_SD9 = "5 I=0\nN10 G75 X100 F1000\n30 WHILE SD(9)=0\n40 I=I+1\n50 END\nM30\n"


def test_c14_while_polls_sd9_l984(run_text, reference):
    """§2.5.5 L984: ``WHILE SD(9)=0`` (no DO; I set to 0 first, the fragment leaves it NUL) loops while the
    condition holds (CPL manual L982-986, the annotation says the opposite). Probe not switched: SD(9)=1, no pass.
    Switched: SD(9) stays 0 in the simulation, so the loop runs until the step limit."""
    r = run_text(WHILE_SD9, name="p.cpl", machine=reference())
    assert r["status"] == "ok" and r["variables"] == {"I": 0.0}
    m = reference(scenario=[{"time": 0.0, "kind": "probe", "X": 40.0}])
    r = run_text(WHILE_SD9, name="p.cpl", machine=m, max_steps=1000)
    assert r["error"]["code"] == "RUN001" and r["variables"]["I"] > 400


def _with_p999(reference, body: str):
    m = reference()
    (m.program_path[0] / "P999").write_text(body, encoding="latin-1")
    return m


@pytest.mark.parametrize("a", [1, 0])
def test_c18_call_inside_if_l1089(run_text, reference, a):
    """§3.3 L1093-1095: CALL in its own block inside IF; P999 runs only when A% = 1."""
    m = _with_p999(reference, "N10 G1 X10 F100\nM30\n")
    r = run_text(f"10 A%={a}\n50 IF A% = 1 THEN\n51 CALL P999\n52 ENDIF\nM30\n", name="p.cpl", machine=m)
    assert r["status"] == "ok", r["error"]
    assert r["position"]["X"] == (10.0 if a == 1 else 0.0)


def test_c18_call_din_of_a_pure_din_program_l1105(run_text, reference):
    """§3.3 L1105-1108: CALL P999 DIN excludes P999 from linking; a DIN-only P999 still runs."""
    m = _with_p999(reference, "N10 G1 X10 F100\nM30\n")
    r = run_text("10 A%=1\n50 IF A% = 1 THEN\n51 CALL P999 DIN\n52 ENDIF\nM30\n", name="p.cpl", machine=m)
    assert r["status"] == "ok", r["error"]
    assert r["position"]["X"] == 10.0 and r["motion"]["feed_moves"] == 1


@pytest.mark.parametrize("main", ["51 CALL P999 DIN\n", "51 CALL P999\n"])
def test_c18_din_excluded_program_with_cpl_is_a_runtime_error_l1101(run_text, reference, main):
    """§3.3 L1101 and L1112-1116: a sub-program holding CPL that is excluded from linking (by ``DIN`` on the
    call or by the ``(DIN)`` remark in its first line) gives an error "at program runtime": only when the
    call is reached."""
    body = "N10 G1 X10 F100\n20 B%=1\nM30\n" if "DIN" in main else "N10 (DIN)\nN20 G1 X10 F100\n30 B%=1\nM30\n"
    m = _with_p999(reference, body)
    prog = "10 A%={}\n50 IF A% = 1 THEN\n" + main + "52 ENDIF\nM30\n"
    r = run_text(prog.format(1), name="p.cpl", machine=m)
    assert r["status"] == "error" and r["error"]["code"] == "CPL030" and r["error"]["line"] == 3
    r = run_text(prog.format(0), name="p.cpl", machine=m)
    assert r["status"] == "ok", r["error"]


PDIM_MAIN = 'N10 (DIN)\nN20 G90\nN50 P SP["TEST"]\nM30\n'


def _with_sp(reference, body: str):
    m = reference()
    (m.program_path[0] / "SP").write_text(body, encoding="latin-1")
    return m


@pytest.mark.parametrize("sub", [
    "10 PDIM P1$(4)\n20 #P1$ = P1$\nM30\n",
    "10 PDIM P1$(4)\n20 GOTO .TAKE\n30 #P1$ = \"NO\"\n40 .TAKE\n50 #P1$ = P1$\nM30\n",  # also in GOTO code
])
def test_c20_pdim_string_from_a_program_selected_without_linking_l1161(run_text, reference, sub):
    """§3.4 L1161-1175: the caller is marked (DIN); with PDIM P1$(4) the sub-program's P1$ is "TEST"."""
    r = run_text(PDIM_MAIN, name="p.cpl", machine=_with_sp(reference, sub))
    assert r["status"] == "ok", r["error"]
    assert r["variables"] == {"#P1$": "TEST"}


def test_c20_without_pdim_the_string_is_an_invalid_variable_l1159(run_text, reference):
    """§3.4 L1149-1159: from a caller selected without linking, a string constant needs PDIM; "missing
    entirely" gives the part program error "invalid variable". A linked caller needs no PDIM."""
    m = _with_sp(reference, "20 #P1$ = P1$\nM30\n")
    r = run_text(PDIM_MAIN, name="p.cpl", machine=m)
    assert r["error"]["code"] == "CPL026" and r["error"]["message"].startswith("invalid variable")
    r = run_text(PDIM_MAIN.replace("N10 (DIN)\n", ""), name="p.cpl", machine=m)
    assert r["status"] == "ok" and r["variables"] == {"#P1$": "TEST"}
