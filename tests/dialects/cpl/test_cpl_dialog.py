"""Manual chapters 7-9 (dialog, graphics, MMC) as CPL programs run through the front end, with key scripts;
the expected values are the ones the cpl_io tests state for the same manual examples."""

from __future__ import annotations

from pathlib import Path

import pytest
from click.testing import CliRunner

from ncvm.api import run
from ncvm.cli import cli
from ncvm.dialects.cpl.io.graphics import GRAPH_TOP
from ncvm.runtime.session import RunOptions

BLACK, WHITE = (0, 0, 0), (255, 255, 255)


def run_cpl(tmp_path: Path, text: str, keys: str | None = None, **opts):
    """(result, session) of a CPL program with an optional key script."""
    prog = tmp_path / "prog.cpl"
    prog.write_text(text, encoding="latin-1")
    if keys is not None:
        opts["keys"] = tmp_path / "prog.keys"
        opts["keys"].write_text(keys)
    return run(prog, options=RunOptions(state_dir=tmp_path / ".ncvm", **opts))


def px(screen, x, y):
    return tuple(int(v) for v in screen.canvas[GRAPH_TOP - y, x])


def test_d1_dsp_root_table(tmp_path):
    # L4565-4577
    r, s = run_cpl(tmp_path, '10 LIN%=4 : COL%=1\n20 FOR I%=1 TO 10\n30 DSP(LIN%+I%,COL%,"###.### IS ROOT OF ##",'
                             'SQRT(I%),I%)\n40 NEXT\nM30\n')
    assert r["error"] is None
    lines = s.screen.grid_lines()
    assert lines[4] == "  1.000 IS ROOT OF  1"
    assert lines[6] == "  1.732 IS ROOT OF  3"
    assert lines[13] == "  3.162 IS ROOT OF 10"
    assert r["output"][0] == "  1.000 IS ROOT OF  1"


def test_d2_d3_default_formats_template_queue_booleans(tmp_path):
    # L4579-4612
    r, s = run_cpl(tmp_path, '10 A=25 : B=SQRT(A)\n20 DSP(5,10,"A=",A," B=",B," C= ",A+B)\n'
                             '30 DSP(6,10," A= ###.#"," B= #.#"," C= ##",A,B,B+A)\n'
                             '40 X=1.5 : Y=2.5 : P?=TRUE : N%=200\n'
                             '50 DSP(7,1,"XPOS ###.### YPOS ###.###"," MEAS.PROBE=",P?,X,Y," NO.=",N%)\nM30\n')
    assert r["error"] is None
    lines = s.screen.grid_lines()
    assert lines[4] == " " * 9 + "A=  25.000 B=   5.000 C=   30.000"
    assert lines[5] == " " * 9 + " A=  25.0 B= 5.0 C= 30"
    assert lines[6] == "XPOS   1.500 YPOS   2.500 MEAS.PROBE=TRUE NO.=      200"


def test_dsp_error_is_a_fault_with_the_manual_text(tmp_path):
    r, _ = run_cpl(tmp_path, '10 DSP(1,1,"X")\n20 DSP(47,1,"X")\nM30\n')
    assert r["error"]["code"] == "CPL701" and r["error"]["line"] == 2
    assert r["error"]["message"].startswith("Invalid line or column number in CPL command")


def test_inkey_example_with_key_script(tmp_path):
    # L4625-4650: poll INKEY until Enter, show every new key number
    r, s = run_cpl(tmp_path, '10 CLS : DSP(10,10,"Press any key! ABORT WITH ENTER")\n20 NEW%=0 : OLD%=0 : P%=0\n'
                             '30 WHILE NEW%<>13 DO\n40 NEW%=INKEY : P%=P%+1\n'
                             '50 IF (OLD%<>NEW%) AND (NEW%>0) THEN DSP(12,10,"KEY NUMBER:###",NEW%) : OLD%=NEW% ENDIF\n'
                             '60 END\n70 CLG\nM30\n', keys="IDLE 3\nKEY 65\nIDLE 2\nTYPE BC\nENTER\n")
    assert r["error"] is None
    assert r["variables"]["P%"] == 9
    assert [line for line in r["output"] if line.startswith("KEY")] == \
        ["KEY NUMBER: 65", "KEY NUMBER: 66", "KEY NUMBER: 67", "KEY NUMBER: 13"]


