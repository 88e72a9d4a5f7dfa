"""The SINUMERIK family's errors: the NC alarm "CL 800 error" at run time, a part program the reader refuses.

The WS 800 A compiler's messages (E/S/W numbers) are :class:`.cl800.errors.CompilerMessage`.
"""

from __future__ import annotations


class Cl800Error(Exception):
    """The NC alarm "CL 800 error" (manual L725-728): the channel stops."""


class ReadError(Exception):
    """A block the NC cannot read (SIN001, SIN003 ...), at column ``col`` of its line."""

    def __init__(self, col: int, message: str, code: str = "SIN001"):
        self.col = col
        self.message = message
        self.code = code
