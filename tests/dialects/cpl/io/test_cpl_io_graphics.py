"""Chapter 8 graphics: colour tables, GWD/MWD, LIN, CIR, GMD, FIL, CLR/CLS/CLG, GPR, BMP, and the PNG."""

from __future__ import annotations

import math

import numpy as np
import pytest

from ncvm.dialects.cpl.io.errors import CplRuntimeError
from ncvm.dialects.cpl.io.graphics import COLOR_TABLES, GRAPH_TOP
from ncvm.dialects.cpl.io.screen import Screen

BLACK, WHITE = (0, 0, 0), (255, 255, 255)


def px(s, x, y):
    """Colour at graphics pixel (x, y), y up."""
    return tuple(int(v) for v in s.canvas[GRAPH_TOP - y, x])


def near(s, x, y, color, r=1):
    return any(px(s, x + dx, y + dy) == color for dx in range(-r, r + 1) for dy in range(-r, r + 1))


def error_of(fn, *args, **kw):
    with pytest.raises(CplRuntimeError) as err:
        fn(*args, **kw)
    return err.value


def cos(a):
    return math.cos(math.radians(a))


def sin(a):
    return math.sin(math.radians(a))


def draw_d8(s):
    # L5049-5056, the manual's graphics example (its figure is lost; the REM lines say what is drawn)
    s.DLF()
    s.COL(7, None, None, 7)
    s.GWD(100, 500, 100, 350)
    s.MWD(0, 400, -150, 100)
    s.LIN(50, -100, 100, -50)
    s.CIR(100, -50, 200, -50, 150, -50)
    s.LIN(None, 0)
    s.CIR(200, 0, None, None, 200, 10)
    s.LIN(300, None)
    s.GMD(3)
    s.CIR(300, 0, 300, -100, 300, -50)
    s.GMD(0)
    s.LIN(50, -100)
    xx, yy, wi = 195, -50, 30
    s.LIN(xx, yy, xx + 15 * cos(wi + 165), yy + 15 * sin(wi + 165))
    s.LIN(xx + 15 * cos(wi + 195), yy + 15 * sin(wi + 195))
    s.LIN(xx, yy)
    s.FIL(xx - 10 * cos(wi), yy - 10 * sin(wi), 0, 7, 7)
    s.LIN(xx - 15 * cos(wi), yy - 15 * sin(wi), xx - 30 * cos(wi), yy - 30 * sin(wi))


def test_d8_graphics_example(tmp_path):
    s = Screen()
    draw_d8(s)
    # user (x, y) -> pixel (100 + x, 250 + y): the MWD window 0..400 x -150..100 on GWD 100..500 x 100..350
    assert s.to_pixel(50, -100) == (150.0, 150.0)
    assert px(s, 150, 150) == BLACK and px(s, 200, 200) == BLACK  # first line, both ends
    assert near(s, 250, 250, BLACK)  # top of the clockwise half circle 100/-50 -> 200/-50 (centre 150/-50)
    assert px(s, 215, 165) == WHITE  # the half circle went over the top, not under
    assert px(s, 300, 225) == BLACK  # LIN(,0): 200/-50 -> 200/0
    assert near(s, 300, 270, BLACK) and px(s, 300, 260) == WHITE  # full circle R=10 around 200/10
    assert px(s, 350, 250) == BLACK  # LIN(300,): 200/0 -> 300/0
    assert near(s, 450, 200, BLACK)  # dash-dot arc through 350/-50 (its rightmost point)
    arc = [px(s, round(400 + 50 * cos(a)), round(200 + 50 * sin(a))) for a in range(-80, 81, 2)]
    assert WHITE in arc and BLACK in arc  # dashed: gaps in the arc
    assert px(s, 250, 150) == BLACK and px(s, 300, 150) == BLACK  # LIN(50,-100) along y = -100
    tip = s.to_pixel(195 - 8 * cos(30), -50 - 8 * sin(30))
    assert px(s, round(tip[0]), round(tip[1])) == BLACK  # the arrowhead is filled
    assert px(s, 250, 200) == WHITE  # the rest of the contour is not
    assert px(s, 50, 50) == WHITE  # outside the window: table 2 background
    path = s.save_png(tmp_path / "d8.png")
    from PIL import Image

    with Image.open(path) as im:
        assert im.size == (633 * 2, 415 * 2)


def test_colour_tables_and_col():
    s = Screen()
    assert s.rgb(0) == COLOR_TABLES[0][0] and s.table == 0
    s.LIN(10, 10, 100, 10)
    assert px(s, 50, 10) == s.rgb(1)
    s.COL(None, None, None, 7)  # table 2; the screen is erased
    assert s.table == 1 and px(s, 50, 10) == s.rgb(0) == WHITE
    s.COL(None, None, None, 10)  # table 3 starts as a copy of table 2
    assert s.tables[2] == list(COLOR_TABLES[1])
    s.RGB(5, 10, 20, 30)
    s.COL(5)
    s.LIN(10, 20, 100, 20)
    assert px(s, 50, 20) == (10, 20, 30) and s.tables[1][5] == COLOR_TABLES[1][5]
    s.COL(None, 6, 5)
    assert (s.text_color, s.text_bg) == (6, 5)
    s.COL(None, None, None, None, 1, 4)
    assert (s.softkey_color, s.softkey_bg) == (1, 4)
    assert error_of(s.COL, 8).code == "CPL023"
    assert error_of(s.COL, None, None, None, 4).code == "CPL023"
    assert error_of(s.RGB, 0, 256, 0, 0).code == "CPL023"


