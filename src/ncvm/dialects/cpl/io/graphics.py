"""Chapter 8 graphics on a 633 x 415 pixel canvas (manual L4887-5176).

Coordinates: graphics y grows upwards. The graphics area is x 0..632, y 0..374; below it lies the
40-pixel softkey band, which GPR (y counted from the band's bottom, so "+40" lines it up with the
other commands) and BMP may use. Canvas row (from the top) = 374 - y for graphics y.

Colours are codes 0..7 in one of 3 tables; the canvas keeps RGB, so switching a table (which erases
the screen anyway) or changing table 3 with RGB affects what is drawn next. The default colours of
the tables are the project's choice (the manual's figure is lost); see :data:`COLOR_TABLES`.
"""

from __future__ import annotations

import io
import math
from collections import deque
from pathlib import Path

from ....lazy import lazy
from ....machine.files import FileRoot, FileRootError
from ....records import Record
from .errors import CplWarning, WarnFn, fail, warning
from .values import text_of

np = lazy("numpy")


WIDTH, HEIGHT = 633, 415  # whole CPL window (A.3.C)
GRAPH_TOP = 374  # highest graphics y (L4988)
BAND = 40  # softkey band under the graphics area (GPR offset, L5100)
#: the largest bitmap BMP decodes (16 times the window; what lies outside the window is cut off anyway)
MAX_BITMAP_PIXELS = 2048 * 2048

RGB = tuple[int, int, int]

#: the three colour tables (codes 0..7). Table 1 is the dark screen of the older controls, table 2 the
#: light one whose code 7 is black (the manual's example: "COL(7,,,7) ... graphic color 'black'").
COLOR_TABLES: tuple[tuple[RGB, ...], ...] = (
    ((0, 0, 0), (255, 255, 255), (0, 255, 0), (255, 255, 0),
     (0, 0, 192), (255, 0, 0), (0, 255, 255), (192, 192, 192)),
    ((255, 255, 255), (0, 0, 192), (0, 100, 0), (160, 0, 0),
     (192, 192, 192), (255, 215, 0), (192, 0, 192), (0, 0, 0)),
)
#: COL's <tab> argument: the text names 1, 2, 3; the examples use 7 for table 2 and 10 for table 3 (CPL manual L4933-4949)
TABLE_CODES = {1: 0, 2: 1, 3: 2, 7: 1, 10: 2}

#: GMD line styles -> on/off run lengths along the line (None = solid)
DASHES = {0: None, 1: None, 2: None, 3: (8, 3, 2, 3), 4: (6, 4)}


class Window(Record):
    __slots__ = ("xl", "xr", "yb", "yt")

    def __init__(self, xl: float, xr: float, yb: float, yt: float):
        self.xl = xl
        self.xr = xr
        self.yb = yb
        self.yt = yt


def _number(value, name: str) -> float:
    """A coordinate or other graphics value: a finite number, else INVALID PARAMETER (not a Python error)."""
    if isinstance(value, bool) or not isinstance(value, (int, float)) or value - value != 0:
        raise fail("INVALID_GRAPHICS_VALUE", f"{name} = {value!r}")
    return float(value)


def _int(value, name: str) -> int:
    return int(round(_number(value, name)))


#: a line longer than this many pixels is first clipped to the window (a LIN to 1e9 would step for hours)
LONG_SEGMENT = 4096


def _clip(x0: float, y0: float, x1: float, y1: float, w) -> tuple[float, float] | None:
    """Liang-Barsky: the parameter range t0..t1 of the segment that lies inside window ``w``, or None."""
    t0, t1 = 0.0, 1.0
    dx, dy = x1 - x0, y1 - y0
    for p, q in ((-dx, x0 - w.xl), (dx, w.xr - x0), (-dy, y0 - w.yb), (dy, w.yt - y0)):
        if p == 0:
            if q < 0:
                return None
            continue
        t = q / p
        if p < 0:
            t0 = max(t0, t)
        else:
            t1 = min(t1, t)
        if t0 > t1:
            return None
    return t0, t1


