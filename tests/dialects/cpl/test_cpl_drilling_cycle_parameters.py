"""What the CPL manual says about the parameters of a drilling cycle G81-G86 (programs 99999081-99999086,
§3.1 L1071-1074), which it calls like any sub-program called by G address (§3.4 L1122-1150, issue 14 part 3):

- the parameters are written in square brackets, separated by commas: numbers, variables or arithmetic
  expressions (L1124);
- the called program reads them as P1, P2, P3 ... in the order of transfer; capital letters after the number
  are ignored (P1 = P1TEST), a type suffix gives the type (P2%) (L1126-1130);
- a variable passes its value at the time of the transfer (L1130: "P2 assumes the value of the variable X% at
  the time of parameter transfer"). The modal repetitions (§3.2 L1079-1081) run with the parameters of the
  selecting block: the transfer happens there (docs/decisions.md).
"""

from __future__ import annotations

CYCLE = ("10 #N% = #N% + 1 : #A = P1 : #B% = P2% : #C% = P3XYZ% : #SUM = #SUM + P1TEST\n"
         "N1 G1 Z[P1] F100\nN2 G0 Z10\n")


def test_the_manuals_parameter_list_numbers_variables_expressions_l1124(run, reference):
    """The manual's example list [2.75, X%, 0] (L1141), with an expression in place of the 0: P1 = 2.75, P2% is
    X% at the transfer, P3XYZ% is P3."""
    (reference().program_path[0] / "99999081").write_text(CYCLE)
    r = run("1 #N% = 0 : #SUM = 0 : X% = 7\nN1 G0 X0 Y0 Z10\nN2 G81 [2.75, X%, X% * 2 - 14]\nN3 G80\nM30\n")
    assert r["status"] == "ok", r["error"]
    v = r["variables"]
    assert (v["#N%"], v["#A"], v["#B%"], v["#C%"], v["#SUM"]) == (1, 2.75, 7, 0, 2.75)


def test_the_repetitions_keep_the_values_of_the_transfer_l1130(run, reference):
    """X% changes after G81: the repetitions at X10 and X20 still get the value it had at the transfer."""
    (reference().program_path[0] / "99999081").write_text(CYCLE)
    r = run("1 #N% = 0 : #SUM = 0 : X% = 7\nN1 G0 X0 Y0 Z10\nN2 G81 [-1, X%, 0]\n3 X% = 99\nN4 X10\nN5 X20\n"
            "N6 G80\nM30\n")
    assert r["status"] == "ok", r["error"]
    v = r["variables"]
    assert (v["#N%"], v["#B%"], v["#SUM"]) == (3, 7, -3.0)


def test_a_new_selection_transfers_new_parameters(run, reference):
    (reference().program_path[0] / "99999081").write_text(CYCLE)
    r = run("1 #N% = 0 : #SUM = 0\nN1 G0 X0 Y0 Z10\nN2 G81 [-1, 1, 0]\nN3 X10\nN4 G81 [-4, 2, 0]\nN5 X20\nN6 G80\n"
            "M30\n")
    assert r["status"] == "ok", r["error"]
    assert (r["variables"]["#N%"], r["variables"]["#SUM"]) == (4, -1 - 1 - 4 - 4)
