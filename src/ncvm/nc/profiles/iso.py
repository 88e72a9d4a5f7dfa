"""The ``iso`` profile: DIN 66025 / ISO 6983 as LinuxCNC's rs274 reads it (the ``din`` dialect).

LinuxCNC 2.9 is the reference (its modal groups, numbered as in its G-code documentation); the
``line`` column names the rs274 group. The handlers below are also the ones the other profiles use
where the control means the same.
"""

from __future__ import annotations

import math

from .. import cutter, threads
from ..cycles import CODES as CYCLE_CODES
from . import (
    AFTER_TOOL_CHANGE,
    ALONE,
    CYCLE,
    DWELL,
    IMPLEMENTED,
    INCH,
    ISO_DWELL_HINT,
    MACHINE,
    MOTION,
    POSITION,
    SET,
    Profile,
    Row,
    dwell_alone,
    refused,
)
from .blockrules import axis_users, d_word

WORK_OFFSETS = {54: "G54", 55: "G55", 56: "G56", 57: "G57", 58: "G58", 59: "G59"}


def plane(k, g, words, src):
    k.plane = g
    k.plane_mirrored = False
    k.plane_unknown = None


def absolute(k, g, words, src):
    k.absolute = True


def incremental(k, g, words, src):
    k.absolute = False


def inch(k, g, words, src):
    k.scale = INCH


def metric(k, g, words, src):
    k.scale = 1.0


def work_offset(k, g, words, src):
    k.set_work_offset(WORK_OFFSETS[g])


def cutter_comp(k, g, words, src):
    cutter.select(k, g, words, src)


def nothing(k, g, words, src):
    """A function whose meaning is the state ncvm always has (G94 feed per minute, G64 path mode)."""


def css_on(k, g, words, src):
    k.css = k.spindle_bound = True


def css_on_limited(k, g, words, src):
    """rs274's G96 D<max> S<speed>: D is the maximum spindle speed while G96 is on; a G96 without D has no
    limit, as in rs274 (no DIN machine file gives a maximum spindle speed; radius 0 stays NC010)."""
    limit = words.get("D", math.inf)
    if limit <= 0:
        k.fault("NC009", f"G96: the spindle speed limit D{limit:g} is not positive", src)
    k.max_speed = limit
    css_on(k, g, words, src)


def set_position_axes(k, g, words, src):
    """rs274 stops a G92 without axis words ("All axes missing with G92"): G92 S is not a speed limit here."""
    if not any(name in words for name in k.axis_of):
        k.fault("NC009", "G92: all axes missing (G92 sets the position of the axes it names; it is no spindle "
                "speed limit in DIN 66025 / rs274)", src)


def css_off(k, g, words, src):
    k._g97()


def tool_length(k, g, words, src):
    """G43/G44 H<n>: the tool length of tool n (H, else the tool in the spindle), plus or minus (a D word in
    the block is refused before, as rs274 refuses it: nc/profiles/blockrules.py)."""
    number = int(words.get("H", k.tool))
    length = k._tool(number, src).length if number else 0.0
    k.set_tool_length(length if g == 43 else -length, src, number, subtracted=g == 44)


def tool_length_off(k, g, words, src):
    k.set_tool_length(0.0, src)


def g92_clear(k, g, words, src):
    k.g92 = [0.0] * k.n_axes
    k._set_offsets_keep_machine()


def offset_table(k, g, words, src):
    k._set_offset_table(words, src)


def dwell(k, g, words, block_g, src):
    """G4 P<seconds>: rs274 dwells, then makes the block's move (LinuxCNC's order of execution: the dwell is
    step 10, the motion step 21), its F a feed. Without P the time is X or F as DIN controls write it, and the
    block is the dwell alone (:func:`~ncvm.nc.profiles.dwell_alone`)."""
    if "P" in words:
        if words["P"] < 0.0:
            k.fault("NC009", f"G4: the dwell time P{words['P']:g} is negative", src)
        return words["P"], False
    return dwell_alone(k, g, words, block_g, src, True, ISO_DWELL_HINT)


def _row(g, group, meaning, line, run=SET, handler=None, status=IMPLEMENTED):
    return Row(g, group, meaning, line, status, run, handler)


_CYCLE_MEANING = {73: "drilling cycle with chip breaking", 74: "left-hand tapping cycle", 80: "cancel canned cycle",
                  81: "drilling cycle", 82: "drilling cycle with dwell", 83: "peck drilling cycle",
                  84: "right-hand tapping cycle", 85: "boring cycle, feed out", 86: "boring cycle, spindle stop, rapid out",
                  87: "back boring cycle", 88: "boring cycle, spindle stop, manual out",
                  89: "boring cycle, dwell, feed out", 98: "canned cycle return to the initial level",
                  99: "canned cycle return to the R level"}

