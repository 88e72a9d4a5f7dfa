"""The machine file, declared: every table and key, its type, unit, default and meaning.

The loader (config.py) checks a file against :data:`MACHINE_FILE`; docs/machine-file.md's reference
tables and docs/machine-file.schema.json are generated from it (docgen.py). The dialect sections live in
sections.py.
"""

from __future__ import annotations

from typing import Any

from .eventforms import CHECKS as EVENT_CHECKS
from .schema import (
    Check,
    Ctx,
    Either,
    Field,
    Flag,
    ListOf,
    Node,
    Number,
    Said,
    SchemaError,
    Table,
    Tagged,
    Text,
    join,
    show,
    unique,
)
from .sections import DIALECT_SECTIONS

NUMBER = Number()
POSITIVE = Number(gt=0)
NONNEG = Number(min=0)
INT = Number(integer=True)
NAME = Text(nonempty=True)
PATH = Text(pattern=r"[^\x00]+", shape="a path (not empty)")


class AxisName(Node):
    """The name of one of the machine's ``[[axis]]`` (upper or lower case), used as a key."""

    def check(self, value, path, ctx):
        if not isinstance(value, str) or value.upper() not in (n.upper() for n in ctx.axis_names):
            raise SchemaError(path, value, f"must be an axis of the machine ({', '.join(ctx.axis_names)})")

    def type_text(self):
        return "an axis name"

    def json(self):
        return {"type": "string"}


def _min_not_above_max(axis: dict, path: str, ctx: Ctx) -> None:
    lo, hi = axis.get("min", -1.0e9), axis.get("max", 1.0e9)
    if lo > hi:
        raise SchemaError(join(path, "min"), lo, f"is greater than max = {show(hi)}")


def _inside_soft_limits(values: list, path: str, ctx: Ctx) -> None:
    for i, (v, (lo, hi), name) in enumerate(zip(values, ctx.axis_limits, ctx.axis_names)):
        if not lo <= v <= hi:
            raise SchemaError(join(path, i), v, f"lies outside the soft limits of axis {name} ({lo:g} to {hi:g})")


AXIS = Table((
    Field("name", Text(pattern=r"[A-Za-z][A-Za-z0-9_]*", shape="a letter, then letters, digits or _"),
          "address letter(s): X, Y, Z, A, B, C, U, V, W, or an extended name such as Q1", required=True),
    Field("kind", Text(choices=("linear", "rotary")), "linear or rotary (degrees)", "linear"),
    Field("min", NUMBER, "lower soft limit (machine coordinates)", -1.0e9, "mm (deg)"),
    Field("max", NUMBER, "upper soft limit (machine coordinates)", 1.0e9, "mm (deg)"),
    Field("rapid", POSITIVE, "rapid rate", 10000.0, "mm/min (deg/min)"),
    Field("max_feed", POSITIVE, "maximum feed", 5000.0, "mm/min (deg/min)"),
    Field("accel", POSITIVE, "acceleration", 1000.0, "mm/s² (deg/s²)"),
), checks=(Check("`min` <= `max`", _min_not_above_max),))

TOOL = Table((
    Field("number", Number(integer=True, min=0), "tool number (T word)", required=True),
    Field("length", NUMBER, "tool length", 0.0, "mm"),
    Field("radius", NONNEG, "tool radius", 0.0, "mm"),
    Field("name", Text(), "description", ""),
))

PLC_BITS = Table(other=Either((Flag(), INT), "true/false or an integer"), keys=NAME, keys_doc="address")

