"""The dialect sections of the machine file ([cpl], [cl800], [sin800], [sympas], [din]), declared.

They live here, beside the rest of the machine-file schema, because machine/ may not import the
dialects and the reference (docgen.py) is generated from machine/ alone: one section per dialect of the
registry (dialects/__init__.py), named by its id (a test ties the two lists). A dialect reads its section
from ``Machine.sections``; one that declares its options as a dataclass gets them checked and filled in
by ``config.dialect_options`` (a test checks that its defaults are the ones declared here).
"""

from __future__ import annotations

from .schema import Check, Ctx, Either, Field, Flag, ListOf, Number, Said, SchemaError, Table, Text, join, unique

NUMBER = Number()
#: the largest magnitude of a SINUMERIK R value (CL 800 manual L7077-7080): every value the NC assigns,
#: and so every MIB value (@212 stores an R value, @211 reads one back); the store's import checks it too
R_LIMIT = 99999999.0
R_NUMBER = Number(min=-int(R_LIMIT), max=int(R_LIMIT))  # whole bounds: "-99999999 to 99999999"
POSITIVE = Number(gt=0)
NONNEG = Number(min=0)
INT = Number(integer=True)
NONNEG_INT = Number(integer=True, min=0)
NAME = Text(nonempty=True)
DIGITS = Text(pattern=r"[0-9]+", shape="a number written as a string (\"12\")")
UNIT = Text(choices=("mm", "inch"))
BITS = Text(pattern=r"[Bb]?[01]{1,8}", shape="a bit pattern such as \"00010010\"")
SCALAR = Either((NUMBER, Text()), "a number or a string")
#: a PLC data word as the SINUMERIK runtime reads it (its _PLC_SOURCE)
PLC_DATA = Text(pattern=r"\s*(?:PLC[1-4]\.)?DB[0-9]+\.DW[0-9]+\s*", shape='PLC data such as "DB20.DW1" or "PLC2.DB20.DW1"',
                ignore_case=True)


def _min_max(table: dict, path: str, ctx: Ctx) -> None:
    if table.get("min", 0.0) > table.get("max", 8000.0):
        raise SchemaError(join(path, "min"), table.get("min"), f"is greater than max = {table.get('max', 8000.0):g}")


def _distinct(fields: tuple[Field, ...], what: str) -> Table:
    """A table of ``fields`` no two of which (given or by default) share a value: two axst flags on one bit
    or two SSF functions on one code would be read as each other."""
    def fn(table: dict, path: str, ctx: Ctx) -> None:
        seen: dict = {}
        for f in fields:
            v = table.get(f.name, f.default)
            if v in seen:
                given = f.name if f.name in table else seen[v]
                other = seen[v] if given == f.name else f.name
                raise SchemaError(join(path, given), v, f"is also the {what} of {other}"
                                                        f"{'' if other in table else ' (its default)'}")
            seen[v] = f.name
    return Table(fields, checks=(Check(f"no two on the same {what}", fn),))


# -- [cpl] ------------------------------------------------------------------------------------------
ZS_ROWS = tuple(f"G{b + i}" for b in (54, 154, 254) for i in range(6))
CPL_AXIS = Table((
    Field("name", NAME, "physical axis name", required=True),
    Field("index", Number(integer=True, min=1), "physical axis number", Said("its place in the list")),
    Field("channel", NONNEG_INT, "channel of the axis (0 = asynchronous)", Said("`channel`")),
    Field("type", Text(choices=("linear", "rotary")), "axis movement", "linear"),
    Field("probe", Flag(), "the probe can be activated (MACODA 1003 00012)", True),
    Field("position", NUMBER, "where an axis the NC kernel does not drive stands", 0.0, "mm (deg)"),
    Field("lag", NUMBER, "following error: APOS = SPOS - lag", 0.0, "mm (deg)"),
    Field("sercos", Table(other=Either((SCALAR, ListOf(SCALAR)), "a number, a string or an array of them"),
                          keys=Text(pattern=r"[SP]-[0-7]-[0-9]{4}", shape="a SERCOS ID such as S-0-0030",
                                    ignore_case=True), keys_doc="SERCOS ID"), "SERCOS parameters", {}),
    Field("jog", POSITIVE, "jog speed (MCODS 27)", 1000.0, "mm/min (deg/min)"),
))
def _rows_fit_columns(table: dict, path: str, ctx: Ctx) -> None:
    columns = table.get("columns")
    for row, values in table.items():
        if columns is not None and row not in ("columns", "unit", "strict") and len(values) > len(columns):
            raise SchemaError(join(path, row), values, f"has more values than the {len(columns)} columns")


