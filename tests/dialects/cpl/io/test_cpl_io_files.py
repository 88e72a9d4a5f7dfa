"""Chapter 6 file handling on real files, each manual example with its stated (or repaired) result."""

from __future__ import annotations

import math
import os
import stat

import pytest

from ncvm.dialects.cpl.io.errors import CplRuntimeError
from ncvm.dialects.cpl.io.files import CplFiles
from ncvm.dialects.cpl.io.strings import CharacterField, StringView
from ncvm.dialects.cpl.io.values import Double
from ncvm.machine.model import SimClock

ETX = "\x03\n"


@pytest.fixture
def fs(tmp_path):
    return CplFiles(root=tmp_path, clock=SimClock(now=0.0, start_epoch=1_700_000_000.0))


def content(fs, name):
    return (fs.root / name).read_bytes().decode("latin-1")


def error_of(fn, *args, **kw):
    with pytest.raises(CplRuntimeError) as err:
        fn(*args, **kw)
    return err.value


def dim(size, text=None):
    f = CharacterField(size)
    if text is not None:
        f.assign(text)
    return f


def test_f1_openw_forms_create_files(fs):
    # L3925-3935
    fs.OPENW(1, "P500", 1024, "This is my best progam")
    fs.OPENW(9, "P501", 1024, "This is my best program")
    fs.OPENW(7, "PData Meas.DAT", 1024, "Store measurement data")
    for n in (1, 9, 7):
        fs.CLOSE(n)
    assert content(fs, "P500") == ETX and content(fs, "PData Meas.DAT") == ETX


def test_open_errors(fs):
    assert error_of(fs.OPENW, 0, "P1").message.startswith("INVALID LOGICAL NUMBER")
    assert error_of(fs.OPENR, 10, "P1").code == "CPL601"
    assert error_of(fs.OPENW, 1, "P1", 129).message.startswith("ILLEGAL FILE SIZE")
    assert error_of(fs.OPENW, 1, "P1", 130, "R", 1025).message.startswith("INVALID COMPONENT LENGTH")
    assert error_of(fs.OPENW, 1, "P1", 130, 0).code == "CPL603"
    assert error_of(fs.OPENW, 1, "../outside").message.startswith("INVALID FILE NAME")
    assert error_of(fs.OPENW, 1, "A" * 31).code == "CPL609"
    assert error_of(fs.OPENW, 1, None).message == "INVALID FILE NAME: NUL"  # not Python's "None"
    assert error_of(fs.OPENR, 1, "MISSING").code == "CPL612"
    fs.OPENW(1, "P1")
    assert error_of(fs.OPENW, 2, "P1").code == "CPL611"  # already open for writing
    fs.OPENR(2, "P1")
    fs.OPENR(3, "P1")  # reading more than once is allowed
    assert error_of(fs.PRN, 2, "X").code == "CPL613"
    assert error_of(fs.INP, 1, "S").code == "CPL613"
    assert error_of(fs.REWRITE, 4).code == "CPL610"
    assert not (fs.root.parent / "outside").exists()


def test_f2_random_file_records_padded(fs):
    # L3937-3951 (one name, CPL manual L3937-3963)
    fs.OPENW(2, "P200", 1024, 10)
    for _ in range(3):
        fs.PRN(2, "TEST")
    fs.CLOSE(2)
    assert content(fs, "P200") == "TEST      \n" * 3 + ETX


def test_f3_openr_with_wrong_record_length(fs):
    # L3953-3963
    fs.OPENW(2, "P200", 130, "TEST", 10)
    fs.PRN(2, "ABC")
    fs.CLOSE(2)
    assert error_of(fs.OPENR, 1, "P200", 5).message.startswith("INVALID COMPONENT LENGTH")
    fs.OPENR(1, "P200", 10)


def test_f4_copy_nc_program_into_random_file(fs):
    # L3965-3993: P1 is an ordinary text file (no EOF marker), copied record by record
    (fs.root / "P1").write_text('N10 G1F10000X1000Y1000Z1000\n1 A$="01234567890123456789"\n2 B$="TEST"\nN20 X0\nM30\n')
    fs.OPENW(1, "PMeas_PRG", 500, "RANDOM FILE", 10)
    fs.OPENR(2, "P1")
    a = dim(30)
    for _ in range(5):
        fs.INP(2, a)
        fs.PRN(1, a)
    fs.CLOSE(2)
    fs.CLOSE(1)
    assert content(fs, "PMeas_PRG") == 'N10 G1F100\n1 A$="0123\n2 B$="TEST\nN20 X0    \nM30       \n' + ETX


