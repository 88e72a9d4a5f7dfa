"""The ``sinumerik8xx`` profile: SINUMERIK 810-880, the controls CL 800 programs and SINUMERIK DIN blocks
(dialects ``cl800`` and ``sin800``) run on.

The groups are the internal G groups of ACG / @36b (CL 800 planning guide §11.5, L7392-7410); ACG reports
the active function of each from this table (dialects/sinumerik/positions.py). The planning guide names
most functions only in that table: a number whose meaning the SINUMERIK 810-880 programming guides give
(which are not among the manuals this project follows) carries that meaning, marked "see decisions" where ncvm runs it; a number
it does not run stops the block naming that meaning, so LinuxCNC's meaning of the number (G10 L2, G92
set position) is never used in its place. docs/decisions.md, "Issue 14: the control profiles".
"""

from __future__ import annotations

from .. import threads
from . import (
    CYCLE,
    DIALECT,
    DWELL,
    FAMILY,
    IMPLEMENTED,
    MACHINE,
    MOTION,
    REFUSED,
    SET,
    Address,
    Profile,
    Row,
    dwell_alone,
    refusal,
    refused,
)
from .iso import absolute, css_off, css_on, cutter_comp, inch, incremental, metric, nothing, plane, work_offset

TABLE = "L7392"  # the internal G groups of @36b (L7392-7410)
SPEED_LIMIT = "G92 (spindle speed limitation)"


def spindle_speed_limit(k, g, words, src):
    """G92 S<n>: the upper spindle speed limit under G96 constant cutting speed (the SINUMERIK 810-880 meaning,
    docs/decisions.md); the block holds nothing else that acts."""
    if "S" not in words or any(a in k.axis_of for a in words):
        k.fault("NC009", f"{SPEED_LIMIT} takes the limit S alone (G92 S3000); LinuxCNC's G92 (set position) is "
                "not a SINUMERIK function", src)
    if words["S"] < 0:
        k.fault("NC009", f"{SPEED_LIMIT}: S{words['S']:g} is negative", src)
    k.max_speed = words["S"]
    if k.css:
        k._css_update(src)


def tool_length_kept(k) -> list[float]:
    """G53 / POS MSYS keep the tool offset: the manual suppresses "all zero point-, PRESET-, and the DRF
    offsets" and leaves the tool offsets to the programmer ("the tool offsets must be cancelled for
    approaching a fixed machine point", L4083). The length stays on the tool axis."""
    kept = [0.0] * k.n_axes
    if k.tool_axis is not None:
        kept[k.tool_axis] = k.tool_length
    return kept


def auxiliary_h(k, value, words, src) -> None:
    """H<n>: an auxiliary function output to the PLC, as a machine-specific M function is (machine data bit
    5400.0 decides whether auxiliary functions go to the PLC, L3072): no motion of its own; the axes stand
    while the PLC takes it, and the trace records it (docs/decisions.md, "Issue 14: the H word"). A block
    with several H words carries the tuple of their values: each goes to the PLC, in the block's order."""
    k.planner.stop()
    for v in value if value.__class__ is tuple else (value,):
        code = f"H{v:g}"
        k.machine.plc.outputs[code] = True
        k.canon.aux(code, src)


def _row(g, group, meaning, run=SET, handler=None, status=IMPLEMENTED, line=TABLE):
    return Row(g, group, meaning, line, status, run, handler)


def _no(g, group, meaning, status=REFUSED):
    return refused(g, group, meaning, TABLE, status)


def _dialect(g, group, meaning):
    """A row the SINUMERIK block compiler takes out of the block (dialects/sinumerik/codegen.py)."""
    return Row(g, group, meaning, TABLE, DIALECT, SET, refusal(meaning + ", outside a SINUMERIK block"))