ZS_TABLE = Table((
    Field("columns", ListOf(NAME, min_len=1), "axis names of the columns", Said("the [cpl] axes")),
    Field("unit", UNIT, "unit of the values", Said("`zs_unit`")),
    Field("strict", Number(integer=True, min=0, max=1), "strict table", 0),
), other=ListOf(NUMBER), keys=Text(choices=ZS_ROWS, ignore_case=True), keys_doc="row G54..G59, G154.., G254..",
    checks=(Check("a row has at most one value per column", _rows_fit_columns),))
PLC_KEY = Text(pattern=r"(I|O|M|D[0-9]+|DB|DF|T|C|SM|S|EI|EO):[0-9]+", shape="<type><DM>:<byte> such as \"I:10\"")

CPL = Table((
    Field("lookahead", NONNEG_INT, "NC blocks prepared ahead of execution; 0 = the control's block buffer: up "
                                   "to 20,000 blocks wait, then the older 10,000 run", 0, "blocks"),
    Field("calls", Table(other=Either((NAME, Table((Field("program", NAME, "sub-program", required=True),
                                                    Field("modal", Flag(), "called again after every block with "
                                                                           "an axis word, until G80", False)))),
                                      "a program name or a table with program and modal"),
                         keys=Text(pattern=r"[GMP][0-9]+", shape="a G, M or P address such as G81",
                                   ignore_case=True), keys_doc="address"),
          "address -> sub-program", Said("G81..G86: 99999081..99999086")),
    Field("channel", Number(integer=True, min=1), "the channel the program runs in", 1),
    Field("axes", ListOf(Either((NAME, CPL_AXIS), "an axis name or a table"),
                         checks=(unique("name", "axis name"),
                                 unique("index", "physical axis number", lambda a, i: i + 1))),
          "physical axes 1..n in order", Said("the [[axis]] list, all on `channel`")),
    Field("zs_unit", UNIT, "unit of new ZS tables (MACODA 9020 00010)", "mm"),
    Field("zs_active", NAME, "the active ZS table (the kernel's G54..G59)", "V1"),
    Field("zs_tables", Table(other=ZS_TABLE, keys=NAME, keys_doc="table name or path"), "ZS tables", {}),
    Field("tc_unit", UNIT, "unit of the compensation tables", "mm"),
    Field("tc_tables", Table(other=Table(other=ListOf(NUMBER, min_len=1, max_len=2), keys=DIGITS,
                                         keys_doc="group: [H length, D radius]"),
                             keys=NAME, keys_doc="table name or path"),
          "tool compensation tables (K4 defaults to the [[tool]] table)", {}),
    Field("tool_database", ListOf(Table((
        Field("sector", Number(integer=True, min=1), "sector", required=True),
        Field("place", Number(integer=True, min=1), "place", required=True),
        Field("fields", Table(other=SCALAR, keys=DIGITS, keys_doc="field number"), "field values", {}),
    )), checks=()), "the tool database", []),
    Field("macoda", Table(other=Either((SCALAR, ListOf(SCALAR)), "a number, a string or an array of them"),
                          keys=Text(pattern=r"[0-9][0-9 ]*", shape="a MACODA number such as \"1003 00001\""),
                          keys_doc="MACODA number"), "MACODA parameters (individual values, index 0..)", {}),
    Field("plc", Table(other=Number(integer=True, min=0), keys=PLC_KEY, keys_doc="<type><DM>:<byte>"),
          "PLC bytes; types I O M D DB DF T C SM S EI EO", {}),
    Field("errors", ListOf(Table((
        Field("number", NONNEG_INT, "error number", required=True),
        Field("channel", Number(integer=True, min=-1), "channel (-1: all)", -1),
        Field("category", Number(integer=True, min=0, max=10), "category", 0),
    ))), "the error log GETERR reads", []),
    Field("override", Table(tuple(Field(k, NONNEG_INT, f"{k} potentiometer", d, "%")
                                  for k, d in (("feed", 100), ("spindle", 100), ("spindle2", 0), ("axis", 100)))),
          "override potentiometers"),
    Field("spindle", Table((
        Field("min", NONNEG, "lowest permissible speed (MCODS 20)", 0.0, "rpm"),
        Field("max", NONNEG, "highest permissible speed (MCODS 19)", 8000.0, "rpm"),
        Field("group", Number(integer=True, min=0, max=4), "spindle group (0: none)", 0),
    ), checks=(Check("`min` <= `max`", _min_max),)), "the spindle"),
    Field("areas", ListOf(Table((
        Field("type", Text(choices=("work", "dead")), "work area or dead range", "work"),
        Field("axes", ListOf(NAME, min_len=2, max_len=2), "two axes of the channel", Said("its first two")),
        Field("centre", ListOf(NUMBER, min_len=2, max_len=2), "centre (machine coordinates)", [0, 0], "mm"),
        Field("extent", ListOf(NONNEG, min_len=2, max_len=2), "width along each axis", [0, 0], "mm"),
        Field("active", Flag(), "watched from the start", True),
    )), max_len=10), "work areas and dead ranges (SD 200)", []),
    Field("language", NONNEG_INT, "national language (MACODA 6010 00010, SD(14))", 1),
    Field("date_format", Text(choices=("DD.MM", "DD.MM.YY")), "what DATE returns (manual L2496: DD.MM)", "DD.MM"),
    Field("file_zeros", Text(choices=("suppress", "keep")), "trailing zeros of REAL and DOUBLE values PRN# writes "
                                                            "to files (manual L4001: suppressed)", "suppress"),
    Field("file_space", NONNEG_INT, "bytes the files a program writes (OPENW/PRN#, SCSL, ZS tables) may grow by "
                                    "in one run, then FILE MEMORY FULL (CPL614); 0 = no limit", 1 << 30, "bytes"),
))

