"""Flat G-code writer: the run as plain ISO / LinuxCNC G-code (no variables, no loops).

Positions are written in machine coordinates under G90 with no offsets active,
so the file reproduces the machine's motion on any control; arcs stay G2/G3
with incremental centres. LinuxCNC's ``rs274`` reads the output.
"""

from __future__ import annotations

from ..nc.canon import CanonSink
from ..outpaths import OutputError

ISO_AXES = "XYZABCUVW"
PLANE_OF = {("X", "Y"): "G17", ("Z", "X"): "G18", ("Y", "Z"): "G19"}
CENTRE_WORDS = {"X": "I", "Y": "J", "Z": "K"}
#: the first line of every file written, by which the next run knows it may write the file again
HEADER = "(written by ncvm: flat G-code in machine coordinates)"


def _f(v: float) -> str:
    text = f"{v:.4f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


class GcodeWriter(CanonSink):
    def __init__(self, path):
        self._f = open(path, "w", encoding="ascii", errors="replace")
        self.names: tuple[str, ...] = ()
        self.feed_rate = None
        self.plane = "G17"

    def _line(self, text: str) -> None:
        try:
            self._f.write(text + "\n")
        except OSError as e:  # a full disk: the run stops with a usage error naming the file
            raise OutputError(self._f.name, e) from None

    def _axes(self, p) -> str:
        return " ".join(f"{n}{_f(v)}" for n, v in zip(self.names, p) if n in ISO_AXES)

    def _feed(self, feed: float) -> str:
        if feed != self.feed_rate:
            self.feed_rate = feed
            return f" F{_f(feed)}"
        return ""

    def begin(self, axis_names, start):
        self.names = tuple(axis_names)
        extra = [n for n in self.names if n not in ISO_AXES]
        self._line(HEADER)
        if extra:
            self._line(f"(axes {' '.join(extra)} have no ISO address and are left out)")
        # every offset cleared, so the numbers below are machine coordinates on the receiving control too
        zero = " ".join(f"{n}0" for n in self.names if n in ISO_AXES)
        self._line("G21 G90 G17 G94 G40 G49 G80 G92.1")
        self._line(f"G10 L2 P1 {zero}")
        self._line("G54")

    def rapid(self, start, end, src):
        self._line(f"G0 {self._axes(end)}")

    def feed(self, start, end, feed, src):
        self._line(f"G1 {self._axes(end)}{self._feed(feed)}")

    def arc(self, start, end, spec, feed, src):
        an, bn = self.names[spec.a], self.names[spec.b]
        plane = PLANE_OF.get((an, bn))
        if plane is None or an not in CENTRE_WORDS or bn not in CENTRE_WORDS:
            self._line(f"(arc in the plane of {an} and {bn} written as a straight move)")
            self._line(f"G1 {self._axes(end)}{self._feed(feed)}")
            return
        if plane != self.plane:
            self.plane = plane
            self._line(plane)
        ci = _f(spec.center[0] - start[spec.a])
        cj = _f(spec.center[1] - start[spec.b])
        turns = f" P{spec.turns + 1}" if spec.turns else ""
        self._line(f"{'G2' if spec.cw else 'G3'} {self._axes(end)} {CENTRE_WORDS[an]}{ci} {CENTRE_WORDS[bn]}{cj}"
                   f"{turns}{self._feed(feed)}")

    def dwell(self, seconds, src):
        self._line(f"G4 P{_f(seconds)}")

    def tool_change(self, tool, src):
        self._line(f"T{tool} M6")

    def spindle(self, speed, direction, src):
        self._line({1: f"M3 S{_f(speed)}", -1: f"M4 S{_f(speed)}"}.get(direction, "M5"))

    def coolant(self, mode, src):
        self._line({"mist": "M7", "flood": "M8"}.get(mode, "M9"))

    def message(self, text, src):
        self._line(f"(MSG, {text.replace('(', '[').replace(')', ']')})")

    def stop(self, kind, src):
        self._line(kind)

    def program_end(self, src):
        self._line("M2")

    def end(self):
        try:
            self._f.close()
        except OSError as e:
            raise OutputError(self._f.name, e) from None
