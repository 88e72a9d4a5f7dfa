"""Axis zero shifts of manual §4.3: FXC (read and write), FXCR, FXDEL, FXINS.

The active ZS table (machine file [cpl] zs_active, default the database table V1) is the one the NC
kernel uses: its rows G54..G59 are the kernel's work offsets, so a value a program writes acts on the
next G54..G59 selection and on the active one at once (kernel.refresh_offsets). External shifts
G160/G260/G360 act as the kernel's additive offsets. The database tables V1..V3 and the active table
are kept in the session store (namespace cpl.zs); every other table is named by a path and is a file
under the controller's file root (zsfile.py), found by the rules of the CPL file functions.
"""

from __future__ import annotations

import math

from ....diagnostics import UsageError
from ....machine.files import FileRootError, Place
from ..errors import CplError
from ..io.values import is_text, text_of
from ..options import options
from . import zsfile
from .axes import kernel_index, nul, resolve, to_unit
from .context import SystemContext
from .controller import EXTERNAL, ZS_ROWS, new_zs_table
from .gfuncs import additive
from .positions import axis_zs

INCH = 25.4
DB_TABLES = {1: "V1", 2: "V2", 3: "V3"}


# -- the tables and the kernel ---------------------------------------------------------------------
def setup(rt: SystemContext) -> None:
    """At start: make sure V1..V3 and the active table exist; the active table and the kernel agree;
    other tables of the machine file (or of an older store) become files."""
    c = rt.ctl
    _tables_to_files(rt)
    names = [c.axes[i].name for i in sorted(c.axes)]
    for n in DB_TABLES.values():
        if n not in c.zs_tables:
            c.zs_tables[n] = new_zs_table(names, c.zs_unit)
    if c.zs_active not in c.zs_tables:
        c.zs_tables[c.zs_active] = new_zs_table(names, c.zs_unit)
    table = c.zs_tables[c.zs_active]
    configured = options(rt.machine).zs_tables
    persisted = c.store is not None and c.zs_active in c.store().items("cpl.zs")
    if c.zs_active not in configured and not persisted:
        # the machine file's [offsets] are the active table's G54..G59 rows
        for row, vec in rt.machine.offsets.items():
            if row in table["rows"]:
                for name, v in zip(rt.kernel.axis_names, vec):
                    if name in table["columns"]:
                        table["rows"][row][table["columns"].index(name)] = _from_mm(v, table["unit"])
    c.external = {g: [0.0] * 8 for g in EXTERNAL}
    push_to_kernel(rt)


def _tables_to_files(rt: SystemContext) -> None:
    """A table of [cpl] zs_tables (or of a store written before tables were files) that is neither a
    database table nor the active one is written to its file under the file root (a name without a
    path lies in the root) when that file does not exist yet; an existing file wins."""
    c = rt.ctl
    store = c.store() if c.store is not None else None
    for name in [n for n in c.zs_tables if n not in DB_TABLES.values() and n != c.zs_active]:
        table = c.zs_tables.pop(name)
        root = rt.io.files.fileroot
        try:
            place = root.place(name)
            missing = root.stat(place) is None
        except FileRootError as e:
            raise UsageError(f"[cpl] zs_tables: {e}") from None
        if missing:
            zsfile.write(rt.io.files, place, table)
        if store is not None and name in store.items("cpl.zs"):
            store.delete("cpl.zs", name)


def _from_mm(v: float, unit: str) -> float:
    return v / INCH if unit == "inch" else v


def _to_mm(v: float, unit: str) -> float:
    return v * INCH if unit == "inch" else v


def push_to_kernel(rt: SystemContext) -> None:
    """The active table's G54..G59 rows, the external shifts and G168/G268 into the NC kernel (in mm)."""
    c, k = rt.ctl, rt.kernel
    table = c.zs_tables[c.zs_active]
    for row in ZS_ROWS[:6]:
        vec = rt.machine.offset(row)
        for i, name in enumerate(k.axis_names):
            if name in table["columns"]:
                vec[i] = _to_mm(table["rows"][row][table["columns"].index(name)], table["unit"])
    k.set_additive_offset(additive(rt, k, c.g_active))
    rt.forget_prepared()  # the prepared state is rebuilt with the new offsets


# -- naming a table ------------------------------------------------------------------------------
class Table:
    """One axis ZS table a statement works on: a database table in the store (``path`` None) or a
    table file under the file root; ``save`` writes it back where it lives."""

    __slots__ = ("key", "place", "data")

    def __init__(self, key: str, place: Place | None, data: dict):
        self.key, self.place, self.data = key, place, data

    def save(self, rt) -> None:
        c = rt.ctl
        if self.place is None:
            c.persist("cpl.zs", self.key, self.data)
            if self.key == c.zs_active:
                push_to_kernel(rt)
        else:
            zsfile.write(rt.io.files, self.place, self.data)