# -- [cl800] ----------------------------------------------------------------------------------------
CONTROLS = ("810", "820", "850", "880")
CL800 = Table((
    Field("strict", Flag(), "drop the compiler's leniencies (docs/cl800.md)", False),
    Field("control", Text(choices=CONTROLS), "the target control", "880"),
))

# -- [sin800] ---------------------------------------------------------------------------------------
BYTE_OR_WORD = Either((NUMBER, BITS), "a number or a bit-pattern string")
DATA_AREA = Table(other=BYTE_OR_WORD, keys=Text(pattern=r"[0-9]+|[A-Za-z_][A-Za-z0-9_]*",
                                                shape="an address such as \"2240\""), keys_doc="address")
PER_AXIS = ListOf(NUMBER, per_axis=True)
TIMER_WIRING = Table((
    Field("start", NAME, "M function or PLC bit whose rising edge starts it (\"M71\", \"I1.2\")"),
    Field("reset", NAME, "... resets it"),
    Field("value", NONNEG, "the time a start loads", unit="s"),
    Field("base", Number(choices=(0.01, 0.1, 1, 10)), "time base", unit="s"),
    Field("done", NAME, "output or flag bit set when the time has run out (\"Q4.0\")"),
))
COUNTER_WIRING = Table((
    *(Field(k, NAME, f"M function or PLC bit that makes it count {k}" if k in ("up", "down")
            else f"... that makes it {k}") for k in ("up", "down", "set", "reset")),
    Field("value", Number(integer=True, min=0, max=999), "the value `set` loads"),
))
BYTES = Table(other=BYTE_OR_WORD, keys=DIGITS, keys_doc="byte")
SIN800_PLC = Table((
    Field("I", BYTES, "input bytes"),
    Field("Q", BYTES, "output bytes"),
    Field("P", BYTES, "peripheral bytes"),
    Field("F", BYTES, "flag bytes"),
    Field("DB", Table(other=ListOf(Number(integer=True, min=0, max=65535)), keys=DIGITS, keys_doc="data block"),
          "data blocks: DW0, DW1, ..."),
    Field("T", Table(other=NONNEG, keys=DIGITS, keys_doc="timer"), "timers at power-on", unit="s"),
    Field("C", Table(other=Number(integer=True, min=0, max=999), keys=DIGITS, keys_doc="counter"),
          "counters at power-on"),
    Field("timers", Table(other=TIMER_WIRING, keys=DIGITS, keys_doc="timer"), "what drives the timers"),
    Field("counters", Table(other=COUNTER_WIRING, keys=DIGITS, keys_doc="counter"), "what drives the counters"),
))
ZO_NAMES = ("G54", "G55", "G56", "G57", "G58", "G59", "EXTERNAL", "DRF", "PRESET")


