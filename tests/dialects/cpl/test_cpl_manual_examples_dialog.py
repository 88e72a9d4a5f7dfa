"""CPL manual examples, dialog (CPL manual §7-9, L4458-5217: COL, softkeys, keys).

Each test runs the manual's program, repaired only where an OCR slip or the
comment says why, and asserts the result the manual states.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from ncvm.api import run as run_program
from ncvm.dialects.cpl.io.graphics import TABLE_CODES
from ncvm.runtime.session import RunOptions


def run_with_keys(tmp_path: Path, text: str, keys: str, subs: dict[str, str] | None = None):
    for name, body in (subs or {}).items():
        (tmp_path / name).write_text(body, encoding="latin-1")
    prog = tmp_path / "prog.cpl"
    prog.write_text(text, encoding="latin-1")
    (tmp_path / "prog.keys").write_text(keys)
    return run_program(prog, options=RunOptions(state_dir=tmp_path / ".ncvm", keys=tmp_path / "prog.keys"))


def test_d7_col_variants_l4942(tmp_path):
    """§8 COL examples L4942-4949 with DSP lines between them: selecting table 2 (7) or 3 (10) erases the
    screen; then softkey text 1 on 4, lines and circles 4, text 6 on 5."""
    text = ('5 DSP(1,1,"BEFORE")\n10 COL(,,,7)\n25 DSP(2,1,"AFTER7")\n30 COL(,,,10)\n40 DSP(3,1,"AFTER10")\n'
            '50 COL(,,,,1,4)\n70 COL(4)\n90 COL(,6,5)\n95 DSP(4,1,"COLOURED")\nM30\n')
    r, s = run_with_keys(tmp_path, text, "")
    assert r["status"] == "ok", r["error"]
    sc = s.screen
    assert sc.grid_lines()[:4] == ["", "", "AFTER10", "COLOURED"]
    assert sc.table == TABLE_CODES[10] != TABLE_CODES[7]
    assert (sc.softkey_color, sc.softkey_bg, sc.line_color) == (1, 4, 4)
    assert tuple(sc.cells[3, 0][:2]) == (6, 5) and tuple(sc.cells[2, 0][:2]) != (6, 5)


UNTPR = """1 Z%=0 : COL(0,7,0)
2 DSP(41,4,P1$) : DSP(41,13,P2$) : DSP(41,22,P3$)
3 DSP(41,31,P4$) : DSP(41,40,P5$) : DSP(41,49,P6$) : DSP(41,58,P7$) : DSP(41,67,P8$)
4 REPEAT
5 REPEAT
6 K%=INKEY
7 UNTIL ((K%=141) OR (K%=142) OR (K%=143) OR (K%=144) OR (K%=145) OR (K%=146) OR (K%=147) OR (K%=148) OR (K%=139))
8 JZ%=Z%-140 : JK%=K%-140
9 IF ((JZ%>0) AND (JZ%<9)) THEN COL(0,7,0)
10 FOR I%=0 TO 2
11 DSP(41+I%,(JZ%-1)*8+JZ%+1,"        ")
12 NEXT I%
13 IF Z%=141 THEN DSP(41,4,P1$) ENDIF
14 IF Z%=142 THEN DSP(41,13,P2$) ENDIF
15 IF Z%=143 THEN DSP(41,22,P3$) ENDIF
16 IF Z%=144 THEN DSP(41,31,P4$) ENDIF
17 IF Z%=145 THEN DSP(41,40,P5$) ENDIF
18 IF Z%=146 THEN DSP(41,49,P6$) ENDIF
19 IF Z%=147 THEN DSP(41,58,P7$) ENDIF
20 IF Z%=148 THEN DSP(41,67,P8$) ENDIF
21 ENDIF
22 IF ((JK%>0) AND (JK%<9)) THEN COL(0,0,7)
23 FOR I%=0 TO 2
24 DSP(41+I%,(JK%-1)*8+JK%+1,"        ")
25 NEXT I%
26 IF K%=141 THEN DSP(41,4,P1$) ENDIF
27 IF K%=142 THEN DSP(41,13,P2$) ENDIF
28 IF K%=143 THEN DSP(41,22,P3$) ENDIF
29 IF K%=144 THEN DSP(41,31,P4$) ENDIF
30 IF K%=145 THEN DSP(41,40,P5$) ENDIF
31 IF K%=146 THEN DSP(41,49,P6$) ENDIF
32 IF K%=147 THEN DSP(41,58,P7$) ENDIF
33 IF K%=148 THEN DSP(41,67,P8$) ENDIF
34 ENDIF
35 Z%=K%
36 UNTIL K%=139 : CLG
M30
"""


def test_d5_softkey_emulation_untpr_l4660(tmp_path):
    """§7.1 INKEY, L4660-4750: the sub-program UNTPR draws eight softkey texts on line 41, highlights the box of
    a pressed softkey (141..148) and restores the previous one, until LEVEL RETURN (139).

    Rebuilt from the OCR: the line numbers are dropped, each IF/ENDIF and the long UNTIL are on one line,
    ``FOR 1%`` / ``LO`` / ``PI$`` / ``F43`` / ``ENDI`` are I%, TO, P1$, the P6$ line and ENDIF, the duplicated
    ``IF Z%=144`` lines are 143/144, the second blanking loop uses JK% (the box of the new key), the main
    program sets E$ (not B$ twice) and passes all eight texts."""
    main = ('1 A$ = "SOFT1" : B$ = "SOFT2" : C$ = "SOFT3"\n'
            '2 D$ = "SOFT4" : E$ = "SOFT5" : F$ = "SOFT6" : G$ = "SOFT7" : H$ = "SOFT8"\n'
            '3 CALL UNTPR [ A$, B$, C$, D$, E$, F$, G$, H$ ]\nM30\n')
    r, s = run_with_keys(tmp_path, main, "SK3\nSK5\nLEVEL RETURN\n", {"UNTPR": UNTPR})
    assert r["status"] == "ok", r["error"]
    blank = ["        "] * 3
    assert r["output"] == (["SOFT1", "SOFT2", "SOFT3", "SOFT4", "SOFT5", "SOFT6", "SOFT7", "SOFT8"]
                           + blank + ["SOFT3"]  # SK3: box 3 highlighted
                           + blank + ["SOFT3"] + blank + ["SOFT5"]  # SK5: box 3 restored, box 5 highlighted
                           + blank + ["SOFT5"])  # LEVEL RETURN: box 5 restored, then CLG
    assert s.screen.grid_lines()[40] == ""  # CLG erased the screen


@pytest.mark.parametrize(("keys", "m"), [("IDLE 20\nKEY 66\n", 22.0), ("", 150.0)])
def test_d5_circles_until_key_b_l4764(tmp_path, keys, m):
    """§7.1 L4764-4768: circles of growing radius while no 'B' (66) is pressed and M < 150; each pass
    polls INKEY once (20 polls find no key, the 21st finds B)."""
    text = "10 M=2\n20 WHILE ((INKEY<>66) AND (M<150)) DO\n30 CIR(250,160,M) : M=M+1\n40 END\n50 CLG\nM30\n"
    r, _ = run_with_keys(tmp_path, text, keys)
    assert r["status"] == "ok", r["error"]
    assert r["variables"]["M"] == m
