"""The rw_SymPas part of the result is in the program's terms (issue 15, rw_SymPas 7): positions and
bounds under the program's axis names in both frames, CI/CD, and the task of each output line."""

from __future__ import annotations

SHIFTED = """{$TASK 0}
program P;
begin
  STARTCNCT(1);
  TRVL := 100.0; TRAC := 1000.0;
  MLAW(A1 := 50.0);
  SZPA(A1 := 20.0);
  MLAW(A1 := 10.0, A2 := 5.0);
  writeln('main');
end.

{$TASK 1}
program Q;
begin
  while TRUE do WT(100);
end.
"""


def test_axes_under_program_names_in_both_frames_L2146(sap):
    r = sap(SHIFTED.replace("MLAW(A1 := 10.0, A2 := 5.0);", "MLAW(A1 := 10.0);\n  CI7 := 3; CD2 := 1.5;")
            .replace("while TRUE do WT(100);", "writeln('other');"))
    assert r["error"] is None
    a1 = r["sympas"]["axes"]["A1"]
    assert a1["machine_axis"] == "X"
    assert a1["position"] == 10.0 and a1["machine_position"] == 30.0
    # the program's bounds: each move less the zero offset it ran with (A1 50 before SZPA, 10 after; review18e)
    assert a1["bounds_machine"] == [0.0, 50.0] and a1["bounds_program"] == [10.0, 50.0]
    assert r["sympas"]["ci"] == {"7": 3} and r["sympas"]["cd"] == {"2": 1.5}
    assert r["sympas"]["output"] == [{"task": 1, "text": "other"}, {"task": 0, "text": "main"}]


def test_position_bounds_and_frames_under_the_program_axis_names_L2146(sap):
    """Issue 15 (rw_SymPas 7): the top-level figures name A1, A2 ... as the program does and say their
    frame: the position is where the program reads it (dp after SZPA), the toolpath bounds are the
    machine's, and the bounds in the program's frame stand beside them."""
    r = sap(SHIFTED)
    assert r["error"] is None
    assert r["position"] == {"A1": 10.0, "A2": 5.0, "A3": 0.0}
    assert r["motion"]["bounds"] == {"A1": [0.0, 50.0], "A2": [0.0, 5.0], "A3": [0.0, 0.0]}
    assert r["bounds_program"] == {"A1": [10.0, 50.0], "A2": [0.0, 5.0], "A3": [0.0, 0.0]}
    assert r["motion"]["bounds_program"] == r["bounds_program"]
    assert r["frames"] == {"position": "program", "bounds_program": "program", "motion.bounds": "machine",
                           "motion.bounds_program": "program", "limit_violations": "machine"}


def test_every_output_line_has_its_task(sap):
    """WRITELN lines, the line of a task still looping at the end, a refused profile (L1415) and a
    soft-limit stop (L1490): each with the task whose statement it is about."""
    r = sap(SHIFTED.replace("  writeln('main');", "  TRVL := 0.0;\n  MLA(A2 := 9.0);\n  TRVL := 100.0;\n"
                                                   "  MLAW(A3 := 2000.0);\n  writeln('main');"))
    assert r["error"] is None
    out = r["sympas"]["output"]
    assert [o["text"] for o in out] == r["output"]
    tasks = [o["task"] for o in out]
    assert "profile refused" in out[0]["text"] and "software limit" in out[1]["text"]
    assert tasks == [0, 0, 0, 1] and out[3]["text"].startswith("task 1 still running")


def test_limit_violation_under_the_program_axis_name_in_machine_coordinates_L1490(sap):
    r = sap(SHIFTED.replace("MLAW(A1 := 10.0, A2 := 5.0);", "MLAW(A1 := 1100.0);"),
            machine_toml='[sympas]\nsoft_limit_reaction = "SMD"\n')
    assert r["limit_violations"] and r["limit_violations"][0].startswith("axis A1 reaches ")
    assert " in machine coordinates, above its soft limit 1000.0000" in r["limit_violations"][0]


def test_summary_line_names_the_program_axes_and_the_frames(tmp_path):
    from click.testing import CliRunner

    from ncvm import cli

    prog = tmp_path / "p.sap"
    prog.write_text(SHIFTED)
    r = CliRunner().invoke(cli.cli, ["run", str(prog), "--state", str(tmp_path / "st")], catch_exceptions=False)
    assert r.exit_code == 0
    summary = r.stderr.strip().splitlines()[-1]
    assert summary.endswith(", program A1[10,50] A2[0,5] A3[0,0]"), summary  # the machine frame's in --json


def test_axes_the_machine_names_as_the_program_does_keep_the_plain_report(sap):
    """With `axis_names` equal to the machine's axes nothing is renamed and no frames are mixed up."""
    r = sap("program P;\nbegin\n  TRVL := 100.0;\n  MLAW(X := 10.0);\nend.\n",
            machine_toml='[sympas]\naxis_names = ["X", "Y", "Z"]\n')
    assert r["error"] is None and r["position"]["X"] == 10.0 and r["motion"]["bounds"]["X"] == [0.0, 10.0]
