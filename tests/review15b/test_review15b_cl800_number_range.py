"""Independent review of issue 15, SINUMERIK / CL 800 item 7 (number ranges, manual L7079).

L7079: "Real number correspond, in CL 800, to normal decimal numbers in floating point, representation.
The value range is from +/- 0.00000001 to +/- 99999999."
"""

import json
import subprocess
import sys
import textwrap

HEADER = textwrap.dedent(
    """\
    PROGRAM 207;
    CHANNEL NC 4;
    ID (0-RANGE TEST-25.02.86-HFH-PJP: PC16/11);
    PAR REAL: R20:=a,R21:=b;
    BEGIN
    """
)


def _run(tmp_path, statements):
    program = tmp_path / "range.cl8"
    program.write_text(HEADER + statements + "\nEND.\n")
    done = subprocess.run(
        [sys.executable, "-m", "ncvm", "run", "--json", str(program)],
        capture_output=True, text=True, cwd=tmp_path, timeout=120,
    )
    return json.loads(done.stdout)


def test_the_range_message_names_the_value_that_left_the_range(tmp_path):
    """a = 99999999; b = a + 0.4 leaves the range by 0.4 (L7079), and the run stops rightly, but the
    message says "1e+08 is outside the R parameter range +/-99999999": the user reads 100000000, a
    value the program never computed, and cannot tell by how much or why. The message must show the
    value (99999999.4)."""
    doc = _run(tmp_path, "a = 99999999; b = a + 0.4;")
    assert doc["status"] == "error"
    assert doc["error"]["line"] == 6
    assert "99999999.4" in doc["error"]["message"]


def test_a_value_below_the_smallest_magnitude_is_not_kept_silently(tmp_path):
    """L7079: the smallest magnitude an R parameter holds is 0.00000001. a = 0.00000001; b = a / 3
    stores b = 3.333e-09 and the run ends normally: a value the NC cannot hold, kept without a word
    (a later b * 100000000 gives 0.33 where the NC's b cannot be 3.333e-09). ncvm must either refuse
    (as it does beyond +/-99999999) or store what the NC holds (0, or 0.00000001 rounded), never
    3.333e-09."""
    doc = _run(tmp_path, "a = 0.00000001; b = a / 3;")
    if doc["status"] == "ok":
        b = doc["variables"]["R21"]
        assert b == 0 or abs(b) >= 0.00000001
