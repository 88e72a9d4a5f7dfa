"""The ``typ3osa`` profile: Bosch Rexroth Typ3 osa / PNC, the control of the CPL manual.

The groups are the indices of SD(1) (the supplementary table of the CPL manual, L2302-2306); SD(1,n,1),
NCF and MCODS report the active function of each from this table (dialects/cpl/system/sysdata.py).
The block syntax and the exact behaviour of most functions are in Bosch's DIN programming manual, which
is not among the manuals this project follows: a function the CPL manual names only by number is refused naming its group,
or, where DIN 66025 gives the number a meaning the Typ3 group table agrees with, that meaning (marked
"see decisions" when ncvm runs it). docs/decisions.md, "Issue 14: the control profiles", records each
reading.
"""

from __future__ import annotations

from .. import threads
from . import (
    CYCLE,
    DIALECT,
    DWELL,
    FAMILY,
    IMPLEMENTED,
    LATE,
    MOTION,
    POSITION,
    REFUSED,
    SET,
    Address,
    Profile,
    Row,
    dwell_alone,
    modal_only,
    refusal,
    refused,
)
from .iso import absolute, cutter_comp, inch, incremental, metric, nothing, work_offset

TABLE = "L2302"  # the supplementary table of SD(1) groups (L2302-2306)
#: the tool compensation tables G22 K<n> selects: the database tables K4 and K5 (TC, L1854-1884), 0 = none
COMP_TABLES = (0, 4, 5)
#: the plane G17/G18/G19 whose main and secondary axes two axis names are (in that order)
PLANE_OF_AXES = {("X", "Y"): 17, ("Z", "X"): 18, ("Y", "Z"): 19}
UNKNOWN = "its meaning is in Bosch's DIN programming manual; the CPL manual does not describe it"


def plane(k, g, words, src):
    """G17/G18/G19: the plane of the first and second axes (SD(11) reads them)."""
    k.plane = g
    k.modal.pop("10", None)


def g20_fault(named: list) -> tuple[str, str] | None:
    """(code, message) of why ``G20`` with the axis words ``named`` (in the block's order) cannot run, None
    when it can; the run and the check ask the same."""
    if len(named) != 2:
        return "NC009", (f"G20 (plane switchover) names the main and the secondary axis with the pole's "
                         f"coordinates, e.g. G20 X0 Y0; this block names {len(named)} axes")
    if tuple(named) not in PLANE_OF_AXES:
        return "NC004", (f"G20 (plane switchover) to main axis {named[0]} and secondary axis {named[1]} is not "
                         "supported by ncvm (it runs the planes of G17 (X Y), G18 (Z X) and G19 (Y Z))")
    return None


def g20(k, g, words, src) -> bool:
    """G20: plane switchover to the two axes of the block, main axis first; their values are the pole
    (L2371-2375: ``N40 G20 [AXP(A%,E)] [AXP(B%,E)]`` "plane switchover with G20; pole at 0,0"). ncvm
    runs the planes of G17, G18 and G19 this way; the pole is kept (no function ncvm runs reads it)."""
    named = [name for name in words if name in k.axis_of]
    fault = g20_fault(named)
    if fault is not None:
        k.fault(*fault, src)
    k.plane = PLANE_OF_AXES[tuple(named)]
    k.modal["10"] = 20
    k.modal["G20 pole"] = tuple(words[n] * k.scale for n in named)
    return True


def zero_shift_off(k, g, words, src):
    """G53: axis zero shift off (the group G53-G59, L2302; DIN 66025 "cancel the zero shift")."""
    k.set_work_offset(None)


def table_fault(n) -> str | None:
    """Why ``G22 K<n>`` (``n`` None: no K word) cannot run (None: it can); the run and the check ask the same."""
    if n is None or n not in COMP_TABLES:
        return (f"G22 selects a tool compensation table with K4 or K5 (K0: none); "
                f"{'no K word' if n is None else f'K{n:g}'} is not one")
    return None


def comp_table(k, g, words, src) -> bool:
    """G22 K<n>: the tool compensation table H and D read (K4, K5; K0 none), see docs/decisions.md."""
    n = words.get("K")
    fault = table_fault(n)
    if fault is not None:
        k.fault("NC009", fault, src)
    k.modal["G22"] = int(n)
    return True


