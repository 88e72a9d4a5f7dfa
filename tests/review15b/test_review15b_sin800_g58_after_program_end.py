"""Independent review of issue 15, SINUMERIK G58/G59 blocks: what a G58 leaves to the next program.

Manual L3240: "Depending on the NC machine data bits, the programmed zero offsets, the DRF and PRESET
offsets are loaded as radius or diameter value. The PRESET offset is always effective after program end
(M2, M30) or "reset"." The manual singles out PRESET as the offset that survives program end; the
programmed zero offsets (G58/G59) are named beside it and not said to survive. ncvm keeps them in the
state directory (docs/sin800.md "The NC state"), so one program's `G58 X10` silently moves every later
program of the folder by 10 mm.

Resolution (docs/decisions.md, "Issue 15, last review"): the manual says when the PRESET offset takes
effect (after program end or reset, L3240) and is silent on clearing the programmable offsets; ZOPR loads
them into the NC's zero offset memory (L3207-3214), which the NC keeps, as it keeps G54-G57. So the offset
stays, as recorded; what was wrong is that it acted silently: a run that starts with offsets an earlier
run left now says so, naming the offset and the state directory.
"""

import json
import subprocess
import sys


def _run(tmp_path, name, text):
    program = tmp_path / name
    program.write_text(text)
    done = subprocess.run(
        [sys.executable, "-m", "ncvm", "run", "--json", str(program)],
        capture_output=True, text=True, cwd=tmp_path, timeout=120,
    )
    return json.loads(done.stdout)


def test_a_g58_offset_kept_for_the_next_program_is_never_silent(tmp_path):
    first = _run(tmp_path, "first.mpf", "%MPF1\nN1 G58 X10 F200 S500 M3\nN2 G90 G1 X20\nN3 M30\n")
    assert first["status"] == "ok"
    assert first["motion"]["bounds"]["X"][1] == 30.0
    assert not any(line.startswith("NC state:") for line in first["output"])
    second = _run(tmp_path, "second.mpf", "%MPF2\nN1 G90 G1 X20 F100\nN2 M30\n")
    assert second["status"] == "ok"
    assert second["motion"]["bounds"]["X"][1] == 30.0  # the NC keeps its programmable offset (L3207-3214)
    assert any(line.startswith("NC state: G58 X10 kept from an earlier run") for line in second["output"])
