"""Ctrl-C at a terminal: "interrupted" on a line of its own (the progress line cleared first), and with
NO_COLOR no ANSI styling at all, bold included (https://no-color.org). A real pseudo-terminal, a real SIGINT."""

from __future__ import annotations

import os
import pty
import re
import select
import signal
import subprocess
import time

from tests.cli.test_terminal import NCVM, terminal_env

SGR = re.compile(r"\x1b\[[0-9;]*m")  # select graphic rendition: colour, bold, ...


def test_ctrl_c_at_a_terminal_with_no_color(tmp_path):
    (tmp_path / "long.cpl").write_text("10 FOR I% = 1 TO 3000000\nN20 G1 X10 Y0 F6000\nN30 G1 X0 Y0\n"
                                       "40 NEXT I%\nM30\n")
    leader, follower = pty.openpty()
    proc = subprocess.Popen([*NCVM, "run", "long.cpl"], cwd=tmp_path, stdin=follower, stdout=follower,
                            stderr=follower, env=terminal_env(NO_COLOR="1"), close_fds=True)
    os.close(follower)
    seen, sent, deadline = b"", False, time.monotonic() + 120
    while time.monotonic() < deadline:
        if select.select([leader], [], [], 0.1)[0]:
            try:
                chunk = os.read(leader, 65536)
            except OSError:
                break
            if not chunk:
                break
            seen += chunk
            if not sent and re.search(rb"[1-9][0-9,]* moves", seen):  # the run is moving, its line drawn
                proc.send_signal(signal.SIGINT)
                sent = True
        elif proc.poll() is not None:
            break
    os.close(leader)
    code = proc.wait(timeout=60)
    text = seen.decode("utf-8", "replace")
    assert sent and code == 1, text
    assert not SGR.findall(text), SGR.findall(text)[:5]
    line = next(part for part in re.split(r"[\r\n]", text) if "interrupted" in part)
    assert re.sub(r"\x1b\[[0-9;?]*[A-Za-z]", "", line).strip() == "interrupted", repr(line)
