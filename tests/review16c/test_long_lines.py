"""Issue 16, "Done means": "rs274 reads each translation without an error, reaches its program end".

rs274ngc reads lines of at most 255 characters ("Command too long"). An operator message of the program
(`(MSG, ...)`, 300 characters) is copied into one line: LinuxCNC stops at that line with an error, and
the rest of the program never runs. The translation must write only lines LinuxCNC can read (shorten or
split the comment), or refuse.
"""

from .helpers import needs_rs274, rs274_canon, translate

PROGRAM = "%\n(MSG, " + "check the clamping of the second part " * 8 + ")\nN10 G90 G71 G54\nN20 G0 X1 Y1 Z1\nN30 M30\n"


@needs_rs274
def test_long_message_is_readable_by_rs274(tmp_path):
    rc, text, err = translate(tmp_path, PROGRAM, "long.din")
    if rc != 0:
        return  # a refusal is safe
    rc, canon = rs274_canon(tmp_path, text)
    assert "Command too long" not in canon and rc == 0, canon[-600:]
    assert "STRAIGHT_TRAVERSE" in canon