def test_d6_sfk_loop_with_labels(tmp_path):
    # L4822-4831: SFK(KEY%,,"ABORT",,"ACTION",,,,), KEY% = 2 -> .END, 4 -> .ACTION
    text = ('10 N%=0\n20 .START SFK(KEY%,,"ABORT",,"ACTION",,,,)\n30 IF KEY%=2 THEN GOTO .END ENDIF\n'
            '40 IF KEY%=4 THEN GOTO .ACTION ENDIF\n50 GOTO .START\n60 .ACTION N%=N%+1 : GOTO .START\n'
            '70 .END DSP(1,1,"ACTIONS ",N%)\nM30\n')
    r, s = run_cpl(tmp_path, text, keys="ENTER\nSK4\nSK1\nSK4\nSK2\n")
    assert r["error"] is None
    assert r["variables"]["N%"] == 2 and r["variables"]["KEY%"] == 2
    assert "SFK [2:ABORT] [4:ACTION]" in r["output"]
    assert s.screen.softkeys is None  # the bar is gone at the end of the program


def test_sfk_into_a_string_and_level_return(tmp_path):
    r, _ = run_cpl(tmp_path, '10 K%=7 : SFK(K%,"A","B")\n20 SFK(T$,"ONE","TWO")\nM30\n', keys="LEVEL RETURN\nSK2\n")
    assert r["variables"] == {"K%": 7, "T$": "TWO"}


def test_sfk_with_the_key_script_used_up(tmp_path):
    r, _ = run_cpl(tmp_path, '10 SFK(K%,"A")\nM30\n', keys="")
    assert r["error"]["code"] == "CPL705" and r["error"]["line"] == 1


def test_d4_dialog_input_and_prn0(tmp_path):
    # L4780-4786: DLG, PRN with formats, INP(WI):INP(DP), ENDDLG, PRN#(0,"Q900[",WI,",",DP,"]")
    text = ('10 DLG\n20 PRN(8,4,"MAX.CUTTING WIDTH: ###.### MM",WI)\n30 PRN(10,4,"MAX. CUTTING DEPTH: ###.### MM",DP)\n'
            '40 INP(WI) : INP(DP)\n50 ENDDLG\n60 PRN#(0,"Q900[",WI,",",DP,"]")\nM30\n')
    r, s = run_cpl(tmp_path, text, keys="TYPE 12.5\nDEL\nTYPE 3.25\n")
    assert r["error"] is None
    assert (r["variables"]["WI"], r["variables"]["DP"]) == (12.5, 3.25)
    lines = s.screen.grid_lines()
    assert lines[7] == "   MAX.CUTTING WIDTH:  12.500 MM"
    assert lines[9] == "   MAX. CUTTING DEPTH:   3.250 MM"
    assert r["output"][-1] == "Q900[  12.500,   3.250]"


def test_inp_integer_and_bad_entry(tmp_path):
    text = '10 DLG : PRN(2,1,"N=##",N%) : INP(N%) : ENDDLG\nM30\n'
    r, _ = run_cpl(tmp_path, text, keys="TYPE 12\n")
    assert r["variables"]["N%"] == 12
    r, _ = run_cpl(tmp_path, text, keys="TYPE 123\n")
    assert r["error"]["code"] == "CPL706"
    r, _ = run_cpl(tmp_path, '10 INP(X)\nM30\n', keys="TYPE 1\n")
    assert r["error"]["code"] == "CPL704"


def test_inkey_animation_runs_until_key_b(tmp_path):
    # L4752-4762: REPEAT KEY%=INKEY : LIN(250,10,M,M) : M=M+1 UNTIL (KEY%=66) OR (M>300) : CLG
    r, s = run_cpl(tmp_path, '10 M=10\n20 REPEAT KEY%=INKEY : LIN(250,10,M,M) : M=M+1 UNTIL (KEY%=66) OR (M>300)\n'
                             '30 DLF\nM30\n', keys="IDLE 20\nKEY 66\n")
    assert r["error"] is None and r["variables"]["M"] == 31
    assert px(s.screen, 30, 30) == s.screen.rgb(1)


