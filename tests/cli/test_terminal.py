"""``ncvm`` at a terminal (issue 17 item 5): the progress display of long runs and batches, also when stdin
is a terminal; colours on a terminal only, off with NO_COLOR or --no-color; plain text in a pipe; the exit
codes in every command's --help. Real processes on a real pseudo-terminal (``pty``)."""

from __future__ import annotations

import os
import pty
import re
import select
import subprocess
import sys
import time
from pathlib import Path

import pytest
from click.testing import CliRunner

from ncvm import cli, termstyle

NCVM = [sys.executable, "-c", "from ncvm.cli import main; main()"]
ESC = "\x1b["
#: about two seconds of moves, then the end (CPL: the loop is counted in steps only at its end)
LONG_CPL = "10 FOR I% = 1 TO 400000\nN20 G1 X10 Y0 F6000\nN30 G1 X0 Y0\n40 NEXT I%\nM30\n"
BAD = "10 A% = 1\nN20 G1 X10 Y0 F6000\n30 B% = \nM30\n"


def terminal_env(**extra) -> dict:
    """A terminal's environment; the progress display shows from the start (a loaded machine must not end a
    run before the display's usual one-second delay and so hide it from the test)."""
    env = {k: v for k, v in os.environ.items() if k not in ("NO_COLOR", "FORCE_COLOR")}
    return {**env, "TERM": "xterm", "COLUMNS": "160", "NCVM_PROGRESS_DELAY": "0", **extra}


def at_terminal(args, cwd, env=None, answers=(), stdout=None) -> tuple[int, str]:
    """Run ``ncvm args`` with stdin, stdout and stderr on one pseudo-terminal; ``answers``: (prompt, line)
    pairs typed when the prompt shows. The exit code and everything the terminal showed."""
    leader, follower = pty.openpty()
    proc = subprocess.Popen([*NCVM, *args], cwd=cwd, stdin=follower, stdout=stdout or follower, stderr=follower,
                            env=env or terminal_env(), close_fds=True)
    os.close(follower)
    seen, pending, deadline = b"", list(answers), time.monotonic() + 120
    while time.monotonic() < deadline:
        ready = select.select([leader], [], [], 0.1)[0]
        if ready:
            try:
                chunk = os.read(leader, 65536)
            except OSError:  # the process has ended and closed the terminal
                break
            if not chunk:
                break
            seen += chunk
            if pending and pending[0][0].encode() in seen.rsplit(b"\n", 3)[-1] + chunk:
                time.sleep(1.0)  # the operator takes a moment: long enough for the display to redraw
                os.write(leader, (pending.pop(0)[1] + "\n").encode())
        elif proc.poll() is not None:
            break
    os.close(leader)
    return proc.wait(timeout=60), seen.decode("utf-8", "replace")


@pytest.fixture
def work(tmp_path) -> Path:
    (tmp_path / "long.cpl").write_text(LONG_CPL)
    (tmp_path / "bad.cpl").write_text(BAD)
    return tmp_path


def test_a_long_run_shows_its_progress_when_stdin_is_a_terminal_too(work):
    code, seen = at_terminal(["run", "long.cpl"], work)
    assert code == 0
    progress = [part for part in re.split(r"[\r\n]", seen) if "running" in part]
    assert progress, seen
    # CPL's moves and simulated time count while it runs, not only at the end
    live = [re.search(r"([\d,]+) moves, (\d+:\d\d:\d\d) simulated", part) for part in progress]
    assert any(m and m.group(1) != "0" and m.group(2) != "0:00:00" for m in live), progress
    assert "ended normally" in seen and f"{ESC}" in seen.split("ncvm: ")[-1]  # the summary in colour


def test_colours_at_a_terminal_and_none_with_no_color_or_no_color_flag(work):
    code, seen = at_terminal(["check", "bad.cpl"], work)
    assert code == 1 and f"{ESC}31" in seen and "error" in seen  # the error in red
    for env, args in ((terminal_env(NO_COLOR="1"), ["check", "bad.cpl"]),
                      (terminal_env(), ["--no-color", "check", "bad.cpl"])):
        code, seen = at_terminal(args, work, env=env)
        assert code == 1 and "bad.cpl:3:" in seen and ESC not in seen