def _name_text(name) -> str:
    if not is_text(nul(name)) or text_of(name) is None:
        raise CplError("CPL032", f"axis ZS table name {name!r}: a string is needed")
    return text_of(name)


def _store_key(c, text: str) -> str | None:
    """The database tables (V1..V3 and the active table) answer to their names spelled exactly."""
    text = text.strip()
    return text if text in c.zs_tables else None


def open_table(rt: SystemContext, name) -> Table:
    """The table ``name`` (a string) means; CPL040 when it does not exist or its file is damaged."""
    c = rt.ctl
    text = _name_text(name)
    key = _store_key(c, text)
    if key is not None:
        return Table(key, None, c.zs_tables[key])
    place = rt.io.files.place_of(text)  # the CPL file functions' rules: INVALID FILE NAME, cwd
    return Table(place.shown, place, zsfile.read(rt.io.files, place))


def f_fileaccess(rt: SystemContext, io, name) -> int:
    """FILEACCESS (§6 L4406). A table file answers like any file; a database table (V1..V3, the active
    table) has no file, and answers as a readable and writable one (6) when no file has its name."""
    bits = io.files.FILEACCESS(nul(name))
    text = text_of(name)
    if bits == -1 and text and _store_key(rt.ctl, text) is not None:
        return 6
    return bits


def _table(rt: SystemContext, table) -> Table:
    """The table of FXC's third argument: omitted = the active one, 1..3 = V1..V3, a string = a name."""
    c = rt.ctl
    if table is None:
        return Table(c.zs_active, None, c.zs_tables[c.zs_active])
    if table.__class__ is int:
        if table not in DB_TABLES:
            raise CplError("CPL023", f"ZS table {table}: 1, 2, 3 (V1..V3), 0 (external) or a file name")
        return Table(DB_TABLES[table], None, c.zs_tables[DB_TABLES[table]])
    if is_text(table):
        return open_table(rt, table)
    raise CplError("CPL032", f"ZS table {table!r}")


def _column(table: dict, sel) -> tuple[int, bool]:
    """(column index 0-based, incremental?) for a column index or an axis name ('-NAME' = incremental)."""
    sel = nul(sel)
    if isinstance(sel, str):
        inc = sel.startswith("-")
        name = sel[1:].upper() if inc else sel.upper()
        if name not in table["columns"]:
            raise CplError("1938", f"axis {name} is not a column of the ZS table")
        return table["columns"].index(name), inc
    if sel.__class__ is not int or sel == 0:
        raise CplError("CPL023", f"ZS column {sel!r}")
    if abs(sel) > len(table["columns"]):
        raise CplError("1938", f"ZS table has no column {abs(sel)}")
    return abs(sel) - 1, sel < 0


def _row(gaddr) -> str:
    row = f"G{nul(gaddr)}"
    if row not in ZS_ROWS:
        raise CplError("CPL023", f"G address {gaddr}: 54..59, 154..159, 254..259 (external: 160, 260, 360)")
    return row


def _unit(unit) -> str | None:
    if unit is None:
        return None
    if unit not in (0, 2):
        raise CplError("CPL023", f"unit {unit}: 0 mm, 2 inch")
    return "mm" if unit == 0 else "inch"


def _convert(v: float, src: str, dst: str | None) -> float:
    if dst is None or src == dst:
        return v
    return v * INCH if src == "inch" else v / INCH


def _external_axis(rt: SystemContext, sel) -> tuple[int, bool]:
    c = rt.ctl
    logical = [a.name for a in c.channel_axes(c.channel)][:8]
    sel = nul(sel)
    if isinstance(sel, str):
        inc = sel.startswith("-")
        name = sel[1:].upper() if inc else sel.upper()
        if name not in logical:
            raise CplError("1970", f"axis {name} is not on channel {c.channel} (external shift)")
        return logical.index(name), inc
    if sel.__class__ is not int or not 1 <= abs(sel) <= len(logical):
        raise CplError("1938", f"external shift: logical axis {sel!r} (1..{len(logical)})")
    return abs(sel) - 1, sel < 0


def f_fxc(rt: SystemContext, sel, gaddr=None, table=None, unit=None):
    """FXC read: a ZS table value, an external shift, or with only the axis the sum of the active shifts."""
    c = rt.ctl
    if gaddr is None and table is None:
        ax = resolve(rt, sel[1:] if isinstance(sel, str) and sel.startswith("-") else
                     (abs(sel) if sel.__class__ is int else sel))
        k = rt.prepared_kernel()
        i = kernel_index(rt, ax)
        if i is None:
            return 0.0
        return to_unit(k, ax, axis_zs(rt, k, i))
    if table == 0:
        g = f"G{gaddr}"
        if g not in EXTERNAL:
            raise CplError("CPL023", f"external shift G{gaddr}: 160, 260 or 360")
        if unit is not None:
            raise CplError("CPL023", "external shifts take no unit (G70/G71 decide)")
        col, _ = _external_axis(rt, sel)
        return c.external[g][col] / rt.prepared_kernel().scale
    t = _table(rt, table).data
    col, _ = _column(t, sel)
    return _convert(t["rows"][_row(gaddr)][col], t["unit"], _unit(unit))