def test_tfo_and_fonts_reset_at_the_end(tmp_path):
    r, s = run_cpl(tmp_path, '10 TFO(,,3)\n20 TFO(4,20+1000*12,1,90)\n30 TFO(11)\nM30\n')
    assert r["error"]["code"] == "CPL023" and r["error"]["line"] == 3
    r, s = run_cpl(tmp_path, '10 TFO(4,12020,1,90)\nM30\n')
    assert s.screen.font == (0, 0, 0, 0)


def test_d8_graphics_example(tmp_path):
    # L5049-5056 (the REM lines say what is drawn); pixels as in the cpl_io test of the same example
    text = ('10 DLF : COL(7,,,7)\n20 GWD(100,500,100,350) : MWD(0,400,-150,100)\n'
            '30 LIN(50,-100,100,-50) : CIR(100,-50,200,-50,150,-50)\n40 LIN(,0) : CIR(200,0,,,200,10) : LIN(300,)\n'
            '50 GMD(3) : CIR(300,0,300,-100,300,-50) : GMD(0)\n60 LIN(50,-100)\n'
            '70 XX=195 : YY=-50 : WI=30\n'
            '80 LIN(XX,YY,XX+15*COS(WI+165),YY+15*SIN(WI+165))\n'
            '90 LIN(XX+15*COS(WI+195),YY+15*SIN(WI+195)) : LIN(XX,YY)\n'
            '100 FIL(XX-10*COS(WI),YY-10*SIN(WI),0,7,7)\n'
            '110 LIN(XX-15*COS(WI),YY-15*SIN(WI),XX-30*COS(WI),YY-30*SIN(WI))\nM30\n')
    r, s = run_cpl(tmp_path, text, screen=tmp_path / "d8.png")
    assert r["error"] is None
    sc = s.screen
    assert px(sc, 150, 150) == BLACK and px(sc, 200, 200) == BLACK
    assert px(sc, 215, 165) == WHITE
    assert px(sc, 300, 225) == BLACK and px(sc, 350, 250) == BLACK
    assert px(sc, 250, 150) == BLACK and px(sc, 300, 150) == BLACK
    assert px(sc, 250, 200) == WHITE and px(sc, 50, 50) == WHITE
    assert (tmp_path / "d8.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_d9_gpr_labels_along_a_sine(tmp_path):
    # L5106-5114
    text = ('10 NR%=49\n20 FOR W%=0 STEP 45 TO 360\n30 X=75+W% : Y=175+100*SIN(W%) : N$=CHR$(NR%) : NR%=NR%+1\n'
            '40 LIN(X,Y+10,X,Y-10) : LIN(X-10,Y,X+10,Y)\n50 GPR(X+16,Y+40,"pixel") : GPR(X+64,Y+40,N$)\n60 NEXT\n'
            '70 GPR(700,0,"X")\nM30\n')
    r, s = run_cpl(tmp_path, text)
    assert r["output"][:4] == ["pixel", "1", "pixel", "2"]
    assert r["error"]["code"] == "CPL023" and r["error"]["line"] == 7


def test_d10_mmc_without_a_client(tmp_path):
    # L5209-5217: no client answers 1 and the variables stay
    r, _ = run_cpl(tmp_path, '10 DIM PROGNAME$(50): PROGNAME$="WinProg": INTPAR%=1: REALPAR=1.1\n'
                             '20 I%=MMC(PROGNAME$,INTPAR%,REALPAR)\n30 MMC(INTPAR%)\nM30\n')
    assert r["error"] is None
    v = r["variables"]
    assert v["I%"] == 1 and v["PROGNAME$"] == "WinProg" and v["INTPAR%"] == 1


def test_cli_run_with_keys_writes_the_screen_png(tmp_path):
    prog = tmp_path / "dlg.cpl"
    prog.write_text('10 CLS : DLG : PRN(5,2,"DIAMETER ###.## MM",DIA) : INP(DIA) : ENDDLG\n'
                    '20 SFK(K%,"DRAW","END")\n30 GWD(0,400,0,250) : MWD(-100,100,-62.5,62.5) : CIR(0,0,DIA/2)\nM30\n')
    keys = tmp_path / "k.txt"
    keys.write_text("TYPE 80\nSK1\n")
    png, shots = tmp_path / "s.png", tmp_path / "shots"
    args = ["run", str(prog), "--keys", str(keys), "--screen", str(png), "--screen-dir", str(shots), "--json",
            "--state", str(tmp_path / ".ncvm")]
    done = CliRunner().invoke(cli, args)
    assert '"status": "ok"' in done.output, done.output
    from PIL import Image

    with Image.open(png) as im:
        assert im.size == (633 * 2, 415 * 2)
        # the circle of radius 40 mm: 400 px for 200 mm, so 80 px right of the centre (200, 125), at scale 2
        assert im.getpixel((2 * 280, 2 * (GRAPH_TOP - 125))) != im.getpixel((2 * 200, 2 * (GRAPH_TOP - 125)))
    assert sorted(p.name for p in shots.iterdir()) == ["screen_001.png", "screen_002.png"]


def test_screen_is_saved_when_the_program_faults(tmp_path):
    r, _ = run_cpl(tmp_path, '10 DSP(1,1,"BEFORE THE FAULT")\n20 X = 1 / 0.0\nM30\n', screen=tmp_path / "f.png")
    assert r["error"]["code"] == "CPL028"
    assert (tmp_path / "f.png").read_bytes()[:4] == b"\x89PNG"


def test_string_function_argument_types_are_checked_when_linking(tmp_path):
    for text in ('10 N% = LEN(5)\nM30\n', '10 A$ = CHR$("A")\nM30\n', '10 X? = EOF("1")\nM30\n'):
        r, _ = run_cpl(tmp_path, text)
        assert r["error"]["code"] == "CPL032", text


MMC_EXAMPLE = ('10 DIM PROGNAME$(50)\n20 PROGNAME$ = "WinProg"\n30 INTPAR% = 1\n40 REALPAR = 1.1\n'
               '50 I% = MMC(PROGNAME$, INTPAR%, REALPAR)\n60 IF I% = 0 THEN\n70 IF INTPAR% = 2 THEN\n'
               '80 R$ = "TWO"\n90 ELSE\n100 R$ = "OTHER"\n110 ENDIF\n120 ENDIF\nM30\n')


def test_d10_mmc_with_a_client_attached_through_the_run_options(tmp_path):
    """L5209-5217: the client gets the names and values, answers 0 and writes INTPAR% = 2 back; block
    preparation goes on only after the answer, so line 70 sees the new value."""
    seen = []

    def client(names, values):
        seen.append((names, [v if isinstance(v, (int, float)) else str(v) for v in values]))
        return 0, {"INTPAR%": 2, "REALPAR": 2.5}

    r, _ = run_cpl(tmp_path, MMC_EXAMPLE, mmc_client=client)
    assert r["error"] is None
    assert seen == [(["PROGNAME$", "INTPAR%", "REALPAR"], ["WinProg", 1, pytest.approx(1.1)])]
    v = r["variables"]
    assert (v["I%"], v["INTPAR%"], v["REALPAR"], v["R$"], v["PROGNAME$"]) == (0, 2, 2.5, "TWO", "WinProg")


@pytest.mark.parametrize("answer, rc", [((2, {"INTPAR%": 2}), 2), (ValueError("client down"), 2)])
def test_mmc_client_error_writes_nothing_back(tmp_path, answer, rc):
    def client(names, values):
        if isinstance(answer, Exception):
            raise answer
        return answer

    r, _ = run_cpl(tmp_path, MMC_EXAMPLE, mmc_client=client)
    assert r["error"] is None
    assert (r["variables"]["I%"], r["variables"]["INTPAR%"]) == (rc, 1) and "R$" not in r["variables"]


def test_mmc_only_as_statement_or_assignment(tmp_path):
    r, _ = run_cpl(tmp_path, '10 A%=1\n20 IF MMC(A%) = 1 THEN A%=2 ENDIF\nM30\n')
    assert r["error"]["code"] == "CPL001" and "MMC" in r["error"]["message"]


def test_colour_tables_rgb_bitmaps_and_clearing(tmp_path):
    # COL table switch (L4923-4949), RGB into table 3, BMP from <file root>/cplbmp with a missing file warning,
    # CLR (window) and CLS (screen), CSF (softkeys gone)
    from PIL import Image

    bmp = tmp_path / ".ncvm" / "files" / "cplbmp"
    bmp.mkdir(parents=True)
    Image.new("RGB", (4, 3), (0, 255, 0)).save(bmp / "logo.bmp")
    text = ('10 COL(,,,10) : RGB(5,10,20,30) : COL(5) : LIN(10,20,100,20)\n'
            '20 BMP(10,100,"logo") : BMP(0,0,"missing")\n'
            '30 SFK(K%,"A") : CSF\n40 DSP(3,1,"TEXT")\nM30\n')
    r, s = run_cpl(tmp_path, text, keys="SK1\n")
    assert r["error"] is None
    sc = s.screen
    assert px(sc, 50, 20) == (10, 20, 30)
    assert px(sc, 10, 100) == (0, 255, 0) and px(sc, 13, 98) == (0, 255, 0)
    assert "warning CPL803: cplbmp\\missing.bmp is not existing" in r["output"]
    assert sc.softkeys is None
    r, s = run_cpl(tmp_path, '10 GWD(0,100,0,100) : LIN(10,10,90,90) : CLR\n20 DSP(3,1,"TEXT") : CLS\nM30\n')
    assert r["error"] is None
    assert px(s.screen, 50, 50) == s.screen.rgb(0) and s.screen.grid_lines()[2] == ""
    r, _ = run_cpl(tmp_path, '10 COL(8)\nM30\n')
    assert r["error"]["code"] == "CPL023"
    r, _ = run_cpl(tmp_path, '10 GWD(100,500,100,350) : MWD(0,400,0,100)\nM30\n')
    assert r["error"]["code"] == "CPL802"


@pytest.mark.parametrize("stmt, code", [
    ("COL(Q%)", "CPL020"), ("LIN(Q,1,2,3)", "CPL020"), ("CIR(1,Q,5)", "CPL020"), ("TFO(Q%)", "CPL020"),
    ("GWD(0,Q%,0,100)", "CPL020"), ('OPENW(1,Q$)', "CPL020"), ('DSP(Q%,1,"X")', "CPL020"),
    ('PRN#(Q%,"X")', "CPL020"), ("INP#(Q%,A)", "CPL020"), ("A?=EOF(Q%)", "CPL020"), ("A%=FILEPOS(Q%)", "CPL020"),
    ("A%=FILESIZE(Q%)", "CPL020"), ("A%=ERASE(Q$)", "CPL020"), ("A$=FILEDATE(Q$)", "CPL020"),
    ("A%=FILEACCESS(Q$)", "CPL020"),
    ("COL(,2)", None), ("LIN(,1)", None), ("DSP(1,1,Q)", None), ("PRN(1,1,Q$)", None)])
def test_an_unassigned_variable_is_not_an_omitted_argument(tmp_path, stmt, code):
    """NUL in an argument is VARIABLE NOT ASSIGNED (CPL manual §2.5, L758-769); only an empty position is omitted
    (LIN(,1) L5015-5030, COL(,2) L4923-4949), and a NUL value to print prints nothing."""
    r, _ = run_cpl(tmp_path, f"10 {stmt}\nM30\n")
    assert (r["error"]["code"] if r["error"] else None) == code


@pytest.mark.parametrize("first", ["N10 (TYP2)", "(TYP2)", "N10 G90"])
def test_typ2_programs_get_five_softkeys_l4464(tmp_path, first):
    """L4462-4468: new programs get 8 softkeys; an old CC 200/220 program, marked by "(TYP2)" as its first
    instruction, always gets 5."""
    r, s = run_cpl(tmp_path, f'{first}\n20 SFK(K%,"A","B","C","D","E","F")\nM30\n', keys="SK5\n")
    assert r["error"] is None and r["variables"]["K%"] == 5
    typ2 = "TYP2" in first
    assert r["output"][0] == "SFK [1:A] [2:B] [3:C] [4:D] [5:E]" + ("" if typ2 else " [6:F]")
    assert s.screen.softkey_count == (5 if typ2 else 8)


def test_dsp_past_column_79_is_cut_in_the_output_too_l4547(tmp_path):
    """L4547: DSP columns run from 1 to 79. Text that runs past column 79 is cut on the screen, and the run's
    output (the JSON "output") says what the screen shows, not the whole text."""
    r, s = run_cpl(tmp_path, '10 DSP(3,70,"ABCDEFGHIJKLMNOP")\n20 DSP(4,1,"X=",12.5)\nM30\n')
    assert r["error"] is None
    assert s.screen.grid_lines()[2] == " " * 69 + "ABCDEFGHIJ"
    assert r["output"] == ["ABCDEFGHIJ", "X=  12.500"]
