"""Manual chapter 6 (files) as CPL programs: each example of the manual run through the front end, with the
file contents the cpl_io tests state for the same example (tests/dialects/cpl/io/test_cpl_io_files.py)."""

from __future__ import annotations

from pathlib import Path

import pytest

ETX = "\x03\n"


@pytest.fixture
def cpl(run_text, tmp_path):
    """cpl(text) -> (result, files folder): runs on the default machine, whose files are under tmp_path."""
    root = tmp_path / ".ncvm" / "files"
    root.mkdir(parents=True, exist_ok=True)

    def _run(text: str, **opts):
        return run_text(text, name="prog.cpl", **opts), root

    return _run


def content(root: Path, name: str) -> str:
    return (root / name).read_bytes().decode("latin-1")


def ok(r):
    assert r["error"] is None, r["error"]
    return r


def test_f1_openw_forms(cpl):
    # L3925-3935
    r, root = cpl('10 OPENW(1,"P500",1024,"This is my best progam")\n'
                  '20 OPENW(9,"P501",1024,"This is my best program")\n'
                  '30 OPENW(7,"PData Meas.DAT",1024,"Store measurement data")\n'
                  '40 CLOSE(1) : CLOSE(9) : CLOSE(7)\nM30\n')
    ok(r)
    assert content(root, "P500") == ETX and content(root, "PData Meas.DAT") == ETX


def test_f2_random_file_records_padded(cpl):
    # L3937-3951
    r, root = cpl('10 OPENW(2,"P200",1024,10)\n20 FOR I%=1 TO 3\n30 PRN#(2,"TEST")\n40 NEXT\n50 CLOSE(2)\nM30\n')
    ok(r)
    assert content(root, "P200") == "TEST      \n" * 3 + ETX


def test_f3_openr_with_wrong_record_length(cpl):
    # L3953-3963
    r, _ = cpl('10 OPENW(2,"P200",130,"TEST",10) : PRN#(2,"ABC") : CLOSE(2)\n20 OPENR(1,"P200",5)\nM30\n')
    assert r["error"]["code"] == "CPL603"
    assert r["error"]["message"].startswith("INVALID COMPONENT LENGTH")
    assert r["error"]["line"] == 2


def test_f4_copy_nc_program_into_random_file(cpl):
    # L3965-3993
    _, root = cpl("M30\n")
    (root / "P1").write_text('N10 G1F10000X1000Y1000Z1000\n1 A$="01234567890123456789"\n2 B$="TEST"\nN20 X0\nM30\n')
    r, root = cpl('10 DIM A$(30)\n20 OPENW(1,"PMeas_PRG",500,"RANDOM FILE",10)\n30 OPENR(2,"P1")\n'
                  '40 FOR I%=1 TO 5\n50 INP#(2,A$) : PRN#(1,A$)\n60 NEXT\n70 CLOSE(2) : CLOSE(1)\nM30\n')
    ok(r)
    assert content(root, "PMeas_PRG") == 'N10 G1F100\n1 A$="0123\n2 B$="TEST\nN20 X0    \nM30       \n' + ETX


def test_f5_overwrite_with_semicolon_keeps_the_tail(cpl):
    # L4043-4049
    r, root = cpl('10 OPENW(2,"PProg123.PRG",200,35)\n'
                  '20 PRN#(2,"TEST1 FOR PRN COMMAND WITH SEMICOLON")\n'
                  '30 PRN#(2,"TEST2 FOR PRN COMMAND WITH SEMICOLON")\n'
                  '40 PRN#(2,"TEST3 FOR PRN COMMAND WITH SEMICOLON")\n'
                  '50 SEEK(2,1) : PRN#(2,"OVERWRITE";) : CLOSE(2)\nM30\n')
    ok(r)
    assert content(root, "PProg123.PRG") == ("OVERWRITE PRN COMMAND WITH SEMICOLO\n"
                                             "TEST2 FOR PRN COMMAND WITH SEMICOLO\n"
                                             "TEST3 FOR PRN COMMAND WITH SEMICOLO\n" + ETX)


