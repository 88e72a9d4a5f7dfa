"""Helpers for the rw_SymPas tests: run a program text on the default machine or a given one."""

from __future__ import annotations

import pytest

from ncvm.api import check, run
from ncvm.runtime.session import RunOptions


@pytest.fixture
def sap(tmp_path):
    """sap(text, machine_toml=None, **options) -> result dict of ``ncvm run --json``."""

    def _run(text: str, machine_toml: str | None = None, name: str = "prog.sap", **opts):
        path = tmp_path / name
        path.write_text(text, encoding="latin-1")
        machine = None
        if machine_toml is not None:
            machine = tmp_path / "machine.toml"
            machine.write_text(MACHINE_HEAD + machine_toml, encoding="utf-8")
        result, _ = run(path, machine=machine, options=RunOptions(state_dir=tmp_path / ".ncvm", **opts))
        return result

    return _run


@pytest.fixture
def sap_on(tmp_path):
    """sap_on(text, machine_text) -> result of a run on a machine file written in full."""

    def _run(text: str, machine_text: str, **opts):
        path = tmp_path / "audit.sap"
        path.write_text(text, encoding="latin-1")
        machine = tmp_path / "audit_machine.toml"
        machine.write_text(machine_text, encoding="utf-8")
        result, _ = run(path, machine=machine, options=RunOptions(state_dir=tmp_path / ".ncvm", **opts))
        return result

    return _run


@pytest.fixture
def sap_check(tmp_path):
    """sap_check(text) -> list of (code, line) of the errors ``ncvm check`` reports."""

    def _check(text: str, name: str = "prog.sap", files: dict | None = None):
        for fname, body in (files or {}).items():
            (tmp_path / fname).write_text(body, encoding="latin-1")
        path = tmp_path / name
        path.write_text(text, encoding="latin-1")
        return [(d.code, d.span.line if d.span else None) for d in check(path) if d.severity == "error"]

    return _check


MACHINE_HEAD = """
[[axis]]
name = "X"
min = -1000.0
max = 1000.0
[[axis]]
name = "Y"
min = -1000.0
max = 1000.0
[[axis]]
name = "Z"
min = -1000.0
max = 1000.0
"""


#: the project's acceptance program (the manual's examples combined), shared by the tests that run it
ACCEPTANCE_PROGRAM = """program Accept;
{$TASK 0}
const sec = 15625; n = 5;
var i, acc: integer; t: timer; d: double; ok: boolean;
function Fak(k: integer): integer;
begin if k <= 1 then Fak := 1 else Fak := k * Fak(k - 1); end;
procedure EVUI; begin CI1 := CI1 + 1; end;
begin
  acc := 0;
  for i := 1 to n do acc := acc + i;          { 15 }
  d := SQRT(SQR(3.0) + SQR(4.0));            { 5.0 }
  ok := (acc = 15) and (Fak(5) = 120) and (7 / 2 = 3) and (-7 mod 2 = -1);
  WRCBD(8, d); WRCBI(16, acc);
  t := CLOCK + sec;
  enev(EVUI);
  repeat until CLOCK > t;
  writeln('acc=', acc, ' d=', RDCBD(8), ' ok=', ok);
  CL(A1, A2); TRVL := 100.0; TRAC := 1000.0;  { PU/TU defaults: mm, s }
  MLAW(A1 := 10.0, A2 := 20.0);
  if (A1.dp = 10.0) and (A2.dp = 20.0) then writeln('moved');
end.
"""


@pytest.fixture
def acceptance_program() -> str:
    return ACCEPTANCE_PROGRAM