def test_piped_output_has_no_escape_codes(work):
    for args in (["run", "long.cpl"], ["run", "bad.cpl"], ["check", "bad.cpl"], ["run", "long.cpl", "bad.cpl"]):
        out = subprocess.run([*NCVM, *args], cwd=work, capture_output=True, text=True, timeout=120, env=terminal_env())
        assert "ncvm: " in out.stderr
        assert ESC not in out.stdout + out.stderr and "\r" not in out.stderr


def test_color_flag_colours_a_pipe(work):
    out = subprocess.run([*NCVM, "--color", "check", "bad.cpl"], cwd=work, capture_output=True, text=True,
                         timeout=120, env=terminal_env(NO_COLOR="1"))
    assert out.returncode == 1 and f"{ESC}31" in out.stderr


def test_a_batch_shows_the_programs_done(work):
    (work / "b").mkdir()
    for i in range(3):
        (work / "b" / f"p{i}.cpl").write_text(LONG_CPL)
    code, seen = at_terminal(["run", "-j", "1", "b"], work)
    assert code == 0
    plain = re.sub(r"\x1b\[[0-9;?]*[A-Za-z]", "", seen)
    assert re.search(r"batch \S+ 1/3 programs 800,000 moves, 45:11:07 simulated", plain), plain
    assert "3 program(s) run" in seen


DIALOG = LONG_CPL.replace("M30\n", '50 SFK(K%,"GO",,,,,,,"END")\n60 PRN(1,1,"KEY ",K%)\nM30\n')


def test_the_progress_steps_aside_while_the_operator_is_asked(work):
    (work / "dialog.cpl").write_text(DIALOG)
    code, seen = at_terminal(["run", "dialog.cpl"], work, answers=[("keys> ", "SK8")])
    assert code == 0, seen
    before, _, after = seen.partition("keys> ")
    assert "running" in before  # the display ran before the wait
    assert "running" not in before.rsplit("\n", 1)[-1]  # and left the prompt's line to the prompt
    assert "SK8" in after and "running" not in after.partition("SK8")[0]  # nothing drawn while the operator types
    assert "ended normally" in seen


@pytest.mark.parametrize("command", [["run"], ["check"], ["compile"], ["translate"], ["machine-schema"],
                                     ["state", "show"], ["state", "reset"], ["state", "export"],
                                     ["state", "import"]])
def test_every_command_lists_its_exit_codes(command):
    out = CliRunner().invoke(cli.cli, [*command, "--help"])
    text = " ".join(out.output.split())
    assert out.exit_code == 0 and "Exit codes: 0 " in text and "2 usage error" in text
    assert "70 internal error" in text


def test_styled_colours_the_parts_of_a_diagnostic_and_a_summary():
    text = termstyle.styled("p.cpl:3:8: error CPL021: bad\n    30 B% =\n           ^\n")
    assert f"{ESC}1mp.cpl:3:8: {ESC}0m" in text and f"{ESC}31m{ESC}1merror CPL021{ESC}0m:" in text
    assert f"{ESC}32m{ESC}1m^{ESC}0m" in text
    assert f"{ESC}31m" in termstyle.styled("ncvm: stopped with error RUN001: 3 steps")
    assert termstyle.styled("ncvm: 2 program(s) checked, 0 diagnostic(s)") == "ncvm: 2 program(s) checked, 0 diagnostic(s)"


MESSAGES = "".join(f"G1 X{i % 100} Y{i % 7} F3000\n" + ("(MSG, hello)\n" if i % 50_000 == 49_999 else "")
                   for i in range(250_000)) + "M2\n"


def test_operator_output_keeps_its_own_lines_and_its_own_stream(work):
    (work / "msg.din").write_text(MESSAGES)
    code, seen = at_terminal(["run", "msg.din"], work)
    assert code == 0 and "running" in seen
    lines = [line for line in re.split(r"[\r\n]", seen) if "hello" in line]
    assert len(lines) == 5 and all("moves" not in line for line in lines)
    # stdout into a file, stderr on the terminal: the file gets the output, plain, the terminal the display
    with (work / "out.txt").open("w") as out:
        code, seen = at_terminal(["run", "msg.din"], work, stdout=out)
    assert code == 0 and "running" in seen and "hello" not in seen
    assert (work / "out.txt").read_text().splitlines().count("hello") == 5