ROWS = (
    _row(0, "1 motion", "rapid positioning", "rs274 group 1", MOTION),
    _row(1, "1 motion", "linear interpolation", "rs274 group 1", MOTION),
    _row(2, "1 motion", "circular interpolation clockwise", "rs274 group 1", MOTION),
    _row(3, "1 motion", "circular interpolation counter-clockwise", "rs274 group 1", MOTION),
    _row(4, "0 non-modal", "dwell P seconds, then the block's move; without P the time is X or F as DIN controls "
         "write it, in a block of its own", "rs274 group 0", DWELL, dwell),
    _row(10, "0 non-modal", "G10 L2 P1..P6: set zero offset G54..G59 (other forms refused)", "rs274 group 0",
         ALONE, offset_table),
    _row(17, "2 plane", "plane XY", "rs274 group 2", SET, plane),
    _row(18, "2 plane", "plane ZX", "rs274 group 2", SET, plane),
    _row(19, "2 plane", "plane YZ", "rs274 group 2", SET, plane),
    _row(20, "6 units", "inch", "rs274 group 6", SET, inch),
    _row(21, "6 units", "millimetre", "rs274 group 6", SET, metric),
    _row(40, "7 cutter radius compensation", "cutter radius compensation off", "rs274 group 7", SET, cutter_comp),
    _row(41, "7 cutter radius compensation", "cutter radius compensation left", "rs274 group 7", SET, cutter_comp),
    _row(42, "7 cutter radius compensation", "cutter radius compensation right", "rs274 group 7", SET, cutter_comp),
    _row(41.1, "7 cutter radius compensation", "dynamic cutter radius compensation left, D = tool diameter",
         "rs274 group 7", SET, cutter_comp),
    _row(42.1, "7 cutter radius compensation", "dynamic cutter radius compensation right, D = tool diameter",
         "rs274 group 7", SET, cutter_comp),
    _row(43, "8 tool length offset", "tool length offset (H)", "rs274 group 8", AFTER_TOOL_CHANGE, tool_length),
    _row(44, "8 tool length offset", "tool length offset, negative (H)", "rs274 group 8", AFTER_TOOL_CHANGE, tool_length),
    _row(49, "8 tool length offset", "tool length offset off", "rs274 group 8", AFTER_TOOL_CHANGE, tool_length_off),
    _row(53, "0 non-modal", "move in machine coordinates (this block)", "rs274 group 0", MACHINE),
    *(_row(g, "12 coordinate system", f"select work offset {name}", "rs274 group 12", SET, work_offset)
      for g, name in WORK_OFFSETS.items()),
    _row(9, "0 non-modal", "exact stop at the end of this block (the planner's path mode, nc/kernel.py ISO_PATH_CODES)",
         "rs274 group 0", SET, nothing),
    _row(33, "1 motion", "spindle-synchronised motion, K the distance per revolution (nc/threads.py, the din "
         "dialect's motion mode)", "rs274 group 1", MOTION),
    refused(33.1, "1 motion", "rigid tapping: K the pitch, the spindle reversed at the depth and the tap back at "
            "its start", "rs274 group 1"),
    refused(76, "1 motion", "multi-pass threading cycle: P pitch, I J K R Q H E L", "rs274 group 1"),
    _row(60, "13 path control", "exact stop, modal (the planner's path mode)", "rs274 group 13", SET, nothing),
    _row(61, "13 path control", "exact path mode (the planner's path mode)", "rs274 group 13", SET, nothing),
    _row(61.1, "13 path control", "exact stop mode (the planner's path mode)", "rs274 group 13", SET, nothing),
    _row(64, "13 path control", "path blending, P the tolerance (the planner's path mode)", "rs274 group 13", SET,
         nothing),
    _row(70, "6 units", "inch (DIN 66025)", "DIN 66025", SET, inch),
    _row(71, "6 units", "millimetre (DIN 66025)", "DIN 66025", SET, metric),
    _row(90, "3 distance mode", "absolute distances", "rs274 group 3", SET, absolute),
    _row(91, "3 distance mode", "incremental distances", "rs274 group 3", SET, incremental),
    _row(92, "0 non-modal", "coordinate system offset (set position)", "rs274 group 0", POSITION,
         set_position_axes),
    _row(92.1, "0 non-modal", "cancel the G92 offsets", "rs274 group 0", SET, g92_clear),
    _row(94, "5 feed rate mode", "units per minute feed", "rs274 group 5", SET, threads.g94),
    _row(95, "5 feed rate mode", "units per revolution feed (nc/threads.py)", "rs274 group 5", SET, threads.g95),
    _row(96, "14 spindle speed mode", "constant surface speed", "rs274 group 14", SET, css_on_limited),
    _row(97, "14 spindle speed mode", "spindle speed in rev/min", "rs274 group 14", SET, css_off),
    *(_row(g, "10 return mode" if g >= 98 else "1 motion", _CYCLE_MEANING[g], "rs274 group 1" if g < 98 else
           "rs274 group 10", CYCLE) for g in sorted(CYCLE_CODES)),
)

#: rs274's M groups (LinuxCNC interp_array.cc): two M functions of one group in a block are refused
M_GROUPS = {**dict.fromkeys((0, 1, 2, 30, 60), "4 stopping"), **dict.fromkeys((3, 4, 5, 19), "7 spindle"),
            **dict.fromkeys((6, 61), "6 tool change"), **dict.fromkeys((7, 8, 9), "8 coolant"),
            **dict.fromkeys(range(48, 54), "9 override switches"), **dict.fromkeys(range(62, 69), "5 digital I/O")}

ISO = Profile("iso", "LinuxCNC 2.9 rs274 (DIN 66025 / ISO 6983)", ROWS,
              defaults={"1 motion": 0, "2 plane": 17, "3 distance mode": 90, "6 units": 21,
                        "7 cutter radius compensation": 40, "12 coordinate system": 54},
              m_groups=M_GROUPS, yielding=frozenset((80,)),  # rs274: G80 gives way to another motion code
              block_rules=(axis_users, d_word))

