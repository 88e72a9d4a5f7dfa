"""JSONL trace: one canon call per line, with the source file and line that caused it.

A move's line also holds what the path planner made of it (:mod:`ncvm.nc.planner`): ``time`` (s),
``v_entry`` and ``v_exit`` (path speed at its start and end, mm/min). The planner times a move when its
look-ahead window is complete, so lines wait here until the moves before and including them are timed:
at most the planner's window and chunk of moves, and every line is out when the run ends.

Every motion carries its end point twice: ``end`` in machine coordinates (every offset applied) and
``work`` in the program's coordinates (the selected zero offset and the tool length removed, as the
kernel's canon call ``frame`` gives them); docs/trace.md describes the records.
"""

from __future__ import annotations

import json
from collections import deque

from ..nc.canon import CanonSink, floats
from ..outpaths import OutputError

_UNTIMED = object()  # a move's time before the planner has timed it
#: the speeds of a block that does not move, until the move before it is timed: the path passes its point
#: at that move's exit speed (the planner never sees it: nothing to time)
_PASSING = object()


class JsonlTrace(CanonSink):
    def __init__(self, path):
        self._f = open(path, "w", encoding="utf-8")
        self.names: tuple[str, ...] = ()
        self._held: deque = deque()  # records waiting for the moves before them (or themselves) to be timed
        self._untimed: deque = deque()  # the move records among them still without a time, oldest first
        self._early: deque = deque()  # timings of moves whose call has not come yet
        self._planned = True  # the path planner times the moves (not a card of its own)
        self._exit = 0.0  # the exit speed of the last move timed (mm/min): where a block that does not move stands
        #: where a place the NC ran stands in the user's source (the API gives it Session.source_place)
        self.place = None
        self.removed: tuple[float, ...] = ()  # what work coordinates take off the machine's (zero offset, tool)

    def _write(self, call: str, src, **data) -> None:
        rec = {"call": call, **data}
        if src is not None:
            if self.place is not None:
                src = self.place(src)
            rec["file"], rec["line"] = src.file, src.line
        self._held.append(rec)
        self._release()

    def _move(self, call: str, src, p0, p1, **data) -> None:
        if not self._planned:
            self._write(call, src, **data)
        elif p0 == p1 and call != "arc":  # not planned: no time, passed at the speed of the move before
            if self._untimed:
                self._write(call, src, **data, time=_UNTIMED, v_entry=_PASSING)
                self._untimed.append(self._held[-1])
            else:
                self._write(call, src, **data, time=0.0, v_entry=self._exit, v_exit=self._exit)
        elif self._early:
            timed = self._early.popleft()
            self._exit = timed["v_exit"]
            self._write(call, src, **data, **timed)
        else:
            self._write(call, src, **data, time=_UNTIMED)
            self._untimed.append(self._held[-1])

    def _release(self) -> None:
        held = self._held
        try:
            while held and held[0].get("time") is not _UNTIMED:
                self._f.write(json.dumps(held.popleft()) + "\n")
        except OSError as e:  # a full disk: the run stops with a usage error naming the file
            raise OutputError(self._f.name, e) from None

    def timing(self, times, entry, exit):
        if times is None:
            self._planned = False
            return
        untimed, early = self._untimed, self._early
        for t, v0, v1 in zip(floats(times), floats(entry), floats(exit)):
            data = {"time": t, "v_entry": round(v0, 6), "v_exit": round(v1, 6)}
            if untimed:
                untimed.popleft().update(data)
                self._exit = passing = data["v_exit"]
                while untimed and untimed[0].get("v_entry") is _PASSING:
                    untimed.popleft().update(time=0.0, v_entry=passing, v_exit=passing)
            else:
                early.append(data)
        self._release()

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
        self._move("rapid", src, start, end, end=self._pos(end), work=self._work(end))

    def feed(self, start, end, feed, src):
        self._move("feed", src, start, end, end=self._pos(end), work=self._work(end), feed=feed)

    def arc(self, start, end, spec, feed, src):
        self._move("arc", src, start, end, end=self._pos(end), work=self._work(end), center=[spec.center[0], spec.center[1]],
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

    def homing(self, axes, src):
        self._write("homing", src, axes=[self.names[i] for i in axes])

    def frozen(self, what, src, scenario=False, warn=False):
        self._write("frozen", src, what=what)

    def message(self, text, src):
        self._write("message", src, text=text)

    def stop(self, kind, src):
        self._write("stop", src, kind=kind)

    def program_end(self, src):
        self._write("program_end", src)

    def end(self):
        for rec in self._untimed:  # a run stopped by a fault before its last moves were timed
            rec["time"] = None
            if rec.get("v_entry") is _PASSING:
                del rec["v_entry"]
        self._untimed.clear()
        self._release()
        try:
            self._f.close()
        except OSError as e:
            raise OutputError(self._f.name, e) from None
