"""Independent review of issue 15, rw_SymPas item 7 (figures in the program's terms).

Found by running programs as a user of the APCI-8001 would (docs/sympas.md, "The `sympas` part of the
JSON document"): the card's axes are A1, A2 ... (rw_SymPas manual L1399: dp in user units, the user-visible
position being the machine position less the zero offsets).
"""

from .helpers import run_json


def test_bounds_contain_the_position_where_the_soft_limit_stopped_the_axis(tmp_path):
    """L2144-2150 (SZPA) and the soft limit slr: TOM stops A1 at slr = 400 (machine_position 400.0,
    position dp 300.0), yet `bounds_machine` / `motion.bounds` say the axis never went beyond
    399.99999999900007 and `bounds_program` 299.999...: the toolpath bounds do not contain the point
    the run reports the axis standing at. Bounds must enclose the axis's end position."""
    doc = run_json(
        tmp_path,
        """\
        {$TASK 0}
        program Main;
        begin
          TRVL := 100.0; TRAC := 1000.0;
          SZPA(A1 := 100.0);
          MLAW(A1 := 350.0);
          writeln('A1 dp ', A1.dp);
        end.
        """,
    )
    assert doc["status"] == "ok"
    axis = doc["sympas"]["axes"]["A1"]
    assert axis["machine_position"] == 400.0
    assert axis["position"] == 300.0
    assert axis["bounds_machine"][1] >= axis["machine_position"]
    assert axis["bounds_program"][1] >= axis["position"]
    assert doc["motion"]["bounds"]["A1"][1] >= axis["machine_position"]


def test_position_of_a_program_that_does_not_compile_is_named_in_the_programs_axes(tmp_path):
    """Issue 15 rw_SymPas 7 / docs/sympas.md: "the top-level `position` ... name the axes as the program
    does (A1 ...)". A run that finishes or stops at run time does so ({'A1': 20.0, ...}); a program
    that stops at a compile error reports `position` {'X': 0.0, 'Y': 0.0, ...} in the machine's
    names, which the program never uses."""
    doc = run_json(
        tmp_path,
        """\
        {$TASK 0}
        program Main;
        begin
          MLAW(A1 := 20.0);
          writeln(A1.ap);
        end.
        """,
    )
    assert doc["status"] == "error"
    assert doc["error"]["code"] == "SP001"
    assert set(doc["position"]) == {"A1", "A2"}
