"""Issue 16 item 4 "Program order kept": the translated program does what the program ordered, in its
order. CPL `WAIT(,<duration>)` (manual §4.1, L1186-1239: "block processing will stop exactly for the
specified period of time") holds the next block back: the classic use is letting the spindle come up to
speed before the plunge. ncvm's run keeps the machine standing there (its cycle time grows by the wait),
but the translation drops the pause: the new control plunges at once."""

from __future__ import annotations

import re

from tests.review16e.helpers import code_lines, mill, ncvm, translate, write

PROGRAM = """N10 G90 G17 G54 G0 X0 Y0 Z5
N20 S1000 M3
30 WAIT(,2000)
N40 G1 Z-1 F100
N50 G0 Z5 M5
N60 M30
"""


def _cycle_seconds(stderr: str) -> float:
    minutes, seconds = re.search(r"cycle (\d+):([\d.]+)", stderr).groups()
    return 60 * int(minutes) + float(seconds)


def test_timed_wait_is_a_dwell_before_the_plunge(tmp_path):
    write(tmp_path, {"machine.toml": mill(), "spin.cpl": PROGRAM,
                     "nowait.cpl": PROGRAM.replace("30 WAIT(,2000)\n", "")})
    waited = _cycle_seconds(ncvm(tmp_path, "run", "spin.cpl", "-m", "machine.toml").stderr)
    straight = _cycle_seconds(ncvm(tmp_path, "run", "nowait.cpl", "-m", "machine.toml").stderr)
    assert waited - straight > 1.5  # the run keeps the machine standing for the wait
    rc, out, err = translate(tmp_path, "spin.cpl", "-m", "machine.toml")
    assert rc == 0, err
    code = code_lines(out)
    plunge = code.index("G1 Z-1 F100")
    spindle = next(i for i, line in enumerate(code) if "M3" in line)
    dwells = [line for line in code[spindle:plunge] if re.match(r"G4 P", line)]
    assert dwells, out
    assert float(dwells[0].split("P")[1]) > 1.5, out
