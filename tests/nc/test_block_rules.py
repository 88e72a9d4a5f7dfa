"""Issue 14: a block with no one meaning is refused, by ``ncvm run`` and ``ncvm check`` alike, not run with one
reading chosen silently (nc/profiles/blockrules.py, docs/decisions.md "Issue 14: in-block order and modal
groups"). ``din`` follows rs274 (LinuxCNC interp_read.cc read_g/read_m, interp_check.cc): two codes of one
modal group ("Two G codes used from same modal group", M codes likewise: NC015), two codes that both take the
axis words ("Cannot use two g codes that both use axis values": NC015), G53 with a motion other than G0/G1
("Must use g0 or g1 with g53": NC009), and a D word without G41, G41.1, G42, G42.1 or G96 in its block
("D word with no G41 ... to use it": NC009). G80 gives way to another motion code, as in rs274."""

from __future__ import annotations

import subprocess
import sys

import pytest
from rs274peer import needs_rs274, rs274

REFUSED = [("G90 G91 G0 X5", "NC015", "G91"), ("G0 G1 X5 F100", "NC015", "G1"), ("G20 G70 X1", "NC015", "G70"),
           ("G17 G19", "NC015", "G19"), ("G43 H1 G49", "NC015", "G49"), ("M3 M5 S100", "NC015", "M5"),
           ("M7 M8", "NC015", "M8"), ("M0 M1", "NC015", "M1"), ("G92 X0 G0", "NC015", "G92 and G0"),
           ("G53 G92 X0", "NC015", "G53 and G92"), ("G2 G53 X0 I-2.5 F100", "NC009", "G53"),
           ("G1 X5 D1 F100", "NC009", "D1"), ("G43 D1", "NC009", "D1"), ("G1 Y5 D2", "NC009", "D2")]
ALLOWED = ["G80 G0 X1", "G0 G80 X1", "G4 P1 G0 X5", "G41 D1 G1 X5 Y20 F100", "G96 D2000 S100 M3", "M3 M8 S100",
           "G17 G90 G21 G0 X1", "G92 X0", "G53 G0 X1", "T1 M6 G43 H1"]


def _ncvm(tmp_path, command: str, text: str, name: str = "p.ngc") -> subprocess.CompletedProcess:
    (tmp_path / name).write_text(text)
    return subprocess.run([sys.executable, "-m", "ncvm", command, str(tmp_path / name)], capture_output=True,
                          text=True, timeout=120, cwd=tmp_path)


@pytest.mark.parametrize(("block", "code", "named"), REFUSED)
@pytest.mark.parametrize("command", ["run", "check"])
def test_din_refuses_a_block_rs274_refuses(tmp_path, command, block, code, named):
    proc = _ncvm(tmp_path, command, f"G21 G90\nG0 X5\n{block}\nG0 X1\nM2\n")
    assert proc.returncode == 1, proc.stdout + proc.stderr
    assert "p.ngc:3:" in proc.stderr and f"error {code}:" in proc.stderr and named in proc.stderr, proc.stderr
    assert "Traceback" not in proc.stderr


def test_the_run_stops_at_the_refused_block_after_running_the_blocks_before(tmp_path):
    proc = _ncvm(tmp_path, "run", "G21 G90\nG0 X5\nG90 G91 X7\nG0 X1\nM2\n")
    assert proc.returncode == 1
    assert "1 moves" in proc.stderr or "1 move" in proc.stderr, proc.stderr


@pytest.mark.parametrize("block", ALLOWED)
@pytest.mark.parametrize("command", ["run", "check"])
def test_din_runs_the_blocks_rs274_runs(tmp_path, command, block):
    proc = _ncvm(tmp_path, command, f"G21 G90\nT1 M6\nG0 X5\n{block}\nG40 G0 X20\nM2\n")
    assert proc.returncode == 0, proc.stdout + proc.stderr


