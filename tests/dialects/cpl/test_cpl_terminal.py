"""The operator at a terminal (docs/cpl-io.md, "Keys from the terminal"): ``ncvm run`` with stdin on a
real pseudo-terminal, key lines written to its master side, no --keys script."""

from __future__ import annotations

import os
import pty
import subprocess
import sys
from pathlib import Path

import pytest

import ncvm

SRC = str(Path(ncvm.__file__).resolve().parents[1])

DIALOG = ('10 CLS : DSP(2,4,"BOLT CIRCLE")\n20 DLG\n30 PRN(8,4,"MAX.CUTTING WIDTH: ###.### MM",WI)\n'
          '40 INP(WI)\n50 ENDDLG\n60 SFK(KEY%,"OK",,"ABORT&NOW")\n70 DSP(3,1,"KEY=",KEY%," WI=",WI)\nM30\n')


def run_on_terminal(tmp_path: Path, program: str, typed: bytes, *args: str, stdin: str = "tty"):
    """(exit code, stdout, stderr) of ``ncvm run`` with stdin on a pseudo-terminal (or /dev/null)
    after ``typed`` was written to the terminal."""
    prog = tmp_path / "prog.cpl"
    prog.write_text(program, encoding="latin-1")
    cmd = [sys.executable, "-c", "from ncvm.cli import main; main()", "run", str(prog),
           "--state", str(tmp_path / "st"), *args]
    env = {**os.environ, "PYTHONPATH": SRC}
    if stdin != "tty":
        r = subprocess.run(cmd, stdin=subprocess.DEVNULL, capture_output=True, env=env, timeout=60)
        return r.returncode, r.stdout.decode(), r.stderr.decode()
    master, slave = pty.openpty()
    try:
        p = subprocess.Popen(cmd, stdin=slave, stdout=subprocess.PIPE, stderr=subprocess.PIPE, env=env)
        os.close(slave)
        os.write(master, typed)
        out, err = p.communicate(timeout=60)
    finally:
        os.close(master)
    return p.returncode, out.decode(), err.decode()


def test_sfk_and_inp_ask_the_operator_and_refuse_bad_lines(tmp_path):
    code, out, err = run_on_terminal(tmp_path, DIALOG, b"HELLO\nTYPE 1234.5\nTYPE 12.5\nSK3\n")
    assert code == 0, err
    assert out.splitlines()[-1] == "KEY=        3 WI=  12.500"
    # the screen shown at the INP: the lines that are not blank and the field being edited
    assert " 2|   BOLT CIRCLE\n 8|   MAX.CUTTING WIDTH: ###.### MM\n" \
           "input WI (line 8, column 4): MAX.CUTTING WIDTH: ###.### MM\n" in err
    assert "refused: 'HELLO' is not a key" in err
    assert "refused: INP(WI): '1234.5' does not fit the input format" in err
    # at the SFK: the value typed is in the field and the softkey labels (3 lines of 9) are listed
    assert " 8|   MAX.CUTTING WIDTH:  12.500 MM\nsoftkeys: [SK1 OK] [SK3 ABORT NOW]\n" in err
    assert err.count("-------- CPL dialog screen") == 2  # a refusal asks again without the screen
    assert "KEY=" not in err  # program output stays on stdout


def test_end_of_input_at_a_wait_is_the_exhausted_script_fault(tmp_path):
    code, out, err = run_on_terminal(tmp_path, DIALOG, b"TYPE 1.5\n\x04")
    assert code == 1
    assert "error CPL705: waiting for a key, but the key script is exhausted: SFK: end of input" in err
    assert "MAX.CUTTING WIDTH:   1.500 MM" in out


def test_inkey_does_not_wait_for_the_terminal(tmp_path):
    # nothing typed and the terminal stays open: 200 polls find no key and the program ends
    program = '10 S%=0\n20 FOR I%=1 TO 200\n30 S%=S%+INKEY\n40 NEXT\n50 DSP(1,1,"SUM=",S%)\nM30\n'
    code, out, err = run_on_terminal(tmp_path, program, b"")
    assert code == 0, err
    assert out.splitlines()[-1] == "SUM=        0"
    assert "CPL dialog screen" not in err


def test_inkey_takes_a_typed_line_as_key_events(tmp_path):
    # L4625-4650 with the operator typing: every new key number is shown until Enter (13)
    program = ('10 NEW%=0\n20 WHILE NEW%<>13 DO\n30 NEW%=INKEY\n'
               '40 IF NEW%>0 THEN DSP(12,10,"KEY NUMBER:###",NEW%) ENDIF\n50 END\nM30\n')
    code, out, err = run_on_terminal(tmp_path, program, b"TYPE AB\nBOGUS\nSK2\nENTER\n")
    assert code == 0, err
    assert [line for line in out.splitlines() if line.startswith("KEY")] == \
        ["KEY NUMBER: 65", "KEY NUMBER: 66", "KEY NUMBER:142", "KEY NUMBER: 13"]
    assert "refused: 'BOGUS' is not a key" in err


@pytest.mark.parametrize("args,stdin", [(("--json",), "tty"), ((), "devnull")])
def test_without_a_terminal_or_with_json_nobody_is_asked(tmp_path, args, stdin):
    code, out, err = run_on_terminal(tmp_path, DIALOG, b"TYPE 1.5\nSK1\n", *args, stdin=stdin)
    assert code == 1
    assert "CPL dialog screen" not in err
    text = out + err
    assert "CPL705" in text and "key script is exhausted: INP(WI)" in text and "end of input" not in text


def test_a_key_script_wins_over_the_terminal(tmp_path):
    keys = tmp_path / "k.keys"
    keys.write_text("TYPE 7\nSK1\n")
    code, out, err = run_on_terminal(tmp_path, DIALOG, b"TYPE 1.5\nSK3\n", "--keys", str(keys))
    assert code == 0, err
    assert out.splitlines()[-1] == "KEY=        1 WI=   7.000"
    assert "CPL dialog screen" not in err