class Graphics:
    """The CPL graphics state and canvas: colours, GWD/MWD, line style, current point, drawing."""

    def __init__(self, bitmap_dir: FileRoot | Path | str | None = None, warn: WarnFn | None = None):
        self.tables = [list(COLOR_TABLES[0]), list(COLOR_TABLES[1]), list(COLOR_TABLES[1])]
        self.table = 0
        # colour codes: lines/circles, text, text background, softkey text, softkey background, graphics bg
        self.line_color, self.text_color, self.text_bg = 1, 2, 0
        self.softkey_color, self.softkey_bg, self.graphics_bg = 3, 4, 0
        self._blank = self.rgb(self.graphics_bg)  # the colour the canvas starts in (made at first use)
        self.line_style = 0
        self.window = Window(0, 632, 0, GRAPH_TOP)
        self.user: Window | None = None  # MWD
        self.point = (0.0, 0.0)  # current point (user coordinates)
        self.last_circle: dict[str, float] = {}
        #: the bitmap folder: BMP's names are confined to it as file names are to the file root
        self.bitmaps = bitmap_dir if isinstance(bitmap_dir, FileRoot) or bitmap_dir is None else FileRoot(bitmap_dir)
        self.warn = warn
        self.warnings: list[CplWarning] = []  # kept only while no warn listener takes them
        self.foreground = True

    def __getattr__(self, name: str):
        """``canvas`` (the RGB pixels, rows from the top) and ``text_pixels`` (those that hold GPR text, which
        the PNG draws again, sharply, over them) are made at their first use: a program that draws nothing
        imports no numpy (start-up). Made, they are plain attributes."""
        if name not in ("canvas", "text_pixels"):
            raise AttributeError(name)
        self.canvas = np.empty((HEIGHT, WIDTH, 3), dtype=np.uint8)
        self.canvas[:, :] = self._blank
        self.text_pixels = np.zeros((HEIGHT, WIDTH), dtype=bool)
        return self.__dict__[name]

    # -- colours ---------------------------------------------------------------------------
    def rgb(self, code: int) -> RGB:
        return self.tables[self.table][code]

    @staticmethod
    def _code(value, name: str) -> int:
        code = _int(value, name)
        if not 0 <= code <= 7:
            raise fail("INVALID_GRAPHICS_VALUE", f"colour code {name} = {value!r} (0..7)")
        return code

    def COL(self, graphics=None, text=None, text_bg=None, table=None, softkey=None, softkey_bg=None):  # noqa: N802
        """``COL([gr],[tx],[txbg],[tab],[sk],[skbg])``; selecting a table erases the whole screen."""
        if table is not None:
            code = _int(table, "tab")
            if code not in TABLE_CODES:
                raise fail("INVALID_GRAPHICS_VALUE", f"colour table {table!r} (1, 2, 3; or 7, 10)")
            self.table = TABLE_CODES[code]
            self.CLS()
        if graphics is not None:
            self.line_color = self._code(graphics, "graphics")
        if text is not None:
            self.text_color = self._code(text, "text")
        if text_bg is not None:
            self.text_bg = self._code(text_bg, "textBG")
        if softkey is not None:
            self.softkey_color = self._code(softkey, "SK")
        if softkey_bg is not None:
            self.softkey_bg = self._code(softkey_bg, "SKBG")

    def RGB(self, code, r, g, b) -> None:  # noqa: N802
        """``RGB(code,R,G,B)``: redefine colour ``code`` of table 3."""
        code = self._code(code, "color code")
        parts = []
        for name, v in (("R", r), ("G", g), ("B", b)):
            v = _int(v, name)
            if not 0 <= v <= 255:
                raise fail("INVALID_GRAPHICS_VALUE", f"{name} = {v} (0..255)")
            parts.append(v)
        self.tables[2][code] = tuple(parts)

    def GMD(self, style) -> None:  # noqa: N802
        """``GMD(type)``: 0 solid, 1 erase, 2 erase/regenerate, 3 dash-dot, 4 dash-dash."""
        style = _int(style, "line type")
        if style not in DASHES:
            raise fail("INVALID_GRAPHICS_VALUE", f"GMD({style}) (0..4)")
        self.line_style = style

    # -- windows and coordinates -----------------------------------------------------------
    def GWD(self, xl, xr, yb, yt) -> None:  # noqa: N802
        """``GWD(xl,xr,yb,yt)``: the graphics window in pixels; clears an MWD mapping."""
        xl, xr, yb, yt = (_int(v, n) for v, n in ((xl, "X left"), (xr, "X right"), (yb, "Y bottom"), (yt, "Y top")))
        if not (0 <= xl < xr <= 632 and 0 <= yb < yt <= GRAPH_TOP):
            raise fail("INVALID_GRAPHICS_VALUE", f"GWD({xl},{xr},{yb},{yt})")
        self.window = Window(xl, xr, yb, yt)
        self.user = None

    def MWD(self, xl, xr, yb, yt) -> None:  # noqa: N802
        """``MWD(xl,xr,yb,yt)``: user coordinates on the GWD window; the side ratio must be the same."""
        xl, xr, yb, yt = (_number(v, n) for v, n in ((xl, "X left"), (xr, "X right"), (yb, "Y bottom"), (yt, "Y top")))
        if not (xl < xr and yb < yt):
            raise fail("INVALID_GRAPHICS_VALUE", f"MWD({xl:g},{xr:g},{yb:g},{yt:g})")
        w = self.window
        mine, theirs = (xr - xl) / (yt - yb), (w.xr - w.xl) / (w.yt - w.yb)
        if abs(mine - theirs) > 1e-6 * theirs:
            raise fail("WINDOW_RATIO", f"MWD {mine:.6g} against GWD {theirs:.6g}")
        self.user = Window(xl, xr, yb, yt)

    def to_pixel(self, x: float, y: float) -> tuple[float, float]:
        """User (or pixel) coordinates to graphics pixels (y up)."""
        if self.user is None:
            return float(x), float(y)
        u, w = self.user, self.window
        scale = (w.xr - w.xl) / (u.xr - u.xl)
        return w.xl + (x - u.xl) * scale, w.yb + (y - u.yb) * scale

    def _scale(self) -> float:
        if self.user is None:
            return 1.0
        return (self.window.xr - self.window.xl) / (self.user.xr - self.user.xl)

    # -- pixels ----------------------------------------------------------------------------
    def _clear_rect(self, x0: int, top: int, x1: int, bottom: int, color: RGB | None = None) -> None:
        """Fill canvas columns x0..x1-1, rows top..bottom-1 with the graphics background."""
        self.canvas[top:bottom, x0:x1] = color or self.rgb(self.graphics_bg)
        self.text_pixels[top:bottom, x0:x1] = False

    def _window_rows(self) -> tuple[int, int, int, int]:
        w = self.window
        return int(w.xl), int(GRAPH_TOP - w.yt), int(w.xr), int(GRAPH_TOP - w.yb)

    def _plot(self, px: float, py: float, step: int) -> None:
        x, row = int(round(px)), int(round(GRAPH_TOP - py))
        x0, top, x1, bottom = self._window_rows()
        if not (x0 <= x <= x1 and top <= row <= bottom):
            return
        dashes = DASHES[self.line_style]
        if dashes is not None:
            pos, on = step % sum(dashes), True
            for run in dashes:
                if pos < run:
                    break
                pos -= run
                on = not on
            if not on:
                return
        color = self.rgb(self.line_color)
        background = self.rgb(self.graphics_bg)
        if self.line_style == 1:
            color = background
        elif self.line_style == 2:  # erase a drawn line, or regenerate an erased one
            color = background if tuple(self.canvas[row, x]) == color else color
        self.canvas[row, x] = color
        self.text_pixels[row, x] = False

    def _segment(self, a: tuple[float, float], b: tuple[float, float]) -> None:
        (x0, y0), (x1, y1) = self.to_pixel(*a), self.to_pixel(*b)
        if any(v - v != 0 for v in (x0, y0, x1, y1)):
            return  # beyond every pixel
        n = int(max(abs(round(x1) - round(x0)), abs(round(y1) - round(y0))))
        first, last = 0, n
        if n > LONG_SEGMENT:  # step only through the part inside the window (the dash pattern keeps its phase)
            inside = _clip(x0, y0, x1, y1, self.window)
            if inside is None:
                return
            first, last = max(0, int(inside[0] * n) - 1), min(n, int(inside[1] * n) + 1)
        seen = set()
        for i in range(first, last + 1):
            t = i / n if n else 0.0
            p = (round(x0 + (x1 - x0) * t), round(y0 + (y1 - y0) * t))
            if p not in seen:
                seen.add(p)
                self._plot(p[0], p[1], i)

    # -- drawing commands ------------------------------------------------------------------
    def LIN(self, *args) -> None:  # noqa: N802
        """``LIN(xs,ys,xe,ye)`` or ``LIN(xe,ye)`` (from the current point); an omitted value (None)
        keeps the current point's coordinate (``LIN(,0)``, ``LIN(300,)``)."""
        cx, cy = self.point
        if len(args) == 2:
            xs, ys, (xe, ye) = cx, cy, args
        elif len(args) == 4:
            xs, ys, xe, ye = args
            xs, ys = (cx if xs is None else xs), (cy if ys is None else ys)
        else:
            raise fail("INVALID_GRAPHICS_VALUE", f"LIN takes 2 or 4 values, not {len(args)}")
        xe, ye = (cx if xe is None else xe), (cy if ye is None else ye)
        start, end = (_number(xs, "X start"), _number(ys, "Y start")), (_number(xe, "X end"), _number(ye, "Y end"))
        self._segment(start, end)
        self.point = end

    def CIR(self, *args) -> None:  # noqa: N802
        """``CIR(xc,yc,r)`` full circle or ``CIR(xs,ys,xe,ye,xc,yc)`` clockwise arc; omitted values
        repeat the previous circle's, an omitted end point of an arc is its start (a full circle)."""
        last = self.last_circle
        if len(args) == 3:
            xc, yc, r = (last.get(k) if v is None else _number(v, k) for k, v in zip(("xc", "yc", "r"), args))
            if None in (xc, yc, r):
                raise fail("INVALID_GRAPHICS_VALUE", "CIR: omitted value with no circle before")
            last.update(xc=xc, yc=yc, r=r)
            self._arc(xc, yc, r, 0.0, 2 * math.pi)
            return
        if len(args) != 6:
            raise fail("INVALID_GRAPHICS_VALUE", f"CIR takes 3 or 6 values, not {len(args)}")
        xs, ys, xe, ye, xc, yc = args
        xs = last.get("xs") if xs is None else _number(xs, "xs")
        ys = last.get("ys") if ys is None else _number(ys, "ys")
        xc = last.get("xc") if xc is None else _number(xc, "xc")
        yc = last.get("yc") if yc is None else _number(yc, "yc")
        if None in (xs, ys, xc, yc):
            raise fail("INVALID_GRAPHICS_VALUE", "CIR: omitted value with no circle before")
        xe = xs if xe is None else _number(xe, "xe")
        ye = ys if ye is None else _number(ye, "ye")
        r = math.hypot(xs - xc, ys - yc)
        a0, a1 = math.atan2(ys - yc, xs - xc), math.atan2(ye - yc, xe - xc)
        sweep = (a0 - a1) % (2 * math.pi) or 2 * math.pi  # clockwise, end = start is a full circle
        last.update(xs=xs, ys=ys, xe=xe, ye=ye, xc=xc, yc=yc, r=r)
        self._arc(xc, yc, r, a0, sweep, clockwise=True)
        self.point = (xe, ye)

    def _arc(self, xc: float, yc: float, r: float, start: float, sweep: float, clockwise: bool = False) -> None:
        radius_px = r * self._scale()
        n = max(8, int(math.ceil(abs(sweep) * radius_px * 2)))
        sign = -1.0 if clockwise else 1.0
        for first, last in self._visible_samples(xc, yc, radius_px, start, sweep, sign, n):
            seen = set()
            step = first // 2  # about the pixels drawn before it: the line style's phase along the arc
            for i in range(first, last + 1):
                a = start + sign * sweep * i / n
                px, py = self.to_pixel(xc + r * math.cos(a), yc + r * math.sin(a))
                p = (round(px), round(py))
                if p not in seen:
                    seen.add(p)
                    self._plot(p[0], p[1], step)
                    step += 1

    def _visible_samples(self, xc: float, yc: float, radius_px: float, start: float, sweep: float, sign: float,
                         n: int) -> list[tuple[int, int]]:
        """The ranges of the arc's n + 1 samples (two a pixel) that can fall into the window: all of them, unless
        the circle is larger than the window; then its centre lies outside the window (or the circle misses
        it) and only the samples under the angles the window is seen at from the centre can show."""
        w = self.window
        corners = [(x, y) for x in (w.xl, w.xr) for y in (w.yb, w.yt)]
        if radius_px <= math.hypot(w.xr - w.xl, w.yt - w.yb):
            return [(0, n)]
        cx, cy = self.to_pixel(xc, yc)
        near = math.hypot(max(w.xl - cx, 0.0, cx - w.xr), max(w.yb - cy, 0.0, cy - w.yt))
        if not near - 1 <= radius_px <= max(math.hypot(x - cx, y - cy) for x, y in corners) + 1:
            return []
        base = math.atan2((w.yb + w.yt) / 2 - cy, (w.xl + w.xr) / 2 - cx)
        offsets = [(math.atan2(y - cy, x - cx) - base + math.pi) % (2 * math.pi) - math.pi for x, y in corners]
        margin = 2.0 / radius_px
        lo = ((base + min(offsets) - margin - start) * sign) % (2 * math.pi)  # along the arc from its start
        hi = lo + (max(offsets) - min(offsets) + 2 * margin)
        ranges = [(lo, min(hi, sweep))] + ([(0.0, min(hi - 2 * math.pi, sweep))] if hi > 2 * math.pi else [])
        return [(max(0, math.floor(a / sweep * n)), min(n, math.ceil(b / sweep * n))) for a, b in ranges if a <= b]

    def FIL(self, x, y, pattern, fill, contour=None) -> None:  # noqa: N802
        """``FIL(x,y,pattern,fill[,contour])``: flood the closed contour around (x,y) with ``fill``;
        the region ends at pixels of the contour colour (the fill colour when none is given)."""
        pattern = _int(pattern, "fill pattern")
        if not 0 <= pattern <= 5:
            raise fail("INVALID_GRAPHICS_VALUE", f"fill pattern {pattern} (0..5)")
        fill_rgb = np.array(self.rgb(self._code(fill, "fill color")), dtype=np.uint8)
        border = np.array(self.rgb(self._code(fill if contour is None else contour, "contour color")),
                          dtype=np.uint8)
        px, py = self.to_pixel(_number(x, "x"), _number(y, "y"))
        sx, srow = int(round(px)), int(round(GRAPH_TOP - py))
        x0, top, x1, bottom = self._window_rows()
        if not (x0 <= sx <= x1 and top <= srow <= bottom):
            return
        region = self.canvas[top:bottom + 1, x0:x1 + 1]
        free = ~np.all(region == border, axis=2)
        if not free[srow - top, sx - x0]:
            return
        done = np.zeros_like(free)
        todo = deque([(srow - top, sx - x0)])
        h, w = free.shape
        while todo:
            r, c = todo.pop()
            if done[r, c] or not free[r, c]:
                continue
            left = c
            while left > 0 and free[r, left - 1] and not done[r, left - 1]:
                left -= 1
            right = c
            while right < w - 1 and free[r, right + 1] and not done[r, right + 1]:
                right += 1
            done[r, left:right + 1] = True
            for nr in (r - 1, r + 1):
                if 0 <= nr < h:
                    row_free = free[nr, left:right + 1] & ~done[nr, left:right + 1]
                    for off in np.flatnonzero(row_free & ~np.concatenate(([False], row_free[:-1]))):
                        todo.append((nr, left + int(off)))
        region[done] = fill_rgb
        self.text_pixels[top:bottom + 1, x0:x1 + 1][done] = False

    def CLR(self) -> None:  # noqa: N802
        """``CLR``: clear the GWD window."""
        x0, top, x1, bottom = self._window_rows()
        self._clear_rect(x0, top, x1 + 1, bottom + 1)

    def CLS(self) -> None:  # noqa: N802
        """``CLS``: clear the whole screen (the screen also clears its text)."""
        self._clear_rect(0, 0, WIDTH, HEIGHT)

    def CLG(self) -> None:  # noqa: N802
        """``CLG``: clear the CPL area and send the dialog window to the background."""
        self._clear_rect(0, 0, WIDTH, HEIGHT)
        self.foreground = False

    def DLF(self) -> None:  # noqa: N802
        """``DLF``: bring the dialog window to the foreground."""
        self.foreground = True

    # -- bitmaps ---------------------------------------------------------------------------
    def BMP(self, x, y, name, copy=None) -> None:  # noqa: N802
        """``BMP(x,y,"file"[,copy])``: ``<bitmap_dir>/<file>.bmp`` with its top-left pixel at graphics
        (x, y), combined with the screen by raster operation ``copy`` 0..8. A missing file (or one
        that holds no image) warns and the program goes on; a name that leads out of the bitmap
        folder is INVALID FILE NAME."""
        x, y = _int(x, "X value"), _int(y, "Y value")
        copy = 0 if copy is None else _int(copy, "copy type")
        file = text_of(name) or ""
        if not (0 <= x <= 632 and 0 <= y <= GRAPH_TOP) or not 0 <= copy <= 8 or len(file) > 70:
            raise fail("INVALID_GRAPHICS_VALUE", f"BMP({x},{y},{file!r},{copy})")
        try:
            data = self.bitmaps.read_bytes(self.bitmaps.place(f"{file}.bmp")) if self.bitmaps is not None else None
        except FileRootError as e:  # out of the bitmap folder, or a FIFO, device or socket
            raise fail("INVALID_FILE_NAME", str(e)) from None
        except OSError:
            data = None
        src, why = _image(data) if data is not None else (None, "")
        if src is None:
            self._warn(warning("BITMAP_MISSING", why, name=file))
            return
        top = GRAPH_TOP - y
        h, w = min(src.shape[0], HEIGHT - top), min(src.shape[1], WIDTH - x)
        src = src[:h, :w]
        dst = self.canvas[top:top + h, x:x + w]
        ops = {
            0: lambda s, d: s,
            1: lambda s, d: np.full_like(s, 255),
            2: lambda s, d: np.zeros_like(s),
            3: lambda s, d: s | d,
            4: lambda s, d: s & d,
            5: lambda s, d: s ^ d,
            6: lambda s, d: s & ~d,
            7: lambda s, d: ~s,
            8: lambda s, d: ~s & ~d,
        }
        dst[...] = ops[copy](src, dst)
        self.text_pixels[top:top + h, x:x + w] = False

    def _warn(self, w: CplWarning) -> None:
        if self.warn is not None:
            self.warn(w)
        else:
            self.warnings.append(w)


def _image(data: bytes) -> tuple[np.ndarray | None, str]:
    """The RGB pixels of a BMP file's bytes, or None and why not. Only the BMP format is decoded (the
    manual's "*.bmp" picture files; other formats can make an image library start helper programs),
    and only up to :data:`MAX_BITMAP_PIXELS`: its header is read first, because a run-length bitmap
    of a few hundred bytes, which a program can write itself, may declare 9000 x 9000 pixels."""
    from PIL import Image

    try:
        with Image.open(io.BytesIO(data), formats=("BMP",)) as im:
            width, height = im.size
            if width * height > MAX_BITMAP_PIXELS:
                return None, f"{width} x {height} pixels, more than {MAX_BITMAP_PIXELS} (2048 x 2048)"
            return np.asarray(im.convert("RGB"), dtype=np.uint8), ""
    except (OSError, ValueError, Image.DecompressionBombError):
        return None, ""