def _coarse_fine_only_settable(offsets: dict, path: str, ctx: Ctx) -> None:
    for name, value in offsets.items():
        if isinstance(value, dict) and name.upper() not in ZO_NAMES[:4]:
            raise SchemaError(join(path, name), value, "only the settable offsets G54..G57 have coarse and fine")

SIN800 = Table((
    Field("control", Text(choices=CONTROLS), "ranges of TO areas, D numbers, MIB, PLC", "880"),
    Field("channel", Number(integer=True, min=1, max=16), "the channel the program runs in (PPCH)", 1),
    Field("m0", Text(choices=("stop", "continue")), "M0 ends the run, or continues as if start were pressed",
          "continue"),
    Field("block_skip", Flag(), "'/' blocks are skipped", Said("[setting_data] block_skip")),
    Field("max_call_depth", Number(integer=True, min=1), "sub-program nesting depth", 8),
    Field("cycle_alarm_stop", Flag(), "ALNZ 4000-4299 stop the program", True),
    Field("to_area", NONNEG_INT, "the channel's TO area", 0),
    Field("r", Table(other=NUMBER, keys=Text(pattern=r"R?[0-9]{1,3}", shape="R0 .. R999", ignore_case=True),
                     keys_doc="R parameter"), "R parameters at power-on", {}),
    *(Field(area, DATA_AREA, doc, {}) for area, doc in (
        ("nc_md", "NC machine data (words and bytes by address; bytes as bit strings)"),
        ("cycle_md", "cycle machine data"), ("plc_md", "PLC machine data"), ("drive_md", "drive machine data"),
        ("nc_sd", "NC setting data"), ("cycle_sd", "cycle setting data"))),
    Field("mib", Table(other=R_NUMBER, keys=Text(pattern=r"[0-9]|[1-9][0-9]|[1-4][0-9][0-9]", shape="0 .. 499"),
                       keys_doc="MIB address"), "MIB values", {}),
    Field("inputs", Table(other=BYTE_OR_WORD, keys=Text(choices=("1", "2")), keys_doc="input byte"),
          "external input bytes 1 and 2", {}),
    Field("alarms", ListOf(NONNEG_INT), "pending NC alarms", []),
    Field("sob", Table(other=NUMBER, keys=NAME, keys_doc="bit"), "special bits (SOB) and drive status bits", {}),
    Field("tool_offsets", ListOf(Table((
        Field("area", NONNEG_INT, "TO area", 0),
        Field("d", Number(integer=True, min=1), "D number", required=True),
        Field("p", ListOf(NUMBER, max_len=16), "P0..P15", required=True),
    ))), "tool offsets", []),
    Field("zero_offsets", Table(other=Either((PER_AXIS, Table((Field("coarse", PER_AXIS, "coarse offset"),
                                                               Field("fine", PER_AXIS, "fine offset")))),
                                             "one number per axis or a table with coarse and fine"),
                                keys=Text(choices=ZO_NAMES, ignore_case=True), keys_doc="offset name",
                                checks=(Check("coarse and fine only for G54..G57", _coarse_fine_only_settable),)),
          "zero offsets", {}, "mm"),
    Field("rotation", Table((Field("settable", ListOf(NUMBER, max_len=4), "angles of G54..G57", unit="deg"),
                             Field("programmable", ListOf(NUMBER, max_len=2), "angles of G58, G59", unit="deg"))),
          "coordinate rotations", {}),
    Field("plc", Table(other=SIN800_PLC, keys=Text(choices=("1", "2", "3", "4")), keys_doc="PLC number"),
          "PLC images and programs (`[sin800.plc.1]`)", {}),
    Field("m_functions", Table(other=Table(other=Either((NUMBER, PLC_DATA), "a number or PLC data (\"DB20.DW1\")"),
                                           keys=Text(pattern=r"R?[0-9]{1,3}", shape="R0 .. R999",
                                                     ignore_case=True), keys_doc="R parameter"),
                               keys=DIGITS, keys_doc="M function number"),
          "what the PLC loads into R parameters for an M function", {}),
    Field("decode_ahead", NONNEG_INT, "blocks decoded ahead of execution (0 = lockstep)", 0, "blocks"),
    Field("strict_nc", Flag(), "R stores keep 8 significant digits", False),
    Field("gear", Number(integer=True, min=1, max=5), "gear stage of the master spindle at power-on", 1),
    Field("gears", ListOf(POSITIVE, max_len=5), "maximum speed of gear stages 1..", [], "rev/min"),
    Field("v24_input", Text(), "what INP reads from the V24 port", ""),
    Field("radius_address", Text(choices=("B", "U")), "the address of the circle radius (machine data; the "
          "manual's contour writes B, many programs U)", "B"),
))

