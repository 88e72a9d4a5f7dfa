"""Chapter 7 dialog on the virtual screen: DSP, DLG/PRN/INP, INKEY, SFK, CSF, TFO, the key script."""

from __future__ import annotations

import math

import pytest

from ncvm.dialects.cpl.io.errors import CplRuntimeError
from ncvm.dialects.cpl.io.screen import KeyScript, Screen


def error_of(fn, *args, **kw):
    with pytest.raises(CplRuntimeError) as err:
        fn(*args, **kw)
    return err.value


def test_d1_dsp_root_table():
    # L4565-4577
    s = Screen()
    lin, col = 4, 1
    for i in range(1, 11):
        s.DSP(lin + i, col, "###.### IS ROOT OF ##", math.sqrt(i), i)
    lines = s.grid_lines()
    assert lines[4] == "  1.000 IS ROOT OF  1"
    assert lines[6] == "  1.732 IS ROOT OF  3"
    assert lines[13] == "  3.162 IS ROOT OF 10"
    assert s.output_lines()[0] == "  1.000 IS ROOT OF  1"


def test_d2_default_formats_and_template_queue():
    # L4579-4601
    s = Screen()
    a = 25.0
    b = math.sqrt(a)
    s.DSP(5, 10, "A=", a, " B=", b, " C= ", a + b)
    s.DSP(6, 10, " A= ###.#", " B= #.#", " C= ##", a, b, b + a)
    assert s.grid_lines()[4] == " " * 9 + "A=  25.000 B=   5.000 C=   30.000"
    assert s.grid_lines()[5] == " " * 9 + " A=  25.0 B= 5.0 C= 30"


def test_d3_booleans_and_strings_in_a_template_line():
    # L4603-4612 repaired (CPL manual L4603-4612)
    s = Screen()
    s.DSP(5, 1, "XPOS ###.### YPOS ###.###", " MEAS.PROBE=", True, 1.5, 2.5, " NO.=", 200)
    assert s.grid_lines()[4] == "XPOS   1.500 YPOS   2.500 MEAS.PROBE=TRUE NO.=      200"


def test_dsp_errors_and_cut_at_the_right_edge():
    s = Screen()
    assert error_of(s.DSP, 0, 1, "X").message.startswith("Invalid line or column number in CPL command")
    assert error_of(s.DSP, 47, 1, "X").code == "CPL701"
    assert error_of(s.DSP, 1, 80, "X").code == "CPL701"
    assert error_of(s.DSP, 1, 1, "X" * 78).message.startswith("maximum string length exceeded")
    assert error_of(s.DSP, 1, 1, "##", 123).message.startswith("format not permitted")
    s.DSP(1.6, 75.4, "ABCDEFGH")  # REAL positions are rounded: line 2, column 75
    assert s.grid_lines()[1] == " " * 74 + "ABCDE"


def test_inkey_example_with_key_script():
    # L4625-4650: poll INKEY until Enter, show every new key number
    s = Screen(KeyScript("IDLE 3\nKEY 65\nIDLE 2\nTYPE BC\nENTER\n"))
    s.CLS()
    s.DSP(10, 10, "Press any key! ABORT WITH ENTER")
    new = old = 0
    shown = []
    polls = 0
    while new != 13:
        new = s.INKEY()
        polls += 1
        if old != new and new > 0:
            s.DSP(12, 10, "KEY NUMBER:###", new)
            shown.append(new)
            old = new
    s.CLG()
    assert shown == [65, 66, 67, 13] and polls == 9
    assert s.INKEY() == 0  # nothing left, never blocks
    assert "KEY NUMBER: 13" in s.output_lines()


def test_inkey_only_in_the_foreground():
    s = Screen(KeyScript("SK1"))
    s.CLG()
    assert s.INKEY() == 0
    s.DLF()
    assert s.INKEY() == 141


def test_untpr_softkey_emulation_codes():
    # L4660-4750: softkeys 1..8 are 141..148, LEVEL RETURN is 139
    s = Screen(KeyScript("SK3\nSK8\nLEVEL RETURN"))
    assert [s.INKEY(), s.INKEY(), s.INKEY()] == [143, 148, 139]


