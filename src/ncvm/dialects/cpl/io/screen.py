"""Chapter 7 dialog on the virtual operator screen (manual L4458-4886).

The screen is the 633 x 415 pixel CPL window of :mod:`.graphics` with a 46-line x 79-column text
grid over it (a cell is 8 x 9 pixels, TFO font 0 size 0), the softkey bar in the 40-pixel band at
the bottom (8 keys, 5 in ``(TYP2)`` mode, 3 lines of 9 characters each), the DLG input fields and
the operator's keys, which come from a *key script* (see :class:`KeyScript` and docs/cpl-io.md).

``output_lines()`` gives what the program showed the operator, in order: every DSP and PRN text and
every message-window line (PRN#(0,...) when :meth:`Screen.message` is the files' message callback),
unless an ``on_output`` listener takes the lines (a run's session keeps a bounded number of them);
``save_png(path)`` renders the whole window.
"""

from __future__ import annotations

from collections import deque
from functools import lru_cache
from pathlib import Path

from ....lazy import lazy
from ....machine.files import FileRoot
from ....records import Record
from .errors import CplRuntimeError, WarnFn, fail
from .format import TEMPLATE, OutputMode, format_items, format_number, template_shape
from .graphics import BAND, HEIGHT, WIDTH, Graphics, _int
from .strings import scan_number
from .values import is_text, kind_of, text_of

np = lazy("numpy")


LINES, COLUMNS = 46, 79
CELL_W, CELL_H = 8, 9
MAX_DSP_STRING = 77

# Key codes (manual A.5/A.6; the A.6 table is lost, CPL manual L5632-5645): 13 Enter and 139 LEVEL RETURN and
# 141..148 softkeys 1..8 are attested by the INKEY example; the cursor codes are the project's choice.
KEY_ENTER, KEY_LEVEL_RETURN, KEY_DEL = 13, 139, 127
KEY_UP, KEY_DOWN, KEY_RIGHT, KEY_LEFT = 135, 136, 137, 138
SOFTKEY_BASE = 140  # softkey n has code 140 + n
NAMED_KEYS = {"ENTER": KEY_ENTER, "LEVELRETURN": KEY_LEVEL_RETURN, "RETURN": KEY_LEVEL_RETURN,
              "DEL": KEY_DEL, "UP": KEY_UP, "DOWN": KEY_DOWN, "RIGHT": KEY_RIGHT, "LEFT": KEY_LEFT,
              "ESC": 27}
CURSOR_KEYS = {KEY_UP, KEY_DOWN, KEY_RIGHT, KEY_LEFT}

#: TFO font number -> (manual's font, font file shipped with matplotlib, forced cut)
FONTS = {
    0: ("Lucida Console", "DejaVuSansMono", 0),
    1: ("Arial", "DejaVuSans", 0),
    2: ("Verdana", "DejaVuSans", 0),
    3: ("Book Antiqua", "DejaVuSerif", 0),
    4: ("Times New Roman", "STIXGeneral", 0),
    5: ("Bosch", "DejaVuSans", 1),
    6: ("Impact", "DejaVuSans", 1),
    7: ("Haettenschweiler", "DejaVuSans", 1),
    8: ("Comic Sans MS", "DejaVuSans", 2),
    9: ("Brush Script MT", "DejaVuSerif", 2),
    10: ("Wingdings", "DejaVuSans", 0),
}
_SUFFIX = {  # cut -> file suffix per family
    "DejaVuSansMono": ("", "-Bold", "-Oblique", "-BoldOblique"),
    "DejaVuSans": ("", "-Bold", "-Oblique", "-BoldOblique"),
    "DejaVuSerif": ("", "-Bold", "-Italic", "-BoldItalic"),
    "STIXGeneral": ("", "Bol", "Ita", "BolIta"),
}


@lru_cache(maxsize=64)
def _whole(value, name: str) -> int:
    """A TFO value: a number (truncated, as before), else INVALID PARAMETER."""
    if isinstance(value, bool) or not isinstance(value, (int, float)) or value - value != 0:
        raise fail("INVALID_PARAMETER", f"TFO {name} {value!r}")
    return int(value)