# -- [sympas] ---------------------------------------------------------------------------------------
AXST_BITS = ("profile_end", "in_position", "loop_closed", "homed", "eo", "dnr", "lsh_left", "lsh_right",
             "lss_left", "lss_right", "mpe", "saf", "spool_running", "spool_halted", "refused", "home_failed")
SYMPAS = Table((
    Field("axis_names", ListOf(Text(nonempty=True, max_len=8), per_axis=True, checks=(unique("", "axis name"),)),
          "axis specifiers, one per machine axis", Said("A1, A2, ...")),
    Field("statements_per_tick", Number(integer=True, min=1), "Q: statements a task executes per 64 µs tick", 1),
    Field("task_slice_ticks", POSITIVE, "how far a task may run ahead of the others before it yields", 20, "ticks"),
    Field("servo_ticks", POSITIVE, "servo period T_A", 20, "ticks"),
    Field("clock_start", Number(integer=True, min=0, max=2 ** 32 - 1), "CLOCK at power-on", 0),
    Field("max_call_depth", Number(integer=True, min=1), "deeper calls: run-time error 8", 256),
    Field("trvl", POSITIVE, "task parameter TRVL (velocity)", 100.0),
    Field("trac", POSITIVE, "task parameter TRAC (acceleration)", 1000.0),
    Field("trtvl", NONNEG, "task parameter TRTVL", 0.0),
    Field("trovr", NONNEG, "task parameter TROVR (override factor)", 1.0),
    Field("pu", NONNEG_INT, "task parameter PU", 0),
    Field("tu", NONNEG_INT, "task parameter TU", 0),
    Field("counts_per_unit", POSITIVE, "dp rounds to whole counts at profile end", 1000.0),
    Field("axst_bits", _distinct(tuple(Field(n, Number(integer=True, min=0, max=31), "axst bit", i)
                                       for i, n in enumerate(AXST_BITS)), "bit"), "**provisional** axst bit layout",
          Said("see the keys")),
    Field("ssf_codes", _distinct(tuple(Field(n, INT, "SSF function code", d) for n, d in
                                       (("write_ci", 1), ("spool_halt", 1000), ("set_output", 1001))), "code"),
          "**provisional** SSF function codes", Said("see the keys")),
    Field("ssf_ci_index", Number(integer=True, min=0, max=999), "SSF write_ci writes CI<n>", 1),
    Field("zero_offsets", Table(other=PER_AXIS, keys=DIGITS, keys_doc="AZO table"), "**provisional** AZO tables",
          {}),
    Field("dtca_always_relative", Flag(), "MHA target mode: DTCA relative to the start point", False),
    Field("event_trigger", Text(choices=("level", "edge")), "events re-fire while active, or on edges", "level"),
    Field("busy_move", Text(choices=("refuse", "override")), "a move on a moving axis", "refuse"),
    Field("loop_closed", Flag(), "position loops closed at power-on", True),
    Field("spool_capacity", Number(integer=True, min=1), "entries per axis spooler", 128),
    Field("inputs", ListOf(Table((
        Field("axis", NAME, "axis specifier", required=True),
        Field("bit", Number(integer=True, min=1, max=32), "digital input", required=True),
        Field("function", Text(choices=("EO", "DR", "LSL", "LSR", "REF", "UI")), "what the input does",
              required=True),
        Field("active_low", Flag(), "the input acts when low", False),
    ))), "digital-input functions", []),
    Field("ref_positions", Table(other=NUMBER, keys=NAME, keys_doc="axis specifier"),
          "machine position of each axis's REF switch", {}),
    Field("index_period", POSITIVE, "distance between index pulses (JHI)", 1.0, "axis units"),
    Field("write_digits", Number(integer=True, min=1, max=17), "significant digits of doubles in WRITE", 10),
    Field("soft_limit_reaction", Text(choices=("SMD", "TOM", "SMA")), "SMD (no EVLSS), TOM or SMA", "TOM"),
    Field("load", ListOf(NAME), "more program files, each loaded into its {$TASK}", []),
    Field("osversion", NONNEG_INT, "value of OSVERSION", 253126),
    Field("boardtype", NONNEG_INT, "value of BOARDTYPE", 8001),
))