def p_fxc_set(rt: SystemContext, sel, gaddr=None, table=None, unit=None, value=None):
    """FXC(...)=value: positive selection replaces, negative (or '-NAME') adds (L1744-1779)."""
    c = rt.ctl
    value = nul(value)
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise CplError("CPL032", "FXC needs a numeric value")
    if not math.isfinite(value):
        raise CplError("CPL023", f"FXC value {value}: a finite number")
    if gaddr is None:
        raise CplError("CPL023", "FXC write needs a G address")
    if table == 0:
        g = f"G{gaddr}"
        if g not in EXTERNAL:
            raise CplError("CPL023", f"external shift G{gaddr}: 160, 260 or 360")
        col, inc = _external_axis(rt, sel)
        mm = value * rt.prepared_kernel().scale
        c.external[g][col] = (c.external[g][col] if inc else 0.0) + mm
        push_to_kernel(rt)
        return
    table = _table(rt, table)
    t = table.data
    col, inc = _column(t, sel)
    row = t["rows"][_row(gaddr)]
    u = _unit(unit)
    v = value if u is None else _convert(value, u, t["unit"])
    row[col] = (row[col] if inc else 0.0) + v
    table.save(rt)


def p_fxcr(rt: SystemContext, layout, name, classif=0):
    """FXCR: create an axis ZS table file, one column per channel axis (chan > 0), per system axis (0),
    or with the layout of an existing table (L1781-1796). The unit is MACODA 9020 00010."""
    c = rt.ctl
    text = _name_text(name)
    if classif not in (0, 1):
        raise CplError("CPL023", f"classification {classif}: 0 or 1")
    if is_text(layout):
        model = open_table(rt, layout).data
        columns, rotary = list(model["columns"]), list(model.get("rotary", ()))
    elif layout.__class__ is int and layout >= 0:
        axes = [c.axes[i] for i in sorted(c.axes)] if layout == 0 else c.channel_axes(layout)
        if not axes:
            raise CplError("1938", f"channel {layout} has no axes")
        columns, rotary = [a.name for a in axes], [a.name for a in axes if a.rotary]
    else:
        raise CplError("CPL023", f"FXCR layout {layout!r}")
    if _store_key(c, text) is not None:
        raise CplError("CPL040", f"axis ZS table {text.strip()!r} exists already (database table)")
    place = rt.io.files.place_of(text)
    if rt.io.files.stat_of(place) is not None:
        raise CplError("CPL040", f"axis ZS table {place.shown} exists already")
    unit = "inch" if c.macoda.get(902000010, [0])[0] == 2 else "mm"
    table = new_zs_table(columns, unit, classif)
    table["rotary"] = rotary
    Table(place.shown, place, table).save(rt)


def p_fxdel(rt: SystemContext, name, col):
    """FXDEL: delete a column given by axis name or index (L1798-1827)."""
    table = open_table(rt, name)
    t = table.data
    i, _ = _column(t, col)
    gone = t["columns"].pop(i)
    for row in t["rows"].values():
        del row[i]
    if gone not in t["columns"] and gone in t.get("rotary", ()):
        t["rotary"].remove(gone)
    table.save(rt)


def p_fxins(rt: SystemContext, name, pos, axis, axtype=1):
    """FXINS: insert a column for an axis in front of column pos (L1829-1840); axtype 0 rotary, 1 linear."""
    table = open_table(rt, name)
    t = table.data
    if axtype not in (0, 1):
        raise CplError("CPL023", f"axis type {axtype}: 0 rotary, 1 linear")
    if not is_text(nul(axis)) or text_of(axis) is None:
        raise CplError("CPL032", "FXINS needs an axis name")
    axis = text_of(axis).strip().upper()
    if not axis or any(ch.isspace() or ch == ":" for ch in axis) or axis.startswith("-"):
        raise CplError("CPL023", f"FXINS axis name {axis!r}")
    if axis in t["columns"]:
        raise CplError("CPL040", f"axis {axis} is a column of the ZS table already")
    if len(t["columns"]) >= zsfile.MAX_COLUMNS:
        raise CplError("CPL040", f"the ZS table has {zsfile.MAX_COLUMNS} columns, no more fit")
    if pos.__class__ is int and pos == len(t["columns"]) + 1:
        i = len(t["columns"])
    else:
        i, _ = _column(t, pos)
    t["columns"].insert(i, axis)
    for row in t["rows"].values():
        row.insert(i, 0.0)
    t.setdefault("rotary", [])
    if axtype == 0:
        t["rotary"].append(axis)
    table.save(rt)
