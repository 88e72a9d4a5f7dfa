"""rw_SymPas: a move the card's software limit cut short (issue 16: "Say what was frozen"; docs/translate.md
rule 2: "The run's soft-limit warnings are said as `run` says them"; "Trust first").

`MCRW(A1 := 100.0, A2 := 0.0, PHI := 180.0)` on a gantry whose A2 stops at -10: the card stops A1 and A2 at
the limit (`run` says "software limit sll = -10 of A2 reached at 0.25 s: TOM stops A1, A2") and the program
goes on. `translate` writes the 6-degree arc to the stop point as if the program had programmed it, and says
nothing: neither on its console nor in the file. On the new machine, with other travel limits, the program cuts
an arc no one programmed; the user must at least be told, as `run` tells.
"""

from __future__ import annotations

from tests.review16c.helpers import ncvm

MACHINE = """
[machine]
name = "gantry"
[[axis]]
name = "X"
min = -10.0
max = 400.0
[[axis]]
name = "Y"
min = -10.0
max = 300.0
[[axis]]
name = "Z"
min = -120.0
max = 10.0
"""

PROGRAM = """program P;
begin
  TRVL := 50.0; TRAC := 500.0;
  MCRW(A1 := 100.0, A2 := 0.0, PHI := 180.0);
  MLAW(A3 := -1.0);
end.
"""


def test_translate_says_the_limit_stop(tmp_path):
    (tmp_path / "machine.toml").write_text(MACHINE)
    (tmp_path / "lim.sap").write_text(PROGRAM)
    run = ncvm(tmp_path, "run", "lim.sap", "-m", "machine.toml")
    assert run.returncode == 0 and "software limit" in run.stdout + run.stderr, run.stderr
    tr = ncvm(tmp_path, "translate", "lim.sap", "-m", "machine.toml", "-o", "out.ngc")
    if tr.returncode == 1:  # refused: safe, with the reason
        assert "limit" in tr.stderr, tr.stderr
        return
    out = (tmp_path / "out.ngc").read_text()
    assert "limit" in tr.stdout + tr.stderr or "limit" in out, (
        f"the limit stop that cut the circle short is said nowhere:\n{tr.stderr}\n{out}")
