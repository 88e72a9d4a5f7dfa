"""The simulated Typ3 osa controller behind chapter 4 (CPL manual §4, L1184-3343): channels, physical and logical axes,
zero-shift tables, tool compensation and the tool database, MACODA, the PLC image, the error log.

Everything is loaded from the machine file's [cpl] section with defaults that match the machine's axes;
the database ZS tables V1..V3 and the active one, tool tables and the tool database changed by a program
are kept in the session's SQLite store (namespaces cpl.zs, cpl.tc, cpl.tdb) so the next run sees them, as
the control keeps them. ZS tables named by a path are files under the file root (offsets.py, zsfile.py).
"""

from __future__ import annotations

from ....diagnostics import UsageError
from ....machine.eventqueue import EventQueue
from ....nc.probe import ProbeLatch
from ....records import Record
from ..options import Options, options
from .gfuncs import NcFuncs

ZS_ROWS = tuple(f"G{b + i}" for b in (54, 154, 254) for i in range(6))
EXTERNAL = ("G160", "G260", "G360")
TDA_FIELDS = 49


class PhysAxis(Record):
    """A physical axis (MACODA 1003 00001 name, 1003 00002 channel, 1003 00012 probe enable)."""

    __slots__ = ("index", "name", "channel", "rotary", "probe", "position", "lag", "jog")

    def __init__(self, index: int, name: str, channel: int, rotary: bool = False, probe: bool = True,
                 position: float = 0.0, lag: float = 0.0, jog: float = 1000.0):
        self.index = index
        self.name = name
        self.channel = channel  # 0 = asynchronous (no channel)
        self.rotary = rotary
        self.probe = probe
        self.position = position  # command position of an axis the NC kernel does not drive (foreign channel)
        self.lag = lag  # following error: APOS = SPOS - lag
        self.jog = jog  # jog speed, mm/min (rotary axes degrees/min)


class Controller(Record):
    """What the CPL control holds of its machine for one run: channels, tables, MACODA, PLC, errors."""

    __slots__ = ("channel", "axes", "zs_unit", "zs_active", "zs_tables", "external", "tc_unit", "tc_last", "tc_tables",
                 "tc_external", "tc_general", "tdb", "macoda", "plc", "errors", "sercos", "sercos_last", "override",
                 "spindle", "message", "language", "date_format", "g_programmed", "g_active", "areas", "ncs", "store",
                 "probe", "probe_events")

    def __init__(self, channel: int = 1, axes: dict[int, PhysAxis] | None = None, zs_unit: str = "mm",
                 zs_active: str = "V1", zs_tables: dict[str, dict] | None = None,
                 external: dict[str, list[float]] | None = None, tc_unit: str = "mm", tc_last: str = "K4",
                 tc_tables: dict[str, dict[int, list[float]]] | None = None,
                 tc_external: dict[int, list[float]] | None = None, tc_general: dict[int, list[float]] | None = None,
                 tdb: dict[tuple[int, int], dict[int, object]] | None = None, macoda: dict[int, list] | None = None,
                 plc: dict[str, int] | None = None, errors: list[dict] | None = None,
                 sercos: dict[int, dict] | None = None, sercos_last: dict | None = None,
                 override: dict[str, int] | None = None, spindle: dict[str, float] | None = None, message: str = "",
                 language: int = 1, date_format: str = "DD.MM", g_programmed: NcFuncs | None = None,
                 g_active: NcFuncs | None = None, areas: list[dict] | None = None,
                 ncs: dict[str, dict] | None = None, store: object = None, probe: ProbeLatch | None = None,
                 probe_events: EventQueue | None = None):
        self.channel = channel
        self.axes = {} if axes is None else axes
        self.zs_unit = zs_unit
        self.zs_active = zs_active
        #: table name -> {"columns": [axis names], "unit": "mm"|"inch", "strict": 0|1, "rows": {"G54": [...]},
        #: "rotary": [axis names]}; at run time only V1..V3 and the active table (the others are files)
        self.zs_tables = {} if zs_tables is None else zs_tables
        self.external = {} if external is None else external  # G160/G260/G360, logical axes 1..8
        self.tc_unit = tc_unit
        self.tc_last = tc_last
        self.tc_tables = {} if tc_tables is None else tc_tables  # group -> [H, D]
        self.tc_external = {} if tc_external is None else tc_external  # G145..G845 -> [L(1)3, R]
        self.tc_general = {} if tc_general is None else tc_general  # G147..G847 -> 8 values
        self.tdb = {} if tdb is None else tdb
        self.macoda = {} if macoda is None else macoda
        self.plc = {} if plc is None else plc  # "type:dm:addr" -> byte
        self.errors = [] if errors is None else errors  # {number, channel, category}
        self.sercos = {} if sercos is None else sercos  # physical axis -> {"S-0-0030": value, ...}
        self.sercos_last = {} if sercos_last is None else sercos_last
        self.override = {"feed": 100, "spindle": 100, "spindle2": 0, "axis": 100} if override is None else override
        #: the spindle's permissible speed range (rpm) and spindle group (MCODS 19, 20, 65)
        self.spindle = {"min": 0.0, "max": 8000.0, "group": 0} if spindle is None else spindle
        self.message = message  # the last message programmed with MSG and executed (MCODS 28)
        self.language = language
        self.date_format = date_format
        self.g_programmed = NcFuncs() if g_programmed is None else g_programmed  # Typ3 G functions at block preparation
        self.g_active = NcFuncs() if g_active is None else g_active  # ... and as executed
        self.areas = [] if areas is None else areas  # work areas and dead ranges 1..10 (SD 200)
        #: what MCOPS changed in the channels of a run: operating modes (MCOPS 7), selected programs,
        #: return-to-path settings, jog recording, automatic re-selection (channel -> value)
        self.ncs = {"mode": {}, "selected": {}, "return": {}, "recording": {}, "reselect": {}} if ncs is None else ncs
        self.store = store
        #: what the last measuring block measured (PROBE, CPROBE read it); code 0: none has run
        self.probe = ProbeLatch(0) if probe is None else probe
        #: the "probe" and "fixed_stop" scenario events no measuring block has used yet (one per block)
        self.probe_events = EventQueue() if probe_events is None else probe_events

    # -- axes ----------------------------------------------------------------------------------
    def channel_axes(self, ch: int) -> list[PhysAxis]:
        """The logical axes of channel ch, numbered 1..k in ascending physical index (CPL manual §4.2, L1256-1337)."""
        return [a for i, a in sorted(self.axes.items()) if a.channel == ch]

    def by_name(self, name: str) -> PhysAxis | None:
        up = name.upper()
        return next((a for a in self.axes.values() if a.name.upper() == up), None)

    # -- persistence ---------------------------------------------------------------------------
    def persist(self, ns: str, key: str, value) -> None:
        if self.store is not None:
            self.store().put(ns, key, value)