ROWS = (
    _row(0, "0", "rapid traverse", MOTION),
    _row(1, "0", "linear interpolation", MOTION),
    _no(10, "0", "linear interpolation in polar coordinates at rapid traverse, G group 0"),
    _no(11, "0", "linear interpolation in polar coordinates"),
    _row(2, "0", "circular interpolation clockwise", MOTION),
    _row(3, "0", "circular interpolation counter-clockwise", MOTION),
    _row(33, "0", "thread cutting, constant lead (nc/threads.py SinumerikThreads, the channel's motion mode)", MOTION,
         status=DIALECT),
    _row(34, "0", "thread cutting, increasing lead (nc/threads.py SinumerikThreads, the channel's motion mode)", MOTION,
         status=DIALECT),
    _row(35, "0", "thread cutting, decreasing lead (nc/threads.py SinumerikThreads, the channel's motion mode)", MOTION,
         status=DIALECT),
    _no(6, "0", "an interpolation of G group 0 the manual does not describe"),
    _no(12, "0", "circular interpolation in polar coordinates clockwise"),
    _no(13, "0", "circular interpolation in polar coordinates counter-clockwise"),
    _no(5, "0", "an interpolation of G group 0 the manual does not describe"),
    _no(7, "0", "an interpolation of G group 0 the manual does not describe"),
    _row(9, "1", "exact stop: this block ends at rest (the planner's path mode; blocks blend otherwise "
         "under G64)", SET, nothing, FAMILY),
    _row(17, "2", "plane X Y", SET, plane),
    _row(18, "2", "plane Z X", SET, plane),
    _row(19, "2", "plane Y Z", SET, plane),
    _dialect(16, "2", "free plane selection and length-compensation direction, G16 X Y Z- (ACAS, L2695)"),
    _row(40, "3", "cutter radius compensation off", SET, cutter_comp),
    _row(41, "3", "cutter radius compensation left (radius of the TO area's D)", SET, cutter_comp),
    _row(42, "3", "cutter radius compensation right (radius of the TO area's D)", SET, cutter_comp),
    _row(53, "4", "zero offsets suppressed for this block: its target in machine coordinates, the tool length "
         "kept (as POS MSYS, L4083)", MACHINE, tool_length_kept, FAMILY),
    *(_row(g, "5", f"settable zero offset G{g} (ZOA group {g - 53}, L2456)", SET, work_offset) for g in (54, 55, 56, 57)),
    _row(4, "6", "dwell, F or X seconds, a block of its own (G4 F=R27, L5465)", DWELL, dwell_alone, line="L5465"),
    _no(25, "6", "lower working area / spindle speed limitation"),
    _no(26, "6", "upper working area / spindle speed limitation"),
    _dialect(58, "6", "programmable zero offset 1, the block's axis values (ZOPR group 1, L2472)"),
    _dialect(59, "6", "programmable zero offset 2, the block's axis values (ZOPR group 2, L2472)"),
    Row(92, "6", "spindle speed limitation S under G96", TABLE, FAMILY, SET, spindle_speed_limit),
    _no(74, "6", "approach to the reference point"),
    _row(60, "7", "exact stop, modal: every block ends at rest (the planner's path mode, SINUMERIK_PATH_CODES)",
         SET, nothing, FAMILY),
    _no(63, "7", "tapping, override fixed at 100 %"),
    _row(64, "7", "continuous-path mode: blocks blend within the corner tolerance (the planner's path mode)",
         SET, nothing, FAMILY, "L5444"),
    _no(62, "7", "a path-control function of G group 7 the manual does not describe"),
    _row(70, "8", "dimensions in inch (PREP CYC, L4262)", SET, inch, line="L4262"),
    _row(71, "8", "dimensions in mm (PREP CYC, L4261)", SET, metric, line="L4261"),
    _row(80, "9", "drilling cycle off", CYCLE),
    *(Row(g, "9", f"drilling cycle G{g}: modal call of L{g} (dialects/sinumerik/drilling.py, the channel's handler)",
          TABLE, DIALECT, CYCLE) for g in range(81, 90)),
    _row(90, "10", "absolute dimensions (L1053)", SET, absolute, line="L1053"),
    _row(91, "10", "incremental dimensions (L1804)", SET, incremental, line="L1804"),
    _no(68, "10", "a dimension function of G group 10 the manual does not describe"),
    _row(94, "11", "feed in mm/min", SET, nothing),
    _row(95, "11", "feed in mm/rev (dialects/sinumerik/feeds.py, the channel's handler)", SET, threads.g95,
         status=DIALECT),
    _row(96, "11", "constant cutting speed (PRVC, L6542)", SET, css_on, line="L6542"),
    _row(97, "11", "constant cutting speed off, spindle speed in rev/min", SET, css_off),
    *(_no(g, "12", "soft approach to the contour") for g in (147, 247, 347)),
    *(_no(g, "12", "soft retract from the contour") for g in (148, 248, 348)),
    _no(48, "12", "retract as approached"),
    _no(110, "12", "a function of G group 12 the manual does not describe"),
    _no(111, "12", "a function of G group 12 the manual does not describe"),
    _no(50, "13", "scale modification off"),
    _no(51, "13", "scale modification on"),
    *(_no(g, "14", "a function of 850/880 G group 14 the manual does not describe") for g in range(150, 160)),
    *(_no(g, str(group), f"a function of 850/880 G group {group} the manual does not describe")
      for group, numbers in ((15, (130, 131)), (16, (230, 231)), (17, (330, 331)), (18, range(930, 935)))
      for g in numbers),
    _no(20, "", "not in the SINUMERIK G groups; units are G70/G71"),
    _no(21, "", "not in the SINUMERIK G groups; units are G70/G71"),
)

