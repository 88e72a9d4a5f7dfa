"""A translation reads the permanent data of the state directory and leaves it as it found it (issue 16,
"Say what was frozen"; docs/translate.md): SINUMERIK central R900-R999 and CPL permanent variables that a
translated program writes stay as the earlier runs left them, so translating twice gives the same file."""

from __future__ import annotations

import hashlib

from tests.review16c.helpers import code_lines, ncvm
from tests.review16d.helpers import machine

COUNTER = """%MPF5
N10 G17 G71 G90 G54 G94
N20 R900=R900+10
N30 G0 X=R900 Y0 Z50
N40 M30
"""


def _digest(folder) -> dict[str, str]:
    return {p.name: hashlib.sha256(p.read_bytes()).hexdigest() for p in sorted(folder.iterdir()) if p.is_file()}


def _moves(tmp_path) -> list[str]:
    r = ncvm(tmp_path, "translate", "count.mpf", "-m", "machine.toml", "--state", "st", "-o", "out.ngc")
    assert r.returncode == 0, r.stderr
    return [line.split()[1] for line in code_lines((tmp_path / "out.ngc").read_text()) if line.startswith("G0 X")]


def test_translations_leave_central_r_as_the_runs_left_it(tmp_path):
    (tmp_path / "machine.toml").write_text(machine("mill"))
    (tmp_path / "count.mpf").write_text(COUNTER)
    assert ncvm(tmp_path, "run", "count.mpf", "-m", "machine.toml", "--state", "st").returncode == 0
    before = _digest(tmp_path / "st")
    assert [_moves(tmp_path) for _ in range(3)] == [["X20"]] * 3
    assert _digest(tmp_path / "st") == before
    run = ncvm(tmp_path, "run", "count.mpf", "-m", "machine.toml", "--state", "st", "--json")
    assert '"R900": 20' in run.stdout.replace(".0", ""), run.stdout  # the second run counts on from the first


def test_a_translation_creates_no_store(tmp_path):
    (tmp_path / "machine.toml").write_text(machine("mill"))
    (tmp_path / "count.mpf").write_text(COUNTER)
    assert _moves(tmp_path) == ["X10"]
    assert not list((tmp_path / "st").glob("store*")), "the translation made a permanent store"


# A CPL program that counts in a permanent variable and logs to a file of the controller (the built-in
# machine keeps the controller's files in the state directory), a SINUMERIK counter in R900, and a rw_SymPas
# program (no permanent data of its own): translated after runs that filled one state directory.
PROGRAMS = {
    "set.cpl": "10 @1 = 5\nM30\n",
    "count.cpl": '10 @1 = @1 + 5\n20 OPENW(1,"LOG",200)\n30 PRN#(1,"RUN ",@1)\n40 CLOSE(1)\n'
                 "N50 G0 X[@1] Y0 Z50\nM30\n",
    "count.mpf": COUNTER,
    "move.sap": "program P;\nbegin\n  TRVL := 50.0; TRAC := 500.0;\n  MLAW(A1 := 20.0, A2 := 0.0, A3 := 0.0);\nend.\n",
}


def _tree(folder) -> dict[str, tuple]:
    """Every entry under ``folder``: its kind, its bytes' hash and its modification time (a file written with
    the same bytes again is changed too: the pid-less lock of a run that ended)."""
    out = {}
    for p in sorted(folder.rglob("*")):
        st = p.lstat()
        data = hashlib.sha256(p.read_bytes()).hexdigest() if p.is_file() and not p.is_symlink() else None
        out[str(p.relative_to(folder))] = (p.is_dir(), data, st.st_mtime_ns if not p.is_dir() else None)
    return out


def test_translating_leaves_the_state_directory_byte_identical(tmp_path):
    """No lock written, no link table, no store side file, no controller file: the directory as it was."""
    (tmp_path / "mill.toml").write_text(machine("mill"))  # named so that no program takes it as its folder's
    for name, text in PROGRAMS.items():
        (tmp_path / name).write_text(text)
    for name in ("set.cpl", "count.cpl", "count.mpf"):  # CPL on the built-in machine: its files are in st
        machine_args = () if name.endswith(".cpl") else ("-m", "mill.toml")
        r = ncvm(tmp_path, "run", name, *machine_args, "--state", "st")
        assert r.returncode == 0, r.stderr
    (tmp_path / "st" / "lock").unlink()  # a state directory no run has locked here (copied from elsewhere)
    before = _tree(tmp_path / "st")
    assert "files/LOG" in before and any(k.startswith("link/") for k in before), before
    for name in PROGRAMS:
        machine_args = () if name.endswith(".cpl") else ("-m", "mill.toml")
        r = ncvm(tmp_path, "translate", name, *machine_args, "--state", "st", "-o", f"{name}.ngc")
        assert r.returncode == 0, r.stderr
    assert _tree(tmp_path / "st") == before