def test_f6_overwrite_without_semicolon_blanks_the_tail(cpl):
    # L4051-4061
    r, root = cpl('10 OPENW(2,"P2",1000,36) : REWRITE(2)\n'
                  '20 FOR I%=1 TO 3 : PRN#(2,"TEST",I%," FOR PRN COMMAND W/O SEMICOLON") : NEXT\n'
                  '30 SEEK(2,1) : PRN#(2,"OVERWRITE") : CLOSE(2)\nM30\n'.replace('"TEST",I%', '"TEST#",I%'))
    ok(r)
    lines = content(root, "P2").split("\n")
    assert lines[0] == "OVERWRITE" + " " * 27
    assert lines[1] == "TEST2 FOR PRN COMMAND W/O SEMICOLON "


def test_f7_semicolon_chaining_and_close_ends_the_record(cpl):
    # L4063-4078
    r, root = cpl('10 OPENW(1,"P2",300,"TEST PRN COMMAND")\n20 A$="TEST" : B$="FOR" : C$="PRN COMMAND"\n'
                  '30 PRN#(1,A$) : PRN#(1,B$) : PRN#(1,C$)\n40 PRN#(1,A$;) : PRN#(1,B$;) : PRN#(1,C$;)\n'
                  '50 CLOSE(1)\nM30\n')
    ok(r)
    assert content(root, "P2") == "TEST\nFOR\nPRN COMMAND\nTESTFORPRN COMMAND\n" + ETX


def test_f8_templates_over_several_arguments(cpl):
    # L4080-4097
    r, root = cpl('10 DIM E$(50) : E$="CDEFGHI" : A%=5000 : B=1.231 : C!=4/3\n'
                  '20 OPENW(1,"P2",300,"TEST2")\n30 PRN#(1,"10";)\n'
                  '40 PRN#(1,"######","###.####","#.######",A%,B,C!,"ABCDE",E$)\n50 CLOSE(1)\nM30\n')
    ok(r)
    assert content(root, "P2") == "10  5000  1.23101.333333ABCDECDEFGHI\n" + ETX


def test_s13_chained_strings_and_s8_trim_in_prn(cpl):
    # L3775-3779 and L3587-3594
    r, root = cpl('10 DIM A$(3) : DIM B$(3) : A$="ABC" : B$="DEF" : C$="GH" : D$="JKL" : T$=" ABCDEF "\n'
                  '20 OPENW(1,"P2",130,"CHAINING TEST",10)\n'
                  '30 PRN#(1,A$+B$) : PRN#(1,A$+C$) : PRN#(1,C$+D$) : PRN#(1,A$+C$+"TEST") : PRN#(1,"UVW"+"XYZ")\n'
                  '40 CLOSE(1)\n50 OPENW(2,"P1")\n'
                  '60 PRN#(2,">",T$,"<") : PRN#(2,">",TRIM$(T$,"L"),"<") : PRN#(2,">",TRIM$(T$,"R"),"<")\n'
                  '70 PRN#(2,">",TRIM$(T$),"<") : CLOSE(2)\nM30\n')
    ok(r)
    assert content(root, "P2") == "ABCDEF    \nABCGH     \nGHJKL     \nABCGHTEST \nUVWXYZ    \n" + ETX
    assert content(root, "P1") == "> ABCDEF <\n>ABCDEF <\n> ABCDEF<\n>ABCDEF<\n" + ETX


