"""The rw_SymPas part of the result is in the program's terms (issue 15, rw_SymPas 7): positions and
bounds under the program's axis names in both frames, CI/CD, and the task of each output line."""

from __future__ import annotations


def test_axes_under_program_names_in_both_frames_L2146(sap):
    r = sap("""{$TASK 0}
program P;
begin
  STARTCNCT(1);
  TRVL := 100.0; TRAC := 1000.0;
  MLAW(A1 := 50.0);
  SZPA(A1 := 20.0);
  MLAW(A1 := 10.0);
  CI7 := 3; CD2 := 1.5;
  writeln('main');
end.

{$TASK 1}
program Q;
begin
  writeln('other');
end.
""")
    assert r["error"] is None
    a1 = r["sympas"]["axes"]["A1"]
    assert a1["machine_axis"] == "X"
    assert a1["position"] == 10.0 and a1["machine_position"] == 30.0
    assert a1["bounds_machine"] == [0.0, 50.0] and a1["bounds_program"] == [-20.0, 30.0]
    assert r["sympas"]["ci"] == {"7": 3} and r["sympas"]["cd"] == {"2": 1.5}
    assert r["sympas"]["output"] == [{"task": 1, "text": "other"}, {"task": 0, "text": "main"}]