#: operating mode (MCOPS 7 / MCODS 31) -> SD(13): 0 single block or step, 1 automatic, 2 program block
SD13_OF_MODE = {5: 1, 13: 1, 6: 2, 7: 0, 10: 0, 12: 0}


def _err(key: str, why: str):
    raise UsageError(f"[cpl] {key}: {why}")


def load_controller(machine, store=None) -> Controller:
    """Build the controller from the machine's ``[cpl]`` options (checked against the schema, unknown keys
    named, by ``options``)."""
    cfg = options(machine)
    try:
        return _build(machine, cfg, store)
    except (KeyError, ValueError, TypeError, AttributeError) as e:
        raise UsageError(f"[cpl]: bad value ({type(e).__name__}: {e})") from None


#: the kinds of scenario event the measuring blocks read (ProbeSwitch, FixedStop; by kind, so that a machine
#: without events imports no event type: start-up, issue 18)
PROBE_KINDS = ("probe", "fixed_stop")


def _build(machine, cfg: Options, store) -> Controller:
    c = Controller(store=store, probe_events=EventQueue([e for e in machine.scenario if e.kind in PROBE_KINDS]))
    c.channel = cfg.channel
    axes = cfg.axes
    if axes is None:
        for i, a in enumerate(machine.axes, 1):
            c.axes[i] = PhysAxis(i, a.name.upper(), c.channel, a.kind == "rotary")
    else:
        for i, a in enumerate(axes, 1):
            if isinstance(a, str):
                a = {"name": a}
            if "name" not in a:
                _err(f"axes[{i}]", "needs a name")
            idx = int(a.get("index", i))
            kind = a.get("type", "linear")
            if kind not in ("linear", "rotary"):
                _err(f"axes[{i}].type", f"{kind!r} (linear or rotary)")
            c.sercos[idx] = {str(k).upper(): v for k, v in (a.get("sercos") or {}).items()}
            c.axes[idx] = PhysAxis(idx, str(a["name"]).upper(), int(a.get("channel", c.channel)), kind == "rotary",
                                   bool(a.get("probe", True)), float(a.get("position", 0.0)), float(a.get("lag", 0.0)),
                                   float(a.get("jog", 1000.0)))
    c.zs_unit, c.tc_unit = cfg.zs_unit, cfg.tc_unit
    c.zs_active = cfg.zs_active
    for name, table in cfg.zs_tables.items():
        c.zs_tables[name] = _zs_table(c, f"zs_tables.{name}", table)
    for name, groups in cfg.tc_tables.items():
        c.tc_tables[name] = {int(g): [float(x) for x in v] + [0.0] * (2 - len(v)) for g, v in groups.items()}
    if "K4" not in c.tc_tables:  # the machine's tool table is compensation table K4
        c.tc_tables["K4"] = {t.number: [t.length, t.radius] for t in machine.tools.values()}
    c.tc_tables.setdefault("K5", {})
    for rec in cfg.tool_database:
        fields = {int(k): v for k, v in (rec.get("fields") or {}).items()}
        c.tdb[(int(rec["sector"]), int(rec["place"]))] = fields
    for num, vals in cfg.macoda.items():
        c.macoda[int(str(num).replace(" ", ""))] = vals if isinstance(vals, list) else [vals]
    for key, val in cfg.plc.items():
        c.plc[str(key)] = int(val)
    for e in cfg.errors:
        c.errors.append({"number": int(e["number"]), "channel": int(e.get("channel", -1)),
                         "category": int(e.get("category", 0))})
    c.override.update({k: int(v) for k, v in cfg.override.items()})
    c.spindle.update({k: (int(v) if k == "group" else float(v)) for k, v in cfg.spindle.items()})
    if not 0 <= c.spindle["group"] <= 4:
        _err("spindle.group", f"{c.spindle['group']} (0 no group, 1..4)")
    c.language = cfg.language
    c.date_format = cfg.date_format
    c.areas = [_area(c, i, a) for i, a in enumerate(cfg.areas, 1)]
    _default_macoda(c)
    if store is not None:
        _load_persistent(c, store())
    return c