def test_f5_overwrite_with_semicolon_keeps_the_tail(fs):
    # L4043-4049: reclen 35, so the records are cut to 35 characters (CPL manual L4043-4049; L3873-3875)
    fs.OPENW(2, "PProg123.PRG", 200, 35)
    for i in (1, 2, 3):
        fs.PRN(2, f"TEST{i} FOR PRN COMMAND WITH SEMICOLON")
    fs.SEEK(2, 1)
    fs.PRN(2, "OVERWRITE", semicolon=True)
    fs.CLOSE(2)
    assert content(fs, "PProg123.PRG") == ("OVERWRITE PRN COMMAND WITH SEMICOLO\n"
                                           "TEST2 FOR PRN COMMAND WITH SEMICOLO\n"
                                           "TEST3 FOR PRN COMMAND WITH SEMICOLO\n" + ETX)


def test_f6_overwrite_without_semicolon_blanks_the_tail(fs):
    # L4051-4061
    fs.OPENW(2, "P2", 1000, 36)
    fs.REWRITE(2)
    for i in (1, 2, 3):
        fs.PRN(2, f"TEST{i} FOR PRN COMMAND W/O SEMICOLON")
    fs.SEEK(2, 1)
    fs.PRN(2, "OVERWRITE")
    fs.CLOSE(2)
    lines = content(fs, "P2").split("\n")
    assert lines[0] == "OVERWRITE" + " " * 27
    assert lines[1] == "TEST2 FOR PRN COMMAND W/O SEMICOLON "
    assert content(fs, "P2").endswith(ETX)


def test_f7_semicolon_chaining_and_close_ends_the_record(fs):
    # L4063-4078 (C$ = "PRN COMMAND" keeps its blank; the manual's result line lost it)
    fs.OPENW(1, "P2", 300, "TEST PRN COMMAND")
    a, b, c = "TEST", "FOR", "PRN COMMAND"
    fs.PRN(1, a)
    fs.PRN(1, b)
    fs.PRN(1, c)
    fs.PRN(1, a, semicolon=True)
    fs.PRN(1, b, semicolon=True)
    fs.PRN(1, c, semicolon=True)
    fs.CLOSE(1)
    assert content(fs, "P2") == "TEST\nFOR\nPRN COMMAND\nTESTFORPRN COMMAND\n" + ETX


def test_f8_templates_over_several_arguments(fs):
    # L4080-4097 (A$ = 5000 read as a numeric variable)
    fs.OPENW(1, "P2", 300, "TEST2")
    e = dim(50, "CDEFGHI")
    fs.PRN(1, "10", semicolon=True)
    fs.PRN(1, "######", "###.####", "#.######", 5000, 1.231, Double(4 / 3), "ABCDE", e)
    fs.CLOSE(1)
    assert content(fs, "P2") == "10  5000  1.23101.333333ABCDECDEFGHI\n" + ETX


def test_chained_strings_in_prn_s13(fs):
    # L3775-3779: OPENW(1,"P2",130,"CHAINING TEST",10) - the records are 10 long
    from ncvm.dialects.cpl.io.strings import concat
    fs.OPENW(1, "P2", 130, "CHAINING TEST", 10)
    a, b, c, d = dim(3, "ABC"), dim(3, "DEF"), "GH", "JKL"
    for item in (concat(a, b), concat(a, c), concat(c, d), concat(a, c, "TEST"), concat("UVW", "XYZ")):
        fs.PRN(1, item)
    fs.CLOSE(1)
    assert content(fs, "P2") == "ABCDEF    \nABCGH     \nGHJKL     \nABCGHTEST \nUVWXYZ    \n" + ETX


def test_s8_trim_written_to_a_file(fs):
    # L3587-3594
    from ncvm.dialects.cpl.io.strings import trim
    fs.OPENW(1, "P1")
    a = " ABCDEF "
    for s in (a, trim(a, "L"), trim(a, "R"), trim(a)):
        fs.PRN(1, ">", s, "<")
    fs.CLOSE(1)
    assert content(fs, "P1") == "> ABCDEF <\n>ABCDEF <\n> ABCDEF<\n>ABCDEF<\n" + ETX


