"""rw_SymPas language core (manual §5): types, operators, statements, routines, compile errors."""

from __future__ import annotations

import pytest


def prog(body: str, decls: str = "") -> str:
    return f"program T;\n{decls}\nbegin\n{body}\nend.\n"


def test_integer_division_and_mod_truncate_toward_zero(sap):
    # L852-856: integer '/' is integer division; mod = i - (i/j)*j (sign of the dividend)
    r = sap(prog("a := 7 / 2; b := -7 / 2; c := -7 mod 2; d := 7 mod -2; e := 17 mod 5;",
                 "var a, b, c, d, e: integer;"))
    assert r["status"] == "ok", r["error"]
    assert r["variables"] == {"a": 3, "b": -3, "c": -1, "d": 1, "e": 2}


def test_real_arithmetic_and_widening(sap):
    # L547-560: d := s * i converts to double; s := i widens integer to single
    r = sap(prog("i := 3; s := 0.5; d := s * i; s := i; x := 7 / 2.0;",
                 "var i: integer; s: single; d, x: double;"))
    assert r["variables"] == {"i": 3, "s": 3.0, "d": 1.5, "x": 3.5}


def test_single_is_rounded_to_binary32(sap):
    r = sap(prog("s := 0.1; d := s; writeln(s);", "var s: single; d: double;"))
    assert r["variables"]["d"] == pytest.approx(0.10000000149011612, abs=0)
    assert r["output"] == ["0.1"]


def test_hex_constants_and_clamping(sap):
    # L398-402: $FFFFFFFF is -1; out-of-range decimals clamp
    r = sap(prog("a := $FFFFFF; b := $FFFFFFFF; c := $7FFFFFFF; d := big; e := small;",
                 "const big = 2147483648; small = -2147483649;\nvar a, b, c, d, e: integer;"))
    assert r["variables"] == {"a": 16777215, "b": -1, "c": 2147483647, "d": 2147483647, "e": -2147483648}


def test_integer_overflow_wraps_and_sets_errorreg_flag(sap):
    r = sap(prog("i := 2147483647; i := i + 1; e := ERRORREG;", "var i, e: integer;"))
    assert r["variables"]["i"] == -2147483648
    assert r["variables"]["e"] == 1 << 30


def test_bitwise_operators_and_shifts(sap):
    # Table 29: not, and, or, xor, shl, shr on integers
    r = sap(prog("a := 12 and 10; b := 12 or 3; c := 12 xor 10; d := not 0; e := 1 shl 4; f := -16 shr 2;",
                 "var a, b, c, d, e, f: integer;"))
    assert r["variables"] == {"a": 8, "b": 15, "c": 6, "d": -1, "e": 16, "f": -4}


def test_boolean_logic_and_casts(sap):
    # §5.3.3.2 L773-784: B := BOOLEAN(I); D := B; I := INTEGER(D); I := B
    r = sap(prog("I := 5; B := BOOLEAN(I); B2 := BOOLEAN(0.0); D := B; I2 := INTEGER(-3.7); I3 := B;"
                 "X := (TRUE xor FALSE) and not FALSE;",
                 "var B, B2, X: BOOLEAN; I, I2, I3: INTEGER; D: DOUBLE;"))
    v = r["variables"]
    assert (v["B"], v["B2"], v["D"], v["I2"], v["I3"], v["X"]) == (True, False, 1.0, -3, 1, True)


def test_precedence_pascal(sap):
    r = sap(prog("i := 2 + 3 * 4; j := (2 + 3) * 4; k := -2 * 3 + 10 / 3; b := 1 + 2 = 3;",
                 "var i, j, k: integer; b: boolean;"))
    assert r["variables"] == {"i": 14, "j": 20, "k": -3, "b": True}


def test_semicolon_before_else_as_in_manual(sap):
    # §5.3.5.5 L972-988: the manual's example writes ';' before else; swaps i and j when i <= 0
    text = prog("i := -1; j := 5;\nif (i > 0) then i := 0; else begin temp := i; i := j; j := temp; end;",
                "var i, j, temp: integer;")
    r = sap(text)
    assert r["variables"] == {"i": 5, "j": -1, "temp": -1}


def test_loops(sap):
    r = sap(prog("s := 0; for i := 1 to 10 do s := s + i; for k := 5 downto 1 do s := s + k;"
                 "n := 0; while n < 7 do n := n + 2; repeat m := m + 1; n := n - 1 until n = 0;"
                 "for z := 3 to 1 do s := 1000;",
                 "var s, i, k, n, m, z: integer;"))
    assert r["variables"] == {"s": 70, "i": 10, "k": 1, "n": 0, "m": 8, "z": 3}


