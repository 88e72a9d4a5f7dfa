"""The operator at a terminal: key presses typed on stdin instead of read from a key script.

``ncvm run`` uses :class:`TerminalKeys` when no ``--keys`` script is given, stdin is a terminal and
``--json`` is not set (docs/cpl-io.md, "Keys from the terminal"). The operator types the same lines
a key script holds (``SK1``, ``ENTER``, ``TYPE 140``, ...). When SFK or INP waits, the dialog screen
is shown as text on stderr (stdout carries the program's output) and one line is read; a line that
is not understood is refused with the reason and asked for again. INKEY never waits: it looks at
stdin with ``select`` (timeout 0) and takes a line already typed as key events. End of input
(Ctrl-D) at a wait stops the run as an exhausted key script does (CPL705).
"""

from __future__ import annotations

import os
from typing import Callable, TextIO

from .errors import ERRORS, CplRuntimeError, fail
from .screen import KeyEvent, KeyScript

PROMPT = "keys> "
KEYS_HELP = "SK1..SK8, ENTER, LEVEL RETURN, UP, DOWN, LEFT, RIGHT, DEL, ESC, KEY n, TYPE text; Ctrl-D ends"
_SYNTAX = ERRORS["KEY_SCRIPT_SYNTAX"][1] + ": "


class TerminalKeys(KeyScript):
    """Key events from lines typed on the file descriptor ``fd``; prompts and screens go to ``out``.

    ``view`` gives the screen as text lines (``Screen.text_view``); CplIO connects it. ``waits`` is told
    when a wait for the operator starts (True) and ends (False): a progress display steps aside.
    """

    def __init__(self, fd: int, out: TextIO, view: Callable[[], list[str]] | None = None,
                 waits: Callable[[bool], None] | None = None):
        super().__init__("")
        self.fd = fd
        self.out = out
        self.view = view
        self.waits = waits or (lambda waiting: None)
        self.ended = False  # end of input seen
        self._pending = b""  # bytes read but not yet a whole line
        self._lines = 0  # lines typed so far
        self._asked = False  # the screen was shown for the wait in progress; a refusal only asks again

    # -- reading lines ---------------------------------------------------------------------------
    def _ready(self) -> bool:
        import select  # here: only a run that reads the keyboard needs it (start-up, issue 18)

        return bool(select.select([self.fd], [], [], 0)[0])

    def _read_line(self) -> str | None:
        """One typed line (blocks until it is complete), or None at end of input. After the end
        nothing more is read: a terminal would wait again."""
        while b"\n" not in self._pending and not self.ended:
            chunk = os.read(self.fd, 4096)
            if not chunk:
                self.ended = True
                break
            self._pending += chunk
        if not self._pending:
            return None
        line, _, self._pending = self._pending.partition(b"\n")
        self._lines += 1
        return line.decode("utf-8", errors="replace").rstrip("\r")

    def _take(self, line: str) -> bool:
        """Queue the events of one typed line; False (and the reason on ``out``) when it is not understood."""
        text = line.strip()
        if text and not text.startswith("#"):
            try:
                self.events.append(self._parse(text, self._lines))
            except CplRuntimeError:
                self._say(f"refused: {text!r} is not a key ({KEYS_HELP})")
                return False
        return True

    # -- the KeyScript interface ------------------------------------------------------------------
    def inkey(self) -> int:
        """INKEY: a line typed meanwhile becomes key events; never waits. A line that is not
        understood is refused on ``out`` and dropped (the program runs on)."""
        while not self.events and not self.ended and b"\n" not in self._pending and self._ready():
            chunk = os.read(self.fd, 4096)
            if not chunk:
                self.ended = True
                break
            self._pending += chunk
        while not self.events and b"\n" in self._pending:
            self._take(self._read_line())
        return super().inkey()

    def wait(self, what: str) -> KeyEvent:
        """SFK/INP: keys typed earlier first, else show the screen and read lines until one is understood."""
        while True:
            if any(e.kind != "idle" for e in self.events):
                self._asked = False  # a refusal before applies to this entry only
                return super().wait(what)
            self.events.clear()  # idle time passes while the operator is asked
            self.waits(True)
            try:
                self._ask(what)
                line = self._read_line()
            finally:
                self.waits(False)
            if line is None:
                self._say("")
                raise fail("KEY_SCRIPT_EMPTY", f"{what}: end of input from the terminal")
            self._asked = not self._take(line)

    def refuse(self, error: CplRuntimeError) -> None:
        """An INP entry the field cannot take: say why; the field waits for the next line."""
        self._say("refused: " + error.message.removeprefix(_SYNTAX))
        self._asked = True

    # -- output ----------------------------------------------------------------------------------
    def _ask(self, what: str) -> None:
        """The screen and the prompt; after a refusal only the prompt."""
        lines = []
        if not self._asked:
            lines = ["-" * 8 + " CPL dialog screen " + "-" * 52]
            lines += self.view() if self.view is not None else []
            lines.append(f"{what} waits for a key: {KEYS_HELP}")
        self._asked = False
        self.out.write("".join(line + "\n" for line in lines) + f"{what} {PROMPT}")
        self.out.flush()

    def _say(self, text: str) -> None:
        self.out.write(text + "\n")
        self.out.flush()