def test_format_overflow_warns_and_ljust_writes_nc_blocks(cpl):
    # L4035 (PRN FORMAT INCORRECT), L3999-4003 (LJUST for NC programs)
    r, root = cpl('10 OPENW(1,"P1") : PRN#(1,"X=##",123)\n20 LJUST\n'
                  '30 PRN#(1,"N10 X",1.5," Y",20," Z","###.###",-3.25)\n40 NJUST\n50 PRN#(1,"N20 X",1.5)\n'
                  '60 CLOSE(1)\nM30\n')
    ok(r)
    # L4001: trailing zeros of the standard format suppressed (blanks where the field is formatted); the
    # template ###.### keeps its decimals
    assert content(root, "P1") == "X=**\nN10 X1.5 Y20 Z-3.250\nN20 X   1.5  \n" + ETX
    assert r["output"] == ["warning CPL620: PRN FORMAT INCORRECT: X=**"]


def test_f9_inp_nul_without_moving_and_string_takes_its_dim(cpl):
    # L4132-4140
    _, root = cpl("M30\n")
    (root / "P2").write_text("ABC123456789ABC\n\x03\n", encoding="latin-1")
    r, _ = cpl('10 DIM C$(3) : DIM D$(3)\n20 OPENR(2,"P2")\n30 INP#(2,A%,B,E?,C$,F%,D$)\n40 CLOSE(2)\nM30\n')
    ok(r)
    v = r["variables"]
    assert "A%" not in v and "B" not in v and "E?" not in v
    assert v["C$"] == "ABC" and v["F%"] == 123456789 and v["D$"] == "ABC"


def test_f10_inp_with_semicolon_inside_a_record(cpl):
    # L4142-4156
    r, _ = cpl('10 DIM A$(3) : DIM C$(5) : DIM D$(4) : DIM E$(4) : DIM G$(25) : DIM H$(7) : DIM I$(7)\n'
               '15 DIM J$(25)\n'
               '20 OPENW(1,"P2",200,"TEST",22)\n30 FOR K%=1 TO 3 : PRN#(1,"-12TEST1.23V12ABCD2.4A") : NEXT\n'
               '40 CLOSE(1)\n50 OPENR(2,"P2",22)\n60 INP#(2,B%,D$,R11,MID$(E$,1,1),R12,A$,C$)\n'
               '70 INP#(2,G$) : INP#(2,H$;) : INP#(2,I$;) : INP#(2,J$)\n80 E? = EOF(2) : CLOSE(2)\nM30\n')
    ok(r)
    v = r["variables"]
    assert v["B%"] == -12 and v["D$"] == "TEST" and v["R11"] == pytest.approx(1.23) and v["E$"] == "V"
    assert v["R12"] == 12.0 and v["A$"] == "ABC" and v["C$"] == "D2.4A"
    assert v["G$"] == "-12TEST1.23V12ABCD2.4A"
    assert (v["H$"], v["I$"], v["J$"]) == ("-12TEST", "1.23V12", "ABCD2.4A")
    assert v["E?"] is True


def test_f11_eof_loop_counts_records(cpl):
    # L4165-4169
    _, root = cpl("M30\n")
    (root / "P").write_text("A\nBB\nCCC\n\x03\n", encoding="latin-1")
    r, _ = cpl('9 DIM A$(10)\n10 OPENR(1,"P") : I%=0\n11 WHILE NOT (EOF(1)) DO\n12 INP#(1,A$)\n13 I%=I%+1\n14 END\n'
               '15 CLOSE(1)\nM30\n')
    assert ok(r)["variables"]["I%"] == 3


def test_f12_close_example_positions_round_trip(cpl):
    # L4183-4195
    r, _ = cpl('10 XPOS=12.5 : YPOS=-3.0\n20 OPENW(1,"P5",500,"AXISPOS") : REWRITE(1)\n'
               '30 PRN#(1,"X AXIS",XPOS,"Y AXIS",YPOS) : CLOSE(1)\n40 DIM A$(35) : OPENR(1,"P5") : INP#(1,A$)\n'
               '50 CLOSE(1)\nM30\n')
    assert ok(r)["variables"]["A$"] == "X AXIS  12.5  Y AXIS  -3    "  # L4001: trailing zeros suppressed


