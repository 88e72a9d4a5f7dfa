"""Positions, diagnostics and run-time faults shared by every dialect.

A user mistake never reaches the user as a Python traceback: the front ends
raise :class:`CompileFailed` (carrying :class:`Diagnostic` s) and the runtime
raises :class:`RuntimeFault` (carrying the manual's run-time error number, the
position and the call stack). Both render as ``path:line:col: error CODE: msg``
followed by the source line and a caret.
"""

from __future__ import annotations

from .records import FrozenRecord, Record
from .source import lines, lines_at, read_text


class Span(FrozenRecord):
    """A place in a source file: 1-based physical line, 1-based column (or None).

    Span, Diagnostic and Frame are records rather than dataclasses: every start-up imports them
    (ncvm/records.py)."""

    __slots__ = ("file", "line", "column", "end_column")

    def __init__(self, file: str, line: int, column: int | None = None, end_column: int | None = None):
        self.file = file
        self.line = line
        self.column = column
        self.end_column = end_column

    def __str__(self) -> str:
        if self.column is None:
            return f"{self.file}:{self.line}"
        return f"{self.file}:{self.line}:{self.column}"


class Diagnostic(Record):
    """One problem found while reading, checking or linking a program."""

    __slots__ = ("code", "message", "span", "severity", "notes")

    def __init__(self, code: str, message: str, span: Span | None, severity: str = "error",
                 notes: list[str] | None = None):
        self.code = code
        self.message = message
        self.span = span
        self.severity = severity
        self.notes = [] if notes is None else notes

    def render(self, source_lines: list[str] | dict[int, str] | None = None) -> str:
        """The diagnostic as ``ncvm`` prints it, with its source line: from ``source_lines`` (the file's lines,
        or some of them by number), else read from the file (that line alone)."""
        where = f"{self.span}: " if self.span else ""
        text = f"{where}{self.severity} {self.code}: {self.message}"
        if self.span and source_lines is None:
            source_lines = read_lines_at(self.span.file, {self.span.line})
        if isinstance(source_lines, list):
            source_lines = dict(enumerate(source_lines, 1)) if self.span else None
        if self.span and source_lines and self.span.line in source_lines:
            src = source_lines[self.span.line].rstrip("\r\n")
            text += f"\n    {src}"
            if self.span.column:
                width = max(1, (self.span.end_column or self.span.column + 1) - self.span.column)
                pad = "".join(c if c == "\t" else " " for c in src[: self.span.column - 1])
                text += f"\n    {pad}{'^' * width}"
        for note in self.notes:
            text += f"\n    note: {note}"
        return text

    def to_json(self) -> dict:
        return {
            "severity": self.severity,
            "code": self.code,
            "message": self.message,
            "file": self.span.file if self.span else None,
            "line": self.span.line if self.span else None,
            "column": self.span.column if self.span else None,
            "notes": list(self.notes),
        }


#: the diagnostics a check keeps of one program (the first, in line order); the others are counted, and the
#: count is shown after them (docs/decisions.md, "Issue 18: a check in bounded memory")
MAX_KEPT = 1000


class Diagnostics(list):
    """The diagnostics of one program: the first ``limit`` of them (:data:`MAX_KEPT`), and ``left_out``, how
    many more of each severity there were (a file of millions of bad lines is checked in bounded memory)."""

    def __init__(self, kept=(), left_out: dict[str, int] | None = None, limit: int = MAX_KEPT):
        super().__init__(kept)
        self.left_out = dict(left_out or {})
        self.limit = limit

    @classmethod
    def capped(cls, diagnostics, limit: int = MAX_KEPT) -> "Diagnostics":
        """The first ``limit`` of ``diagnostics``, the others counted (with those ``diagnostics`` left out already,
        when they are :class:`Diagnostics` themselves)."""
        out = cls(diagnostics[:limit], getattr(diagnostics, "left_out", None), limit)
        out.count_out(diagnostics[limit:])
        return out

    def count_out(self, diagnostics) -> None:
        for d in diagnostics:
            self.left_out[d.severity] = self.left_out.get(d.severity, 0) + 1

    def errors(self) -> int:
        """The errors among them, those left out too."""
        return sum(1 for d in self if d.severity == "error") + self.left_out.get("error", 0)

    def not_shown(self) -> str | None:
        """What the line after the kept diagnostics says (None when none was left out)."""
        if not self.left_out:
            return None
        errors, warnings = self.left_out.get("error", 0), sum(self.left_out.values()) - self.left_out.get("error", 0)
        counts = " and ".join(f"{n} more {what}{'s' if n != 1 else ''}" for n, what in ((errors, "error"),
                                                                                         (warnings, "warning")) if n)
        return f"{counts} not shown (a check lists the first {self.limit} diagnostics of a program)"


def render_all(diagnostics: list[Diagnostic]) -> list[str]:
    """Each diagnostic rendered, every file read once (a file with 100,000 errors was read 100,000 times), and
    only up to the last line a diagnostic shows."""
    wanted: dict[str, set[int]] = {}
    for d in diagnostics:
        if d.span:
            wanted.setdefault(d.span.file, set()).add(d.span.line)
    files = {path: read_lines_at(path, numbers) for path, numbers in wanted.items()}
    return [d.render(files[d.span.file] if d.span else None) for d in diagnostics]


