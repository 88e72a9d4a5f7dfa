"""Turning a lowered program into Python source, compiling it once, caching it by content.

Front ends emit Python lines through :class:`PySource`, tagging each with the
source line it came from. The compiled code object is cached by the hash of
the generated text (the analogue of a control's link table), and the line map
turns a Python traceback back into the program's file and line when a fault
happens (runtime.locate), so generated code need not track its position at run time.
"""

from __future__ import annotations

import hashlib
from contextlib import contextmanager
from types import CodeType

_CODE_CACHE: dict[str, CodeType] = {}


class PySource:
    """Python source under construction, with a map from generated line to program line."""

    def __init__(self, filename: str):
        self.filename = filename
        self.lines: list[str] = []
        self.line_map: list[int] = []  # index = generated line - 1 -> source line (0 = none)
        self.col_map: list[int | None] = []  # index = generated line - 1 -> source column (None = unknown)
        self._indent = 0
        self.current_line = 0
        self.current_col: int | None = None

    def emit(self, text: str, src_line: int | None = None, src_col: int | None = None) -> None:
        if src_line is not None:
            self.current_line = src_line
            self.current_col = src_col
        self.lines.append("    " * self._indent + text)
        self.line_map.append(self.current_line)
        self.col_map.append(self.current_col)

    def append(self, other: PySource) -> None:
        """Take over the lines of ``other`` as they are (a body generated apart), with their source places."""
        self.lines.extend(other.lines)
        self.line_map.extend(other.line_map)
        self.col_map.extend(other.col_map)

    @contextmanager
    def block(self, header: str, src_line: int | None = None, src_col: int | None = None):
        """``with src.block("while x:"):`` emits the header and indents its body."""
        self.emit(header, src_line, src_col)
        self._indent += 1
        start = len(self.lines)
        yield
        if len(self.lines) == start:
            self.emit("pass")
        self._indent -= 1

    def text(self) -> str:
        return "\n".join(self.lines) + "\n"

    def compile(self) -> CodeType:
        return compile_cached(self.text(), self.filename)

    def source_line(self, py_line: int) -> int:
        if 1 <= py_line <= len(self.line_map):
            return self.line_map[py_line - 1]
        return 0

    def source_col(self, py_line: int) -> int | None:
        """The column a front end gave with the line (None when it gave none, or added lines without one)."""
        if len(self.col_map) == len(self.line_map) and 1 <= py_line <= len(self.col_map):
            return self.col_map[py_line - 1]
        return None


def compile_cached(text: str, filename: str) -> CodeType:
    """``compile(text)`` once per distinct text and file name."""
    key = hashlib.sha256((filename + "\0" + text).encode()).hexdigest()
    code = _CODE_CACHE.get(key)
    if code is None:
        code = compile(text, filename, "exec")
        _CODE_CACHE[key] = code
    return code