#: ``kernel.modal`` key of the length (mm) the selected external and general tool compensations add to H's
#: on the tool axis (dialects/cpl/system/gfuncs.py sets it; docs/decisions.md "Typ3 external compensation")
EXTERNAL_LENGTH = "external tool length"


def length_fault(value, table: int) -> str | None:
    """Why ``H<value>`` cannot run under ``G22 K<table>`` (None: it can); the run and the check ask the same."""
    if value != int(value) or not 0 <= value <= 48:
        return f"H{value:g}: the length compensation is a compensation group 1..48 (H0: off)"
    if value and not table:
        return (f"H{value:g}: no tool compensation table is selected (G22 K0, L1146): the length of "
                f"compensation group {value:g} has no table to come from; select K4 or K5 with G22 first")
    return None


def length_comp(k, value, words, src):
    """H<n>: tool length compensation of compensation group n of the selected table (TC selection 1,
    L1854; "Hx", L1573) on the tool axis (SD(10), L2231); H0 ends it. The selected external and general
    compensations (G145..G845, G147..G847) add to it (``EXTERNAL_LENGTH``)."""
    table = k.modal.get("G22", 4)
    fault = length_fault(value, table)
    if fault is not None:
        k.fault("NC009", fault, src)
    n = int(value)
    k.modal["H"] = n
    source = k.length_compensation or machine_tools
    k.set_tool_length((source(k, table, n, src) if n else 0.0) + k.modal.get(EXTERNAL_LENGTH, 0.0), src, n)


def literal_fault(g, words: dict, axes, complete: bool) -> tuple | None:
    """``ncvm check``: (code, message, address, value) of what the run refuses in a block from its text alone,
    by the handlers' own rules (G20's axes, G22's K, H's group), or None. ``words``: address -> value of the
    block's words, None for a computed one; ``complete``: every address of the block is written (no
    standalone [expr] word). The table an H reads is the run's to know (a G22 K may be computed)."""
    if 20 in g and complete and (fault := g20_fault([a for a in words if a in axes])) is not None:
        return (*fault, "G", 20)
    k = words.get("K")
    if 22 in g and (k is not None or (complete and "K" not in words)) and (fault := table_fault(k)) is not None:
        return ("NC009", fault, "G", 22)
    h = words.get("H")
    if h is not None and (fault := length_fault(h, 4)) is not None:
        return ("NC009", fault, "H", h)
    return None


def machine_tools(k, table: int, group: int, src) -> float:
    """The length of compensation group ``group`` of table K<table> when the dialect keeps no tables: K4 is
    the machine's tool table, another table has no values."""
    tool = k.machine.tools.get(group) if table == 4 else None
    return tool.length if tool is not None else 0.0


def _row(g, group, meaning, line, run=SET, handler=None, status=IMPLEMENTED):
    return Row(g, group, meaning, line, status, run, handler)


def _unknown(g, group, what=""):
    return refused(g, group, f"{what or f'a function of G group {group}'}; {UNKNOWN}", TABLE)


def _dialect(g, group, meaning, line, status=DIALECT):
    """A row the CPL runtime runs itself: taken out of the block before the kernel (dialects/cpl/system/gfuncs.py,
    the linker's cycle calls) or a handler it registers (``kernel.g_handlers``, cpl/system/transforms.py)."""
    return Row(g, group, meaning, line, status, SET, refusal(meaning + ", outside a CPL program"))


_CUTTER_REFUSED = "the CPL control's radius source (D / TC selection 2) is not read yet"