#: [[scenario]] events by kind (machine/scenario.py types them); the dialect that reads each kind is named in
#: its doc, and a dialect refuses an event it cannot use
INPUT_VALUE = Either((Flag(), Number(integer=True, min=0, max=1)), "true/false or 0/1")
PLC_NO = Number(integer=True, min=1, max=4)
SCENARIO = Tagged("kind", (
    Field("time", NONNEG, "when it happens (simulated time from the start)", unit="s", required=True),
), {
    "input": Table((
        Field("address", NAME, "CPL: the interface bit, e.g. \"IC(3,0,1)\" (no byte, bit or axis with it)"),
        Field("byte", Number(integer=True, min=1, max=2), "SINUMERIK: external input byte (with bit)", 1),
        Field("bit", Number(integer=True, min=0, max=32), "SINUMERIK: bit 0-7 of the byte (0 when left out); "
                                                          "rw_SymPas: digital input 1-32 of the axis"),
        Field("axis", NAME, "rw_SymPas: the axis whose digital input changes (with bit)"),
        Field("value", INPUT_VALUE, "the new level", True),
    ), checks=(Check(*EVENT_CHECKS["input"]),)),
    "probe": Table((
        Field("input", Number(integer=True, min=1, max=2), "the probe input (SINUMERIK MEAS M: 1 or 2; CPL: 1)", 1),
        Field("position", Table(other=NUMBER, keys=AxisName(), keys_doc="axis name"),
              "where the probe switches (machine coordinates), as a table (SINUMERIK's form)", unit="mm"),
    ), other=NUMBER, keys=AxisName(), keys_doc="axis name (CPL: where the probe switches, machine coordinates, mm)", checks=(Check(*EVENT_CHECKS["probe"]),)),
    "fixed_stop": Table(other=NUMBER, keys=AxisName(), keys_doc="axis name (CPL G375: where the axis stops, mm)"),
    "sercos": Table((Field("locked", Flag(), "CPL: the SERCOS service channel is locked from now on", True),)),
    "plc": Table((
        Field("plc", PLC_NO, "SINUMERIK: PLC number", 1),
        Field("area", Text(choices=("I", "Q", "P", "F")), "inputs, outputs, peripherals or flags", "I"),
        Field("byte", Number(integer=True, min=0, max=255), "byte address", 0),
        Field("bit", Number(integer=True, min=0, max=7), "bit (else the whole byte changes)"),
        Field("value", Either((Flag(), Number(integer=True, min=0, max=11111111),
                               Text(pattern=r"[01]{1,8}", shape="a bit pattern such as \"00010010\"")),
                              "true/false, a digit-coded byte or a bit-pattern string"), "the new bit or byte"),
    )),
    "timer": Table((
        Field("plc", PLC_NO, "SINUMERIK: PLC number", 1),
        Field("number", Number(integer=True, min=0, max=255), "timer number", required=True),
        Field("action", Text(choices=("start", "reset")), "what the PLC does", "start"),
        Field("value", NONNEG, "the time it loads", unit="s"),
        Field("base", Number(choices=(0.01, 0.1, 1, 10)), "time base", unit="s"),
    )),
    "counter": Table((
        Field("plc", PLC_NO, "SINUMERIK: PLC number", 1),
        Field("number", Number(integer=True, min=0, max=255), "counter number", required=True),
        Field("action", Text(choices=("up", "down", "set", "reset")), "what the PLC does", "up"),
        Field("value", Number(integer=True, min=0, max=999), "the value `set` loads"),
    )),
    "alarm": Table((Field("number", Number(integer=True, min=0), "SINUMERIK: the NC alarm that becomes pending",
                          required=True),)),
    "poserr": Table((
        Field("axis", NAME, "rw_SymPas: the axis", required=True),
        Field("value", NUMBER, "the following error", 0.0, "axis units"),
    )),
    "ci": Table((
        Field("index", Number(integer=True, min=0, max=999), "rw_SymPas: the common integer CI<index>", 0),
        Field("value", Number(integer=True, min=-(2 ** 31), max=2 ** 31 - 1), "its new value", 0),
    )),
})
SCENARIOS = ListOf(SCENARIO)