def test_a_translation_of_a_new_program_writes_no_link_table(tmp_path):
    (tmp_path / "set.cpl").write_text(PROGRAMS["set.cpl"])
    assert ncvm(tmp_path, "run", "set.cpl", "--state", "st").returncode == 0
    (tmp_path / "other.cpl").write_text("N10 G0 X1 Y0 Z5\nM30\n")
    before = _tree(tmp_path / "st")
    r = ncvm(tmp_path, "translate", "other.cpl", "--state", "st", "-o", "out.ngc")
    assert r.returncode == 0, r.stderr
    assert _tree(tmp_path / "st") == before


def test_a_translation_while_a_run_holds_the_state_is_refused(tmp_path):
    """The reader's shared lock: a run holding the directory (its exclusive lock) refuses the translation."""
    import fcntl
    import os

    (tmp_path / "machine.toml").write_text(machine("mill"))
    (tmp_path / "count.mpf").write_text(COUNTER)
    (tmp_path / "st").mkdir()
    fd = os.open(tmp_path / "st" / "lock", os.O_RDWR | os.O_CREAT)
    try:
        fcntl.flock(fd, fcntl.LOCK_EX)
        r = ncvm(tmp_path, "translate", "count.mpf", "-m", "machine.toml", "--state", "st", "-o", "out.ngc")
    finally:
        os.close(fd)
    assert r.returncode == 2 and "in use by another run" in r.stderr, r.stderr
    assert not (tmp_path / "out.ngc").exists()


# Central R900-R999 left by an earlier run (R900 = 10 after one run of COUNTER) are input from outside the
# program where the program reads them, and only there: the FROZEN mark names the block that read one.
CENTRAL_READS = {
    "count.mpf": (COUNTER, ["FROZEN: central R parameter R900=10 left by earlier runs at count.mpf:3"]),
    "never.mpf": ("%MPF6\nN10 G17 G71 G90 G54 G94\nN20 G0 X10 Y0 Z50\nN30 M30\n", []),
    "own.mpf": ("%MPF6\nN10 G17 G71 G90 G54 G94\nN20 R900=3\nN30 G0 X=R900 Y0 Z50\nN40 M30\n", []),
    "pointer.mpf": ("%MPF6\nN10 G17 G71 G90 G54 G94\nN20 R5=900\nN30 @201 R6 P5\nN40 G0 X=R6 Y0 Z50\nN50 M30\n",
                    ["FROZEN: central R parameter R900=10 left by earlier runs at pointer.mpf:4"]),
}


def test_central_r_is_marked_where_the_program_reads_it(tmp_path):
    (tmp_path / "machine.toml").write_text(machine("mill"))
    (tmp_path / "count.mpf").write_text(COUNTER)
    assert ncvm(tmp_path, "run", "count.mpf", "-m", "machine.toml", "--state", "st").returncode == 0
    for name, (text, marks) in CENTRAL_READS.items():
        (tmp_path / name).write_text(text)
        r = ncvm(tmp_path, "translate", name, "-m", "machine.toml", "--state", "st", "-o", "out.ngc")
        assert r.returncode == 0, r.stderr
        out = (tmp_path / "out.ngc").read_text()
        found = [line[1:].split(";")[0] for line in out.splitlines() if line.startswith("(FROZEN")]
        assert found == marks, f"{name}:\n{out}"


def test_a_program_in_the_file_root_reads_its_own_folder_in_a_translation(tmp_path):
    """CPL manual L4381: a main program in the controller's file root reads names without a path in its own
    folder. The translation runs on a scratch copy of the file root and still reads DEPTH beside the program,
    not a DEPTH at the top of the root."""
    from tests.review16e.helpers import mill, translate, write

    program = '10 OPENR(1,"DEPTH") : INP#(1,D) : CLOSE(1)\nN20 G90 G17 G54 G0 X[D] Y0 Z5\nN30 M30\n'
    write(tmp_path, {"machine.toml": mill(), "files/part/p.cpl": program, "files/part/DEPTH": "7\n",
                     "files/DEPTH": "3\n"})
    rc, out, err = translate(tmp_path, "files/part/p.cpl", "-m", "machine.toml")
    assert rc == 0, err
    assert "G0 X7 Y0 Z5" in code_lines(out), out
    assert (tmp_path / "files" / "part" / "DEPTH").read_text() == "7\n"