def test_f13_filepos_sequential(cpl):
    # L4241-4258
    r, _ = cpl('10 OPENW(1,"P2",200,"TEST")\n20 FOR I%=1 TO 10 : PRN#(1,"TEST FOR FILEPOS") : NEXT\n'
               '30 CLOSE(1) : OPENR(1,"P2")\n40 SEEK(1,3) : A%=FILEPOS(1) : B%=FILEPOS(1,1)\n'
               '50 SEEK(1,0) : C%=FILEPOS(1) : D%=FILEPOS(1,1)\nM30\n')
    v = ok(r)["variables"]
    assert (v["A%"], v["B%"], v["C%"], v["D%"]) == (3, 3, 171, 171)
    r, _ = cpl('10 OPENR(1,"P2")\n20 E%=FILEPOS(1,2)\nM30\n')
    assert r["error"]["code"] == "CPL023" and r["error"]["line"] == 2
    assert r["error"]["message"].startswith("INVALID PARAMETER")


def test_f14_filepos_random(cpl):
    # L4260-4262 with reclen 127
    r, root = cpl('10 OPENW(1,"P2",200,"TEST",127)\n20 FOR I%=1 TO 10 : PRN#(1,"TEST FOR FILEPOS") : NEXT\n'
                  '30 SEEK(1,3,2) : A%=FILEPOS(1) : B%=FILEPOS(1,1) : C%=FILEPOS(1,2) : D%=FILEPOS(1,3)\n'
                  '40 PRN#(1,"OVERWRITING OF 3RD RECORD FROM BYTE 2 WITH THIS TEXT")\n'
                  '50 SEEK(1,0) : E%=FILEPOS(1) : F%=FILEPOS(1,1) : G%=FILEPOS(1,2) : H%=FILEPOS(1,3)\n'
                  '60 CLOSE(1)\nM30\n')
    v = ok(r)["variables"]
    assert [v[k] for k in ("A%", "B%", "C%", "D%")] == [3, 258, 3, 2]
    assert [v[k] for k in ("E%", "F%", "G%", "H%")] == [11, 1281, 11, 1]
    records = content(root, "P2").split("\n")
    assert records[2] == "TOVERWRITING OF 3RD RECORD FROM BYTE 2 WITH THIS TEXT".ljust(127)


def test_f15_seek_sequential_byte_by_byte(cpl):
    # L4288-4299
    r, _ = cpl('1 DIM A$(1):LJUST:OPENW(1,"P271",130,"TEST"):FOR I%=1 TO 10\n'
               '2 PRN#(1,"!/-!/-!/-!/-!/-!/-!/-!/-"):NEXT:CLOSE(1)\n'
               '3 OPENR(2,"P271") : N%=FILESIZE(2,2)\n'
               '4 FOR I%=1 TO N%-28\n'
               '5 IF NOT EOF(2) THEN SEEK(2,I%) : INP#(2,A$) ENDIF\n'
               '6 IF EOF(2) THEN PRN#(0,"###",I%,". BYTE: <EOF>") ELSE PRN#(0,"###",I%,". BYTE: <",A$,">") ENDIF\n'
               '7 NEXT : CLOSE(2)\nM30\n')
    out = ok(r)["output"]
    assert r["variables"]["N%"] == 250
    assert out[:4] == ["1. BYTE: <!>", "2. BYTE: </>", "3. BYTE: <->", "4. BYTE: <!>"]
    assert out[24] == "25. BYTE: <>"
    assert len(out) == 222