DIN = Table((
    Field("arc_radius_tolerance", POSITIVE, "an arc's end radius may differ from its start radius by this much "
                                            "in a metric program (LinuxCNC's CENTER_ARC_RADIUS_TOLERANCE_MM: "
                                            "2 × 0.01 × √2), or by `arc_radius_relative` of the radius; never "
                                            "by more than 100 times this", 0.02 * 2 ** 0.5, "mm"),
    Field("arc_radius_tolerance_inch", POSITIVE, "... in an inch program (G20/G70; LinuxCNC's "
                                                 "CENTER_ARC_RADIUS_TOLERANCE_INCH: 2 × 0.001 × √2)",
          0.002 * 2 ** 0.5, "inch"),
    Field("arc_radius_relative", NONNEG, "relative tolerance of the end radius (of the larger radius)", 0.001),
    Field("profile", Text(choices=("iso", "typ3osa", "sinumerik8xx")), "the control whose G table the program's "
          "G functions are read with (docs/profiles.md): iso = LinuxCNC rs274; typ3osa = Bosch Typ3 osa; "
          "sinumerik8xx = SINUMERIK 810-880", "iso"),
))

DIALECT_SECTIONS = (
    Field("cpl", CPL, "Bosch Rexroth CPL (docs/cpl.md)"),
    Field("cl800", CL800, "CL 800 compiler (docs/cl800.md)"),
    Field("sin800", SIN800, "SINUMERIK 800 @ code (docs/sin800.md)"),
    Field("sympas", SYMPAS, "rw_SymPas card (docs/sympas.md)"),
    Field("din", DIN, "plain DIN 66025 / ISO 6983, LinuxCNC rs274 the reference (docs/din.md)"),
)

#: dialect id -> the table of its section
SECTIONS: dict[str, Table] = {f.name: f.type for f in DIALECT_SECTIONS}