def test_format_overflow_prints_stars_and_warns(fs):
    fs.OPENW(1, "P1")
    fs.PRN(1, "X=##", 123)
    fs.CLOSE(1)
    assert content(fs, "P1") == "X=**\n" + ETX
    assert [w.message for w in fs.warnings] == ["PRN FORMAT INCORRECT: X=**"]


def test_block_exceeds_1024_bytes(fs):
    fs.OPENW(1, "P1")
    fs.PRN(1, "A" * 1024)
    assert error_of(fs.PRN, 1, "A" * 1025).message.startswith("BLOCK EXCEEDS 1024 BYTES")
    fs.PRN(1, "A" * 1000, semicolon=True)
    assert error_of(fs.PRN, 1, "A" * 25).code == "CPL604"


def test_files_of_a_run_grow_by_at_most_the_file_space(fs):
    """A runaway PRN# loop ends with FILE MEMORY FULL (CPL614), over every file the run writes; the file
    keeps its records and its EOF marker; what REWRITE gives back can be written again."""
    fs.space = 1000
    fs.OPENW(1, "LOG")
    for _ in range(9):
        fs.PRN(1, "A" * 99)  # 100 bytes a record
    fs.OPENW(2, "OTHER")
    err = error_of(fs.PRN, 2, "B" * 99)
    assert err.code == "CPL614" and "1,000 bytes" in err.message, err.message
    assert content(fs, "LOG") == ("A" * 99 + "\n") * 9 + ETX and content(fs, "OTHER") == ETX
    fs.REWRITE(1)
    for _ in range(9):
        fs.PRN(1, "C" * 99)  # as much as the file held before
    fs.CLOSE(1)
    assert content(fs, "LOG") == ("C" * 99 + "\n") * 9 + ETX


def test_a_write_the_host_refuses_is_a_file_error_not_a_crash(fs, monkeypatch):
    fs.OPENW(1, "LOG")

    def disk_full(fd, data, offset):
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(os, "pwrite", disk_full)
    err = error_of(fs.PRN, 1, "A")
    assert err.code == "CPL615" and err.message == "FILE CANNOT BE WRITTEN: LOG: No space left on device"


def test_chr13_starts_a_new_record(fs):
    fs.OPENW(1, "P1")
    fs.PRN(1, "ONE", "\r", "TWO")
    fs.CLOSE(1)
    assert content(fs, "P1") == "ONE\nTWO\n" + ETX


def test_ljust_for_nc_programs(fs):
    fs.mode.LJUST()
    fs.OPENW(1, "P1")
    fs.PRN(1, "N10 X", 1.5, " Y", 20, " Z", "###.###", -3.25)
    fs.mode.NJUST()
    fs.PRN(1, "N20 X", 1.5)
    fs.CLOSE(1)
    assert content(fs, "P1") == "N10 X1.5 Y20 Z-3.250\nN20 X   1.5  \n" + ETX  # L4001


def test_f9_inp_nul_without_moving_and_string_takes_its_dim(fs):
    # L4132-4140, file content without the OCR blanks (CPL manual L4132-4140)
    (fs.root / "P2").write_text("ABC123456789ABC\n\x03\n", encoding="latin-1")
    fs.OPENR(2, "P2")
    c, d = dim(3), dim(3)
    values = fs.INP(2, "I", "R", "B", c, "I", d)
    fs.CLOSE(2)
    assert values[:3] == [None, None, None]
    assert c.text == "ABC" and values[4] == 123456789 and d.text == "ABC"


def test_f10_inp_with_semicolon_inside_a_record(fs):
    # L4142-4156
    fs.OPENW(1, "P2", 200, "TEST", 22)
    for _ in range(3):
        fs.PRN(1, "-12TEST1.23V12ABCD2.4A")
    fs.CLOSE(1)
    a, c, d, e, g, h, i, j = dim(3), dim(5), dim(4), dim(4), dim(25), dim(7), dim(7), dim(25)
    fs.OPENR(2, "P2", 22)
    b, _, r11, _, r12, _, _ = fs.INP(2, "I", d, "R", StringView(e, 1, 1), "R", a, c)
    fs.INP(2, g)
    fs.INP(2, h, semicolon=True)
    fs.INP(2, i, semicolon=True)
    fs.INP(2, j)
    assert fs.EOF(2)
    fs.CLOSE(2)
    assert b == -12 and d.text == "TEST" and r11 == pytest.approx(1.23) and e.text == "V"
    assert r12 == 12.0 and a.text == "ABC" and c.text == "D2.4A"
    assert g.text == "-12TEST1.23V12ABCD2.4A"
    assert (h.text, i.text, j.text) == ("-12TEST", "1.23V12", "ABCD2.4A")


