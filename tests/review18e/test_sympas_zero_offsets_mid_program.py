"""Fifth review of issue 18: an rw_SymPas program that changes its zero offsets part way (SZPA/SZPR).

The rw_SymPas manual (§10.6, L2144-2158): the user coordinate is ``u = m - zerooffset``; SZPA sets the zero
offset, SZPR shifts it. ``ncvm run`` writes each move's user coordinates into the trace (``work``) right, but
the summary's program bounds (``bounds_program``, the "program A1[..]" of the last line) and the work-frame plot
take the machine positions less the zero offset in force at the END of the run: every move made before the
offset changed is shifted by it. The program below only moves to user positions between 1 and 10; ncvm reports
"program A1[-60,1] A2[-20,5]" and draws its first move ending at (-50, -10). A maintenance engineer checking the
work area against the summary is told of places the program never goes to.
"""

from __future__ import annotations

import json
import subprocess
import sys

PROGRAM = """\
program Zo;
begin
  TRVL := 100.0; TRAC := 10000.0;
  MLAW(A1 := 10.0, A2 := 10.0);
  SZPA(A1 := 50.0, A2 := 20.0);
  MLAW(A1 := 5.0, A2 := 5.0);
  SZPR(A1 := 10.0);
  MLAW(A1 := 1.0, A2 := 1.0);
end.
"""


def test_program_bounds_are_where_the_moves_go_in_the_program_coordinates(tmp_path):
    program, trace = tmp_path / "zo.sap", tmp_path / "zo.jsonl"
    program.write_text(PROGRAM)
    done = subprocess.run([sys.executable, "-m", "ncvm", "run", "-d", "sympas", "--state", str(tmp_path / "st"),
                           "--json", "--trace", str(trace), str(program)], capture_output=True, text=True,
                          timeout=120)
    assert done.returncode == 0, done.stderr
    moves = [r for r in map(json.loads, trace.read_text().splitlines()) if "work" in r]
    assert [(m["work"]["X"], m["work"]["Y"]) for m in moves] == [(10.0, 10.0), (5.0, 5.0), (1.0, 1.0)]
    bounds = json.loads(done.stdout)["motion"]["bounds_program"]
    assert (bounds["A1"], bounds["A2"]) == ([1.0, 10.0], [1.0, 10.0])
