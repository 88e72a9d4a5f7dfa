"""One CPL program run's I/O, wired to an ncvm Session: files, screen, MMC and the shared LJUST state.

The CPL code generator creates one :class:`CplIO` per run (``CplIO.for_session(session)``) and
calls its parts: ``io.files.PRN(1, ...)``, ``io.screen.DSP(...)``, ``io.mmc.MMC(...)``,
``io.mode.LJUST()``; at the end of the main program it calls ``io.end_program()``.
Operator output (DSP/PRN texts, PRN#(0) message lines, SFK bars, GPR texts and warnings) goes to
``session.say`` as it happens, so it lands in the JSON ``output``.
"""

from __future__ import annotations

import sys
from pathlib import Path

from ....machine.files import FileRoot
from ..options import options as cpl_options
from .errors import CplWarning
from .files import CplFiles
from .format import OutputMode
from .mmc import Mmc
from .screen import KeyScript, Screen
from .terminal import TerminalKeys


class CplIO:
    def __init__(self, file_root: Path | str, clock=None, keys: KeyScript | str | None = None,
                 say=None, typ2: bool = False, bitmap_dir: Path | str | None = None, private: tuple = ()):
        """``private``: folders no name a program writes may reach (the state directory)."""
        self.mode = OutputMode()
        self.say = say
        root = Path(file_root)
        bitmaps = FileRoot(bitmap_dir if bitmap_dir is not None else root / "cplbmp", private)
        self.screen = Screen(keys=keys, mode=self.mode, warn=self._warn, typ2=typ2, bitmap_dir=bitmaps)
        self.screen.on_output = self._out
        self.files = CplFiles(root=root, clock=clock, message=self.screen.message, warn=self._warn, mode=self.mode,
                              private=private)
        self.mmc = Mmc()

    @classmethod
    def for_session(cls, session, typ2: bool = False) -> "CplIO":
        """The I/O of a run: the machine's file root and clock, output to say; the key script of
        ``--keys`` or, with ``keyboard``, the operator at the terminal on stdin; the file space of
        ``[cpl] file_space``, the zeros of ``[cpl] file_zeros``; the editor block of
        ``--editor-block``, whose text after the run is the result's ``editor_block``; the MMC client of
        ``RunOptions.mmc_client``."""
        options = session.options
        keys = None
        if isinstance(options.keys, KeyScript):  # read once already (a pipe cannot be read twice)
            keys = options.keys
        elif options.keys:
            keys = KeyScript.from_file(options.keys)
        elif options.keyboard:
            keys = TerminalKeys(sys.stdin.fileno(), sys.stderr, waits=options.on_operator_wait)
        io = cls(session.machine.file_root, clock=session.machine.clock, keys=keys, say=session.say, typ2=typ2,
                 private=(options.state_dir, *session.machine.own_files()))
        cpl = cpl_options(session.machine)
        io.files.space = cpl.file_space
        io.files.trim_zeros = cpl.file_zeros == "suppress"
        if isinstance(keys, TerminalKeys):
            keys.view = io.screen.text_view
        io.mmc.attach(options.mmc_client)
        if options.editor_block is not None:
            io.files.editor_block = options.editor_block
            session.extra["editor_block"] = options.editor_block
            io.files.on_editor_block = lambda text: session.extra.__setitem__("editor_block", text)
        return io

    def _out(self, line: str) -> None:
        if self.say is not None:
            self.say(line)

    def _warn(self, w: CplWarning) -> None:
        self._out(f"warning {w.code}: {w.message}")

    def end_program(self, png: Path | str | None = None) -> None:
        """End of the main program: files closed (pending records ended), LJUST off, TFO reset,
        softkeys gone; the screen saved as a PNG first when ``png`` is given."""
        self.files.close_all()
        if png is not None:
            self.screen.save_png(png)
        self.screen.end_program()
        self.mode.NJUST()