def test_inp_boolean_and_value_errors(fs):
    (fs.root / "P3").write_text("TRUE FALSE MAYBE\n99999999999\n1E\n", encoding="latin-1")
    fs.OPENR(1, "P3")
    assert fs.INP(1, "B", "B", "B", semicolon=True) == [True, False, None]
    fs.INP(1, "S")
    assert error_of(fs.INP, 1, "I").message.startswith("INVALID INTEGER VALUE")
    fs.CLOSE(1)


def test_f11_eof_loop_counts_records(fs):
    # L4165-4169
    (fs.root / "P").write_text("A\nBB\nCCC\n\x03\n", encoding="latin-1")
    fs.OPENR(1, "P", None)
    a, count = dim(10), 0
    while not fs.EOF(1):
        fs.INP(1, a)
        count += 1
    fs.CLOSE(1)
    assert count == 3
    (fs.root / "E").write_text("\x03\n")
    fs.OPENR(1, "E")
    assert fs.EOF(1)


def test_f12_close_example_positions_round_trip(fs):
    # L4183-4195 rebuilt: PRN#(1,"X AXIS",XPOS,"Y AXIS",YPOS) then read back into A$(35)
    fs.OPENW(1, "P5", 500, "AXISPOS")
    fs.REWRITE(1)
    fs.PRN(1, "X AXIS", 12.5, "Y AXIS", -3.0)
    fs.CLOSE(1)
    fs.OPENR(1, "P5")
    a = dim(35)
    fs.INP(1, a)
    fs.CLOSE(1)
    assert a.text == "X AXIS  12.5  Y AXIS  -3    "  # L4001: trailing zeros suppressed


def test_f13_filepos_sequential(fs):
    # L4241-4258
    fs.OPENW(1, "P2", 200, "TEST")
    for _ in range(10):
        fs.PRN(1, "TEST FOR FILEPOS")
    fs.CLOSE(1)
    fs.OPENR(1, "P2")
    fs.SEEK(1, 3)
    assert (fs.FILEPOS(1), fs.FILEPOS(1, 1)) == (3, 3)
    fs.SEEK(1, 0)
    assert (fs.FILEPOS(1), fs.FILEPOS(1, 1)) == (171, 171)
    assert error_of(fs.FILEPOS, 1, 2).message.startswith("INVALID PARAMETER")
    assert error_of(fs.FILEPOS, 0).message.startswith("INVALID FILE NUMBER")
    fs.CLOSE(1)


def test_f14_filepos_random(fs):
    # L4260-4262 with reclen 127 (CPL manual L4262: the offsets imply a 128-byte stride)
    fs.OPENW(1, "P2", 200, "TEST", 127)
    for _ in range(10):
        fs.PRN(1, "TEST FOR FILEPOS")
    fs.SEEK(1, 3, 2)
    assert [fs.FILEPOS(1), fs.FILEPOS(1, 1), fs.FILEPOS(1, 2), fs.FILEPOS(1, 3)] == [3, 258, 3, 2]
    fs.PRN(1, "OVERWRITING OF 3RD RECORD FROM BYTE 2 WITH THIS TEXT")
    fs.SEEK(1, 0)
    assert [fs.FILEPOS(1), fs.FILEPOS(1, 1), fs.FILEPOS(1, 2), fs.FILEPOS(1, 3)] == [11, 1281, 11, 1]
    fs.CLOSE(1)
    records = content(fs, "P2").split("\n")
    assert records[2] == "TOVERWRITING OF 3RD RECORD FROM BYTE 2 WITH THIS TEXT".ljust(127)
    assert len(content(fs, "P2")) == 1282


