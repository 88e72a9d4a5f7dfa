"""Axis zero shifts of manual §4.3: FXC (read and write), FXCR, FXDEL, FXINS.

The active ZS table (machine file [cpl] zs_active, default the database table V1) is the one the NC
kernel uses: its rows G54..G59 are the kernel's work offsets, so a value a program writes acts on the
next G54..G59 selection and on the active one at once (kernel.refresh_offsets). External shifts
G160/G260/G360 act as the kernel's additive offsets. Tables changed by a program are kept in the
session store (namespace cpl.zs).
"""

from __future__ import annotations

from ..errors import CplError
from ..io.values import text_of
from .axes import kernel_index, nul, resolve, to_unit
from .controller import EXTERNAL, ZS_ROWS, new_zs_table
from .gfuncs import additive
from .positions import axis_zs

INCH = 25.4
DB_TABLES = {1: "V1", 2: "V2", 3: "V3"}


# -- the tables and the kernel ---------------------------------------------------------------------
def setup(rt) -> None:
    """At start: make sure V1..V3 and the active table exist; the active table and the kernel agree."""
    c = rt.ctl
    names = [c.axes[i].name for i in sorted(c.axes)]
    for n in DB_TABLES.values():
        if n not in c.zs_tables:
            c.zs_tables[n] = new_zs_table(names, c.zs_unit)
    if c.zs_active not in c.zs_tables:
        c.zs_tables[c.zs_active] = new_zs_table(names, c.zs_unit)
    table = c.zs_tables[c.zs_active]
    configured = rt.machine.sections.get("cpl", {}).get("zs_tables", {}) or {}
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


def _from_mm(v: float, unit: str) -> float:
    return v / INCH if unit == "inch" else v


def _to_mm(v: float, unit: str) -> float:
    return v * INCH if unit == "inch" else v


def push_to_kernel(rt) -> None:
    """The active table's G54..G59 rows, the external shifts and G168/G268 into the NC kernel (in mm)."""
    c, k = rt.ctl, rt.kernel
    table = c.zs_tables[c.zs_active]
    for row in ZS_ROWS[:6]:
        vec = rt.machine.offset(row)
        for i, name in enumerate(k.axis_names):
            if name in table["columns"]:
                vec[i] = _to_mm(table["rows"][row][table["columns"].index(name)], table["unit"])
    k.set_additive_offset(additive(rt, k, c.g_active))
    rt._shadow = None  # the prepared state is rebuilt with the new offsets


def _table_key(c, name: str) -> str | None:
    """The axis ZS table a name means: the full name, else the first table with the same file name."""
    if name in c.zs_tables:
        return name
    base = name.rsplit("/", 1)[-1]
    return next((key for key in c.zs_tables if key.rsplit("/", 1)[-1] == base), None)


def find_table(c, name: str) -> str:
    if not isinstance(name, str):
        raise CplError("CPL032", f"axis ZS table name {name!r}: a string is needed")
    key = _table_key(c, name)
    if key is None:
        raise CplError("CPL040", f"axis ZS table {name!r} does not exist")
    return key


def f_fileaccess(rt, io, name) -> int:
    """FILEACCESS (§6 L4406). The axis ZS tables live in the controller's store, not as files; one answers
    as a readable and writable file (6), since the manual's FXCR example (L1809-1827) asks FILEACCESS
    whether a table exists before creating it."""
    bits = io.files.FILEACCESS(nul(name))
    text = text_of(name)
    if bits == -1 and text and _table_key(rt.ctl, text.strip()) is not None:
        return 6
    return bits


def _table_name(c, table) -> str:
    if table is None:
        return c.zs_active
    if table.__class__ is int:
        if table not in DB_TABLES:
            raise CplError("CPL023", f"ZS table {table}: 1, 2, 3 (V1..V3), 0 (external) or a file name")
        return DB_TABLES[table]
    if isinstance(table, str):
        return find_table(c, table)
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


def _external_axis(rt, sel) -> tuple[int, bool]:
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


def f_fxc(rt, sel, gaddr=None, table=None, unit=None):
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
    t = c.zs_tables[_table_name(c, table)]
    col, _ = _column(t, sel)
    return _convert(t["rows"][_row(gaddr)][col], t["unit"], _unit(unit))


def p_fxc_set(rt, sel, gaddr=None, table=None, unit=None, value=None):
    """FXC(...)=value: positive selection replaces, negative (or '-NAME') adds (L1744-1779)."""
    c = rt.ctl
    value = nul(value)
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise CplError("CPL032", "FXC needs a numeric value")
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
    name = _table_name(c, table)
    t = c.zs_tables[name]
    col, inc = _column(t, sel)
    row = t["rows"][_row(gaddr)]
    u = _unit(unit)
    v = value if u is None else _convert(value, u, t["unit"])
    row[col] = (row[col] if inc else 0.0) + v
    c.persist("cpl.zs", name, t)
    if name == c.zs_active:
        push_to_kernel(rt)


def p_fxcr(rt, layout, name, classif=0):
    """FXCR: create an axis ZS table, one column per channel axis (chan > 0), per system axis (0),
    or with the layout of an existing table (L1781-1796). The unit is MACODA 9020 00010."""
    c = rt.ctl
    name = nul(name)
    if not isinstance(name, str):
        raise CplError("CPL032", "FXCR needs a table name")
    if classif not in (0, 1):
        raise CplError("CPL023", f"classification {classif}: 0 or 1")
    if isinstance(layout, str):
        columns = list(c.zs_tables[find_table(c, layout)]["columns"])
    elif layout == 0:
        columns = [c.axes[i].name for i in sorted(c.axes)]
    elif layout.__class__ is int and layout > 0:
        columns = [a.name for a in c.channel_axes(layout)]
        if not columns:
            raise CplError("1938", f"channel {layout} has no axes")
    else:
        raise CplError("CPL023", f"FXCR layout {layout!r}")
    if name in c.zs_tables:
        raise CplError("CPL040", f"axis ZS table {name!r} exists already")
    unit = "inch" if c.macoda.get(902000010, [0])[0] == 2 else "mm"
    c.zs_tables[name] = new_zs_table(columns, unit, classif)
    c.persist("cpl.zs", name, c.zs_tables[name])


def p_fxdel(rt, name, col):
    """FXDEL: delete a column given by axis name or index (L1798-1827)."""
    c = rt.ctl
    key = find_table(c, nul(name))
    t = c.zs_tables[key]
    i, _ = _column(t, col)
    del t["columns"][i]
    for row in t["rows"].values():
        del row[i]
    c.persist("cpl.zs", key, t)
    if key == c.zs_active:
        push_to_kernel(rt)


def p_fxins(rt, name, pos, axis, axtype=1):
    """FXINS: insert a column for an axis in front of column pos (L1829-1840); axtype 0 rotary, 1 linear."""
    c = rt.ctl
    key = find_table(c, nul(name))
    t = c.zs_tables[key]
    if axtype not in (0, 1):
        raise CplError("CPL023", f"axis type {axtype}: 0 rotary, 1 linear")
    if not isinstance(axis, str):
        raise CplError("CPL032", "FXINS needs an axis name")
    if pos.__class__ is int and pos == len(t["columns"]) + 1:
        i = len(t["columns"])
    else:
        i, _ = _column(t, pos)
    t["columns"].insert(i, axis.upper())
    for row in t["rows"].values():
        row.insert(i, 0.0)
    t.setdefault("rotary", [])
    if axtype == 0:
        t["rotary"].append(axis.upper())
    c.persist("cpl.zs", key, t)
