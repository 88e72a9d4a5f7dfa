"""Generated valid CPL programs: no traceback, and no internal error disguised as a CPL run-time fault.

cpl_gen writes random programs that use the language as the manual describes it; cpl_probe runs
them and reports every fault whose Python exception came from ncvm's library rather than from the
program (a TypeError in a helper would otherwise read as VARIABLE NOT ASSIGNED). The regression
cases below are the smallest programs for the bugs the generator and a review of its findings turned up.
"""

from __future__ import annotations

import pytest
from cpl_gen import program
from cpl_probe import run_program, watch_faults

from ncvm.api import check

SEEDS = range(40)  # fixed: the same programs on every run, well under 5 s


@pytest.mark.parametrize("seed", SEEDS)
def test_generated_program_runs_cleanly(tmp_path, seed):
    main, subs = program(seed)
    try:
        result, suspects = run_program(tmp_path, main, subs, max_steps=5_000)
    except Exception as e:  # noqa: BLE001 - the point of the test
        pytest.fail(f"seed {seed} raised {type(e).__name__}: {e}\n{main}")
    assert not suspects, f"seed {seed}: internal error behind {result['error']}: {suspects}\n{main}"
    assert result["status"] in ("ok", "error")


def _run(run_text, text: str) -> dict:
    found: list = []
    with watch_faults(found):
        result = run_text(text, name="p.cpl")
    assert not found, found
    return result


def test_double_beyond_the_decimal_precision_prints(run_text):
    """PRN# of a DOUBLE with more than 28 digits: the standard 9.6 format widens (it used to raise
    decimal.InvalidOperation out of the run)."""
    r = _run(run_text, "10 D! = 1000000000000000.0 * 1000000000000000.0\n20 PRN#(0,D!)\n"
                       '30 DIM A$(60) : A$ = STR$("#.#",D!)\nM30\n')
    assert r["status"] == "ok", r["error"]
    assert r["output"] == ["1000000000000000000000000000000.000000"]
    assert r["variables"]["A$"] == "***"  # the value does not fit its template


def test_val_reads_ascii_digits_only(run_text):
    """VAL of a Latin-1 superscript digit (CHR$(178) is "²") finds no number: NUL, not a run-time error."""
    r = _run(run_text, '10 A = 1 : A = VAL(CHR$(178)) : B% = VAL("4" + CHR$(179))\nM30\n')
    assert r["status"] == "ok", r["error"]
    assert "A" not in r["variables"]  # assigning NUL deletes the variable
    assert r["variables"]["B%"] == 4


def test_int_of_a_number_beyond_the_integer_range(run_text):
    """I% = INT(R) with R = 3e9: INVALID INTEGER VALUE, not an INTEGER variable holding 3000000000."""
    r = _run(run_text, "10 R = 3000000000.0\n20 I% = INT(R)\nM30\n")
    assert r["error"]["code"] == "CPL027" and r["error"]["line"] == 2


def test_double_overflow_is_a_range_error(run_text):
    """A DOUBLE result beyond +/-1e308 is refused where it is stored (it used to become infinity,
    which later surfaced as a misleading error in INT or an asterisk in PRN#)."""
    r = _run(run_text, "10 D! = 100000000000000000000.0 * 100000000000000000000.0\n"
                       "20 FOR K% = 1 TO 5 : D! = D! * D! : NEXT\nM30\n")
    assert r["error"]["code"] == "CPL042" and r["error"]["line"] == 2
    assert "DOUBLE range" in r["error"]["message"]


def test_real_overflow_through_infinity_is_a_range_error(run_text):
    """R = D! * D! where the product is infinite: the REAL range error, as for any value beyond 1e38."""
    r = _run(run_text, "10 D! = 1000000000000000000000000000000.0\n"
                       "20 FOR K% = 1 TO 4 : D! = D! * 1000000000000000000000000000000.0 : NEXT\n"
                       "30 R = D! * D!\nM30\n")
    assert r["error"]["code"] == "CPL042" and r["error"]["line"] == 3
    assert "REAL range" in r["error"]["message"]


