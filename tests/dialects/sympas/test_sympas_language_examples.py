"""The manual's language examples (§5: constants, variables, axis variables, timers, casts, routines,
identifiers) and the notes that go with them, run as the manual writes them (ncvm's reading; the rw_SymPas manual is silent).
Each test runs the manual's own lines (cited by line of the German manual). Where a fragment is
not a whole program, it is completed into one: the completion is named in the test. Expected
values are the manual's, or computed by hand in the test (CLOCK ticks of 64 us, 15625 per second).
"""

from __future__ import annotations

import pytest
from sympas_examples import SEC, axes_toml, errors_of, prog

# --- §5: language examples -------------------------------------------------------------------------


def test_integer_constant_L423(sap):
    # L423 `const one = 1;` is an Integer constant: 7 / (one + one) is integer division, 3
    r = sap(prog("i := 7 / (one + one); d := one;", "const one = 1;\nvar i: integer; d: double;"))
    assert r["status"] == "ok", r["error"]
    assert r["variables"] == {"i": 3, "d": 1.0}


def test_double_constant_with_capital_const_L466(sap, tmp_path):
    # L466 `Const one = 1.0;` (keyword case-insensitive, A-1) is a Double constant: 7 / (one + one) = 3.5
    r = sap(prog("d := 7 / (one + one);", "Const one = 1.0;\nvar d: double;"))
    assert r["status"] == "ok", r["error"]
    assert r["variables"] == {"d": 3.5}
    # ... so it cannot be stored in an Integer without a cast (L533-539)
    assert errors_of(tmp_path, prog("i := one;", "Const one = 1.0;\nvar i: integer;")) == [("SP003", 5)]


def test_variable_declarations_L702_708(sap):
    # L702-708 verbatim as the var block; the statements that use each type are the completion
    decls = "var\n    on, off:      BOOLEAN;\n    eins:        INTEGER;\n    dvalue:      DOUBLE;\n    ticks:       TIMER;"
    r = sap(prog("on := TRUE; off := not on; eins := 1; dvalue := eins / 2.0; ticks := CLOCK;", decls))
    assert r["status"] == "ok", r["error"]
    # one statement per 64 us tick, CLOCK counts before the statement runs: the 5th reads CLOCK = 5
    assert r["variables"] == {"on": True, "off": False, "eins": 1, "dvalue": 0.5, "ticks": 5}


def test_axis_variable_example_on_six_axes_L718_724(sap_on):
    # L718-724: VA.an := 0; ol(VA); for VA.an := 0 to 5 do cl(VA); needs NOA >= 6 (axes 0..5).
    # Completion: the statements go into the main block; the loop states are read back through axst
    # (provisional bit 2 = loop closed, i.e. axstb.3).
    text = prog("VA.an := 0;\nol(VA);\nopen0 := A1.axstb.3;\nfor VA.an := 0 to 5 do cl(VA);\n"
                "last := VA.an;\nall := A1.axstb.3 and A2.axstb.3 and A3.axstb.3 and A4.axstb.3 and A5.axstb.3"
                " and A6.axstb.3;",
                "var\n    VA : AXIS;\n    open0, all: boolean; last: integer;")
    r = sap_on(text, axes_toml(6))
    assert r["status"] == "ok", r["error"]
    assert r["variables"] == {"VA": 5, "open0": False, "all": True, "last": 5}


def test_axis_variable_example_needs_six_axes_L723(sap):
    # the same loop on the 3-axis machine: VA.an = 3 names no axis, run-time error 256
    r = sap(prog("for VA.an := 0 to 5 do cl(VA);", "var VA: AXIS;"))
    assert r["error"]["code"] == "256"
    assert r["error"]["line"] == 4


def test_timer_example_as_printed_L741_749(sap):
    # L741-749 with the manual's own `Const s := 15625;` (lenient reading, A-9); `Var t: timer` gets
    # its `;`, the `...` are left out. t := CLOCK + 5*s is the first statement, run at CLOCK = 1, so
    # t = 78126 and the loop ends at the first test with CLOCK > 78126.
    text = ("program T;\nConst\n    s := 15625;\nVar\n    t: timer;\n    done: timer;\nbegin\n"
            "t := CLOCK + 5*s;\nrepeat\nuntil CLOCK > t;\ndone := CLOCK;\nend.\n")
    r = sap(text)
    assert r["status"] == "ok", r["error"]
    assert r["variables"]["t"] == 5 * SEC + 1
    assert 5 * SEC + 1 < r["variables"]["done"] <= 5 * SEC + 4
    assert r["cycle_time_s"] == pytest.approx(5.0, abs=0.001)


