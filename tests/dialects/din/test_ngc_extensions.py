"""LinuxCNC's extensions of G-code in a `din` program give one NC013 per program (issue 14 part 4), not an
NC001 per line; a plain .ngc file runs."""

from __future__ import annotations

import json

from click.testing import CliRunner

from ncvm import cli

LINUXCNC = """(a LinuxCNC program)
#1 = 5
#<depth> = -2
G21 G90 F100
o100 sub
  G1 X[#1 * 2] Y#1
o100 endsub
o100 call
G0 X0 Y0 ; plain
M2
"""


def ncvm(tmp_path, command: str, text: str) -> tuple[int, dict]:
    (tmp_path / "p.ngc").write_text(text)
    args = [command, str(tmp_path / "p.ngc"), "--json"] + (["--state", str(tmp_path / "st")] if command == "run" else [])
    r = CliRunner().invoke(cli.cli, args, catch_exceptions=False)
    return r.exit_code, json.loads(r.stdout)


def test_a_linuxcnc_program_gets_one_diagnostic_that_says_so(tmp_path):
    code, doc = ncvm(tmp_path, "check", LINUXCNC)
    diags = doc["files"][0]["diagnostics"]
    assert code == 1 and [(d["code"], d["line"]) for d in diags] == [("NC013", 2)]
    message = diags[0]["message"]
    assert "not DIN 66025" in message and "6 lines" in message
    for what in ("# parameters", "named parameters", "O-words", "expressions in brackets"):
        assert what in message
    code, doc = ncvm(tmp_path, "run", LINUXCNC)
    assert code == 1 and doc["error"]["code"] == "NC013" and doc["error"]["line"] == 2


def test_thousands_of_parameter_lines_are_one_diagnostic(tmp_path):
    text = "G21 G90 F100\n" + "".join(f"#{i} = [{i} * 2]\nG1 X#{i}\n" for i in range(1, 2001)) + "M2\n"
    _code, doc = ncvm(tmp_path, "check", text)
    diags = doc["files"][0]["diagnostics"]
    assert [d["code"] for d in diags] == ["NC013"] and "4000 lines" in diags[0]["message"]


def test_other_syntax_errors_stay_as_they_are(tmp_path):
    _code, doc = ncvm(tmp_path, "check", "G21 F100\nG1 X1 @\n#1 = 2\nM2\n")
    assert [(d["code"], d["line"]) for d in doc["files"][0]["diagnostics"]] == [("NC001", 2), ("NC013", 3)]


def test_a_plain_ngc_runs(tmp_path):
    code, doc = ncvm(tmp_path, "run", "%\n(plain)\nG21 G90 G17 F100\nG0 X0 Y0 Z5\nG1 Z-1\nG2 X10 Y0 R5\nM2\n%\n")
    assert code == 0 and doc["status"] == "ok" and doc["position"] == {"X": 10.0, "Y": 0.0, "Z": -1.0}