def test_goto_within_block_forward_and_backward(sap):
    text = """program G;
label again, done;
var i: integer;
begin
  i := 0;
again:
  i := i + 1;
  if i < 5 then goto again;
  while TRUE do
    if i >= 5 then goto done;
  i := 100;
done:
  writeln('i=', i);
end.
"""
    r = sap(text)
    assert r["output"] == ["i=5"]


def test_procedures_functions_forward_recursion(sap):
    # §5.3.6: forward declarations, value parameters, recursion, result by assignment to the name
    text = """program R;
var total: integer; r: double;
procedure Add(a, b: integer; c: double); forward;
function Fib(n: integer): integer;
begin
  if n < 2 then Fib := n else Fib := Fib(n - 1) + Fib(n - 2);
end;
function Half: double;
begin Half := 0.5; Half := Half * 2; end;
procedure Add(a, b: integer; c: double);
var local: integer;
begin
  local := a + b;
  total := total + local;
  r := r + c;
  a := 0;
end;
begin
  Add(1, 2, 0.25);
  Add(Fib(10), 0, Half);
end.
"""
    r = sap(text)
    assert r["status"] == "ok", r["error"]
    assert r["variables"] == {"total": 58, "r": 1.25}


def test_function_without_parameters_called_bare_and_with_parens(sap):
    text = """program F;
var a, b: integer;
function FuncA: integer;
begin FuncA := 42; end;
begin a := FuncA; b := FuncA() + 1; end.
"""
    assert sap(text)["variables"] == {"a": 42, "b": 43}


def test_write_formats(sap):
    # rw_SymPas manual L2216; L2224: integers decimal, booleans TRUE/FALSE, reals %g with 10 digits, no separators
    r = sap(prog("write('a', 1); write(' b', TRUE); writeln(' c', 100.0, ' ', 1.0/3.0); writeln('next');"))
    assert r["output"] == ["a1 bTRUE c100 0.3333333333", "next"]


def test_task_string_keeps_the_255_characters_it_shows(sap):
    """A WRITE loop without WRITELN: the string is cut at 255 characters as it grows (it used to grow and be
    copied at every WRITE, and at the program end the whole string was shown)."""
    r = sap(prog("for i := 1 to 2000 do write('0123456789');", "var i: integer;"))
    assert r["output"] == ["0123456789" * 25 + "01234"]
    r = sap(prog("for i := 1 to 2000 do write('0123456789'); writeln('end'); writeln('next');", "var i: integer;"))
    assert r["output"] == ["0123456789" * 25 + "01234", "next"]


def test_common_buffer_roundtrip(sap):
    # §6.6.52-54, 76-78
    r = sap(prog("WRCBD(8, 100.2e-128); WRCBI(500, -1000); WRCBS(504, 3.99);"
                 "d := RDCBD(8); i := RDCBI(500); s := RDCBS(504);",
                 "var d: double; i: integer; s: single;"))
    assert r["variables"]["d"] == 100.2e-128
    assert r["variables"]["i"] == -1000
    assert r["variables"]["s"] == pytest.approx(3.99, rel=1e-7)


@pytest.mark.parametrize("stmt,code", [
    ("d := RDCBD(500);", "2048"),       # manual's own example offset is not divisible by 8
    ("WRCBD(500, 1.0);", "2048"),
    ("i := RDCBI(502);", "256"),
    ("i := RDCBI(1000);", "256"),
    ("i := 5; i := i mod 0;", "32768"),
    ("i := 0; i := 10 / i;", "32768"),
    ("d := 0.0; d := 1.0 / d;", "32768"),
])
def test_runtime_errors_with_manual_numbers(sap, stmt, code):
    r = sap(prog(stmt, "var d: double; i: integer;"))
    assert r["error"]["code"] == code
    assert r["error"]["line"] == 4


def test_runtime_error_names_line_and_call_stack(sap):
    text = """program S;
var i: integer;
procedure Inner(k: integer);
begin
  i := 10 mod k;
end;
procedure Outer;
begin
  Inner(0);
end;
begin
  Outer;
end.
"""
    r = sap(text)
    assert r["error"]["code"] == "32768"
    assert r["error"]["line"] == 5
    assert r["error"]["stack"] == [f"called from Outer at {r['error']['file']}:9",
                                   f"called from main program at {r['error']['file']}:12"]


def test_recursion_depth_is_error_8(sap):
    text = "program P;\nprocedure R(k: integer);\nbegin R(k + 1); end;\nbegin\n  R(0);\nend.\n"
    r = sap(text)
    assert r["error"]["code"] == "8"
    assert r["error"]["line"] == 3


