"""JSONL trace: one canon call per line, with the source file and line that caused it."""

from __future__ import annotations

import json

from ..nc.canon import CanonSink
from ..outpaths import OutputError


class JsonlTrace(CanonSink):
    def __init__(self, path):
        self._f = open(path, "w", encoding="utf-8")
        self.names: tuple[str, ...] = ()
        #: where a place the NC ran stands in the user's source (the API gives it Session.source_place)
        self.place = None

    def _write(self, call: str, src, **data) -> None:
        rec = {"call": call, **data}
        if src is not None:
            if self.place is not None:
                src = self.place(src)
            rec["file"], rec["line"] = src.file, src.line
        try:
            self._f.write(json.dumps(rec) + "\n")
        except OSError as e:  # a full disk: the run stops with a usage error naming the file
            raise OutputError(self._f.name, e) from None

    def _pos(self, p) -> dict:
        return {n: round(v, 6) for n, v in zip(self.names, p)}

    def begin(self, axis_names, start):
        self.names = tuple(axis_names)
        self._write("begin", None, position=self._pos(start))

    def rapid(self, start, end, src):
        self._write("rapid", src, end=self._pos(end))

    def feed(self, start, end, feed, src):
        self._write("feed", src, end=self._pos(end), feed=feed)

    def arc(self, start, end, spec, feed, src):
        self._write("arc", src, end=self._pos(end), center=[spec.center[0], spec.center[1]],
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