def test_type_casts_in_the_manual_order_L779_784(sap):
    # L779-784 in order, with I = 5 and D = 2.5 before them; each result is copied aside
    r = sap(prog("I := 5; D := 2.5;\n"
                 "B := BOOLEAN (I); b1 := B;\nB := BOOLEAN (D); b2 := B;\nD := B; d1 := D;\n"
                 "I := INTEGER (D); i1 := I;\nI := B; i2 := I;",
                 "var\n    B : BOOLEAN;\n    I : INTEGER;\n    D : DOUBLE;\n    b1, b2: BOOLEAN; d1: DOUBLE; i1, i2: INTEGER;"))
    assert r["status"] == "ok", r["error"]
    v = r["variables"]
    assert (v["b1"], v["b2"], v["d1"], v["i1"], v["i2"]) == (True, True, 1.0, 1, 1)


def test_if_else_example_then_branch_L980_988(sap):
    # L980-988 with i > 0: the then-branch sets i to 0 and j stays (the else-branch is in test_sympas_language)
    text = prog("i := 3; j := 5;\nif (i > 0) then i := 0;\nelse begin\n    temp := i;\n    i := j;\n    j := temp;\nend;",
                "var\n    i: Integer;\n    j: Integer;\n    temp: Integer;")
    r = sap(text)
    assert r["status"] == "ok", r["error"]
    assert r["variables"] == {"i": 0, "j": 5, "temp": 0}


def test_procedure_declarations_as_printed_L1064_1131(sap):
    # L1064-1131: ProcA and ProcB forward, then defined; ProcC with local variables. The bodies
    # "(Prozedurblock ...)" are completed with statements that use the parameters and locals.
    text = """program P;
var g: integer; r: double;
procedure ProcA; forward;
procedure ProcB (ParamA, ParamB : integer; ParamC : double); forward;
procedure ProcC (ParamA : integer);
var locVarA, locVarB : integer;
    locVarC : double;
begin
    locVarA := ParamA; locVarB := 2 * ParamA; locVarC := locVarB / 4.0;
    g := g + locVarA + locVarB; r := r + locVarC;
    ProcB(ParamA, locVarB, locVarC);
end;
procedure ProcA;
begin
    g := g * 10;
end;
procedure ProcB (ParamA, ParamB : integer; ParamC : double);
begin
    g := g + ParamA * ParamB; r := r + ParamC;
    ProcA;
end;
begin
    ProcC(3);
end.
"""
    r = sap(text)
    assert r["status"] == "ok", r["error"]
    # ProcC(3): g = 3 + 6 = 9, r = 1.5; ProcB(3, 6, 1.5): g = 9 + 18 = 27, r = 3.0; ProcA: g = 270
    assert r["variables"] == {"g": 270, "r": 3.0}


FUNC_B = """program F;
var x: double;
function FuncB (ParamA, ParamB : integer; ParamC : double) : double; forward;
function Twice(k: integer): double;
begin
    Twice := FuncB(k, k, 0.5);
end;
function FuncB (ParamA, ParamB : integer; ParamC : double) : double;{DEF}
begin
    FuncB := (ParamA + ParamB) * ParamC;
end;
begin
    x := Twice(7);
end.
"""


def test_function_with_parameters_forward_L1182_1194(sap):
    # L1182-1194 (without the spurious second `forward`, A-20): FuncB used before its definition
    r = sap(FUNC_B.replace("{DEF}", ""))
    assert r["status"] == "ok", r["error"]
    assert r["variables"] == {"x": 7.0}  # (7 + 7) * 0.5


def test_function_definition_with_forward_repeated_as_printed_L1191(tmp_path):
    # L1191 repeats `; forward;` on the defining header; ncvm reads it as a slip and
    # does not accept it; the error is at the stray `forward` of the definition (line 8), not at the
    # `end;` (line 11) where the block, read as the main program, would want its `.` (issue 15)
    errors = errors_of(tmp_path, FUNC_B.replace("{DEF}", " forward;"))
    assert errors == [("SP001", 8)]