@pytest.mark.parametrize("call", ["INT", "ROUND"])
def test_int_and_round_of_an_infinite_value(run_text, call):
    """INT/ROUND of a value beyond every range report INVALID INTEGER VALUE from the range check."""
    r = _run(run_text, f"10 D! = 1000000000000000000000000000000.0\n20 I% = {call}(D! * D! * D! * D! * D! * D!"
                       " * D! * D! * D! * D! * D!)\nM30\n")
    assert r["error"]["code"] == "CPL027"
    assert "outside the INTEGER range" in r["error"]["message"]


def test_inp_of_a_number_beyond_the_double_range(run_text):
    """INP# of a 400-digit number into a DOUBLE: INVALID FLOAT VALUE (it was INVALID INTEGER VALUE)."""
    r = _run(run_text, f'10 OPENW(1,"BIG",2000) : PRN#(1,"{"9" * 400}") : CLOSE(1)\n'
                       '20 OPENR(1,"BIG") : INP#(1,D!) : CLOSE(1)\nM30\n')
    assert r["error"]["code"] == "CPL042"


@pytest.mark.parametrize("stmt", ['OPENW(1,"A"+CHR$(0))', 'OPENR(1,"A"+CHR$(0))', 'I% = ERASE("A"+CHR$(0))'])
def test_file_name_with_chr0_is_an_invalid_file_name(run_text, stmt):
    """A file name holding CHR$(0): INVALID FILE NAME (the operating system's ValueError used to read as
    "argument outside the domain of the function")."""
    r = _run(run_text, f"10 {stmt}\nM30\n")
    assert r["error"]["code"] == "CPL609"


def test_fileaccess_of_a_name_with_chr0_does_not_exist(run_text):
    r = _run(run_text, '10 I% = FILEACCESS("A"+CHR$(0))\nM30\n')
    assert r["status"] == "ok" and r["variables"]["I%"] == -1


@pytest.mark.parametrize("stmt, message", [
    ("DSP(1)", "DSP takes 2 or more arguments, not 1"),
    ('OPENW(1)', "OPENW takes 2 or more arguments, not 1"),
    ("CLOSE(1,2)", "CLOSE takes 1..1 arguments, not 2"),
    ("SEEK(1)", "SEEK takes 2..3 arguments, not 1"),
    ("PRN(1)", "PRN takes 3 or more arguments, not 1"),
    ("RGB(1)", "RGB takes 4..4 arguments, not 1"),
    ("ERASE()", "ERASE takes 1..1 arguments, not 0"),
])
def test_statement_with_a_wrong_argument_count_is_a_compile_error(tmp_path, stmt, message):
    """File and screen statements check their argument count like the functions do; a wrong count used to
    reach the run and fail inside the call, reported as VARIABLE NOT ASSIGNED."""
    path = tmp_path / "p.cpl"
    path.write_text(f"10 {stmt}\nM30\n", encoding="latin-1")
    diags = check(path)
    assert diags and diags[0].code == "CPL001" and message in diags[0].message


def test_parameter_not_passed_copies_as_nul(run_text, tmp_path):
    """``G = P7`` when the caller passed fewer parameters: G becomes NUL, as ``A% = P7%`` and ``B$ = P7$`` do
    (the UNTPR example reads parameters that were not passed, L4672). The REAL view raised NUL used."""
    (tmp_path / "SUBN.cpl").write_text("10 G = P3 : H! = P3! : A% = P3% : E = P1! : D! = P2%\n"
                                       "20 SEEN? = (G = NUL) AND (H! = NUL) AND (A% = NUL)\n"
                                       "30 #OK? = SEEN? AND (E = 2.5) AND (D! = 4)\nM30\n", encoding="latin-1")
    r = _run(run_text, "10 CALL SUBN [2.5, 4]\nM30\n")
    assert r["status"] == "ok", r["error"]
    assert r["variables"]["#OK?"] is True