def test_gwd_mwd_checks_and_clipping():
    s = Screen()
    for bad in ((0, 633, 0, 100), (10, 10, 0, 100), (0, 100, 50, 375), (-1, 100, 0, 100)):
        assert error_of(s.GWD, *bad).code == "CPL023"
    s.GWD(100, 500, 100, 350)
    assert error_of(s.MWD, 0, 400, 0, 100).code == "CPL802"
    s.MWD(0, 40, 0, 25)
    assert s.to_pixel(40, 25) == (500.0, 350.0)
    s.GWD(0, 100, 0, 100)  # a new window drops the MWD mapping; drawing stays inside it
    s.LIN(50, 50, 300, 50)
    assert px(s, 100, 50) == s.rgb(1) and px(s, 101, 50) == s.rgb(0)


def test_gmd_erase_and_toggle():
    s = Screen()
    s.LIN(0, 5, 50, 5)
    s.GMD(1)
    s.LIN(0, 5, 20, 5)
    assert px(s, 10, 5) == s.rgb(0) and px(s, 30, 5) == s.rgb(1)
    s.GMD(2)
    s.LIN(0, 5, 50, 5)  # erased part comes back, drawn part goes
    assert px(s, 10, 5) == s.rgb(1) and px(s, 30, 5) == s.rgb(0)
    s.GMD(4)
    s.LIN(0, 9, 100, 9)
    row = [px(s, x, 9) == s.rgb(1) for x in range(0, 100)]
    assert row[:6] == [True] * 6 and row[6:10] == [False] * 4
    assert error_of(s.GMD, 5).code == "CPL023"


def test_cir_full_circle_omitted_values_repeat():
    # L5030-5047 and the INKEY example: CIR(250,160,M) with a growing M
    s = Screen()
    s.CIR(250, 160, 20)
    assert px(s, 270, 160) == s.rgb(1) and px(s, 250, 180) == s.rgb(1) and px(s, 250, 160) == s.rgb(0)
    s.CIR(None, None, 30)
    assert px(s, 280, 160) == s.rgb(1)
    s.CIR(100, None, None)
    assert px(s, 130, 160) == s.rgb(1)
    assert error_of(Screen().CIR, None, 1, 1).code == "CPL023"


def test_fil_with_contour_colour_and_clear_commands():
    s = Screen()
    s.COL(3)
    for args in ((10, 10, 60, 10), (60, 10, 60, 60), (60, 60, 10, 60), (10, 60, 10, 10)):
        s.LIN(*args)
    s.FIL(30, 30, 0, 5, 3)
    assert px(s, 30, 30) == s.rgb(5) and px(s, 11, 11) == s.rgb(5) and px(s, 10, 10) == s.rgb(3)
    assert px(s, 70, 30) == s.rgb(0)
    assert error_of(s.FIL, 30, 30, 6, 5).code == "CPL023"
    s.GWD(0, 40, 0, 40)
    s.CLR()
    assert px(s, 30, 30) == s.rgb(0) and px(s, 50, 50) == s.rgb(5)
    s.DSP(1, 1, "TEXT")
    s.CLS()
    assert px(s, 50, 50) == s.rgb(0) and s.grid_lines()[0] == ""
    s.softkeys = ["A"] + [None] * 7
    s.DSP(1, 1, "TEXT")
    s.CLG()
    assert s.softkeys is None and s.grid_lines()[0] == "" and not s.foreground


def test_d9_gpr_labels_along_a_sine(tmp_path):
    # L5106-5114: crosses with labels "pixel" and 1..9 at (X+16, Y+40) and (X+64, Y+40)
    s = Screen()
    nr = 49
    for w in range(0, 361, 45):
        x, y = 75 + w, 175 + 100 * sin(w)
        n = chr(nr)
        nr += 1
        s.LIN(x, y + 10, x, y - 10)
        s.LIN(x - 10, y, x + 10, y)
        s.GPR(x + 16, y + 40, "pixel")
        s.GPR(x + 64, y + 40, n)
    text = s.rgb(s.text_color)
    # the first label "pixel" starts 16 px right of the cross at (75, 175): its letters sit on y = 175
    box = s.canvas[GRAPH_TOP - 175 - 9: GRAPH_TOP - 175 + 3, 91:130]
    assert np.all(box == text, axis=2).sum() > 20
    assert not np.all(s.canvas[GRAPH_TOP - 175 - 9: GRAPH_TOP - 175 + 3, 10:60] == text, axis=2).any()
    assert s.output_lines()[:2] == ["pixel", "1"]
    assert error_of(s.GPR, 700, 0, "X").code == "CPL023"
    s.save_png(tmp_path / "d9.png")