def read_lines(path: str) -> list[str] | None:
    try:
        return lines(read_text(path))
    except OSError:
        return None


def read_lines_at(path: str, numbers) -> dict[int, str]:
    """Lines ``numbers`` of a file (:func:`ncvm.source.lines_at`); none when it cannot be read."""
    try:
        return lines_at(path, numbers)
    except (OSError, ValueError):  # ValueError: a path with a NUL byte, as read_text raises it too
        return {}


class NcvmError(Exception):
    """Base of every error that is the user's (or the program's) doing."""


class CompileFailed(NcvmError):
    """A program could not be read, checked or linked."""

    def __init__(self, diagnostics: list[Diagnostic]):
        self.diagnostics = diagnostics
        super().__init__("; ".join(f"{d.code}: {d.message}" for d in diagnostics))


class Frame(Record):
    """One entry of a run-time call stack, innermost last."""

    __slots__ = ("unit", "span")

    def __init__(self, unit: str, span: Span | None):
        self.unit = unit
        self.span = span

    def __str__(self) -> str:
        return f"{self.unit} at {self.span}" if self.span else self.unit


class RuntimeFault(NcvmError):
    """The running program stopped with an error the control would report.

    ``code`` is the manual's error number (e.g. ``"2167"`` for CPL, ``"E017"``);
    project-specific codes are listed in :data:`NCVM_CODES`.
    """

    def __init__(self, code: str, message: str, span: Span | None = None, stack: list[Frame] | None = None):
        self.code = code
        self.message = message
        self.span = span
        self.stack = stack or []
        self.notes: list[str] = []  # more about where it happened (e.g. the object block of a CL 800 statement)
        super().__init__(f"{code}: {message}")

    def diagnostic(self) -> Diagnostic:
        notes = [f"called from {f}" for f in reversed(self.stack[:-1])] if len(self.stack) > 1 else []
        return Diagnostic(self.code, self.message, self.span, notes=self.notes + notes)


class UsageError(NcvmError):
    """The command line or the machine file is wrong (exit code 2)."""


# Codes that are ncvm's own, where no manual has a number. Each dialect keeps
# its manual's codes in its own table; these are shared by all of them.
NCVM_CODES = {
    "NC001": "syntax error in NC block",
    "NC002": "arc radius mismatch between start and end point",
    "NC003": "arc needs a centre (I/J/K) or a radius (R)",
    "NC004": "unsupported G or M code",
    "NC005": "cutter radius compensation not supported here (the control's tool data for it is not read yet)",
    "NC006": "feed rate is zero for a feed move",
    "NC007": "unknown address letter",
    "NC008": "tool not in tool table",
    "NC009": "invalid parameter of a G function (a scaling factor of 0, a plane without its axes)",
    "NC010": "G96 at radius 0 without a spindle speed limit",
    "NC011": "axis word for an axis the machine does not have (the CPL control's run-time error 1938)",
    "NC012": "cutter radius compensation cannot place the tool (gouging, entry too short, tool too large for an "
             "arc, or a change not allowed while it is on)",
    "NC013": "a LinuxCNC program: # parameters, O-words or [expressions] are not DIN 66025 (one per program)",
    "NC014": "a thread (G33-G35) the axes cannot follow: the spindle stands, or an axis would have to run "
             "faster than its limit",
    "NC015": "a block with no one meaning: two functions of one modal group, or two that both take the axis "
             "words (rs274's \"Two G codes used from same modal group\"; nc/profiles/blockrules.py)",
    "NC016": "a DIN program opened with a % line ends with neither a closing % line nor M2/M30: the file may be cut "
             "short, nothing runs (rs274's \"File ended with no percent sign\"); a check warns of lines after the "
             "closing %, which are not read",
    "LIM001": "travel limit exceeded",
    "RUN001": "step limit reached (runaway program?)",
    "RUN002": "sub-program not found",
    "RUN003": "call nesting too deep",
    "RUN004": "run interrupted by the user",
    "RUN005": "waiting for ever (motion held, or every task waiting, with no way to go on)",
    "RUN006": "memory limit reached (--max-memory)",
    "RUN007": "a program of a batch could not be set up (its machine file, the state directory; docs/batch.md)",
    "RUN008": "program file changed while it ran: a long DIN program read a second time as it runs is not the "
              "program its first reading checked (docs/decisions.md)",
    "RUN009": "run stopped by a signal from outside, not by the user: SIGTERM (kill, timeout, a batch system or "
              "service manager) or SIGHUP (the terminal closed); exit 128 + the signal",
    "TRN001": "translation refused: the target control has no way to say what the run did (a probe move, a "
              "plane, an axis, a zero offset); no output written",
    "TRN002": "translation refused: the run did not end normally, or needs input it was not given; no output "
              "written",
    "TRN003": "translation written, with a warning: at this block the written program does what the simulated "
              "control did not (it goes on past an M0 the simulated run stopped at), or what the simulated "
              "machine made of the program (a move its limit cut short)",
    "IO001": "file access outside the controller's file root",
    "NEST001": "statements or expressions nested deeper than ncvm reads where the manual sets no limit "
               "(64 levels, 16 loops; docs/decisions.md)",
}