@needs_rs274
@pytest.mark.parametrize("block", [b for b, _, _ in REFUSED] + ALLOWED)
def test_din_refuses_exactly_what_rs274_refuses(tmp_path, block):
    text = f"G21 G90\nG0 X5\n{block}\nG40 G0 X20\nM2\n"
    ngc = tmp_path / "p.ngc"
    ngc.write_text(text)
    peer = rs274(ngc, tmp_path / "canon")
    proc = _ncvm(tmp_path, "run", text)
    assert (proc.returncode == 1) == (peer.returncode != 0), (peer.stdout[-400:], proc.stderr)


CL800 = "PROGRAM 7;\nCHANNEL NC 4;\nBEGIN\n(:G0 X5:); LF;\n(:{block}:); LF;\n(:M30:);\nEND.\n"
#: the controls keep one function of each G group (CPL manual's SD(1) group table L2302-2306; CL 800 manual
#: §11.5 L7392-7410): dialect, file, program, line of the refused block, its code
CONTROLS = [
    ("cpl", "p.cpl", "N10 G0 X5\nN20 G90 G91 X5\nN30 M30\n", 2, "CPL040"),
    ("cpl", "p.cpl", "N10 G0 X5\nN20 G54 G55 G0 X5\nN30 M30\n", 2, "CPL040"),
    ("cpl", "p.cpl", "N10 G0 X5\nN20 G17 G19\nN30 M30\n", 2, "CPL040"),
    ("cpl", "p.cpl", "N10 G0 X5\nN20 G154 G155\nN30 M30\n", 2, "CPL040"),
    ("sin800", "p.mpf", "%MPF1\nN10 G0 X5\nN20 G0 G1 X5 F100\nN30 M30\n", 3, "SIN001"),
    ("sin800", "p.mpf", "%MPF1\nN10 G0 X5\nN20 G54 G57\nN30 M30\n", 3, "SIN001"),
    ("cl800", "p.cl8", CL800.format(block="G90 G91 X5"), 5, "SIN001"),
]


@pytest.mark.parametrize(("dialect", "name", "text", "line", "code"), CONTROLS)
@pytest.mark.parametrize("command", ["run", "check"])
def test_the_controls_refuse_two_functions_of_one_g_group(tmp_path, command, dialect, name, text, line, code):
    (tmp_path / name).write_text(text)
    proc = subprocess.run([sys.executable, "-m", "ncvm", command, "--dialect", dialect, str(tmp_path / name)],
                          capture_output=True, text=True, timeout=120, cwd=tmp_path)
    assert proc.returncode == 1, proc.stdout + proc.stderr
    assert f"{name}:{line}" in proc.stderr and f"error {code}" in proc.stderr, proc.stderr
    assert "in one block: two functions of G group" in proc.stderr
    assert "Traceback" not in proc.stderr


@pytest.mark.parametrize(("dialect", "name", "text"), [
    ("cpl", "p.cpl", "N10 G17 G90 G71 G94 G40 G54 G1 X5 F100\nN20 M30\n"),
    ("sin800", "p.mpf", "%MPF1\nN10 G17 G90 G71 G94 G40 G54 G60 G1 X5 F100\nN20 M30\n"),
])
def test_one_function_of_each_group_runs(tmp_path, dialect, name, text):
    (tmp_path / name).write_text(text)
    for command in ("run", "check"):
        proc = subprocess.run([sys.executable, "-m", "ncvm", command, "--dialect", dialect, str(tmp_path / name)],
                              capture_output=True, text=True, timeout=120, cwd=tmp_path)
        assert proc.returncode == 0, proc.stdout + proc.stderr


def test_g53_under_a_modal_arc_is_refused_when_the_run_reaches_it(tmp_path):
    """rs274 judges G53 by the block's motion, the modal one included ("Must use g0 or g1 with g53"); check
    cannot see the modal motion from the text, the run stops at the block (NC009)."""
    proc = _ncvm(tmp_path, "run", "G21 G90\nG0 X3\nG2 X0 I-1.5 F100\nG53 X0\nM2\n")
    assert proc.returncode == 1
    assert "p.ngc:4: error NC009: G53 (machine coordinates) under G2" in proc.stderr, proc.stderr