ROWS = (
    _row(0, "2", "rapid traverse", TABLE, MOTION),
    _row(1, "2", "linear interpolation", TABLE, MOTION),
    _row(2, "2", "circular interpolation clockwise", TABLE, MOTION),
    _row(3, "2", "circular interpolation counter-clockwise", TABLE, MOTION),
    _unknown(5, "2"),
    _unknown(11, "2", "polar interpolation, linear (DIN 66025 G11)"),
    _unknown(12, "2", "polar interpolation, circle clockwise (DIN 66025 G12)"),
    _unknown(13, "2", "polar interpolation, circle counter-clockwise (DIN 66025 G13)"),
    _unknown(73, "2"),
    _row(4, "", "dwell (the dwell of MCODS 39, L2949), its time X or F in a block of its own", "L2949", DWELL,
         dwell_alone),
    _row(70, "3", "dimensions in inch", TABLE, SET, inch),
    _row(71, "3", "dimensions in mm", TABLE, SET, metric),
    _row(90, "4", "absolute dimensions", TABLE, SET, absolute),
    _row(91, "4", "incremental dimensions", TABLE, SET, incremental),
    _unknown(189, "4"),
    _unknown(190, "4"),
    _unknown(191, "4"),
    refused(63, "5", "feed and speed override fixed at 100 %, tapping (SD(5,1,1) L2221, DIN 66025 G63)",
            "L2221"),
    _row(66, "5", "override effective (the state at power-on; G63 off)", TABLE, SET, modal_only("5"), FAMILY),
    _unknown(543, "6"),
    _unknown(93, "7", "inverse time feed (DIN 66025 G93)"),
    _row(94, "7", "feed in mm/min (inch/min)", TABLE, SET, threads.g94),
    _row(95, "7", "feed in mm/rev (MCODS 3, L2817; nc/threads.py, registered by the CPL runtime)", "L2817", SET,
         threads.g95),
    _row(40, "8", "tool radius compensation off", TABLE, SET, cutter_comp),
    Row(41, "8", f"tool radius compensation left ({_CUTTER_REFUSED})", TABLE, REFUSED, SET, cutter_comp, "NC005"),
    Row(42, "8", f"tool radius compensation right ({_CUTTER_REFUSED})", TABLE, REFUSED, SET, cutter_comp, "NC005"),
    _unknown(6, "9"),
    _unknown(7, "9"),
    _row(17, "10", "plane: main axis 1 (X), secondary axis 2 (Y)", TABLE, SET, plane),
    _row(18, "10", "plane: main axis 3 (Z), secondary axis 1 (X)", TABLE, SET, plane),
    _row(19, "10", "plane: main axis 2 (Y), secondary axis 3 (Z)", TABLE, SET, plane),
    _row(20, "10", "plane switchover to the block's two axes, their values the pole (G17-G19 planes only)",
         "L2372", LATE, g20),
    _unknown(8, "11", "acceleration (DIN 66025 G08)"),
    _unknown(9, "11", "deceleration, exact stop at the block end (DIN 66025 G09)"),
    _unknown(14, "13"),
    _unknown(15, "13"),
    _row(53, "15", "axis zero shift off", TABLE, SET, zero_shift_off),
    *(_row(g, "15", f"axis zero shift G{g} of the active ZS table", TABLE, SET, work_offset)
      for g in range(54, 60)),
    _dialect(153, "16", "additive axis zero shift of rows G154-G159 off", TABLE),
    *(_dialect(g, "16", f"additive axis zero shift: row G{g} of the active ZS table", TABLE)
      for g in range(154, 160)),
    _dialect(253, "17", "second additive axis zero shift of rows G254-G259 off", TABLE),
    *(_dialect(g, "17", f"second additive axis zero shift: row G{g} of the active ZS table", TABLE)
      for g in range(254, 260)),
    _dialect(60, "18", "contour shift of the named coordinates (COF, L1969)", "L1969"),
    _dialect(67, "18", "contour shift off", TABLE),
    _dialect(37, "19", "scaling about a pole (SCL, L2022)", "L2022"),
    _dialect(38, "19", "scaling and rotation of the main plane (SCL, L2022)", "L2022"),
    _dialect(39, "19", "scaling and rotation off", TABLE),
    _row(61, "20", "exact stop, modal (the planner's path mode; CPL_PATH_CODES in dialects/cpl/runtime.py)", TABLE,
         SET, nothing, FAMILY),
    _row(62, "20", "continuous path, the state at power-on (the planner's path mode)", TABLE, SET, nothing, FAMILY),
    _row(64, "25", "continuous-path mode (the state at power-on)", TABLE, SET, modal_only("25"), FAMILY),
    _unknown(65, "25", "exact stop, the other function of the continuous-path group"),
    _unknown(68, "26"),
    _unknown(69, "26"),
    *(_dialect(g, "28", f"external tool compensation G{g} (TC, L1888)", "L1888") for g in range(145, 846, 100)),
    _dialect(146, "28", "external and general tool compensation off", TABLE),
    *(_dialect(g, "", f"general tool compensation G{g} (TC, L1891)", "L1891") for g in range(147, 848, 100)),
    _unknown(114, "29"),
    _unknown(115, "29"),
    _dialect(160, "30", "external axis zero shift G160 (FXC, L1759)", "L1759"),
    _dialect(260, "30", "external axis zero shift G260 (FXC, L1759)", "L1759"),
    _dialect(360, "30", "external axis zero shift G360 (FXC, L1759)", "L1759"),
    _dialect(167, "30", "external axis zero shift off", TABLE),
    _row(22, "", "select tool compensation table K<n> for H and D (K4, K5; K0 none)", "L364", LATE,
         comp_table, FAMILY),
    _row(92, "", "set actual value (MCODS 1, L2817)", "L2817", POSITION),
    _row(80, "", "modal cycle call off (the CPL linker's G81-G86 calls)", "L364", CYCLE),
    *(_dialect(g, "", f"drilling cycle G{g}: call of program 99999{g:03d} ([cpl] calls)", "")
      for g in range(81, 87)),
    _dialect(75, "", "probe input (PPOS, L1437)", "L1437"),
    _dialect(275, "", "on-the-fly measurement (L1589)", "L1589"),
    _dialect(375, "", "measuring to a fixed stop (SD(9), L2229)", "L2229"),
    _dialect(138, "", "workpiece-position compensation, shift and rotation (DPC, L1992)", "L1992"),
    refused(352, "", "coordinate transformation (L1578)", "L1578"),
    *(refused(g, "", "coordinate transformation (L1578)", "L1578") for g in range(354, 360)),
    *(_dialect(g, "", f"G{g} (gfuncs.py: SD groups 68, 131, 328, 581)", "L2259") for g in (130, 131, 168, 268,
                                                                                          328, 580, 581)),
    refused(33, "", "thread cutting (the CPL manual names no thread function)", ""),
    refused(21, "", "not a G function of the Typ3 osa; units are G70/G71", TABLE),
    refused(43, "", "not a G function of the Typ3 osa; the length compensation is the H word", "L1573"),
    refused(44, "", "not a G function of the Typ3 osa; the length compensation is the H word", "L1573"),
    refused(49, "", "not a G function of the Typ3 osa; H0 ends the length compensation", "L1573"),
)

