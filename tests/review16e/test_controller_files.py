"""Issue 16: "the same program translated twice gives identical output", and what a translation reads from
outside the program is said ("Say what was frozen"). docs/translate.md promises that a translation "leaves
[the permanent data] as it found it ... so translating twice gives the same file". A CPL program's
controller files (manual §6, OPENW / PRN# / ERASE, L3835-4457) are such data: the run of a translation
must not erase or write them on the user's disk."""

from __future__ import annotations

from tests.review16e.helpers import mill, ncvm, translate, write

COUNTER = """(COUNT - the part number lives in the controller file PCOUNT; each part one mm further in X)
10 N% = 0
20 IF FILEACCESS("PCOUNT") >= 0 THEN
30 OPENR(1,"PCOUNT") : INP#(1,N%) : CLOSE(1)
40 ERASE("PCOUNT")
50 ENDIF
60 N% = N% + 1
70 OPENW(1,"PCOUNT",200,"PART COUNT")
80 PRN#(1,N%)
90 CLOSE(1)
N100 G90 G17 G54 G0 X[N%] Y0 Z5
N110 G1 Z-1 F100
N120 G0 Z5
N130 M30
"""


def test_translating_twice_gives_the_same_file(tmp_path):
    """A program that counts its parts in a controller file: two translations in a row are the same."""
    write(tmp_path, {"machine.toml": mill(), "count.cpl": COUNTER, "files/.keep": ""})
    rc1, first, err1 = translate(tmp_path, "count.cpl", "-m", "machine.toml", out="first.ngc")
    rc2, second, err2 = translate(tmp_path, "count.cpl", "-m", "machine.toml", out="second.ngc")
    assert (rc1, rc2) == (0, 0), err1 + err2
    assert first == second


def test_translation_leaves_the_controller_files_as_it_found_them(tmp_path):
    """The shop's real measurement log in the controller files survives translating the program that logs."""
    program = """10 IF FILEACCESS("PLOG") >= 0 THEN ERASE("PLOG") ENDIF
20 OPENW(1,"PLOG",2000,"LOG")
30 PRN#(1,"SIMULATED")
40 CLOSE(1)
N50 G90 G17 G54 G0 X1 Y2 Z3
N60 M30
"""
    write(tmp_path, {"machine.toml": mill(), "log.cpl": program, "files/.keep": ""})
    log = tmp_path / "files" / "PLOG"
    log.write_text("REAL MEASUREMENTS FROM THE SHOP\n")
    rc, _out, err = translate(tmp_path, "log.cpl", "-m", "machine.toml")
    assert rc == 0, err
    assert log.read_text() == "REAL MEASUREMENTS FROM THE SHOP\n"


def test_a_value_read_from_a_file_an_earlier_run_left_is_marked_frozen(tmp_path):
    """The part number read from PCOUNT (left by the machine's earlier runs) decides where the part is cut:
    the output marks it FROZEN, as it marks a CPL permanent variable an earlier run left."""
    write(tmp_path, {"machine.toml": mill(), "count.cpl": COUNTER, "files/PCOUNT": "        41\n"})
    rc, out, err = translate(tmp_path, "count.cpl", "-m", "machine.toml")
    assert rc == 0, err
    assert "G0 X42 Y0 Z5" in out
    assert any("FROZEN" in line and "count.cpl:4" in line for line in out.splitlines()), out


def test_translation_leaves_an_axis_zero_shift_table_file_as_it_found_it(tmp_path):
    """A ZS table named by a path is a file of the controller (manual §4.3, FXC L1724-1779): translating a
    program that writes G54 into it must not rewrite the shop's table on disk."""
    write(tmp_path, {"machine.toml": mill(), "files/.keep": "", "make.cpl": '10 FXCR(1,"ZS.NPV")\nM30\n',
                     "zs.cpl": '10 FXC(1,54,"ZS.NPV") = 12.5\nN20 G90 G54 G0 X1 Y0 Z5\nN30 M30\n'})
    made = subprocess_run_ok(tmp_path, "make.cpl")
    table = tmp_path / "files" / "ZS.NPV"
    before = table.read_text()
    assert made and "G54" in before
    rc, _out, err = translate(tmp_path, "zs.cpl", "-m", "machine.toml")
    assert rc == 0, err
    assert table.read_text() == before


def subprocess_run_ok(folder, program: str) -> bool:
    """``ncvm run PROGRAM`` on the folder's machine ended normally."""
    return ncvm(folder, "run", program, "-m", "machine.toml").returncode == 0