def test_parameterless_function_recursion_needs_empty_parens_L1146(sap):
    # L1146: inside the function its name is the result variable; a recursive call of a function
    # without parameters is written with an empty pair of parentheses.
    text = """program R;
var n: integer;
function Count : integer;
begin
    CI1 := CI1 + 1;
    if CI1 < 3 then Count := Count() + 10 else Count := 0;
    Count := Count + 1;
end;
begin
    CI1 := 0;
    n := Count;
end.
"""
    r = sap(text)
    assert r["status"] == "ok", r["error"]
    # 3rd call: 0 + 1 = 1; 2nd: 1 + 10 + 1 = 12; 1st: 12 + 10 + 1 = 23
    assert r["variables"] == {"n": 23}


def test_program_header_L1236(sap):
    r = sap("program Test;\nbegin\nend.\n")
    assert r["status"] == "ok", r["error"]


# --- identifiers (§5.2.3.2, L283-286) -------------------------------------------------------------


def test_valid_identifiers_of_the_example_L285(sap):
    # L285: A, AA, AB, _A are valid identifiers (A1 and A2 are too, but name the predefined axes)
    r = sap(prog("A := 1; AA := 2; AB := 3; _A := A + AA + AB;", "var A, AA, AB, _A: integer;"))
    assert r["status"] == "ok", r["error"]
    assert r["variables"] == {"A": 1, "AA": 2, "AB": 3, "_A": 6}


@pytest.mark.parametrize("name", ["1A", "?B"])
def test_invalid_identifiers_of_the_example_L286(tmp_path, name):
    # L286: 1A and ?B are not identifiers: a compile error in the declaration line, no traceback
    errors = errors_of(tmp_path, prog("", f"var {name}: integer;"))
    assert errors and errors[0][1] == 2, errors


# --- notes that go with the examples -------------------------------------------------------------


def test_predefined_axis_gets_a_new_number_L726(sap):
    # L726: the axis number of a predefined specifier (A1 .. An) can be changed like VA.an: after
    # A1.an := 1, A1 names channel 2 (Y); A1.an := 0 gives it back
    r = sap(prog("A1.an := 1;\nMLAW(A1 := 5.0);\ny := A2.dp; n := A1.an;\nA1.an := 0;\nx := A1.dp;",
                 "var y, x: double; n: integer;"))
    assert r["status"] == "ok", r["error"]
    assert r["variables"] == {"y": 5.0, "n": 1, "x": 0.0}
    assert r["position"] == {"A1": 0.0, "A2": 5.0, "A3": 0.0}


def test_clock_in_an_integer_turns_negative_timer_does_not_L732_L756(sap_on):
    # L732: after the largest positive value the clock gives the smallest negative one (in an
    # Integer); L756: a Timer holds 0 .. 4294967295. CLOCK starts at 2^31 - 8: WT(20) runs from
    # tick 1 to 21, i := CLOCK reads 2^31 - 8 + 22, t := CLOCK one tick later
    r = sap_on(prog("WT(20);\ni := CLOCK;\nt := CLOCK;\nlater := t > 100;", "var i: integer; t: timer; later: boolean;"),
               axes_toml(3, extra="clock_start = 2147483640\n"))
    assert r["status"] == "ok", r["error"]
    v = r["variables"]
    assert v["t"] == 2147483640 + 23
    assert v["i"] == 2147483640 + 22 - 2**32
    assert v["later"] is True  # modular: t - 100 is a positive int32


@pytest.mark.parametrize("text,code", [
    (prog("i := A2.DIGI;", "var i: integer;"), "SP001"),          # L1424: qualifiers are case-sensitive
    (prog("b := A2.DIGIB.1;", "var b: boolean;"), "SP001"),       # L1501
    (prog("i := a2.digi;", "var i: integer;"), "3"),              # L1420: axis specifiers too
])
def test_qualifiers_and_axis_names_are_case_sensitive(tmp_path, text, code):
    assert errors_of(tmp_path, text) == [(code, 4)]


def test_local_labels_and_fresh_locals_in_a_routine_L1058_L1150(sap):
    # L1058 / L1150: local variables and local labels between the header and the block. Locals start
    # at 0 on every call: Count(3) = 100 + 3, Count(2) = 100 + 2
    text = """program P;
var r1, r2: integer;
function Count(k: integer): integer;
label again;
var acc: integer;
begin
  acc := acc + 100;
again:
  acc := acc + 1;
  k := k - 1;
  if k > 0 then goto again;
  Count := acc;
end;
begin
  r1 := Count(3);
  r2 := Count(2);
end.
"""
    r = sap(text)
    assert r["status"] == "ok", r["error"]
    assert r["variables"] == {"r1": 103, "r2": 102}