def test_f16_seek_on_a_random_file_with_numeric_name(cpl):
    # L4301-4303 with reclen 30
    r, root = cpl('1 OPENW(1,27272,200,"TEST",30):LJUST 2 FOR I%= 1 TO 10 3 PRN#(1,I%,". Record") 4 NEXT\n'
                  .replace(" 2 FOR", "\n2 FOR").replace(" 3 PRN", "\n3 PRN").replace(" 4 NEXT", "\n4 NEXT") +
                  '5 SEEK(1,3,4) : PRN#(1,"OVERWRITE THE 3RD RECORD FROM BYTE 4 WITH THIS TEXT")\n'
                  '7 SEEK(1,11):PRN#(1,"11th record")\n8 SEEK(1,11,5):PRN#(1,"@@")\n9 SEEK(1,0):PRN#(1,"e@")\n'
                  '10 SEEK(1,0,1):PRN#(1,"new <EOF>")\n11 CLOSE(1)\nM30\n')
    ok(r)
    records = content(root, "P27272").split("\n")
    assert records[0] == "1. Record".ljust(30)
    assert records[2] == "3. OVERWRITE THE 3RD RECORD FR"
    assert records[10] == "11th@@".ljust(30)
    assert records[11] == "e@".ljust(30) and records[12] == "new <EOF>".ljust(30)


def test_f17_f18_filesize(cpl):
    # L4340-4377
    r, _ = cpl('10 OPENW(1,2,1000)\n20 FOR I%=1 TO 20 : PRN#(1,"TEST FILE SIZE") : NEXT\n30 CLOSE(1)\n'
               '40 OPENR(2,2) : A%=FILESIZE(2) : B%=FILESIZE(2,1) : C%=FILESIZE(2,2) : CLOSE(2)\n'
               '50 ERASE("P2")\n60 OPENW(1,"P2",1000,10)\n70 FOR I%=1 TO 20 : PRN#(1,"TEST FILESIZE") : NEXT\n'
               '80 CLOSE(1) : OPENR(2,2,10)\n'
               '90 D%=FILESIZE(2) : E%=FILESIZE(2,1) : F%=FILESIZE(2,2) : G%=FILESIZE(2,3) : H%=FILESIZE(2,4)\n'
               '100 CLOSE(2)\nM30\n')
    v = ok(r)["variables"]
    assert (v["A%"], v["B%"], v["C%"]) == (302, 302, 300)
    assert [v[k] for k in ("D%", "E%", "F%", "G%", "H%")] == [222, 222, 220, 20, 20]


def test_f19_erase(cpl):
    # L4398-4405: an open file is active (3), then erased (0); a missing one gives 1 and a warning
    r, root = cpl('10 OPENW(1,"P2",200) : OPENW(2,"P3",200)\n20 PRN#(1,"TEST1 FOR ERASE") : PRN#(2,"TEST2 FOR ERASE")\n'
                  '30 A%=ERASE("P2")\n40 CLOSE(1) : CLOSE(2)\n50 B%=ERASE("P2")\n60 DIM N$(5) : N$="P3" : ERASE(N$)\n'
                  '70 C%=ERASE("P1")\nM30\n')
    v = ok(r)["variables"]
    assert (v["A%"], v["B%"], v["C%"]) == (3, 0, 1)
    assert not (root / "P2").exists() and not (root / "P3").exists()
    assert [line.split(":")[0] for line in r["output"]] == ["warning CPL621", "warning CPL621"]


def test_f20_fileaccess_and_filedate(cpl):
    # L4406-4457
    _, root = cpl("M30\n")
    (root / "usrfep").mkdir()
    (root / "usrfep" / "test.cnc").write_text("x")
    r, _ = cpl('10 A%=FILEACCESS("/usrfep/test.cnc") : B%=FILEACCESS("/usrfep/none")\n'
               '20 OPENR(1,"/usrfep/test.cnc") : C%=FILEACCESS("/usrfep/test.cnc") : CLOSE(1)\n'
               '30 OPENW(2,"/usr/user/Test.txt") : PRN#(2,"X") : CLOSE(2)\n'
               '40 DIM D$(8) : D$=FILEDATE("/usr/user/Test.txt",1) : E$=FILEDATE("/usr/user/none.txt")\nM30\n')
    v = ok(r)["variables"]
    assert v["A%"] & 6 == 6 and v["B%"] == -1 and v["C%"] & 16
    assert len(v["D$"]) == 8 and v["D$"][2] == "." and v["D$"][5] == "."
    assert v["E$"] == ""


