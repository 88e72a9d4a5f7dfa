"""Issue 16, rule 4: "comments `(file:line)` optional (`--source-comments`)" — optional comments must not
change what the program does.

rs274ngc takes one comment per line, the last: in `(MSG, clamp the second part now) (part.din:2)` the
operator message is an ordinary comment and LinuxCNC never shows it. Without `--source-comments` the same
translation shows it (MESSAGE in rs274's canon). A message that tells the operator to act before the next
move (here before an M0 stop) is lost only because the user asked for source references.
"""

from .helpers import needs_rs274, rs274_canon, translate

PROGRAM = """%
N10 G90 G17 G71 G54
N20 G0 X10 Y10 Z5
(MSG, clamp the second part now)
N30 M0
N40 G1 Z-1 F100
N50 M30
"""


@needs_rs274
def test_message_survives_source_comments(tmp_path):
    rc, plain, err = translate(tmp_path, PROGRAM, "part.din")
    assert rc == 0, err
    rc, with_refs, err = translate(tmp_path, PROGRAM, "part.din", "--source-comments", out_name="refs.ngc")
    assert rc == 0, err
    _, canon_plain = rs274_canon(tmp_path, plain)
    assert "MESSAGE(" in canon_plain and "clamp the second part now" in canon_plain, canon_plain
    _, canon_refs = rs274_canon(tmp_path, with_refs)
    messages = [line for line in canon_refs.splitlines() if "MESSAGE(" in line]
    assert any("clamp the second part now" in line for line in messages), (
        "with --source-comments LinuxCNC no longer shows the operator message:\n" + with_refs)