ADDRESSES = (
    Address("H", "tool length compensation: compensation group of the selected table, H0 off", "L1573",
            IMPLEMENTED, length_comp),
    Address("D", "tool radius compensation group for G41/G42 (refused, see G41)", "L1854", IMPLEMENTED),
    Address("K", "the table of G22; the third circle centre word otherwise", "L364", IMPLEMENTED),
    Address("F", "feed", "L2221", IMPLEMENTED),
    Address("S", "spindle speed", "L2221", IMPLEMENTED),
    Address("T", "tool", "", IMPLEMENTED),
    Address("I", "circle centre, first axis", "", IMPLEMENTED),
    Address("J", "circle centre, second axis", "", IMPLEMENTED),
    Address("R", "circle radius", "L2372", IMPLEMENTED),
)

TYP3OSA = Profile(
    "typ3osa", "Bosch Rexroth CPL programming manual (Typ3 osa / PNC)", ROWS, ADDRESSES,
    defaults={"2": 0, "3": 71, "4": 90, "5": 66, "7": 94, "8": 40, "10": 17, "15": 54, "20": 62, "16": 153, "17": 253,
              "18": 67, "19": 39, "25": 64, "28": 146, "30": 167},
    groups={"2": "interpolation", "3": "units", "4": "dimensions", "5": "override", "7": "feed",
            "8": "tool radius compensation", "10": "plane", "15": "axis zero shift", "16": "additive axis zero shift",
            "17": "second additive axis zero shift", "18": "contour shift", "19": "scaling", "25": "path mode",
            "28": "external tool compensation", "30": "external axis zero shift"},
)