def test_nul_variable_copied_into_another_numeric_type(run_text):
    """``R = I%`` with I% unassigned copies NUL (as ``J% = I%`` does) instead of failing."""
    r = _run(run_text, "10 R = 1 : D! = 1 : R = I% : D! = I%\n20 OK? = (R = NUL) AND (D! = NUL)\nM30\n")
    assert r["status"] == "ok", r["error"]
    assert r["variables"]["OK?"] is True


def test_file_written_after_a_very_long_simulated_time(run_text):
    """A feed move over 1e20 mm takes longer than a file time stamp can express: the file is still
    written (os.utime's OverflowError used to read as INVALID INTEGER VALUE)."""
    r = _run(run_text, '10 R = 99999999999999999999.5\nN20 G1 X[R] F100\n30 WAIT\n'
                       '40 OPENW(1,"LOG") : PRN#(1,"A") : CLOSE(1)\n50 OPENR(1,"LOG") : INP#(1,A$) : CLOSE(1)\nM30\n')
    assert r["status"] == "ok", r["error"]
    assert r["variables"]["A$"] == "A"


def test_mid_view_into_a_row_of_a_two_dimensional_field(run_text):
    """``B$ = MID$(H$(1),2)`` is a live view into row 1 of ``DIM H$(2,4)`` (the view took the whole field and
    failed with a TypeError read as VARIABLE NOT ASSIGNED)."""
    r = _run(run_text, '10 DIM H$(2,4) : H$(1) = "ABCDEFG" : B$ = MID$(H$(1),2) : C$ = MID$(H$(2),1,1)\n'
                       '20 H$(1) = "WXYZ" : PRN#(0,B$,"|",H$(1),"|",LEN(C$))\nM30\n')
    assert r["status"] == "ok", r["error"]
    assert r["output"] == ["XYZ|WXYZ|       -1"]


@pytest.mark.parametrize("stmt, code", [
    ('MWD(0,"A",0,1)', "CPL023"), ('LIN(0,0,"A",1)', "CPL023"), ('CIR(0,0,"A")', "CPL023"),
    ('GPR("A",1,"X")', "CPL023"), ("GPR(1,1,5)", "CPL023"), ("BMP(1,1,5)", "CPL023"), ('TFO("A")', "CPL023"),
    ("I% = ERASE(1.5)", "CPL023"),
])
def test_graphics_and_text_arguments_of_the_wrong_type(run_text, stmt, code):
    """A string where a coordinate belongs, or a number where a text belongs, is INVALID PARAMETER; the
    Python ValueError/TypeError behind them used to read as a domain error or as VARIABLE NOT ASSIGNED."""
    r = _run(run_text, f"10 {stmt}\nM30\n")
    assert r["error"]["code"] == code


def test_very_long_line_is_clipped_to_the_window():
    """LIN to 3e9 pixels used to step through every pixel (hours); only the part inside the window is drawn,
    with the same pixels as a line that ends at the window's edge. The steps are counted, not timed: a
    line stepped pixel by pixel stops at the bound and fails at once."""
    from ncvm.dialects.cpl.io.screen import Screen

    long, short = Screen(), Screen()
    steps = 0
    plot = long._plot

    def counted(px, py, step):
        nonlocal steps
        steps += 1
        assert steps <= 10_000, "the long line is stepped pixel by pixel outside the window"
        plot(px, py, step)

    long._plot = counted
    long.LIN(0, 5, 3000000000, 5)
    long.LIN(10, 0, 3000000010, 3000000000)
    short.LIN(0, 5, 632, 5)
    short.LIN(10, 0, 632, 622)
    assert (long.canvas == short.canvas).all()


@pytest.mark.parametrize("expr", ["ABS(I%)", "BCD(99999999)"])
def test_integer_function_result_outside_the_range_is_not_stored(run_text, expr):
    """``J% = ABS(-2147483648)`` stored 2147483648 in an INTEGER variable: function results are range-checked
    on assignment like any other expression (INVALID INTEGER VALUE)."""
    r = _run(run_text, f"10 I% = -2147483648 : J% = {expr}\nM30\n")
    assert r["error"]["code"] == "CPL027"
    assert "J%" not in r["variables"]