def font_for(number: int, cut: int, em_px: int):
    """A PIL font for TFO font ``number`` with ``cut`` (0..3), ``em_px`` pixels to the em."""
    import matplotlib  # imported when text is drawn: 0.16 s with PIL that most runs never need
    from PIL import ImageFont

    _name, family, forced = FONTS[number]
    cut = cut | forced
    path = Path(matplotlib.get_data_path()) / "fonts" / "ttf" / f"{family}{_SUFFIX[family][cut]}.ttf"
    return ImageFont.truetype(str(path), max(4, int(em_px)))


def text_mask(text: str, style: tuple[int, int, int, int], scale: int = 1) -> tuple[np.ndarray, float, float]:
    """The glyphs of ``text`` in TFO ``style`` as a 0..255 mask, and where in it the text's start
    point (left end of the baseline) lies, after turning it by the style's orientation.

    Font 0 in size 0 is the 9 x 8 pixel cell font: each character is centred in its own cell, so
    text stays on the 79-column grid. Other sizes give the font's height in pixels (ascent plus
    descent); a size with a width part (height + 1000 x width) stretches the characters to that width.
    The orientation turns the text counter-clockwise about its start point (not for font 5, L4877).
    """
    from PIL import Image, ImageDraw

    # control characters (CHR$(0..31), 127) have no glyph: they take a blank place, as on the panel
    text = "".join(c if c.isprintable() else " " for c in text)
    number, size, cut, orientation = style
    if number == 0 and size == 0:
        cw, ch = CELL_W * scale, CELL_H * scale
        font = font_for(0, cut, int(round(1.15 * ch)))
        baseline = ch - int(round(0.2 * ch))
        img = Image.new("L", (max(1, cw * len(text)), ch), 0)
        draw = ImageDraw.Draw(img)
        for i, c in enumerate(text):
            draw.text((i * cw + (cw - font.getlength(c)) / 2, baseline), c, fill=255, font=font, anchor="ls")
    else:
        height = (size % 1000 or CELL_H) * scale
        char_w = (size // 1000) * scale
        font = font_for(number, cut, int(round(height / 1.17)))
        ascent, descent = font.getmetrics()
        img = Image.new("L", (max(1, int(np.ceil(font.getlength(text))) + 1), ascent + descent), 0)
        ImageDraw.Draw(img).text((0, 0), text, fill=255, font=font)
        if char_w and text:
            img = img.resize((char_w * len(text), ascent + descent), Image.BILINEAR)
        baseline = ascent
    ax, ay = 0.0, float(baseline)
    if orientation % 360 and number != 5:
        w, h = img.size
        img = img.rotate(orientation, resample=Image.BILINEAR, expand=True)
        t = np.radians(orientation)
        dx, dy = ax - w / 2, ay - h / 2
        ax = img.size[0] / 2 + dx * np.cos(t) + dy * np.sin(t)
        ay = img.size[1] / 2 - dx * np.sin(t) + dy * np.cos(t)
    return np.asarray(img), ax, ay


# -- the key script -----------------------------------------------------------------------------

class KeyEvent(Record):
    __slots__ = ("kind", "value")

    def __init__(self, kind: str, value: object):
        self.kind = kind  # "key", "type" or "idle"
        self.value = value


class KeyScript:
    """The operator's key presses, one per line (docs/cpl-io.md):

    ``SK1``..``SK8`` softkeys; ``ENTER``; ``LEVEL RETURN``; ``UP`` ``DOWN`` ``LEFT`` ``RIGHT``; ``DEL``;
    ``ESC``; ``KEY n`` any key code 1..255; ``TYPE text`` the operator types ``text`` (INKEY sees its
    characters one by one; an INP takes it as the whole input, ended by ENTER); ``IDLE n`` the next n
    INKEY polls find no key. Blank lines and lines starting with ``#`` are ignored.
    """

    def __init__(self, text: str = ""):
        self.events: deque[KeyEvent] = deque()
        for number, raw in enumerate(text.splitlines(), 1):
            line = raw.strip()
            if not line or line.startswith("#"):
                continue
            self.events.append(self._parse(line, number))

    @classmethod
    def from_file(cls, path: Path | str) -> "KeyScript":
        return cls(Path(path).read_text(encoding="utf-8"))

    @staticmethod
    def _parse(line: str, number: int) -> KeyEvent:
        word, _, rest = line.partition(" ")
        upper = word.upper()
        try:
            if upper == "TYPE":
                if any(ord(c) > 255 for c in rest):
                    raise ValueError  # the panel has no such character
                return KeyEvent("type", rest)
            if upper == "IDLE":
                n = int(rest)
                if n < 0:
                    raise ValueError
                return KeyEvent("idle", n)
            if upper == "KEY":
                code = int(rest)
                if not 1 <= code <= 255:
                    raise ValueError
                return KeyEvent("key", code)
            if upper.startswith("SK") and upper[2:].isdigit() and 1 <= int(upper[2:]) <= 8 and not rest:
                return KeyEvent("key", SOFTKEY_BASE + int(upper[2:]))
            name = (upper + rest.upper()).replace(" ", "")
            if name in NAMED_KEYS:
                return KeyEvent("key", NAMED_KEYS[name])
        except ValueError:
            pass
        raise fail("KEY_SCRIPT_SYNTAX", f"line {number}: {line!r}")

    def inkey(self) -> int:
        """The next key code, or 0 at once when none is waiting (INKEY never blocks)."""
        while self.events:
            head = self.events[0]
            if head.kind == "idle":
                if head.value > 0:
                    head.value -= 1
                    return 0
                self.events.popleft()
                continue
            if head.kind == "type":
                if not head.value:
                    self.events.popleft()
                    continue
                code = ord(head.value[0])
                head.value = head.value[1:]
                if not head.value:
                    self.events.popleft()
                return code
            self.events.popleft()
            return head.value
        return 0

    def wait(self, what: str) -> KeyEvent:
        """The next key or typed text for a command that waits (SFK, INP): idle time just passes."""
        while self.events:
            head = self.events.popleft()
            if head.kind != "idle":
                return head
        raise fail("KEY_SCRIPT_EMPTY", what)

    def refuse(self, error: CplRuntimeError) -> None:
        """A typed entry the waiting command cannot take (INP: not a number, too long for the
        format): a script is wrong, so the run stops; an operator at a terminal types again."""
        raise error


# -- the screen ---------------------------------------------------------------------------------

class Field(Record):
    __slots__ = ("line", "column", "text")

    def __init__(self, line: int, column: int, text: str):
        self.line = line
        self.column = column
        self.text = text


class Screen(Graphics):
    """The CPL dialog window: text grid, softkeys, DLG fields, keys and the graphics of chapter 8."""

    def __init__(self, keys: KeyScript | str | None = None, mode: OutputMode | None = None,
                 bitmap_dir: FileRoot | Path | str | None = None, warn: WarnFn | None = None, typ2: bool = False):
        self.chars = [[" "] * COLUMNS for _ in range(LINES)]
        super().__init__(bitmap_dir=bitmap_dir, warn=warn)
        self.keys = keys if isinstance(keys, KeyScript) else KeyScript(keys or "")
        self.mode = mode or OutputMode()
        self.typ2 = typ2
        self.softkeys: list[str | None] | None = None
        self.font = (0, 0, 0, 0)
        self.styles: list[tuple[int, int, int, int]] = [self.font]
        self.fields: dict[str, Field] = {}
        self.in_dialog = False
        self.log: list[str] = []  # the lines shown, kept only while no on_output listener takes them
        self.on_output = None  # called with every line shown, instead of the log (CplIO sends it to session.say)
        self.on_wait = None  # called when SFK or INP starts waiting for the operator (--screen-dir pictures)
        self.on_input = None  # called with what the operator gave (a run-time input: ncvm translate marks it)
        self.editing: str | None = None  # the variable whose INP field waits for the operator
        self.labels: list[tuple[int, int, str, tuple[int, int, int, int], int]] = []  # GPR texts

    def __getattr__(self, name: str):
        """``cells`` (per text cell: foreground, background, style, used; -1: empty) is made at its first use,
        as the canvas is (Graphics.__getattr__): a program that shows nothing imports no numpy."""
        if name != "cells":
            return super().__getattr__(name)
        self.cells = np.full((LINES, COLUMNS, 4), -1, dtype=np.int16)
        return self.cells

    # -- text ------------------------------------------------------------------------------
    @staticmethod
    def _position(line, column) -> tuple[int, int]:
        try:
            ln, col = (int(round(v)) if not isinstance(v, bool) else None for v in (line, column))
        except TypeError:
            ln = col = None
        if ln is None or col is None or not (1 <= ln <= LINES and 1 <= col <= COLUMNS):
            raise fail("INVALID_LINE_OR_COLUMN", f"line {line!r}, column {column!r}")
        return ln, col

    def _style(self) -> int:
        if self.font not in self.styles:
            self.styles.append(self.font)
        return self.styles.index(self.font)

    def _write(self, line: int, column: int, text: str) -> None:
        style = self._style()
        row = line - 1
        shown = text[: COLUMNS - column + 1]  # cut at the right edge (column 79, L4547), no error
        for i, ch in enumerate(shown):
            c = column - 1 + i
            self.chars[row][c] = ch
            self.cells[row, c] = (self.text_color, self.text_bg, style, 1)
        self._log(shown)  # the output says what the screen shows

    def grid_lines(self) -> list[str]:
        """The 46 text lines as shown (trailing blanks dropped)."""
        return ["".join(r).rstrip() for r in self.chars]

    def text_view(self) -> list[str]:
        """The screen as text for an operator at a terminal: the grid lines that are not blank
        (numbered 1..46), the softkey bar and the INP field waiting for input."""
        view = [f"{n:2d}|{line}" for n, line in enumerate(self.grid_lines(), 1) if line.strip()]
        if self.softkeys is not None:
            keys = [f"[SK{i} {' '.join(self.softkey_lines(t))}]" for i, t in enumerate(self.softkeys, 1) if t]
            view.append("softkeys: " + (" ".join(keys) if keys else "(no labels)"))
        field = self.fields.get(self.editing) if self.editing is not None else None
        if field is not None:
            view.append(f"input {self.editing} (line {field.line}, column {field.column}): {field.text}")
        return view

    def output_lines(self) -> list[str]:
        """What the program showed the operator, in order: DSP/PRN texts and message-window lines."""
        return list(self.log)

    def message(self, text: str) -> None:
        """A line in the message window (PRN#(0,...), MSG)."""
        self._log(text)

    def _log(self, text: str) -> None:
        if self.on_output is not None:
            self.on_output(text)
        else:
            self.log.append(text)

    def _clear_text(self) -> None:
        self.chars = [[" "] * COLUMNS for _ in range(LINES)]
        if "cells" in self.__dict__:
            self.cells[...] = -1

    def CLS(self) -> None:  # noqa: N802
        super().CLS()
        self._clear_text()
        self.labels = []

    def CLG(self) -> None:  # noqa: N802
        super().CLG()
        self._clear_text()
        self.labels = []
        self.softkeys = None

    def CLR(self) -> None:  # noqa: N802
        super().CLR()
        w = self.window
        self.labels = [lb for lb in self.labels if not (w.xl <= lb[0] <= w.xr and w.yb <= lb[1] - BAND <= w.yt)]

    def DSP(self, line, column, *items) -> None:  # noqa: N802
        """``DSP(line,col,e1,...)``: formatted text at line/col (REAL positions are rounded)."""
        ln, col = self._position(line, column)
        for item in items:
            if kind_of(item) == "S" and len(text_of(item) or "") > MAX_DSP_STRING:
                raise fail("MAX_STRING_LENGTH", f"{len(text_of(item))} characters, at most {MAX_DSP_STRING}")
        text = format_items(items, ljust=self.mode.ljust, on_overflow="error").text
        self._write(ln, col, text)

    # -- dialog fields ---------------------------------------------------------------------
    def DLG(self) -> None:  # noqa: N802
        """``DLG``: start of a dialog-input range; PRN fields are collected for INP."""
        self.in_dialog = True
        self.fields = {}

    def ENDDLG(self) -> None:  # noqa: N802
        self.in_dialog = False

    def PRN(self, line, column, text, *value, name: str | None = None) -> None:  # noqa: N802
        """``PRN(line,col,"text")`` or ``PRN(line,col,"[text]fmt[text]",var)``: the value in the format,
        or the bare format when var is NUL. ``name`` (the variable's name) binds the field for INP."""
        ln, col = self._position(line, column)
        shown = format_items([text, *value], ljust=self.mode.ljust).text
        if value and name is not None and self.in_dialog:
            self.fields[name] = Field(ln, col, text_of(text) or "")
        self._write(ln, col, shown)

    def INP(self, name: str, current=None, kind: str = "R"):  # noqa: N802
        """``INP(var)``: the operator's input for the variable ``name`` (type letter ``kind``) through
        the field of its PRN. Returns the new value: the typed one, ``current`` after ENTER or a cursor
        key (skip), None after DEL (the value is cleared). INP of a string does nothing."""
        field = self.fields.get(name)
        if field is None:
            raise fail("INP_WITHOUT_PRN", name)
        if kind == "S":
            return current
        m = TEMPLATE.search(field.text)
        int_digits, decimals = template_shape(m.group()) if m else (9, 0 if kind == "I" else 3)
        value = current
        self.editing = name  # the picture taken while the operator is asked frames this field
        try:
            if self.on_wait is not None:
                self.on_wait()
            while True:
                event = self.keys.wait(f"INP({name})")
                if event.kind == "type":
                    try:
                        value = self._typed(event.value, kind, int_digits, decimals, name)
                    except CplRuntimeError as e:
                        self.keys.refuse(e)
                        continue
                    break
                if event.value == KEY_DEL:
                    value = None
                    continue
                if event.value == KEY_ENTER or event.value in CURSOR_KEYS:
                    break
        finally:
            self.editing = None
        self._write(field.line, field.column, format_items([field.text, value], ljust=self.mode.ljust).text)
        self._gave(f"operator input INP({name}) = {value}")
        return value

    def _gave(self, what: str) -> None:
        if self.on_input is not None:
            self.on_input(what)

    @staticmethod
    def _typed(text: str, kind: str, int_digits: int, decimals: int, name: str):
        found = scan_number(text.strip())
        if found is None or found[1] != len(text.strip()) or (kind == "I" and isinstance(found[0], float)):
            raise fail("KEY_SCRIPT_SYNTAX", f"INP({name}): {text!r} is not a {'INTEGER' if kind == 'I' else 'number'}")
        value = int(found[0]) if kind == "I" else float(found[0])
        digits = text.strip().lstrip("+-").split(".")
        if format_number(value, "I" if kind == "I" else "D", int_digits, decimals) is None or \
                (len(digits) > 1 and len(digits[1]) > decimals):
            raise fail("KEY_SCRIPT_SYNTAX", f"INP({name}): {text!r} does not fit the input format")
        return value

    # -- keys and softkeys -----------------------------------------------------------------
    def INKEY(self) -> int:  # noqa: N802
        """``INKEY``: the code of a key pressed and not yet processed, 0 if none (never waits); keys
        reach the program only while the dialog window is in the foreground."""
        code = self.keys.inkey() if self.foreground else 0
        if code:
            self._gave(f"key {code} (INKEY)")
        return code

    @property
    def softkey_count(self) -> int:
        return 5 if self.typ2 else 8

    def SFK(self, current, *texts, want_text: bool = False):  # noqa: N802
        """``SFK(var,[t1],...,[t8])``: show the bar and wait for a softkey. Returns its number (or its
        text when ``want_text``, for a string variable); LEVEL RETURN returns ``current`` unchanged."""
        if len(texts) > 8:
            raise fail("INVALID_PARAMETER", f"SFK takes at most 8 texts, not {len(texts)}")
        bar = [text_of(t) if is_text(t) else None for t in texts]
        self.softkeys = (bar + [None] * 8)[: self.softkey_count]
        self._log("SFK " + " ".join(f"[{i}:{t.replace('&', ' ')}]" for i, t in
                                          enumerate(self.softkeys, 1) if t))
        if self.on_wait is not None:
            self.on_wait()
        while True:
            event = self.keys.wait("SFK")
            if event.kind != "key":
                continue
            if event.value == KEY_LEVEL_RETURN:
                self._gave("LEVEL RETURN key (SFK)")
                return current
            n = event.value - SOFTKEY_BASE
            if 1 <= n <= self.softkey_count:
                self._gave(f"softkey {n} (SFK)")
                return (self.softkeys[n - 1] or "") if want_text else n

    def CSF(self) -> None:  # noqa: N802
        """``CSF``: remove the softkey bar."""
        self.softkeys = None

    @staticmethod
    def softkey_lines(text: str | None) -> list[str]:
        """A softkey text as its (at most) 3 lines of 9 characters; ``&`` breaks a line."""
        return [part[:9] for part in (text or "").split("&")[:3]]

    # -- fonts and text in the graphics ----------------------------------------------------
    def TFO(self, font=None, size=None, cut=None, orientation=None) -> None:  # noqa: N802
        """``TFO(font,size,cut,orientation)``: omitted values stay as they are."""
        f, s, c, o = self.font
        if font is not None:
            f = _whole(font, "font")
            if f not in FONTS:
                raise fail("INVALID_PARAMETER", f"TFO font {font!r} (0..10)")
        if size is not None:
            s = _whole(size, "size")
            height, width = s % 1000, s // 1000
            if s < 0 or height > 500 or width > 500 or (s and not height):
                raise fail("INVALID_PARAMETER", f"TFO size {size!r}")
        if cut is not None:
            c = _whole(cut, "cut")
            if not 0 <= c <= 3:
                raise fail("INVALID_PARAMETER", f"TFO cut {cut!r} (0..3)")
        if orientation is not None:
            o = _whole(orientation, "orientation")
            if not 0 <= o <= 360:
                raise fail("INVALID_PARAMETER", f"TFO orientation {orientation!r} (0..360)")
        self.font = (f, s, c, o)

    def GPR(self, x, y, text) -> None:  # noqa: N802
        """``GPR(xpix,ypix[+40],text)``: text with its bottom-left at pixel (x, y), y counted from the
        bottom of the softkey band (add 40 to match the other graphics commands)."""
        px, py = _int(x, "X value"), _int(y, "Y value")
        if not (0 <= px <= WIDTH - 1 and 0 <= py <= HEIGHT - 1):
            raise fail("INVALID_GRAPHICS_VALUE", f"GPR({x!r},{y!r})")
        string = text_of(text) or ""
        mask, ax, ay = text_mask(string, self.font)
        top, left = int(round(HEIGHT - 1 - py - ay)), int(round(px - ax))
        h, w = mask.shape
        r0, c0 = max(0, top), max(0, left)
        r1, c1 = min(HEIGHT, top + h), min(WIDTH, left + w)
        if r1 > r0 and c1 > c0:
            on = mask[r0 - top: r1 - top, c0 - left: c1 - left] >= 96
            self.canvas[r0:r1, c0:c1][on] = self.rgb(self.text_color)
            self.text_pixels[r0:r1, c0:c1] |= on
        # the canvas holds the text at the control's resolution; the PNG draws it again sharply
        self.labels.append((px, py, string, self.font, self.text_color))
        self._log(string)

    # -- the end of the program ------------------------------------------------------------
    def end_program(self) -> None:
        """What the control does at the end of a program: TFO back to (0,0,0,0), the softkey bar goes."""
        self.font = (0, 0, 0, 0)
        self.softkeys = None

    # -- rendering -------------------------------------------------------------------------
    def image(self, scale: int = 2):
        """The whole window (graphics, text grid, softkey bar) as a PIL image, ``scale`` times larger."""
        from PIL import Image, ImageDraw

        canvas = self.canvas.copy()
        canvas[self.text_pixels] = self.rgb(self.graphics_bg)  # GPR text is drawn sharply below
        img = Image.fromarray(canvas, "RGB").resize((WIDTH * scale, HEIGHT * scale), Image.NEAREST)
        draw = ImageDraw.Draw(img)
        for row in range(LINES):
            col = 0
            while col < COLUMNS:
                fg, bg, style, used = (int(v) for v in self.cells[row, col])
                if used < 0:
                    col += 1
                    continue
                end = col
                while end < COLUMNS and tuple(int(v) for v in self.cells[row, end]) == (fg, bg, style, used):
                    end += 1
                x0, y0 = col * CELL_W * scale, row * CELL_H * scale
                draw.rectangle([x0, y0, end * CELL_W * scale - 1, (row + 1) * CELL_H * scale - 1], fill=self.rgb(bg))
                mask, ax, ay = text_mask("".join(self.chars[row][col:end]), self.styles[style], scale)
                base = (row + 1) * CELL_H * scale - int(round(0.2 * CELL_H * scale))  # the line's baseline
                img.paste(self.rgb(fg), (int(round(x0 - ax)), int(round(base - ay))), Image.fromarray(mask))
                col = end
        for x, y, string, style, color in self.labels:
            mask, ax, ay = text_mask(string, style, scale)
            img.paste(self.rgb(color), (int(round(x * scale - ax)), int(round((HEIGHT - 1 - y) * scale - ay))),
                      Image.fromarray(mask))
        if self.softkeys is not None:
            self._draw_softkeys(draw, scale)
        self._frame_input_field(draw, scale)
        return img

    def _frame_input_field(self, draw, scale: int) -> None:
        """The INP field waiting for the operator: a frame in the text colour around its format."""
        field = self.fields.get(self.editing) if self.editing is not None else None
        if field is None:
            return
        m = TEMPLATE.search(field.text)
        first, last = (m.start(), m.end()) if m else (0, len(field.text))
        x0 = (field.column - 1 + first) * CELL_W * scale
        x1 = min(COLUMNS, field.column - 1 + last) * CELL_W * scale - 1
        y0 = (field.line - 1) * CELL_H * scale
        draw.rectangle([x0 - scale, y0, x1 + scale, y0 + CELL_H * scale - 1], outline=self.rgb(self.text_color),
                       width=scale)

    def _draw_softkeys(self, draw, scale: int) -> None:
        n = len(self.softkeys)
        key_w = WIDTH * scale / n
        top = (HEIGHT - BAND) * scale
        font = font_for(0, 0, 11 * scale)
        for i, text in enumerate(self.softkeys):
            x0 = int(i * key_w)
            draw.rectangle([x0 + scale, top + scale, int(x0 + key_w) - 2 * scale, HEIGHT * scale - scale],
                           fill=self.rgb(self.softkey_bg), outline=self.rgb(self.softkey_color))
            lines = self.softkey_lines(text)
            for j, part in enumerate(lines):
                y = top + (BAND * scale - len(lines) * 12 * scale) / 2 + (j + 1) * 12 * scale
                draw.text((x0 + key_w / 2, y), part, fill=self.rgb(self.softkey_color), font=font, anchor="md")

    def save_png(self, path: Path | str, scale: int = 2) -> Path:
        """Render the window to a PNG file."""
        path = Path(path)
        self.image(scale).save(path, "PNG")
        return path
