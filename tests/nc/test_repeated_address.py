"""Issue 14: an address written twice in one block (``G1 X10 X20``) is refused in every profile, by ``ncvm run``
and ``ncvm check`` alike, at the second word -- the control keeps one value per address, so the block would
otherwise silently run with the last one. LinuxCNC's rs274 refuses the same blocks ("Multiple X words on one
line"). The manuals (CPL, CL 800) give no block format that allows it; docs/decisions.md, "Issue 14: an
address twice in one block". Words a block may hold several times stay allowed: G words, M words, and the
SINUMERIK H words (each goes to the PLC)."""

from __future__ import annotations

import subprocess
import sys

import pytest
from rs274peer import needs_rs274, rs274

CL800 = "PROGRAM 7;\nCHANNEL NC 4;\nBEGIN\n{block}\n(:M30:);\nEND.\n"

#: dialect, file name, program text, line:column of the second word, the error code
REPEATED = [
    ("din", "p.din", "G1 X10 X20 F100\nM30\n", "1:8", "NC001"),
    ("din", "p.din", "G0 Y1\nG1 X1 F100 F200\nM30\n", "2:12", "NC001"),
    ("cpl", "p.cpl", "N10 A=5\nN20 G1 X[A] X20 F100\nN30 M30\n", "2:13", "CPL001"),
    ("sin800", "p.mpf", "%MPF1\nN10 G1 X10 X20 F100\nN20 M30\n", "2:12", "SIN001"),
    ("sin800", "p.mpf", "%MPF1\nN10 G1 X10 F100 F200\nN20 M30\n", "2:17", "SIN001"),
    ("sin800", "p.mpf", "%MPF1\nN10 R1=5\nN20 G1 X=R1 Y2 X7 F100\nN30 M30\n", "3:16", "SIN001"),
    ("sin800", "p.mpf", "%MPF1\nN10 G0 Q1=2 Q1=3\nN20 M30\n", "2:13", "SIN001"),
    ("cl800", "p.cl8", CL800.format(block="(:G1 X10 X20 F100:);"), "4:10", "SIN001"),
]


def _ncvm(tmp_path, command: str, dialect: str, name: str, text: str) -> subprocess.CompletedProcess:
    (tmp_path / name).write_text(text)
    return subprocess.run([sys.executable, "-m", "ncvm", command, "--dialect", dialect, str(tmp_path / name)],
                          capture_output=True, text=True, timeout=120, cwd=tmp_path)


@pytest.mark.parametrize("command", ["run", "check"])
@pytest.mark.parametrize(("dialect", "name", "text", "where", "code"), REPEATED)
def test_address_twice_in_one_block_is_refused_at_the_second_word(tmp_path, command, dialect, name, text, where,
                                                                  code):
    proc = _ncvm(tmp_path, command, dialect, name, text)
    assert proc.returncode == 1, proc.stdout + proc.stderr
    line, column = where.split(":")
    if dialect == "cl800" and command == "run":  # the object program's block: the source line, no column
        assert f"{name}:{line}: error {code}:" in proc.stderr
    else:
        assert f"{name}:{line}:{column}: error {code}:" in proc.stderr
    assert "twice in one block" in proc.stderr
    assert "Traceback" not in proc.stderr


ALLOWED = [
    ("din", "p.din", "G17 G90 G1 X10 F100 M3 M8\nM30\n"),
    ("cpl", "p.cpl", "N10 G17 G90 G1 X10 M3 M8 F100\nN20 M30\n"),
    ("sin800", "p.mpf", "%MPF1\nN10 G17 G90 G1 X10 F100 M3 M8 H1 H2\nN20 M30\n"),
    ("cl800", "p.cl8", CL800.format(block="(:G17 G90 G1 X10 F100 M3 M8 H1 H2:);")),
]


@pytest.mark.parametrize("command", ["run", "check"])
@pytest.mark.parametrize(("dialect", "name", "text"), ALLOWED)
def test_g_m_and_h_words_may_repeat_in_one_block(tmp_path, command, dialect, name, text):
    proc = _ncvm(tmp_path, command, dialect, name, text)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    assert "twice" not in proc.stderr


BLOCKS = ["G1 X10 X20 F100", "G1 X10 F100 F200", "G2 X10 Y0 I5 I6 F100", "G0 Z1 Z2", "G1 X1 Y2 Y3 F100",
          "G1 X5 F100", "G0 X1 Y2 Z3", "G1 X1 F100 M3 M8"]


@needs_rs274
@pytest.mark.parametrize("block", BLOCKS)
def test_din_refuses_what_rs274_refuses(tmp_path, block):
    """The differential: a block rs274 refuses for a repeated word, ncvm refuses too, and the other way round."""
    ngc = tmp_path / "p.ngc"
    ngc.write_text(f"G21 G17 G90\n{block}\nM2\n")
    peer = rs274(ngc, tmp_path / "canon")
    peer_refuses = "Multiple" in peer.stdout + peer.stderr
    proc = subprocess.run([sys.executable, "-m", "ncvm", "run", "--dialect", "din", str(ngc)], capture_output=True,
                          text=True, timeout=120, cwd=tmp_path)
    ours_refuses = "twice in one block" in proc.stderr
    assert ours_refuses == peer_refuses, (peer.stdout + peer.stderr, proc.stderr)
    assert proc.returncode == (1 if ours_refuses else 0), proc.stderr
