"""JSONL trace: one canon call per line, with the source file and line that caused it.

Every motion carries its end point twice: ``end`` in machine coordinates (every offset applied) and
``work`` in the program's coordinates (the selected zero offset and the tool length removed, as the
kernel's canon call ``frame`` gives them); docs/trace.md describes the records.
"""

from __future__ import annotations

import json

from ..nc.canon import CanonSink
from ..outpaths import OutputError


class JsonlTrace(CanonSink):
    def __init__(self, path):
        self._f = open(path, "w", encoding="utf-8")
        self.names: tuple[str, ...] = ()
        self.removed: tuple[float, ...] = ()  # what work coordinates take off the machine's (zero offset, tool)

    def _write(self, call: str, src, **data) -> None:
        rec = {"call": call, **data}
        if src is not None:
            rec["file"], rec["line"] = src.file, src.line
        try:
            self._f.write(json.dumps(rec) + "\n")
        except OSError as e:  # a full disk: the run stops with a usage error naming the file
            raise OutputError(self._f.name, e) from None

    def _pos(self, p) -> dict:
        return {n: round(v, 6) for n, v in zip(self.names, p)}

    def _work(self, p) -> dict:
        return {n: round(v - r, 6) for n, v, r in zip(self.names, p, self.removed)}

    def begin(self, axis_names, start):
        self.names = tuple(axis_names)
        self.removed = (0.0,) * len(self.names)
        self._write("begin", None, position=self._pos(start))

    def frame(self, frame, src):
        self.removed = frame.removed()

    def rapid(self, start, end, src):
        self._write("rapid", src, end=self._pos(end), work=self._work(end))

    def feed(self, start, end, feed, src):
        self._write("feed", src, end=self._pos(end), work=self._work(end), feed=feed)

    def arc(self, start, end, spec, feed, src):
        self._write("arc", src, end=self._pos(end), work=self._work(end), center=[spec.center[0], spec.center[1]],
                    plane=[self.names[spec.a], self.names[spec.b]], cw=spec.cw, turns=spec.turns, feed=feed)

    def dwell(self, seconds, src):
        self._write("dwell", src, seconds=seconds)

    def tool_change(self, tool, src):
        self._write("tool_change", src, tool=tool)

    def tool_offset(self, length, src):
        self._write("tool_offset", src, length=length)

    def spindle(self, speed, direction, src):
        self._write("spindle", src, speed=speed, direction=direction)

    def coolant(self, mode, src):
        self._write("coolant", src, mode=mode)

    def aux(self, code, src):
        self._write("aux", src, code=code)

    def probe(self, trip, target, src):
        removed = dict(zip(self.names, self.removed))
        self._write("probe", src, trip=trip, target=None if target is None else
                    {n: round(v - removed[n], 6) for n, v in target.items()})

    def frozen(self, what, src):
        self._write("frozen", src, what=what)

    def message(self, text, src):
        self._write("message", src, text=text)

    def stop(self, kind, src):
        self._write("stop", src, kind=kind)

    def program_end(self, src):
        self._write("program_end", src)

    def end(self):
        try:
            self._f.close()
        except OSError as e:
            raise OutputError(self._f.name, e) from None