def test_bmp_raster_operations_and_missing_file(tmp_path):
    from PIL import Image

    Image.new("RGB", (4, 3), (0, 255, 0)).save(tmp_path / "logo.bmp")
    s = Screen(bitmap_dir=tmp_path)
    s.BMP(10, 100, "logo")
    assert px(s, 10, 100) == (0, 255, 0) and px(s, 13, 98) == (0, 255, 0) and px(s, 14, 100) == s.rgb(0)
    s.BMP(10, 100, "logo", 5)  # XOR with itself
    assert px(s, 10, 100) == (0, 0, 0)
    s.BMP(10, 100, "logo", 1)
    assert px(s, 11, 99) == WHITE
    s.BMP(10, 100, "logo", 7)
    assert px(s, 11, 99) == (255, 0, 255)
    s.BMP(0, 0, "missing")  # into the softkey band; a missing file warns and the program goes on
    assert [w.message for w in s.warnings] == ["cplbmp\\missing.bmp is not existing"]
    assert error_of(s.BMP, 0, 0, "logo", 9).code == "CPL023"


def test_screen_png_with_text_softkeys_and_fonts(tmp_path):
    s = Screen()
    s.DSP(1, 1, "TEXT GRID LINE 1")
    s.TFO(4, 20, 1)
    s.DSP(3, 1, "Times 20 px bold")
    s.TFO(0, 0, 0)
    s.COL(None, 0, 7)
    s.DSP(40, 70, "INVERSE")
    s.softkeys = ["ONE", "TWO&LINES", None, None, None, None, None, "A&B&C"]
    img = s.image(scale=1)
    assert img.size == (633, 415)
    arr = np.asarray(img)
    assert (arr[9 * 39: 9 * 40, 69 * 8: 76 * 8] == s.rgb(7)).all(axis=2).sum() > 100  # inverse cell background
    assert (arr[378:412, 2:76] == s.rgb(s.softkey_bg)).all(axis=2).sum() > 1000  # softkey 1 box
    s.save_png(tmp_path / "screen.png")


def test_tfo_orientation_turns_gpr_text_about_its_start(tmp_path):
    s = Screen()
    s.TFO(1, 16, 0, 90)
    s.GPR(300, 240, "UPWARDS TEXT")  # start at graphics (300, 200)
    on = np.all(s.canvas == s.rgb(s.text_color), axis=2)
    rows, cols = np.nonzero(on)
    assert rows.max() <= GRAPH_TOP - 200 + 1 and rows.min() < GRAPH_TOP - 260  # it runs upwards
    assert cols.min() >= 300 - 17 and cols.max() <= 300 + 2  # on the left of the start point, 16 px high
    s.TFO(5, 16, 0, 90)  # no orientation for font 5 (Bosch)
    s.CLS()
    s.GPR(300, 240, "FLAT")
    rows, cols = np.nonzero(np.all(s.canvas == s.rgb(s.text_color), axis=2))
    assert cols.max() > 320 and rows.min() > GRAPH_TOP - 200 - 17
    s.save_png(tmp_path / "tfo.png")
    assert not s.text_pixels[:, :290].any()


def _drawing_screen() -> Screen:
    s = Screen()
    s.DLF()
    s.COL(7, None, None, 7)
    return s


@pytest.mark.parametrize("centre, radius", [((-700.0, 200.0), 1000.0), ((300.0, -900.0), 1100.0),
                                            ((1500.0, 1500.0), 1800.0)])
def test_a_circle_larger_than_the_window_draws_the_pixels_of_the_full_sampling(centre, radius):
    """A circle whose radius exceeds the window's diagonal is sampled only where the window can see it; it
    sets the same pixels as sampling the whole circle two samples a pixel (done here by hand)."""
    s, ref = _drawing_screen(), _drawing_screen()
    s.CIR(centre[0], centre[1], radius)
    n = int(math.ceil(2 * math.pi * radius * 2))
    seen: set = set()
    for i in range(n + 1):
        a = 2 * math.pi * i / n
        p = (round(centre[0] + radius * math.cos(a)), round(centre[1] + radius * math.sin(a)))
        if p not in seen:
            seen.add(p)
            ref._plot(p[0], p[1], len(seen) - 1)
    assert np.array_equal(s.canvas, ref.canvas)
    assert np.any(s.canvas != _drawing_screen().canvas)


def test_a_huge_circle_is_drawn_where_it_crosses_the_window_without_tracing_all_of_it():
    """A circle of radius 1e9 pixels through the window's middle looks like a straight vertical line there
    (sampling all of it would take 1.3e10 samples); CIR(554,135,7e30), found by generated programs, used to
    exhaust memory: its centre is in the window, so it misses the window and draws nothing."""
    s = _drawing_screen()
    s.CIR(300 - 1e9, 200, 1e9)
    changed = np.argwhere(np.any(s.canvas != _drawing_screen().canvas, axis=2))
    assert len(changed) > 300 and set(changed[:, 1]) == {300}
    blank = _drawing_screen()
    blank.CIR(554, 135, 7e30)
    assert np.array_equal(blank.canvas, _drawing_screen().canvas)