def test_f15_seek_sequential_byte_by_byte(fs):
    # L4288-4299: LJUST, 10 records of 24 characters, read byte by byte, PRN#(0) per byte
    fs.mode.LJUST()
    fs.OPENW(1, "P271", 130, "TEST")
    for _ in range(10):
        fs.PRN(1, "!/-!/-!/-!/-!/-!/-!/-!/-")
    fs.CLOSE(1)
    fs.OPENR(2, "P271")
    a = dim(1)
    assert fs.FILESIZE(2, 2) == 250
    for i in range(1, fs.FILESIZE(2, 2) - 28 + 1):
        if not fs.EOF(2):
            fs.SEEK(2, i)
            fs.INP(2, a)
        if fs.EOF(2):
            fs.PRN(0, "###", i, ". BYTE: <EOF>")
        else:
            fs.PRN(0, "###", i, ". BYTE: <", a, ">")
    fs.CLOSE(2)
    assert fs.messages[:4] == ["1. BYTE: <!>", "2. BYTE: </>", "3. BYTE: <->", "4. BYTE: <!>"]
    assert fs.messages[24] == "25. BYTE: <>"  # byte 25 is the record's LF
    assert len(fs.messages) == 222
    assert error_of(fs.SEEK, 1, 1, 1).code == "CPL610"


def test_seek_errors(fs):
    (fs.root / "S").write_text("ABC\n\x03\n")
    fs.OPENR(1, "S")
    assert error_of(fs.SEEK, 1, 5).message.startswith("INVALID COMPONENT")
    assert error_of(fs.SEEK, 1, 1, 1).message.startswith("INVALID PARAMETER")
    assert error_of(fs.SEEK, 10, 1).message.startswith("INVALID FILE NUMBER")
    fs.OPENW(2, "SEQ")
    assert error_of(fs.SEEK, 2, 1).code == "CPL613"
    fs.OPENW(3, "RND", 130, 5)
    fs.PRN(3, "A")
    assert error_of(fs.SEEK, 3, 3).code == "CPL608"
    assert error_of(fs.SEEK, 3, 1, 7).code == "CPL023"
    fs.SEEK(3, 1, 6)


def test_f16_seek_on_a_random_file_with_numeric_name(fs):
    # L4301-4303 with reclen 30 so the annotated records fit the page
    fs.OPENW(1, 27272, 200, "TEST", 30)
    fs.mode.LJUST()
    for i in range(1, 11):
        fs.PRN(1, i, ". Record")
    fs.SEEK(1, 3, 4)
    fs.PRN(1, "OVERWRITE THE 3RD RECORD FROM BYTE 4 WITH THIS TEXT")
    fs.SEEK(1, 11)
    fs.PRN(1, "11th record")
    fs.SEEK(1, 11, 5)
    fs.PRN(1, "@@")
    fs.SEEK(1, 0)
    fs.PRN(1, "e@")
    fs.SEEK(1, 0, 1)
    fs.PRN(1, "new <EOF>")
    fs.CLOSE(1)
    records = content(fs, "P27272").split("\n")
    assert records[0] == "1. Record".ljust(30)
    assert records[2] == "3. OVERWRITE THE 3RD RECORD FR"
    assert records[10] == "11th@@".ljust(30)
    assert records[11] == "e@".ljust(30) and records[12] == "new <EOF>".ljust(30)
    assert records[13:] == ["\x03", ""]


def test_f17_filesize_sequential(fs):
    # L4340-4355 (14-character record text, CPL manual L4340-4355; L4017)
    fs.OPENW(1, 2, 1000)
    for _ in range(20):
        fs.PRN(1, "TEST FILE SIZE")
    fs.CLOSE(1)
    fs.OPENR(2, 2)
    assert (fs.FILESIZE(2), fs.FILESIZE(2, 1), fs.FILESIZE(2, 2)) == (302, 302, 300)
    assert error_of(fs.FILESIZE, 2, 3).message.startswith("INVALID PARAMETER")
    fs.CLOSE(2)


def test_f18_filesize_random(fs):
    # L4357-4377
    fs.OPENW(1, "P2", 1000, 10)
    for _ in range(20):
        fs.PRN(1, "TEST FILESIZE")
    assert error_of(fs.FILESIZE, 1).code == "CPL613"  # only on files opened with OPENR (CPL manual L4309)
    fs.CLOSE(1)
    fs.OPENR(2, 2, 10)
    assert [fs.FILESIZE(2), fs.FILESIZE(2, 1), fs.FILESIZE(2, 2), fs.FILESIZE(2, 3), fs.FILESIZE(2, 4)] == \
        [222, 222, 220, 20, 20]
    fs.CLOSE(2)