def test_d6_sfk_loop():
    # L4822-4831: SFK(KEY%,,"ABORT",,"ACTION",,,,)
    s = Screen(KeyScript("ENTER\nSK4\nLEVEL RETURN\nSK2"))
    texts = (None, "ABORT", None, "ACTION", None, None, None, None)
    key = s.SFK(0, *texts)
    assert key == 4 and s.softkeys[1] == "ABORT"
    assert s.SFK(key, *texts) == 4  # LEVEL RETURN leaves the variable as it was
    assert s.SFK(0, *texts, want_text=True) == "ABORT"
    assert error_of(s.SFK, 0, *texts).code == "CPL705"  # the script is used up
    assert "SFK [2:ABORT] [4:ACTION]" in s.output_lines()
    s.CSF()
    assert s.softkeys is None


def test_softkey_text_lines():
    assert Screen.softkey_lines("TOOL&CHANGE&NOW&X") == ["TOOL", "CHANGE", "NOW"]
    assert Screen.softkey_lines("ABCDEFGHIJK") == ["ABCDEFGHI"]
    s = Screen(KeyScript("SK5\nSK6\nSK1"), typ2=True)
    assert s.SFK(0, "A", "B", "C", "D", "E", "F") == 5
    assert len(s.softkeys) == 5
    # SK6 does not exist in (TYP2) mode and is ignored; SK1 is taken
    assert s.SFK(0, "A") == 1


def test_d4_dialog_input_and_editor_block():
    # L4780-4786: DLG, PRN with formats, INP(WI):INP(DP), ENDDLG, PRN#(0,"Q900[",WI,",",DP,"]")
    from ncvm.dialects.cpl.io.files import CplFiles

    s = Screen(KeyScript("TYPE 12.5\nDEL\nTYPE 3.25\n"))
    wi = dp = None
    s.DLG()
    s.PRN(8, 4, "MAX.CUTTING WIDTH: ###.### MM", wi, name="WI")
    s.PRN(10, 4, "MAX. CUTTING DEPTH: ###.### MM", dp, name="DP")
    assert s.grid_lines()[7] == "   MAX.CUTTING WIDTH: ###.### MM"
    wi = s.INP("WI", wi)
    dp = s.INP("DP", dp)
    s.ENDDLG()
    assert (wi, dp) == (12.5, 3.25)
    assert s.grid_lines()[7] == "   MAX.CUTTING WIDTH:  12.500 MM"
    assert s.grid_lines()[9] == "   MAX. CUTTING DEPTH:   3.250 MM"
    fs = CplFiles(root=".", editor_block="Q900[1,2]")
    fs.PRN(0, "Q900[", wi, ",", dp, "]")
    assert fs.editor_block == "Q900[  12.500,   3.250]"


def test_inp_rules():
    s = Screen(KeyScript("UP\nENTER\nTYPE 1234.5\nTYPE 1.2345\nTYPE 12\n"))
    assert error_of(s.INP, "X", 1.0).message.startswith("INP without a PRN")
    s.DLG()
    s.PRN(1, 1, "X=###.#", 7.0, name="X")
    s.PRN(2, 1, "N=##", 7, name="N")
    s.PRN(3, 1, "TEXT", "ABC", name="T$")
    assert s.INP("X", 7.0) == 7.0  # cursor key: skipped
    assert s.INP("X", 7.0) == 7.0  # ENTER: kept
    assert error_of(s.INP, "X", 7.0).code == "CPL706"  # 1234.5 does not fit ###.#
    assert error_of(s.INP, "X", 7.0).code == "CPL706"  # too many decimals
    assert s.INP("T$", "ABC", kind="S") == "ABC"  # INP on a string is ignored
    assert s.INP("N", 7, kind="I") == 12


def test_key_script_format():
    ks = KeyScript("# comment\n\nsk1\nKEY 27\nLevel Return\nESC\nTYPE a b\nIDLE 1\nLEFT\n")
    assert [ks.inkey() for _ in range(9)] == [141, 27, 139, 27, 97, 32, 98, 0, 138]
    assert ks.inkey() == 0
    for bad in ("SK9", "KEY 256", "IDLE x", "HELLO"):
        assert error_of(KeyScript, bad).code == "CPL706"