AREA_TYPES = {"dead": 1, "work": 2}  # SD(200,3,i): 1 dead range, 2 work area
MAX_AREAS = 10


def _area(c: Controller, i: int, a: dict) -> dict:
    """A work area or dead range: a rectangle on two logical axes of the channel (centre, extent in mm)."""
    if i > MAX_AREAS:
        _err(f"areas[{i}]", f"at most {MAX_AREAS} areas")
    kind = a.get("type", "work")
    if kind not in AREA_TYPES:
        _err(f"areas[{i}].type", f"{kind!r} (work or dead)")
    names = [ax.name for ax in c.channel_axes(c.channel)]
    axes = [str(n).upper() for n in a.get("axes", names[:2])]
    if len(axes) != 2 or any(n not in names for n in axes):
        _err(f"areas[{i}].axes", f"two axes of channel {c.channel} ({', '.join(names)})")
    centre, extent = [float(x) for x in a.get("centre", [0, 0])], [float(x) for x in a.get("extent", [0, 0])]
    if len(centre) != 2 or len(extent) != 2:
        _err(f"areas[{i}]", "centre and extent give two values (1st and 2nd axis)")
    return {"type": AREA_TYPES[kind], "axes": axes, "centre": centre, "extent": extent,
            "active": bool(a.get("active", True))}


def _zs_table(c: Controller, where: str, table: dict) -> dict:
    """A ZS table from the machine file: rows G54 ... G259 (one value per column), optional columns/unit."""
    columns = [str(n).upper() for n in table.get("columns", [c.axes[i].name for i in sorted(c.axes)])]
    out = new_zs_table(columns, table.get("unit", c.zs_unit), int(table.get("strict", 0)))
    out["rotary"] = [a.name for a in c.axes.values() if a.rotary and a.name in columns]
    for row, vals in table.items():
        if row in ("columns", "unit", "strict"):
            continue
        if row.upper() not in ZS_ROWS:
            _err(f"{where}.{row}", f"unknown row (rows: {', '.join(ZS_ROWS)}, columns, unit, strict)")
        v = [float(x) for x in vals]
        if len(v) > len(columns):  # a value without a column would be dropped unseen
            _err(f"{where}.{row}", f"{v} has more values than the {len(columns)} columns ({', '.join(columns)})")
        out["rows"][row.upper()] = v + [0.0] * (len(columns) - len(v))
    return out


def new_zs_table(columns: list[str], unit: str, strict: int = 0) -> dict:
    return {"columns": list(columns), "unit": unit, "strict": strict,
            "rows": {r: [0.0] * len(columns) for r in ZS_ROWS}}


def _default_macoda(c: Controller) -> None:
    axes = [c.axes[i] for i in sorted(c.axes)]
    defaults = {
        100300001: [a.name for a in axes],  # physical axis names
        100300002: [a.channel for a in axes],  # axis -> channel
        100300004: [2 if a.rotary else 1 for a in axes],  # type of axis movement (1 linear, 2 rotary)
        100300012: [1 if a.probe else 0 for a in axes],  # probe can be activated
        206000100: [98],  # first writable PLC DM
        206000110: [2],  # number of writable DMs
        308000005: [c.channel],  # CPL dialog channel
        308000200: [".npv"],  # ZS table extension
        601000010: [c.language],  # national language
        902000010: [0 if c.zs_unit == "mm" else 2],  # table unit
    }
    for k, v in defaults.items():
        c.macoda.setdefault(k, v)


def _load_persistent(c: Controller, store) -> None:
    for name, rows in store.items("cpl.zs").items():
        c.zs_tables[name] = rows
    for name, groups in store.items("cpl.tc").items():
        c.tc_tables[name] = {int(g): v for g, v in groups.items()}
    for key, fields in store.items("cpl.tdb").items():
        s, p = key.split(",")
        c.tdb[(int(s), int(p))] = {int(k): v for k, v in fields.items()}