def test_f19_erase(fs):
    # L4398-4405
    fs.OPENW(1, "P2", 200)
    fs.OPENW(2, "P3", 200)
    fs.PRN(1, "TEST1 FOR ERASE")
    fs.PRN(2, "TEST2 FOR ERASE")
    assert fs.ERASE("P2") == 3  # still open: active
    fs.CLOSE(1)
    fs.CLOSE(2)
    assert fs.ERASE("P2") == 0 and not (fs.root / "P2").exists()
    assert fs.ERASE(dim(5, "P3")) == 0
    assert fs.ERASE("P1") == 1
    (fs.root / "RO").write_text("x")
    os.chmod(fs.root / "RO", stat.S_IRUSR)
    assert fs.ERASE("RO") == 2
    assert [w.code for w in fs.warnings] == ["CPL621"] * 3
    assert error_of(fs.ERASE, "X" * 31).message.startswith("INVALID FILE NAME")


def test_f20_fileaccess_and_filedate(fs):
    # L4406-4457
    (fs.root / "usrfep").mkdir()
    (fs.root / "usrfep" / "test.cnc").write_text("x")
    os.chmod(fs.root / "usrfep" / "test.cnc", stat.S_IRUSR | stat.S_IWUSR)
    assert fs.FILEACCESS("/usrfep/test.cnc") == 6
    assert fs.FILEACCESS("/usrfep") & 8
    assert fs.FILEACCESS("/usrfep/none") == -1
    fs.OPENR(1, "/usrfep/test.cnc")
    assert fs.FILEACCESS("/usrfep/test.cnc") == 6 | 16
    fs.clock.now = 3 * 3600 + 25 * 60 + 7.0  # written 3 h 25 min 7 s after power-on
    fs.OPENW(2, "/usr/user/Test.txt")
    fs.PRN(2, "X")
    fs.CLOSE(2)
    # 1_700_000_000 is 14.11.2023 22:13:20 UTC; plus 3:25:07 gives 15.11.2023 01:38:27
    assert fs.FILEDATE("/usr/user/Test.txt", 1) == "15.11.23"
    assert fs.FILEDATE("/usr/user/Test.txt") == "15.11.23"
    assert fs.FILEDATE("/usr/user/Test.txt", 2) == "01.38.27"
    assert fs.FILEDATE("/usr/user/none.txt") == "" and fs.FILEDATE("../x") == ""


def test_prn0_goes_to_the_message_window_and_editor_block(fs):
    seen = []
    fs.message = seen.append
    fs.PRN(0, "A=", 1, semicolon=True)
    fs.PRN(0, " B=", 2.0)
    assert seen == ["A=        1 B=   2.000"]
    # editor dialog (L4503-4532, L4780-4786): the selected block is read and overwritten
    fs.editor_block = "N20 Q900[12.5,3]"
    wi, dp = fs.INP(0, "R", "R")
    assert (wi, dp) == (12.5, 3.0)
    fs.mode.LJUST()
    fs.PRN(0, "Q900[", wi, ",", math.floor(dp), "]")
    assert fs.editor_block == "Q900[12.500,3]"


def test_reopen_for_writing_appends_and_normalises_foreign_files(fs):
    (fs.root / "DOS").write_bytes(b"ONE\r\nTWO\r\n")
    fs.OPENW(1, "DOS")
    fs.PRN(1, "THREE")
    fs.CLOSE(1)
    assert content(fs, "DOS") == "ONE\nTWO\nTHREE\n" + ETX
    fs.OPENW(1, "DOS")
    fs.PRN(1, "FOUR")
    fs.CLOSE(1)
    assert content(fs, "DOS") == "ONE\nTWO\nTHREE\nFOUR\n" + ETX


def test_filepos_counts_a_record_open_with_semicolon(fs):
    fs.OPENW(1, "P1", 130.0)
    fs.PRN(1, "ABC")
    fs.PRN(1, "DE", semicolon=True)
    assert fs.FILEPOS(1) == 4 + 2 + 1
    fs.CLOSE(1)
    assert content(fs, "P1") == "ABC\nDE\n" + ETX


def test_inp_invalid_float_value(fs):
    (fs.root / "F").write_text("1" + "0" * 40 + "\n2.5\n\x03\n")
    fs.OPENR(1, "F")
    assert error_of(fs.INP, 1, "R").message.startswith("INVALID FLOAT VALUE")
    fs.CLOSE(1)
    fs.OPENR(1, "F")
    assert fs.INP(1, "D") == [1e40]  # a DOUBLE holds it
    assert fs.INP(1, "R") == [2.5]