G_TABLES = tuple(f"G{n}" for n in range(54, 60))
MACHINE_FILE = Table((
    Field("machine", Table((
        Field("name", Text(), "shown in results", "machine"),
        Field("units", Text(choices=("mm",)), "machine files are metric (programs switch to inch with G70/G20)",
              "mm"),
        Field("start_position", ListOf(NUMBER, per_axis=True, checks=(
            Check("inside the soft limits", _inside_soft_limits),)), "machine coordinates at start", Said("all 0"),
              "mm (deg)"),
    )), "the machine as a whole"),
    Field("axis", ListOf(AXIS, min_len=1, checks=(unique("name", "axis name"),)),
          "one `[[axis]]` table per axis, in axis order", required=True),
    Field("offsets", Table(other=ListOf(NUMBER, per_axis=True), keys=Text(choices=G_TABLES), keys_doc="G54 ... G59"),
          "zero offsets G54..G59, one number per axis", Said("all 0"), "mm"),
    Field("tool", ListOf(TOOL, checks=(unique("number", "tool number"),)), "the tool table, one `[[tool]]` per tool"),
    Field("machine_data", Table(closed_why="no dialect reads [machine_data]: a control's machine data is "
                                           "in its own section ([cpl] macoda, [sin800] nc_md ...)"),
          "must be empty: machine data lives in the dialect sections"),
    Field("setting_data", Table((Field("block_skip", Flag(), "'/' blocks are skipped", True),)), "setting data"),
    Field("plc", Table((
        Field("inputs", PLC_BITS, "PLC inputs by address (CPL: \"IC(bit,group,index)\")", {}),
        Field("outputs", PLC_BITS, "PLC outputs by address", {}),
        Field("flags", PLC_BITS, "PLC flags (markers) by address", {}),
        Field("words", Table(other=INT, keys=NAME, keys_doc="address"), "PLC data words by address", {}),
    )), "the PLC interface image at power-on"),
    Field("motion", Table((
        Field("model", Text(choices=("lookahead", "rest-to-rest")),
              "how move times are planned: blocks blended in continuous-path mode with look-ahead, or every "
              "block from rest to rest (the old model; `ncvm run --time-model` overrides it)", "lookahead"),
        Field("lookahead", Number(integer=True, min=1, max=100000),
              "blocks the path control looks ahead (its block buffer): every move can still brake to rest "
              "within this many", 100, "blocks"),
        Field("corner_tolerance", NONNEG,
              "how far a blended corner may pass the programmed corner point in continuous-path mode "
              "(0: every corner is an exact stop); a DIN program's `G64 P..` sets it", 0.02, "mm"),
        Field("tool_change_time", NONNEG, "how long an M6 tool change takes (the axes stand)", 0.0, "s"),
    )), "the path control of the DIN, CPL and SINUMERIK runs: cycle-time planning (docs/planner.md)"),
    Field("clock", Table((Field("start", Number(min=0, max=253402300799), "the controller's calendar at power-on",
                                1700000000, "Unix time, s"),)), "the simulated clock"),
    Field("paths", Table((
        Field("program_path", ListOf(PATH), "where sub-programs are looked for", ["."]),
        Field("file_root", PATH, "the controller's file system; programs cannot reach outside it", "files"),
    )), "folders, relative to the machine file's folder"),
    Field("scenario", SCENARIOS, "things that happen over simulated time (see below)"),
    *DIALECT_SECTIONS,
))

#: a --scenario file holds only [[scenario]] tables
SCENARIO_FILE = Table((Field("scenario", SCENARIOS, "things that happen over simulated time"),),
                      closed_why="a scenario file holds only [[scenario]] tables")


def section_defaults(name: str) -> dict[str, Any]:
    """The documented defaults of a table of the machine file (a dialect section or a fixed table)."""
    node = next(f.type for f in MACHINE_FILE.fields if f.name == name)
    assert isinstance(node, Table)
    return {f.name: f.default for f in node.fields}
