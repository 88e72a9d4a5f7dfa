"""A program that does not compile is reported in the program's terms as well (issue 15 rw_SymPas 7,
docs/sympas.md: the top-level `position` names the axes as the program does): the error may stand in
the program run or in a task file the machine file loads (`sympas.load`), and the axes may carry the
machine file's own `axis_names`."""

from __future__ import annotations


def test_an_error_in_a_loaded_task_file_reports_the_programs_axis_names(sap, tmp_path):
    (tmp_path / "mon.sap").write_text("{$TASK 1}\nprogram Mon;\nbegin\n  MLAW(A1 := 5.0)\nend\n")
    r = sap("{$TASK 0}\nprogram Main;\nbegin\n  MLAW(A1 := 5.0);\nend.\n",
            machine_toml='[sympas]\nload = ["mon.sap"]\n')
    assert r["error"]["code"].startswith("SP") and r["error"]["file"].endswith("mon.sap"), r["error"]
    assert set(r["position"]) == {"A1", "A2", "A3"}


def test_a_compile_error_uses_the_machine_files_axis_names(sap):
    r = sap("program Main;\nbegin\n  writeln(Spindle.ap);\nend.\n",
            machine_toml='[sympas]\naxis_names = ["Slide", "Cross", "Spindle"]\n')
    assert r["error"] is not None and r["error"]["code"].startswith("SP"), r["error"]
    assert set(r["position"]) == {"Slide", "Cross", "Spindle"}