def test_math_functions_manual_examples(sap):
    # §6.6.3 ff.: ABS(-5.0)=5, COS(3.1415)~-1, POWER(2,3)=8, SIN(3.1415)~0, SQR(9)=81, SQRT(9)=3, TAN(0.5)~0.5463
    r = sap(prog("a := ABS(-5.0); b := COS(3.1415); c := POWER(2.0, 3.0); d := SIN(3.1415); e := SQR(9.0);"
                 "f := SQRT(9.0); g := TAN(0.5); h := ABS(-5); n := SQRT(-1.0); ok := n <> n;",
                 "var a, b, c, d, e, f, g, h, n: double; ok: boolean;"))
    v = r["variables"]
    assert v["a"] == 5.0 and v["c"] == 8.0 and v["e"] == 81.0 and v["f"] == 3.0 and v["h"] == 5.0
    assert v["b"] == pytest.approx(-1.0, abs=1e-4) and v["d"] == pytest.approx(0.0, abs=1e-4)
    assert v["g"] == pytest.approx(0.5463, abs=1e-4)
    assert v["ok"] is True


def test_identifiers_case_sensitive_keywords_not(sap):
    # L298: Position and position are different; keywords and commands are case-insensitive
    r = sap("PROGRAM t;\nVAR Position, position: INTEGER;\nBEGIN Position := 1; position := 2; WriteLn(Position) END.\n")
    assert r["variables"] == {"Position": 1, "position": 2}
    assert r["output"] == ["1"]


def test_only_32_characters_are_significant(sap):
    name = "a" * 32
    r = sap(prog(f"{name}x := 7;", f"var {name}y: integer;"))
    assert r["variables"] == {name: 7}


def test_include_directive(sap, tmp_path):
    (tmp_path / "decls.inc").write_text("const seven = 7;\n{! more.inc}\n")
    (tmp_path / "more.inc").write_text("var k: integer;\n")
    r = sap("program I;\n{! decls.inc}\nbegin k := seven; end.\n")
    assert r["variables"] == {"k": 7}


@pytest.mark.parametrize("text,code,line", [
    (prog("i := j;", "var i: integer;"), "3", 4),                       # L662
    (prog("i := 1;\nk := 2;", "var i: integer;"), "3", 5),
    (prog("SQRT(4.0);"), "91", 4),                                        # L1138
    ("program P;\nfunction F: integer; begin F := 1; end;\nbegin F; end.\n", "91", 3),
    (prog("mlr (A1, A2);"), "SP005", 4),                                  # L453
    (prog("i := d;", "var i: integer; d: double;"), "SP003", 4),          # L533-539
    (prog("s := d;", "var s: single; d: double;"), "SP003", 4),
    (prog("b := 1;", "var b: boolean;"), "SP003", 4),
    (prog("i := 1;", "var i: integer; i: double;"), "SP002", 2),          # L666
    (prog("goto nowhere;", "label l1;"), "3", 4),
    ("program P;\nlabel a;\nbegin\na: ;\na: ;\nend.\n", "SP004", 5),      # L594
    (prog("if 1 then ;"), "SP003", 4),
    ("program P;\nfunction F: integer; begin F := 1; end;\nbegin F := 2; end.\n", "SP006", 3),
    (prog("NOA := 3;"), "SP006", 4),                                      # L1305
    (prog("i := A1.rp;", "var i: integer;"), "SP003", 4),
    (prog("A1.digib.1 := TRUE;"), "SP006", 4),
    (prog("b := A1.digib.33;", "var b: boolean;"), "SP010", 4),
    (prog("STARTCNCT(4);"), "SP010", 4),
    ("program P;\nprocedure Q; forward;\nbegin Q; end.\n", "SP009", 2),
    ("program P;\nprocedure Q;\nvar VA: AXIS;\nbegin end;\nbegin end.\n", "SP008", 3),  # L728
    (prog("i := 1 +;", "var i: integer;"), "SP001", 4),
    (prog("enev(Foo);"), "SP005", 4),
    ("program P;\nbegin\nend\n", "SP001", 3),
])
def test_compile_errors(sap_check, text, code, line):
    errors = sap_check(text)
    assert errors and errors[0] == (code, line), errors


def test_include_nesting_limit(sap_check, tmp_path):
    files = {f"i{k}.inc": f"{{! i{k + 1}.inc}}\n" for k in range(16)}
    files["i16.inc"] = "\n"
    errors = sap_check("program P;\n{! i0.inc}\nbegin end.\n", files=files)
    assert errors and errors[0][0] == "SP007"


def test_step_limit_stops_runaway(sap):
    r = sap(prog("while TRUE do i := i + 1;", "var i: integer;"), max_steps=10_000)
    assert r["error"]["code"] == "RUN001"