def test_prn_file_output_survives_a_fault_afterwards(cpl):
    # what PRN# wrote is in the file even when the program stops with a run-time error later
    r, root = cpl('10 OPENW(1,"PLOG",500)\n20 FOR I%=1 TO 3 : PRN#(1,"MEASURE ",I%) : NEXT\n'
                  '30 X = 1 / 0.0\n40 CLOSE(1)\nM30\n')
    assert r["error"]["code"] == "CPL028" and r["error"]["line"] == 3
    assert content(root, "PLOG") == "".join(f"MEASURE         {i}\n" for i in (1, 2, 3)) + ETX


def test_io_fault_names_line_cpl_line_and_message(cpl):
    r, _ = cpl('10 OPENR(1,"MISSING")\nM30\n')
    assert r["error"]["code"] == "CPL612"
    assert r["error"]["message"] == "FILE DOES NOT EXIST: MISSING (CPL line 10)"
    assert r["error"]["line"] == 1


def test_io_fault_in_a_sub_program_names_it_and_the_call_stack(tmp_path, run_text):
    (tmp_path / "READLOG.cpl").write_text('10 OPENR(3,"PNONE")\nM30\n')
    r = run_text('10 A%=1\n20 CALL READLOG\nM30\n', name="main.cpl")
    err = r["error"]
    assert err["code"] == "CPL612" and err["file"].endswith("READLOG.cpl") and err["line"] == 1
    assert err["message"] == "FILE DOES NOT EXIST: PNONE (CPL line 10)"
    assert any("main.cpl:2" in note for note in err["stack"])


@pytest.mark.parametrize("stmt", ["INP#(1)", "INP#(1;)"])
def test_inp_without_a_variable_is_a_syntax_error_l4107(cpl, stmt):
    """INP#(n,v1[,v2...]) (L4107-4130) reads into at least one variable."""
    r, _ = cpl(f'10 OPENR(1,"P1")\n20 {stmt}\nM30\n')
    assert r["error"]["code"] == "CPL001" and "at least one variable" in r["error"]["message"]


def test_running_programs_are_active_for_erase_and_fileaccess_l4396(tmp_path):
    """ERASE answers 3 "active" (L4390-4396) and FILEACCESS sets bit 16 (L4418-4425) for a program that is running
    or called, here the main program and its sub-program, kept in the file root; neither is erased."""
    from ncvm.api import run
    from ncvm.runtime.session import RunOptions

    root = tmp_path / ".ncvm" / "files"
    root.mkdir(parents=True)
    (root / "SELF.cpl").write_text('10 A%=FILEACCESS("SELF.cpl")\n20 E%=ERASE("SELF.cpl")\n30 CALL SUBP\nM30\n')
    (root / "SUBP.cpl").write_text('10 F%=ERASE("SUBP.cpl")\nM30\n')
    (root / "OTHER.cpl").write_text("M30\n")
    r, _ = run(root / "SELF.cpl", options=RunOptions(state_dir=tmp_path / ".ncvm"))
    assert r["error"] is None
    assert (r["variables"]["A%"], r["variables"]["E%"]) == (16 + 4 + 2, 3)
    assert r["output"] == ["warning CPL621: FILE NOT ERASED: SELF.cpl is active",
                           "warning CPL621: FILE NOT ERASED: SUBP.cpl is active"]
    assert (root / "SELF.cpl").exists() and (root / "SUBP.cpl").exists()
    r, _ = run(root / "SELF.cpl", options=RunOptions(state_dir=tmp_path / ".ncvm"))
    assert r["variables"]["A%"] == 22  # after the run SUBP is no longer active: a program erasing it may
    (root / "Q.cpl").write_text('10 G%=ERASE("SUBP.cpl")\nM30\n')
    r, _ = run(root / "Q.cpl", options=RunOptions(state_dir=tmp_path / ".ncvm"))
    assert r["variables"]["G%"] == 0 and not (root / "SUBP.cpl").exists()


