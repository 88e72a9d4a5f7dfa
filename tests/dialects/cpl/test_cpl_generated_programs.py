"""Programs CPL writes itself: a file ends with the control's end-of-file marker ETX LF (manual §6.1.2 L3867),
LJUST output makes NC programs that run in AUTOMATIC mode (§6.3 L4003), and ``CALL name DIN`` excludes the
called program from linking (§3.3 L1097), so a program may write it before it calls it."""

from __future__ import annotations

import subprocess
import sys

import pytest

from ncvm.api import check

#: writes the NC program PGEN (two blocks) into the file memory, then runs it as a sub-program
WRITER = ('10 LJUST\n20 OPENW(1,"PGEN",1024,"generated")\n30 PRN#(1,"N10 G1 F1000 X",12.5," Y",3.0)\n'
          '40 PRN#(1,"M30")\n50 CLOSE(1)\n')


@pytest.fixture
def machine(reference):
    """The reference machine whose program path holds the file memory (one part program memory, §6.1)."""
    return reference(paths={"program_path": [".", "files"], "file_root": "files"})


def test_a_program_cpl_wrote_runs_l3867_l4003(run_text, machine, tmp_path):
    """L4003: with LJUST, CPL writes NC programs that run in AUTOMATIC mode; the file ends in ETX LF (L3867),
    which used to be refused as `CPL001 cannot read '\\x03'`. Its name has no extension: the marker tells the
    control's file from a plain DIN program."""
    r = run_text(WRITER + "M30\n", name="writer.cpl", machine=machine)
    assert r["error"] is None, r["error"]
    written = tmp_path / "files" / "PGEN"
    assert written.read_bytes().endswith(b"M30\n\x03\n")
    text = written.read_text(encoding="latin-1")
    r = run_text(text, name="PGEN", machine=machine)
    assert r["error"] is None, r["error"]
    assert r["position"]["X"] == 12.5 and r["position"]["Y"] == 3.0 and r["motion"]["feed_moves"] == 1


def test_lines_after_the_end_of_file_marker_are_not_the_program_l3867(run_text, machine):
    """L3867: "An EOF pointer indicates the end of the usable data (<ETX>)": what a SEEK/PRN# left behind the
    marker (§6.3 L4049) is not run."""
    r = run_text("10 A%=1\nN10 G0 X5\n\x03\nN20 G0 X99\n20 A%=2\n", name="p.cpl", machine=machine)
    assert r["error"] is None, r["error"]
    assert r["variables"] == {"A%": 1} and r["position"]["X"] == 5.0


def test_an_etx_inside_a_block_stays_an_error(run_text, machine):
    """Only a line that starts with ETX is the marker: a control character inside a block is not read."""
    r = run_text("N10 G0 X5\x03\nM30\n", name="p.cpl", machine=machine)
    assert r["error"]["code"] == "CPL001" and r["error"]["line"] == 1


def test_cli_runs_the_written_file_by_its_marker(machine, tmp_path, run_text):
    """`ncvm run files/PGEN` in a real process: no extension, no --dialect, the marker names the dialect."""
    run_text(WRITER + "M30\n", name="writer.cpl", machine=machine)
    (tmp_path / "machine.toml").write_text('[[axis]]\nname = "X"\n[[axis]]\nname = "Y"\n[[axis]]\nname = "Z"\n')
    p = subprocess.run([sys.executable, "-m", "ncvm", "run", "--state", str(tmp_path / "st"), "files/PGEN"],
                       cwd=tmp_path, capture_output=True, text=True, timeout=120)
    assert p.returncode == 0, p.stderr
    assert "ended normally" in p.stderr and "program X[12.5,12.5]" in p.stderr


def test_call_din_of_a_program_written_in_the_same_run_l1097(run_text, machine):
    """L1097: a CALL ... DIN sub-program is excluded from linking, so it need not exist when the main program is
    linked: the program writes PGEN with OPENW/PRN#/CLOSE and then calls it. This used to fail at link time
    with CPL005 before a block ran."""
    r = run_text(WRITER + "60 CALL PGEN DIN\n70 WAIT\n80 X = MPOS(1) : Y = MPOS(2)\nM30\n", name="main.cpl",
                 machine=machine)
    assert r["error"] is None, r["error"]
    assert r["variables"]["X"] == 12.5 and r["variables"]["Y"] == 3.0


def test_call_din_of_a_missing_program_is_found_when_it_runs(run_text, machine, tmp_path):
    """Not linked, so not looked for at link time: the blocks before the call run, the call is CPL005. Check
    warns (the program may be written before the call), and the warning does not refuse the run."""
    main = tmp_path / "main.cpl"
    main.write_text("10 #A% = 1\n20 CALL NOSUCH DIN\n30 #A% = 2\nM30\n")
    assert [(d.code, d.severity, d.span.line) for d in check(main, machine=machine)] == [("CPL005", "warning", 2)]
    r = run_text(main.read_text(), name="main.cpl", machine=machine)
    assert r["error"]["code"] == "CPL005" and r["error"]["line"] == 2 and r["variables"]["#A%"] == 1


def test_a_linked_call_of_a_missing_program_is_still_a_link_error(run_text, machine):
    r = run_text('10 PRN#(0,"started")\n20 CALL NOSUCH\nM30\n', name="main.cpl", machine=machine)
    assert r["error"]["code"] == "CPL005" and r["output"] == []


def test_check_warns_of_a_din_called_program_with_cpl_l1104(run_text, machine, tmp_path):
    """L1104: a CPL program called with DIN gives an error "at program runtime". Check says so beforehand, as
    a warning at the call (the program may still change before the call runs); the run still stops there."""
    (tmp_path / "PSUB").write_text("N10 G1 X10 F100\n20 X = 1\n")
    main = tmp_path / "main.cpl"
    main.write_text("10 #A% = 1\n20 CALL PSUB DIN\nM30\n")
    diags = check(main, machine=machine)
    assert [(d.code, d.severity, d.span.line) for d in diags] == [("CPL030", "warning", 2)]
    assert "PSUB contains CPL blocks" in diags[0].message
    r = run_text(main.read_text(), name="main.cpl", machine=machine)
    assert r["error"]["code"] == "CPL030" and r["variables"]["#A%"] == 1
    (tmp_path / "PSUB").write_text("N10 G1 X10 F100\n")
    assert check(main, machine=machine) == []
