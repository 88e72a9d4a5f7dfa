"""Issue 16: translation is for a user "whose machine will crash if the output is wrong"; the project's
quality bar: "Trust first: a silently wrong answer is the worst defect".

`ncvm run` of this program warns "axis X reaches 9000.0000, above its soft limit 500.0000"; `ncvm translate`
of the same run writes `G1 X9000` and says only "wrote ... 2 moves", dropping the run's warning. The user
setting up the new control never learns that the simulated path left the machine's travel.
"""

import subprocess
import sys

from .helpers import translate

BEYOND_TRAVEL = """%
N10 G90 G17 G71 G54
N20 G0 X10 Y10 Z5
N30 G1 X9000 F100
N40 M30
"""


def test_the_runs_soft_limit_warning_reaches_the_translate_user(tmp_path):
    prog = tmp_path / "travel.din"
    prog.write_text(BEYOND_TRAVEL)
    run = subprocess.run([sys.executable, "-m", "ncvm", "run", str(prog)], capture_output=True, text=True,
                         timeout=120, cwd=tmp_path)
    assert "soft limit" in run.stderr + run.stdout  # the run itself warns
    rc, text, err = translate(tmp_path, BEYOND_TRAVEL, "travel.din")
    assert "soft limit" in err or "soft limit" in text or rc != 0, (
        f"translate hid the run's soft-limit warning (exit {rc}): {err!r}")