def test_names_without_a_path_are_in_the_main_programs_directory(tmp_path):
    """L4414, L4441, CPL manual L4381: a name without a path means the current directory, the one of the main
    program when it lies in the file root; a name with a path starts at the root."""
    from ncvm.api import run
    from ncvm.runtime.session import RunOptions

    root = tmp_path / ".ncvm" / "files"
    (root / "usr" / "user").mkdir(parents=True)
    main = root / "usr" / "user" / "MAIN.cpl"
    main.write_text('10 OPENW(1,"LOG1")\n20 PRN#(1,"HELLO")\n30 CLOSE(1)\n40 A%=FILEACCESS("LOG1")\n'
                    '50 B%=FILEACCESS("/usr/user/LOG1")\n60 C%=FILEACCESS("/LOG1")\n70 OPENW(2,"/TOP")\n'
                    '80 CLOSE(2)\nM30\n')
    r, _ = run(main, options=RunOptions(state_dir=tmp_path / ".ncvm"))
    assert r["error"] is None
    assert (r["variables"]["A%"], r["variables"]["B%"], r["variables"]["C%"]) == (6, 6, -1)
    assert content(root / "usr" / "user", "LOG1") == "HELLO\n" + ETX and (root / "TOP").exists()


@pytest.mark.parametrize("name, code", [("../../LOG2", None), ("../../../ESCAPE", "CPL609"),
                                        ("C:\\usr\\LOG3", None), ("/../ESCAPE", "CPL609")])
def test_names_never_leave_the_file_root_from_a_sub_directory(tmp_path, name, code):
    """A name may climb from the current directory (/usr/user) up to the root, never above it: INVALID FILE
    NAME, and nothing is written outside."""
    from ncvm.api import run
    from ncvm.runtime.session import RunOptions

    root = tmp_path / ".ncvm" / "files"
    (root / "usr" / "user").mkdir(parents=True)
    main = root / "usr" / "user" / "MAIN.cpl"
    main.write_text(f'10 OPENW(1,"{name}")\n20 PRN#(1,"X")\n30 CLOSE(1)\nM30\n')
    r, _ = run(main, options=RunOptions(state_dir=tmp_path / ".ncvm"))
    assert (r["error"]["code"] if r["error"] else None) == code
    assert not (tmp_path / ".ncvm" / "ESCAPE").exists() and not (tmp_path / "ESCAPE").exists()
    if code is None:
        assert any(p.name in ("LOG2", "LOG3") for p in root.rglob("*"))


def test_file_output_suppresses_trailing_zeros_l4001(cpl, reference, tmp_path):
    """L4001: for file output "Leading and trailing zeros are suppressed. This also applies to left-justified
    output": REAL 12.5 is written 12.5, 3.0 as 3, DOUBLE 0.25 as 0.25; formatted output keeps the field's
    width (the point stays in its column), STR$ keeps its fixed decimals (L3531-3538), and a template the
    same. ``[cpl] file_zeros = "keep"`` writes the fixed decimals of STR$ and DSP."""
    text = ('10 OPENW(1,"P1") : D! = 0.25 : R = 3.0 : DIM A$(10) : A$ = STR$(2.5)\n20 PRN#(1,"[",12.5,"][",R,"][",D!,"]")\n'
            '30 LJUST : PRN#(1,"X",12.5," Y",R," Z",-0.5," U",D!," V","##.##",1.5," ",A$," ",100)\n'
            '40 CLOSE(1)\nM30\n')
    r, root = cpl(text)
    ok(r)
    assert content(root, "P1") == ("[  12.5  ][   3    ][        0.25    ]\nX12.5 Y3 Z-0.5 U0.25 V1.50    2.500 100\n"
                                   + ETX)
    r, _ = cpl(text, machine=reference(cpl={"file_zeros": "keep"}))
    ok(r)
    assert content(tmp_path / "files", "P1").splitlines()[1] == "X12.500 Y3.000 Z-0.500 U0.250000 V1.50    2.500 100"