ADDRESSES = (
    Address("F", "feed; the dwell time after G4 (G4 F=R27, L5465)", "L1053", IMPLEMENTED),
    Address("S", "spindle speed; the cutting speed under G96; the limit after G92", "L6542", IMPLEMENTED),
    Address("T", "tool", "", IMPLEMENTED),
    Address("D", "tool offset of the TO area (length, and the radius of G41/G42)", "", IMPLEMENTED),
    Address("L", "sub-program call (L50 P1)", "", IMPLEMENTED),
    Address("P", "number of passes of an L call", "", IMPLEMENTED),
    Address("I", "circle centre, first axis (PRIP)", "L3350", IMPLEMENTED),
    Address("J", "circle centre, second axis (PRIP)", "L3350", IMPLEMENTED),
    Address("K", "circle centre, third axis (PRIP)", "L3350", IMPLEMENTED),
    Address("R", "circle radius (PRAD)", "", IMPLEMENTED),
    Address("B", "circle radius where B is no axis ([sin800] radius_address: B or U; on a straight block the "
            "rounding to the next, N5 X400 Y50 B100, L4237)", "L4237", IMPLEMENTED),
    Address("H", "auxiliary function output to the PLC (L3072), recorded like an M function to the PLC", "L3072",
            IMPLEMENTED, auxiliary_h),
    Address("A", "the angle address where A is no axis (PANG)", "", IMPLEMENTED),
)

SINUMERIK8XX = Profile(
    "sinumerik8xx", "Siemens CL 800 planning guide §11.5 (SINUMERIK 810-880)", ROWS, ADDRESSES,
    defaults={"0": 0, "2": 17, "3": 40, "5": 54, "7": 60, "8": 71, "9": 80, "10": 90, "11": 94},
    groups={"0": "interpolation", "1": "exact stop", "2": "plane", "3": "cutter radius compensation",
            "4": "zero offset suppression", "5": "settable zero offset", "6": "blockwise functions",
            "7": "path control", "8": "units", "9": "drilling cycles", "10": "dimensions", "11": "feed and speed",
            "12": "approach and retract", "13": "scale modification"},
)