def test_tfo_values_and_reset():
    s = Screen()
    s.TFO(None, None, 3)
    assert s.font == (0, 0, 3, 0)
    s.TFO(4, 20 + 1000 * 12, 1, 90)
    assert s.font == (4, 12020, 1, 90)
    for bad in ((11,), (0, 501), (0, 0, 4), (0, 0, 0, 361)):
        assert error_of(s.TFO, *bad).code == "CPL023"
    s.end_program()
    assert s.font == (0, 0, 0, 0)


def test_prn0_messages_join_the_output(tmp_path):
    from ncvm.dialects.cpl.io.files import CplFiles

    s = Screen()
    fs = CplFiles(root=tmp_path, message=s.message, mode=s.mode)
    s.DSP(1, 1, "FIRST")
    fs.PRN(0, "MESSAGE ", 3)
    assert s.output_lines() == ["FIRST", "MESSAGE         3"]


def test_inkey_animation_examples_run_until_key_b():
    # L4752-4762: REPEAT KEY%=INKEY : LIN(250,10,M,M) : M=M+1 UNTIL (KEY%=66) OR (M>300) : CLG
    s = Screen(KeyScript("IDLE 20\nKEY 66\n"))
    m = 10
    while True:
        key = s.INKEY()
        s.LIN(250, 10, m, m)
        m += 1
        if key == 66 or m > 300:
            break
    assert m == 31  # 20 polls without a key, then 'B' on the 21st
    assert tuple(s.canvas[374 - 30, 30]) == s.rgb(1)  # the last line ended at (30, 30)
    s.CLG()
    # WHILE ((INKEY<>66) AND (M<150)) DO CIR(250,160,M) : M=M+1 END, without keys: runs to M = 150
    s = Screen()
    m = 2
    while s.INKEY() != 66 and m < 150:
        s.CIR(250, 160, m)
        m += 1
    assert m == 150 and tuple(s.canvas[374 - 160, 250 + 149]) == s.rgb(1)


def test_text_view_shows_lines_softkeys_and_the_field_being_edited():
    seen = []

    class Watch(KeyScript):
        def wait(self, what):
            seen.append((what, s.text_view()))
            return super().wait(what)

    s = Screen(Watch("TYPE 2\nSK2\n"))
    s.DSP(2, 4, "TITLE")
    s.DLG()
    s.PRN(5, 1, "N=##", 1, name="N%")
    s.INP("N%", 1, kind="I")
    s.SFK(0, "ONE", "TWO&KEYS")
    assert seen == [
        ("INP(N%)", [" 2|   TITLE", " 5|N= 1", "input N% (line 5, column 1): N=##"]),
        ("SFK", [" 2|   TITLE", " 5|N= 2", "softkeys: [SK1 ONE] [SK2 TWO KEYS]"]),
    ]
    assert s.editing is None and s.text_view()[-1] == "softkeys: [SK1 ONE] [SK2 TWO KEYS]"


def test_the_picture_taken_at_an_inp_frames_the_field_being_edited():
    """L4764-4776: the operator types into the field of the INP; the screen picture shows which one."""
    s = Screen(keys=KeyScript("TYPE 12.5\nTYPE 3\n"))
    s.DLG()
    s.PRN(5, 4, "WIDTH: ###.### MM", None, name="WI")
    s.PRN(6, 4, "DEPTH: ##.# MM", None, name="DP")
    pictures = []
    s.on_wait = lambda: pictures.append(s.image(scale=1))
    assert s.INP("WI", None, "R") == 12.5 and s.INP("DP", None, "R") == 3.0
    s.ENDDLG()
    green = s.rgb(s.text_color)
    # the format ###.### of line 5 starts at column 4 + 7 = 11 (x 80..135), ##.# of line 6 at x 80..111;
    # the frame's top edge is the first pixel row of the line (y 36 for line 5, 45 for line 6) at x 100
    first, second = pictures
    assert first.getpixel((100, 36)) == green and first.getpixel((100, 45)) != green
    assert second.getpixel((100, 45)) == green and second.getpixel((100, 36)) != green
    assert s.image(scale=1).getpixel((100, 45)) != green  # no field waits any more
